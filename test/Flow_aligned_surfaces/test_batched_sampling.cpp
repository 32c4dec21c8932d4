// Fields that answer batches (the optional `sample()` of FlowField_3 and UnsteadyFlowField_3):
// the algorithms give the same results, bit for bit, as with the same field point by point,
// and ask for every sample in batches: a stream surface around a cylinder (tears, lost and
// inserted particles), the same surface with both directions, a path surface, the measures, the
// parametrization, the growth across the flow, and the flow on a path surface; a field in two
// pieces that integrates ahead (integration_ahead.h) gives the same surfaces in fewer batches.
// The peer is the same field without `sample()`.

#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Path_surface_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

// This file's tests and helpers in a namespace of their own (unity batches).
namespace test_batched_sampling {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Polyline = std::vector<Point_3>;

// What a batched field was asked.
struct Counts {
  std::size_t single = 0;  // calls of the call operator
  std::size_t batches = 0; // calls of sample()
  std::size_t points = 0;  // points in the batches
};

// `Field` (steady) with a batch operation that answers as the call operator does, counting.
template <class Field>
struct Batched {
  Field field;
  std::shared_ptr<Counts> counts = std::make_shared<Counts>();

  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    ++counts->single;
    return field(p);
  }
  std::vector<std::optional<Vector_3>> sample(const std::vector<Point_3>& points) const
  {
    ++counts->batches;
    counts->points += points.size();
    std::vector<std::optional<Vector_3>> answers;
    for (const Point_3& p : points)
      answers.push_back(field(p));
    return answers;
  }
};

// The same for an unsteady field.
template <class Field>
struct Batched_unsteady {
  Field field;
  std::shared_ptr<Counts> counts = std::make_shared<Counts>();

  std::optional<Vector_3> operator()(const Point_3& p, double t) const
  {
    ++counts->single;
    return field(p, t);
  }
  std::vector<std::optional<Vector_3>> sample(const std::vector<Point_3>& points,
                                              const std::vector<double>& times) const
  {
    ++counts->batches;
    counts->points += points.size();
    std::vector<std::optional<Vector_3>> answers;
    for (std::size_t i = 0; i < points.size(); ++i)
      answers.push_back(field(points[i], times[i]));
    return answers;
  }
};

// `Field` split into two pieces at the plane x = `cut`, as on two processes, the algorithm on the
// process of the piece x < cut: it answers the samples that its piece alone decides (farther
// than `margin` from the cut) at once (`sample_here()`), and the batch operation integrates the
// waiting particles on in the other piece while their samples lie in it alone, as the ranks of a
// distributed field do.
template <class Field, bool unsteady>
struct Two_pieces {
  Field field;
  double cut = 0, margin = 1e-3;
  std::shared_ptr<Counts> counts = std::make_shared<Counts>();
  std::shared_ptr<std::size_t> along_paths = std::make_shared<std::size_t>(0);  // samples ahead
  std::shared_ptr<std::size_t> sent_back = std::make_shared<std::size_t>(0);    // of those, returned
  std::shared_ptr<std::size_t> states = std::make_shared<std::size_t>(0);       // particles taken on
  std::shared_ptr<std::size_t> meanwhile = std::make_shared<std::size_t>(0);    // first rounds
  std::shared_ptr<std::size_t> here = std::make_shared<std::size_t>(0);         // answered at once
  std::shared_ptr<std::size_t> last_samples = std::make_shared<std::size_t>(0); // particles past the line
  std::shared_ptr<std::size_t> told = std::make_shared<std::size_t>(0);         // particles of first rounds
  std::shared_ptr<std::size_t> told_here = std::make_shared<std::size_t>(0);    // of those, in this piece
  // Samples answered at once on another thread while the other piece integrated (the work of a
  // first round: the backward half of a BOTH surface, integrated in turns with the forward one).
  std::shared_ptr<std::size_t> here_meanwhile_elsewhere = std::make_shared<std::size_t>(0);
  std::shared_ptr<std::optional<std::thread::id>> meanwhile_on = std::make_shared<std::optional<std::thread::id>>();
  std::shared_ptr<std::size_t> rounds_with_work_elsewhere = std::make_shared<std::size_t>(0); // of the first rounds

  using Answer = std::optional<Vector_3>;
  Answer at(const Point_3& p, double t) const
  {
    if constexpr (unsteady)
      return field(p, t);
    else
      return field(p);
  }
  template <bool u = unsteady, std::enable_if_t<!u, int> = 0>
  Answer operator()(const Point_3& p) const
  {
    ++counts->single;
    return field(p);
  }
  template <bool u = unsteady, std::enable_if_t<u, int> = 0>
  Answer operator()(const Point_3& p, double t) const
  {
    ++counts->single;
    return field(p, t);
  }
  bool decides(double side, const Eigen::Vector3d& x) const { return side * (x[0] - cut) > margin; }
  template <bool u = unsteady, std::enable_if_t<!u, int> = 0>
  std::optional<Answer> sample_here(const Point_3& p) const
  {
    return sample_here(p, 0.);
  }
  std::optional<Answer> sample_here(const Point_3& p, double t) const
  {
    if (!decides(-1, Eigen::Vector3d(p.x(), p.y(), p.z())))
      return std::nullopt;
    ++*here;
    if (*meanwhile_on && **meanwhile_on != std::this_thread::get_id())
      ++*here_meanwhile_elsewhere;
    return at(p, t);
  }
  template <bool u = unsteady, std::enable_if_t<!u, int> = 0>
  std::vector<Answer> sample(const std::vector<Point_3>& points) const
  {
    return sample(points, std::vector<double>(points.size(), 0.));
  }
  std::vector<Answer> sample(const std::vector<Point_3>& points, const std::vector<double>& times) const
  {
    FAS::internal::Integrated_ahead<Answer> none;
    return sample(points, times, FAS::internal::Integration_ahead(), none);
  }
  template <bool u = unsteady, std::enable_if_t<!u, int> = 0>
  std::vector<Answer> sample(const std::vector<Point_3>& points,
                             const FAS::internal::Integration_ahead& ahead,
                             FAS::internal::Integrated_ahead<Answer>& along) const
  {
    return sample(points, std::vector<double>(points.size(), 0.), ahead, along);
  }
  std::vector<Answer> sample(const std::vector<Point_3>& points, const std::vector<double>& times,
                             const FAS::internal::Integration_ahead& ahead,
                             FAS::internal::Integrated_ahead<Answer>& along) const
  {
    ++counts->batches;
    counts->points += points.size();
    std::vector<Answer> answers;
    for (std::size_t i = 0; i < points.size(); ++i)
      answers.push_back(at(points[i], times[i]));
    integrate_ahead(ahead, along);
    return answers;
  }
  // The other piece integrates while the algorithm's runs its first round of tasks.
  template <class Work>
  void integrate_ahead_meanwhile(const FAS::internal::Integration_ahead& ahead,
                                 FAS::internal::Integrated_ahead<Answer>& along, const Work& work) const
  {
    ++*meanwhile;
    *told += ahead.size();
    for (std::size_t i = 0; i < ahead.size(); ++i)
      *told_here += decides(-1, ahead.position(i)) ? 1 : 0;
    integrate_ahead(ahead, along);
    *meanwhile_on = std::this_thread::get_id();
    const std::size_t elsewhere_before = *here_meanwhile_elsewhere;
    work();
    meanwhile_on->reset();
    *rounds_with_work_elsewhere += *here_meanwhile_elsewhere > elsewhere_before ? 1 : 0;
  }
  // The other piece integrates the particles `ahead` on, through the numbers it would receive.
  void integrate_ahead(const FAS::internal::Integration_ahead& ahead,
                       FAS::internal::Integrated_ahead<Answer>& along) const
  {
    for (std::size_t i = 0; i < ahead.size(); ++i)
      *last_samples += ahead.kind(i) == FAS::internal::Integration_ahead::LAST_SAMPLE ? 1 : 0;
    FAS::internal::integrate_ahead<Answer>(
        FAS::internal::Integration_ahead::from_numbers(ahead.to_numbers()),
        [&](const Eigen::Vector3d& x, double t) {
          ++*along_paths;
          return at(Point_3(x[0], x[1], x[2]), t);
        },
        [&](const Eigen::Vector3d& x) { return decides(1, x); }, along);
    *sent_back += along.samples.size();
    *states += along.states.size();
  }
};

// `Two_pieces` that also tells where its piece alone decides, as the plugin's distributed field does.
template <class Field, bool unsteady>
struct Two_pieces_telling : Two_pieces<Field, unsteady> {
  bool decides_here(const Point_3& p) const
  {
    return this->decides(-1, Eigen::Vector3d(p.x(), p.y(), p.z()));
  }
};

// `Two_pieces` that tells, while the first round's work runs, that the other piece still
// integrates for the first `busy` times it is asked in each round.
template <class Field>
struct Two_pieces_busy : Two_pieces<Field, false> {
  int busy = 3;
  std::shared_ptr<int> asked = std::make_shared<int>(0);
  template <class Work>
  void integrate_ahead_meanwhile(const FAS::internal::Integration_ahead& ahead,
                                 FAS::internal::Integrated_ahead<typename Two_pieces<Field, false>::Answer>& along,
                                 const Work& work) const
  {
    *asked = 0;
    Two_pieces<Field, false>::integrate_ahead_meanwhile(ahead, along, work);
  }
  bool others_still_integrating() const { return ++*asked <= busy; }
};

struct Surface {
  Mesh tm;
  Mesh::Property_map<Vertex, double> u, t;
  FAS::Stream_surface_report report;

  template <class Field, class NP>
  Surface(const Field& field, const Polyline& seed, const NP& np)
  {
    u = tm.add_property_map<Vertex, double>("v:u", -1).first;
    t = tm.add_property_map<Vertex, double>("v:t", -1).first;
    report = FAS::integrate_stream_surface(
        field, seed, tm,
        FAS::parameters::seed_parameter_map(u, FAS::parameters::integration_time_map(t, np)));
  }
};

// The two surfaces are the same: vertices (points, u, t) and faces in the same order, the
// same report.
void expect_same_surface(const Surface& a, const Surface& b)
{
  ASSERT_GT(a.tm.number_of_faces(), 0u);
  ASSERT_EQ(a.tm.number_of_vertices(), b.tm.number_of_vertices());
  ASSERT_EQ(a.tm.number_of_faces(), b.tm.number_of_faces());
  for (Vertex v : a.tm.vertices()) {
    ASSERT_EQ(a.tm.point(v), b.tm.point(v)) << "vertex " << v;
    ASSERT_EQ(a.u[v], b.u[v]);
    ASSERT_EQ(a.t[v], b.t[v]);
  }
  for (auto f : a.tm.faces()) {
    auto ha = a.tm.halfedge(f), hb = b.tm.halfedge(f);
    for (int k = 0; k < 3; ++k, ha = a.tm.next(ha), hb = b.tm.next(hb))
      ASSERT_EQ(a.tm.target(ha), b.tm.target(hb)) << "face " << f;
  }
  EXPECT_EQ(a.report.number_of_time_lines, b.report.number_of_time_lines);
  EXPECT_EQ(a.report.number_of_inserted_particles, b.report.number_of_inserted_particles);
  EXPECT_EQ(a.report.number_of_removed_particles, b.report.number_of_removed_particles);
  EXPECT_EQ(a.report.number_of_tears, b.report.number_of_tears);
  EXPECT_EQ(a.report.number_of_lost_particles, b.report.number_of_lost_particles);
  EXPECT_EQ(a.report.final_parameter, b.report.final_parameter);
  EXPECT_EQ(a.report.termination, b.report.termination);
}

// Every sample in batches, as many as the report says (and one more, where the default time-line
// step samples the seed curve).
void expect_batched(const Counts& counts, const Surface& s)
{
  EXPECT_EQ(counts.single, 0u);
  EXPECT_GE(counts.batches, s.report.number_of_sample_batches);
  EXPECT_LE(counts.batches, s.report.number_of_sample_batches + 1);
  ASSERT_GT(counts.batches, 0u);
  EXPECT_GT(counts.points, counts.batches);
}

// Under the sanitizers (FAS_TEST_SANITIZED, at -O0) the cylinder's surface stops once the front
// has torn around the cylinder, the linear flow's after less stretching: the same code paths at
// a fraction of the cost.
#ifdef FAS_TEST_SANITIZED
constexpr double cylinder_time = 4.0, linear_time = 1.0;
#else
constexpr double cylinder_time = 10.0, linear_time = 1.5;
#endif

// A surface around a cylinder of radius 1 on the z-axis: tears, lost and inserted particles.
Polyline cylinder_seed()
{
  return {Point_3(-3, -0.6, 0.2), Point_3(-3, 0.6, 0.2)};
}
auto cylinder_surface_parameters()
{
  return FAS::parameters::front_spacing(
      0.05,
      FAS::parameters::max_time(cylinder_time, FAS::parameters::max_number_of_time_lines(std::size_t(1000))));
}

TEST(BatchedSampling, StreamSurfaceAroundACylinderIsTheSameBitForBit)
{
  const FAS::Cylinder_potential_flow<K> cylinder(1.0, 1.0);
  const Batched<FAS::Cylinder_potential_flow<K>> batched{cylinder};
  const Polyline seed = cylinder_seed();
  const auto np = cylinder_surface_parameters();
  const Surface one_by_one(cylinder, seed, np);
  const Surface in_batches(batched, seed, np);
  expect_same_surface(one_by_one, in_batches);
  EXPECT_GE(one_by_one.report.number_of_tears + one_by_one.report.number_of_lost_particles, 1u);
  EXPECT_GE(one_by_one.report.number_of_inserted_particles, 1u);
  EXPECT_EQ(one_by_one.report.number_of_sample_batches, 0u);
  expect_batched(*batched.counts, in_batches);
  std::cout << "cylinder: " << batched.counts->points << " samples in " << batched.counts->batches
            << " batches over " << in_batches.report.number_of_time_lines << " time lines\n";
}

TEST(BatchedSampling, AFrontWithoutInsertionsTakesABatchPerStageOfEachTimeLine)
{
  // A uniform flow: no particle is inserted, and one Runge-Kutta step (six stages after the
  // first) and the sample of the direction at its end bring a time line, or only that sample
  // where the last step reaches beyond it.  Two batches at the seed (the particles' first
  // samples, their directions).
  const FAS::Uniform_flow<K> uniform(Vector_3(0.3, 1, 0.2));
  const Batched<FAS::Uniform_flow<K>> batched{uniform};
  const Polyline seed = {Point_3(0, 0, 0), Point_3(1, 0, 0.5)};
  const auto np = FAS::parameters::front_spacing(
      0.05, FAS::parameters::max_time(2.0, FAS::parameters::time_line_step(0.1)));
  const Surface one_by_one(uniform, seed, np);
  const Surface in_batches(batched, seed, np);
  expect_same_surface(one_by_one, in_batches);
  expect_batched(*batched.counts, in_batches);
  EXPECT_EQ(in_batches.report.number_of_inserted_particles, 0u);
  EXPECT_LE(in_batches.report.number_of_sample_batches, 2 + 7 * in_batches.report.number_of_time_lines);
  // Most of the front in each of them (its particles start with steps of their own size: the
  // starting step depends on the point).
  std::size_t particles = 0;
  for (Vertex v : in_batches.tm.vertices())
    particles += in_batches.t[v] == 0. ? 1 : 0;
  EXPECT_GE(2 * batched.counts->points, particles * batched.counts->batches);
}

TEST(BatchedSampling, BothDirectionsInALinearFlowAreTheSameBitForBit)
{
  // Diverging particles: insertions, level after level.
  const FAS::Linear_flow<K> linear;
  const Batched<FAS::Linear_flow<K>> batched{linear};
  const Polyline seed = {Point_3(0.2, 0.1, 1.0), Point_3(0.4, 0.5, 0.8)};
  const auto np = FAS::parameters::integration_direction(
      FAS::Integration_direction::BOTH,
      FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(linear_time)));
  const Surface one_by_one(linear, seed, np);
  const Surface in_batches(batched, seed, np);
  expect_same_surface(one_by_one, in_batches);
  EXPECT_GE(one_by_one.report.number_of_inserted_particles, 10u);
  expect_batched(*batched.counts, in_batches);
}

TEST(BatchedSampling, PathSurfaceIsTheSameBitForBit)
{
  const Vector_3 U0(1, 0, 0), U1(1, 2, 0.5);
  const FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>> flow(
      {0., 2.}, {FAS::Uniform_flow<K>(U0), FAS::Uniform_flow<K>(U1)});
  const Batched_unsteady<FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>>> batched{flow};
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 0, 1)};
  const auto np = FAS::parameters::front_spacing(
      0.1, FAS::parameters::start_time(0.5, FAS::parameters::time_line_step(0.1)));
  const Surface one_by_one(flow, seed, np);
  const Surface in_batches(batched, seed, np);
  expect_same_surface(one_by_one, in_batches);
  expect_batched(*batched.counts, in_batches);
}

TEST(BatchedSampling, MeasuresAndParametrizationAskOneBatch)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0.2, 0.1, 0.3), Vector_3(0.3, 0.2, 1), 0.5, 0.5, 800);
  const FAS::ABC_flow<K> abc;
  const Batched<FAS::ABC_flow<K>> batched{abc};

  const FAS::Normalized_flux a = FAS::normalized_flux(tm, abc);
  const FAS::Normalized_flux b = FAS::normalized_flux(tm, batched);
  ASSERT_TRUE(a.value && b.value);
  EXPECT_EQ(*a.value, *b.value);
  EXPECT_EQ(a.sampled_area_fraction, b.sampled_area_fraction);
  EXPECT_EQ(batched.counts->batches, 1u);
  EXPECT_EQ(batched.counts->single, 0u);
  EXPECT_EQ(batched.counts->points, tm.number_of_faces());

  *batched.counts = Counts();
  auto ra = tm.add_property_map<Vertex, double>("v:ra", 0).first;
  auto sa = tm.add_property_map<Vertex, double>("v:sa", 0).first;
  auto rb = tm.add_property_map<Vertex, double>("v:rb", 0).first;
  auto sb = tm.add_property_map<Vertex, double>("v:sb", 0).first;
  ASSERT_TRUE(FAS::parametrize_tangential(tm, abc, ra, sa));
  ASSERT_TRUE(FAS::parametrize_tangential(tm, batched, rb, sb));
  for (Vertex v : tm.vertices()) {
    ASSERT_EQ(ra[v], rb[v]);
    ASSERT_EQ(sa[v], sb[v]);
  }
  EXPECT_EQ(batched.counts->batches, 1u);
  EXPECT_EQ(batched.counts->single, 0u);
}

TEST(BatchedSampling, GrowthAcrossTheFlowAsksOneBatch)
{
  // A swirl about the z-axis through a patch beside it: the border edges face across the flow
  // on some sides only.
  const FAS::Helical_flow<K> swirl;
  const Batched<FAS::Helical_flow<K>> batched{swirl};
  Mesh a, b;
  FAS::make_planar_patch(a, Point_3(1.5, 0.2, 0.3), Vector_3(0, 1, 0.2), 0.8, 0.6, 600);
  b = a;
  const FAS::Growth_report one_by_one =
      FAS::grow_boundary(a, 0.1, FAS::parameters::across_flow(true, FAS::parameters::flow_field(swirl)));
  const FAS::Growth_report in_a_batch =
      FAS::grow_boundary(b, 0.1, FAS::parameters::across_flow(true, FAS::parameters::flow_field(batched)));
  ASSERT_GT(one_by_one.number_of_new_faces, 0u);
  EXPECT_EQ(one_by_one.number_of_new_faces, in_a_batch.number_of_new_faces);
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  for (Vertex v : a.vertices())
    ASSERT_EQ(a.point(v), b.point(v));
  EXPECT_EQ(batched.counts->batches, 1u);
  EXPECT_EQ(batched.counts->single, 0u);
}

TEST(BatchedSampling, ThePathSurfaceFlowPassesItsBatchesOn)
{
  // The flow a surface saw, its vertices passed at the times t = x: measured through an unsteady
  // field that answers batches, in one batch of points and their times.
  const Vector_3 U0(1, 0, 0), U1(1, 2, 0.5);
  const FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>> flow(
      {0., 2.}, {FAS::Uniform_flow<K>(U0), FAS::Uniform_flow<K>(U1)});
  const Batched_unsteady<FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>>> batched{flow};
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(1, 0, 0), Vector_3(0, 0.3, 1), 1.5, 1, 400);
  auto times = tm.add_property_map<Vertex, double>("v:time", 0).first;
  for (Vertex v : tm.vertices())
    times[v] = tm.point(v).x();
  using Times = decltype(times);
  const FAS::Path_surface_flow_field_3<decltype(flow), Mesh, Times> one_by_one(flow, tm, times);
  const FAS::Path_surface_flow_field_3<decltype(batched), Mesh, Times> in_a_batch(batched, tm, times);
  const FAS::Normalized_flux a = FAS::normalized_flux(tm, one_by_one);
  const FAS::Normalized_flux b = FAS::normalized_flux(tm, in_a_batch);
  ASSERT_TRUE(a.value && b.value);
  EXPECT_EQ(*a.value, *b.value);
  EXPECT_EQ(batched.counts->batches, 1u);
  EXPECT_EQ(batched.counts->single, 0u);
  EXPECT_EQ(batched.counts->points, tm.number_of_faces());
}

TEST(BatchedSampling, IntegratingAheadInTwoPiecesIsTheSameBitForBitInFewerBatches)
{
  // The cylinder's surface of the first test, its flow in two pieces cut across the flow in
  // front of the cylinder: every particle crosses from one piece into the other, also in the
  // shorter integration under the sanitizers.
  const FAS::Cylinder_potential_flow<K> cylinder(1.0, 1.0);
  const Batched<FAS::Cylinder_potential_flow<K>> batched{cylinder};
  const Two_pieces<FAS::Cylinder_potential_flow<K>, false> pieces{cylinder, -1.5};
  const Polyline seed = cylinder_seed();
  const auto np = cylinder_surface_parameters();
  const Surface one_by_one(cylinder, seed, np);
  const Surface in_batches(batched, seed, np);
  const Surface ahead(pieces, seed, np);
  expect_same_surface(one_by_one, ahead);
  expect_batched(*pieces.counts, ahead);
  EXPECT_GE(ahead.report.number_of_inserted_particles, 1u);
  EXPECT_GT(*pieces.along_paths, pieces.counts->points);
  EXPECT_GT(*pieces.here, pieces.counts->points);
  // The tasks go on from where the particles got to: the paths are not sent back to be replayed.
  EXPECT_GT(*pieces.states, 0u);
  EXPECT_LE(5 * *pieces.sent_back, *pieces.along_paths);
  EXPECT_GE(*pieces.meanwhile, ahead.report.number_of_time_lines);
  // A particle whose last step passed the time line is sent as the sample it still takes there.
  EXPECT_GT(*pieces.last_samples, 0u);
  // A time line costs the stages of a step where a particle crosses the cut, not a round per
  // stage of every path from the seed.
  EXPECT_LE(5 * ahead.report.number_of_sample_batches, in_batches.report.number_of_sample_batches);
  std::cout << "cylinder in two pieces: " << ahead.report.number_of_sample_batches << " batches against "
            << in_batches.report.number_of_sample_batches << " over " << ahead.report.number_of_time_lines
            << " time lines\n";
}

TEST(BatchedSampling, ASurfaceInTheOtherPieceTakesNoBatchAfterItsFirstRounds)
{
  // The saddle's surface from a seed beyond the cut, moving away from it: the other piece takes
  // every particle to each time line while the first round runs, and the tasks then go on from
  // there without asking for the points that round asked for.
  const FAS::Linear_flow<K> linear;
  const Two_pieces<FAS::Linear_flow<K>, false> pieces{linear, 0.3};
  const Polyline seed = {Point_3(0.4, 0.1, 1.0), Point_3(0.5, 0.5, 0.8)};
  const auto np = FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(linear_time));
  const Surface ahead(pieces, seed, np);
  expect_same_surface(Surface(linear, seed, np), ahead);
  EXPECT_GE(ahead.report.number_of_inserted_particles, 1u);
  EXPECT_GE(*pieces.meanwhile, ahead.report.number_of_time_lines);
  EXPECT_EQ(ahead.report.number_of_sample_batches, 0u);
}

TEST(BatchedSampling, AFieldThatTellsWhereItDecidesHearsOfTheOtherParticlesOnly)
{
  const FAS::Cylinder_potential_flow<K> cylinder(1.0, 1.0);
  const Two_pieces<FAS::Cylinder_potential_flow<K>, false> pieces{cylinder, -1.5};
  const Two_pieces_telling<FAS::Cylinder_potential_flow<K>, false> telling{{cylinder, -1.5}};
  const Polyline seed = cylinder_seed();
  const auto np = cylinder_surface_parameters();
  const Surface ahead(pieces, seed, np), told(telling, seed, np);
  expect_same_surface(ahead, told);
  // The same first rounds, of the same particles; those that stand where the algorithm's piece
  // alone decides are left out before their states are written.
  EXPECT_EQ(*telling.meanwhile, *pieces.meanwhile);
  EXPECT_GT(*pieces.told_here, 0u);
  EXPECT_EQ(*telling.told_here, 0u);
  EXPECT_GT(*telling.told, 0u);
  EXPECT_EQ(*telling.told, *pieces.told - *pieces.told_here);
}

TEST(BatchedSampling, IntegratingAheadBothWaysAndOnAPathSurfaceIsTheSameBitForBit)
{
  const FAS::Linear_flow<K> linear;
  const Two_pieces<FAS::Linear_flow<K>, false> pieces{linear, 0.3};
  const Polyline seed = {Point_3(0.2, 0.1, 1.0), Point_3(0.4, 0.5, 0.8)};
  const auto np = FAS::parameters::integration_direction(
      FAS::Integration_direction::BOTH,
      FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(linear_time)));
  expect_same_surface(Surface(linear, seed, np), Surface(pieces, seed, np));
  EXPECT_GT(*pieces.along_paths, 0u);

  const Vector_3 U0(1, 0, 0), U1(1, 2, 0.5);
  using Flow = FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>>;
  const Flow flow({0., 2.}, {FAS::Uniform_flow<K>(U0), FAS::Uniform_flow<K>(U1)});
  const Two_pieces<Flow, true> unsteady_pieces{flow, 0.4};
  const Polyline path_seed = {Point_3(0, 0, 0), Point_3(0, 0, 1)};
  const auto path_np = FAS::parameters::front_spacing(
      0.1, FAS::parameters::start_time(0.5, FAS::parameters::time_line_step(0.1)));
  const Surface path(flow, path_seed, path_np), path_ahead(unsteady_pieces, path_seed, path_np);
  expect_same_surface(path, path_ahead);
  expect_batched(*unsteady_pieces.counts, path_ahead);
  EXPECT_GT(*unsteady_pieces.along_paths, 0u);
  EXPECT_GT(*unsteady_pieces.here, 0u);
}

// The cylinder's surface in both directions, its flow cut behind the seed: the backward half
// stays in the algorithm's piece, the forward half crosses into the other.
struct Cylinder_both_ways {
  FAS::Cylinder_potential_flow<K> cylinder{1.0, 1.0};
  Two_pieces<FAS::Cylinder_potential_flow<K>, false> pieces{cylinder, -2.5};
  Polyline seed = cylinder_seed();
  template <class NP>
  auto parameters(const NP& np) const
  {
    return FAS::parameters::integration_direction(
        FAS::Integration_direction::BOTH,
        FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(cylinder_time / 2, np)));
  }
  auto parameters() const { return parameters(FAS::parameters::max_number_of_time_lines(std::size_t(1000))); }
};

void expect_same_backward_half(const FAS::Stream_surface_report& a, const FAS::Stream_surface_report& b)
{
  ASSERT_TRUE(a.backward && b.backward);
  EXPECT_EQ(a.backward->number_of_time_lines, b.backward->number_of_time_lines);
  EXPECT_EQ(a.backward->final_parameter, b.backward->final_parameter);
  EXPECT_EQ(a.backward->termination, b.backward->termination);
  EXPECT_EQ(a.backward->message, b.backward->message);
  EXPECT_EQ(a.number_of_vertices, b.number_of_vertices);
  EXPECT_EQ(a.number_of_faces, b.number_of_faces);
  EXPECT_EQ(a.stopped, b.stopped);
  EXPECT_EQ(a.message, b.message);
}

TEST(BatchedSampling, TheBackwardHalfInTurnsWithTheForwardOneGivesTheSameSurfaceBitForBit)
{
  // With a field whose other piece integrates while the algorithm's works, the backward half
  // runs while the other piece integrates the forward half's particles.
  const Cylinder_both_ways c;
  const Surface one_by_one(c.cylinder, c.seed, c.parameters()), in_turns(c.pieces, c.seed, c.parameters());
  expect_same_surface(one_by_one, in_turns);
  expect_same_backward_half(one_by_one.report, in_turns.report);
  EXPECT_GT(one_by_one.report.backward->number_of_time_lines, 2u);
  EXPECT_GT(*c.pieces.here_meanwhile_elsewhere, 0u);
  EXPECT_GT(*c.pieces.states, 0u);
}

TEST(BatchedSampling, TheBackwardHalfTakesTurnsAsLongAsTheOtherPieceIntegrates)
{
  // One turn (a time line, or fewer samples) per first round of the forward half where the field
  // does not tell how long the other piece integrates; three where it says the other piece still
  // does.
  const Cylinder_both_ways c;
  const Two_pieces_busy<FAS::Cylinder_potential_flow<K>> busy{{c.cylinder, -2.5}};
  const Surface one_by_one(c.cylinder, c.seed, c.parameters()), in_turns(c.pieces, c.seed, c.parameters());
  const Surface while_busy(busy, c.seed, c.parameters());
  expect_same_surface(one_by_one, while_busy);
  expect_same_backward_half(one_by_one.report, while_busy.report);
  const std::size_t lines = one_by_one.report.backward->number_of_time_lines;
  const std::size_t one_turn = *c.pieces.rounds_with_work_elsewhere, three = *busy.rounds_with_work_elsewhere;
  EXPECT_GE(one_turn, lines - 1);
  ASSERT_GT(three, 0u);
  EXPECT_NEAR(double(one_turn) / double(three), 3.0, 0.3);
}

TEST(BatchedSampling, AStopInTheBackwardHalfInTurnsLeavesOutTheForwardHalf)
{
  const Cylinder_both_ways c;
  auto stop_at_third = [] {
    return std::function<bool(double)>([calls = std::make_shared<int>(0)](double) { return ++*calls < 3; });
  };
  const auto np = c.parameters(CGAL::parameters::callback(stop_at_third()));
  const auto np_in_turns = c.parameters(CGAL::parameters::callback(stop_at_third()));
  const Surface one_by_one(c.cylinder, c.seed, np), in_turns(c.pieces, c.seed, np_in_turns);
  expect_same_surface(one_by_one, in_turns);
  expect_same_backward_half(one_by_one.report, in_turns.report);
  EXPECT_TRUE(in_turns.report.stopped);
  EXPECT_EQ(in_turns.report.backward->number_of_time_lines, 3u);
  EXPECT_EQ(in_turns.report.termination, FAS::Stream_surface_termination::STOPPED);
}

TEST(BatchedSampling, AForwardHalfInTurnsThatMayPassItsVertexLimitIsIntegratedAgain)
{
  // The limit falls on the forward half's first time line: left out while the backward half's
  // vertices were not known, it is found passed once they are (the backward half takes a time
  // line per first round of the forward half), and the forward half is integrated again.
  const Cylinder_both_ways c;
  const auto backward = FAS::parameters::integration_direction(
      FAS::Integration_direction::BACKWARD,
      FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(cylinder_time / 2)));
  const std::size_t limit = Surface(c.cylinder, c.seed, backward).report.number_of_vertices + 10;
  const auto np = c.parameters(FAS::parameters::max_number_of_vertices(limit));
  const Surface one_by_one(c.cylinder, c.seed, np), in_turns(c.pieces, c.seed, np);
  expect_same_surface(one_by_one, in_turns);
  expect_same_backward_half(one_by_one.report, in_turns.report);
  EXPECT_EQ(in_turns.report.termination, FAS::Stream_surface_termination::MAX_NUMBER_OF_VERTICES);
  EXPECT_NE(in_turns.report.backward->termination, FAS::Stream_surface_termination::MAX_NUMBER_OF_VERTICES);
  EXPECT_GE(in_turns.report.number_of_time_lines, 1u);
}

// The cylinder's flow in two pieces, failing behind the seed.
struct Failing_behind : Two_pieces<FAS::Cylinder_potential_flow<K>, false> {
  std::optional<Answer> sample_here(const Point_3& p) const
  {
    if (p.x() < -3.3)
      throw std::runtime_error("no flow behind the seed");
    return Two_pieces::sample_here(p);
  }
};

TEST(BatchedSampling, AFailureOfTheBackwardHalfInTurnsReachesTheCaller)
{
  const Cylinder_both_ways c;
  const Failing_behind failing{{c.cylinder, -2.5}};
  try {
    Surface(failing, c.seed, c.parameters());
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no flow behind the seed");
  }
}

TEST(BatchedSampling, AStopInTheForwardHalfInTurnsKeepsTheWholeBackwardHalf)
{
  // The callback hears of the forward half once the backward half has ended: here in the first
  // rounds of the forward half, as the other piece says it still integrates for a long while.
  const Cylinder_both_ways c;
  Two_pieces_busy<FAS::Cylinder_potential_flow<K>> busy{{c.cylinder, -2.5}};
  busy.busy = 100000;
  const Surface whole(c.cylinder, c.seed, c.parameters());
  const int backward_lines = int(whole.report.backward->number_of_time_lines);
  auto calls = std::make_shared<int>(0);
  const auto np = c.parameters(CGAL::parameters::callback(
      std::function<bool(double)>([calls, backward_lines](double) { return ++*calls <= backward_lines; })));
  const Surface in_turns(busy, c.seed, np);
  EXPECT_TRUE(in_turns.report.stopped);
  EXPECT_EQ(in_turns.report.termination, FAS::Stream_surface_termination::STOPPED);
  EXPECT_EQ(in_turns.report.backward->termination, whole.report.backward->termination);
  EXPECT_EQ(in_turns.report.backward->number_of_time_lines, whole.report.backward->number_of_time_lines);
  EXPECT_GE(in_turns.report.number_of_time_lines, 1u);
  EXPECT_LT(in_turns.report.number_of_time_lines, whole.report.number_of_time_lines);
  EXPECT_EQ(*calls, backward_lines + 1);
}

// A swirl that answers `budget` more samples and then waits for the rest (a task in rounds).
struct Rationed_swirl {
  std::shared_ptr<int> budget = std::make_shared<int>(1000);
  bool waiting() const { return *budget < 0; }
  std::optional<Eigen::Vector3d> operator()(const Eigen::Vector3d& x, double) const
  {
    if (--*budget < 0)
      return std::nullopt;
    return Eigen::Vector3d(-x[1], x[0], 0.5);
  }
};

TEST(BatchedSampling, ASuspendedStepLeavesTheIntegratorAsItWas)
{
  using Integrator = FAS::internal::Dormand_prince_integrator<Rationed_swirl>;
  const auto state_of = [](const Integrator& it) {
    std::vector<double> numbers(Integrator::state_size);
    it.write_state(numbers.data());
    return numbers;
  };
  const Rationed_swirl rationed, unlimited;
  Integrator it(rationed, Eigen::Vector3d(1, 0, 0), 0, 1),
      reference(unlimited, Eigen::Vector3d(1, 0, 0), 0, 1);
  // The first step also chooses the starting step size (two samples), then takes 6 stages.
  for (int round = 0; round < 3; ++round) {
    std::size_t suspended = 0;
    for (int budget = 0;; ++budget) {
      const std::vector<double> before = state_of(it);
      *rationed.budget = budget;
      const FAS::internal::Step_result r = it.resumable_step();
      if (r != FAS::internal::Step_result::SUSPENDED) {
        ASSERT_EQ(r, reference.step());
        break;
      }
      ++suspended;
      ASSERT_EQ(state_of(it), before) << "round " << round << ", " << budget << " samples";
    }
    EXPECT_GE(suspended, 6u);
    ASSERT_EQ(state_of(it), state_of(reference)) << "round " << round;
  }
}

TEST(BatchedSampling, AnIntegratorGoesOnFromItsNumbers)
{
  // Written and read back, an integrator takes the same steps as the one that wrote it.
  using Field = std::function<std::optional<Eigen::Vector3d>(const Eigen::Vector3d&, double)>;
  const Field swirl = [](const Eigen::Vector3d& x, double t) {
    return std::optional<Eigen::Vector3d>(Eigen::Vector3d(-x[1], x[0], 0.1 + t));
  };
  using Integrator = FAS::internal::Dormand_prince_integrator<Field>;
  Integrator a(swirl, Eigen::Vector3d(1, 0, 0), 0.3, -1);
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(a.step(), FAS::internal::Step_result::ACCEPTED);
  std::vector<double> numbers(Integrator::state_size);
  a.write_state(numbers.data());
  Integrator b(swirl, numbers.data());
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(a.step(), b.step());
    ASSERT_EQ(a.position(), b.position());
    ASSERT_EQ(a.parameter(), b.parameter());
    ASSERT_EQ(a.time(), b.time());
    ASSERT_EQ(a.dense_output(a.parameter() - 1e-3), b.dense_output(b.parameter() - 1e-3));
  }
  EXPECT_EQ(a.number_of_evaluations(), b.number_of_evaluations());

  // The particles to integrate ahead tell where they stand, also when only some are kept.
  FAS::internal::Integration_ahead ahead;
  ahead.add_start(Eigen::Vector3d(1, 2, 3));
  ahead.add_state(a);
  EXPECT_EQ(ahead.position(0), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(ahead.position(1), a.position());
  const FAS::internal::Integration_ahead kept = ahead.only({1});
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept.position(0), a.position());
  EXPECT_THROW(FAS::internal::Integration_ahead::from_numbers(std::vector<double>(14, 0.)),
               std::invalid_argument);

  // A particle past the target takes its one sample there and no step.
  FAS::internal::Integration_ahead past;
  past.target = a.parameter() - 1e-3;
  past.add_last_sample(a.dense_output(past.target), 0.25);
  EXPECT_EQ(past.kind(0), FAS::internal::Integration_ahead::LAST_SAMPLE);
  EXPECT_EQ(past.position(0), a.dense_output(past.target));
  using Answer = std::optional<Vector_3>;
  FAS::internal::Integrated_ahead<Answer> along;
  FAS::internal::integrate_ahead<Answer>(
      FAS::internal::Integration_ahead::from_numbers(past.to_numbers()),
      [](const Eigen::Vector3d& x, double t) { return Answer(Vector_3(x[0], x[1], t)); },
      [](const Eigen::Vector3d&) { return true; }, along);
  EXPECT_TRUE(along.states.empty());
  ASSERT_EQ(along.samples.size(), 1u);
  EXPECT_EQ(along.samples[0].x, past.position(0));
  EXPECT_EQ(along.samples[0].t, 0.25);
  EXPECT_EQ(along.samples[0].answer, Answer(Vector_3(past.position(0)[0], past.position(0)[1], 0.25)));

  // A record of no kind is refused.
  std::vector<double> no_kind = past.to_numbers();
  no_kind[no_kind.size() - FAS::internal::Integration_ahead::record_size] = 3;
  EXPECT_THROW(FAS::internal::Integration_ahead::from_numbers(no_kind), std::invalid_argument);
}

// A batch operation that answers a point less than asked.
struct Short_batches {
  std::optional<Vector_3> operator()(const Point_3&) const { return Vector_3(1, 0, 0); }
  std::vector<std::optional<Vector_3>> sample(const std::vector<Point_3>& points) const
  {
    return std::vector<std::optional<Vector_3>>(points.empty() ? 0 : points.size() - 1, Vector_3(1, 0, 0));
  }
};

TEST(BatchedSampling, ABatchOfTheWrongSizeIsRefusedWithItsCounts)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1, 1, 50);
  try {
    FAS::normalized_flux(tm, Short_batches());
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("answered " + std::to_string(tm.number_of_faces() - 1) + " of " +
                                         std::to_string(tm.number_of_faces()) + " points"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace test_batched_sampling
