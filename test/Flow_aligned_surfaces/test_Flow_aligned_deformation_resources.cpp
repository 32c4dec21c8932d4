// What a deformation costs its caller besides time: it neither copies the user's field (a field
// that holds a 128^3 grid by value would be copied, and its memory doubled, by every
// construction), nor starts threads the caller did not ask for (CHOLMOD 3's supernodal
// factorization starts OpenMP threads, CHOLMOD_OMP_NUM_THREADS = 4, and calls the system's
// multi-threaded BLAS; on a loaded machine their spinning made the same solve vary 20 times).
//
// The answers are known without the package: a field that counts its own copies must count none;
// the threads of the process (/proc/self/task) must be those it had before; with
// use_parallelism(true) in a tbb::task_arena of one thread, the field is called from the calling
// thread only.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Flow_aligned_deformation_resources {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

// A uniform flow along x that, like a field read from a file, holds its samples by value (a
// 128^3 grid of 3 floats, 25 MB) and counts how often it is copied.
class Counting_grid_field {
public:
  static inline std::atomic<int> copies{0};

  Counting_grid_field() : m_samples(std::size_t(3) * 128 * 128 * 128, 0.0f)
  {
    for (std::size_t i = 0; i < m_samples.size(); i += 3)
      m_samples[i] = 1.0f;
  }
  Counting_grid_field(const Counting_grid_field& other) : m_samples(other.m_samples) { ++copies; }
  Counting_grid_field& operator=(const Counting_grid_field& other)
  {
    m_samples = other.m_samples;
    ++copies;
    return *this;
  }

  std::optional<Vector> operator()(const Point&) const
  {
    return Vector(m_samples[0], m_samples[1], m_samples[2]);
  }

private:
  std::vector<float> m_samples;
};

// A 2 x 1 rectangle in the plane z = 0 with its long sides along the flow (x): a stream surface.
Mesh make_rectangle(std::size_t faces)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), 2.0, 1.0, faces,
                         FAS::parameters::patch_axis(Vector(1, 0, 0)));
  return tm;
}

std::size_t number_of_threads()
{
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++n;
  return n;
}

// The point source |v| = 1/r^2 at (0, 0, -1.6): a curved flow, so iterations do real work.
std::optional<Vector> point_source(const Point& p)
{
  const Vector d = p - Point(0, 0, -1.6);
  const double r2 = d.squared_length();
  return d / (r2 * std::sqrt(r2));
}

// Constructs and steps a deformation of a 2e4-face patch (above CHOLMOD's supernodal switch, near
// 5e3 faces) and grows it; exits with the number of threads the process gained.
template <class NamedParameters>
[[noreturn]] void exit_with_new_threads(const NamedParameters& np)
{
  const std::size_t before = number_of_threads();
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0.2), Vector(0.3, 0, 1), 1.0, 1.0, 20000);
  auto field = &point_source;
  FAS::Flow_aligned_deformation<Mesh, decltype(field)> deformation(tm, field, FAS::Alignment::ORTHOGONAL, np);
  deformation.step();
  deformation.step();
  deformation.grow(0.01);
  deformation.step();
  const std::size_t after = number_of_threads();
  std::fprintf(stderr, "threads before %zu, after %zu\n", before, after);
  std::fflush(stderr);
  std::_Exit(int(after - before));
}

} // namespace

TEST(FlowAlignedDeformationResources, NoCopyOfTheField)
{
  const Counting_grid_field field;
  Counting_grid_field::copies = 0;

  Mesh tm = make_rectangle(800);
  {
    FAS::Flow_aligned_deformation<Mesh, Counting_grid_field> deformation(tm, field,
                                                                         FAS::Alignment::TANGENTIAL);
    EXPECT_EQ(Counting_grid_field::copies, 0) << "construction";
    EXPECT_EQ(&deformation.field(), &field);
    deformation.step();
    deformation.translate(Vector(0.1, 0.2, 0));
    deformation.rotate(Vector(0, 0, 1), 0.01);
    EXPECT_TRUE(deformation.run().converged);
    deformation.rotate(Vector(0, 0, 1), -0.01);
    const FAS::Growth_report grown = deformation.grow(0.05, FAS::parameters::across_flow(true));
    EXPECT_NEAR(grown.added_area, 2 * 2.0 * 0.05, 1e-6); // the two long sides, answer of the plane
    deformation.step();
    auto r = tm.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
    auto s = tm.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
    deformation.parametrize_tangential(r, s);
    EXPECT_NEAR(deformation.current_normalized_flux().value.value(), 0.0, 1e-9);
    EXPECT_EQ(Counting_grid_field::copies, 0) << "step, run, moves, grow, parametrize";
  }

  // The free functions take the field by reference too, flow_field() included.
  Mesh other = make_rectangle(800);
  EXPECT_NEAR(FAS::normalized_flux(other, field).value.value(), 0.0, 1e-12);
  EXPECT_TRUE(FAS::align_to_flow(other, field, FAS::Alignment::TANGENTIAL).converged);
  const FAS::Growth_report grown =
      FAS::grow_boundary(other, 0.05, FAS::parameters::across_flow(true, FAS::parameters::flow_field(field)));
  EXPECT_NEAR(grown.added_area, 2 * 2.0 * 0.05, 1e-6);
  auto r = other.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
  auto s = other.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
  FAS::parametrize_tangential(other, field, r, s);
  EXPECT_EQ(Counting_grid_field::copies, 0) << "free functions";
}

// Where the preparation's time went: the constructor's two factorization phases are the whole
// FACTOR that run(0) reports, and after grow() the report holds the refactorization only (the
// check and the mesh arrays are grow()'s own).
TEST(FlowAlignedDeformationResources, ConstructionReportAccountsForTheFactorizations)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0.2), Vector(0.3, 0, 1), 1.0, 1.0, 2000);
  auto field = &point_source;
  FAS::Flow_aligned_deformation<Mesh, decltype(field)> deformation(tm, field, FAS::Alignment::ORTHOGONAL);
  const FAS::Construction_report built = deformation.construction_report();
  for (double phase : {built.check_ms, built.mesh_arrays_ms, built.operators_ms, built.constraints_ms,
                       built.analyze_ms, built.factorize_ms}) {
    EXPECT_TRUE(std::isfinite(phase));
    EXPECT_GE(phase, 0);
  }
  const double constructor_factor_ms = deformation.run(0).factor_ms;
  EXPECT_GT(constructor_factor_ms, 0);
  EXPECT_DOUBLE_EQ(built.analyze_ms + built.factorize_ms, constructor_factor_ms);

  deformation.step();
  deformation.grow(0.02);
  const FAS::Construction_report grown = deformation.construction_report();
  EXPECT_EQ(grown.check_ms, 0);
  EXPECT_EQ(grown.mesh_arrays_ms, 0);
  EXPECT_NEAR(grown.analyze_ms + grown.factorize_ms, deformation.run(0).factor_ms - constructor_factor_ms,
              1e-9 * deformation.run(0).factor_ms);
}

// Compile-time: a temporary field cannot be given to the deformation, which holds a reference.
static_assert(!std::is_constructible_v<FAS::Flow_aligned_deformation<Mesh, Counting_grid_field>, Mesh&,
                                       Counting_grid_field, FAS::Alignment>);
static_assert(std::is_constructible_v<FAS::Flow_aligned_deformation<Mesh, Counting_grid_field>, Mesh&,
                                      const Counting_grid_field&, FAS::Alignment>);

// Each case runs in a process of its own (the "threadsafe" death-test style re-executes the
// test binary), so that threads left by other tests in this process cannot hide new ones.
TEST(FlowAlignedDeformationResources, NoThreadStartedWithoutParallelism)
{
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(exit_with_new_threads(CGAL::parameters::default_values()), testing::ExitedWithCode(0), "");
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(FlowAlignedDeformationResources, ParallelismStaysInTheCallersArena)
{
  // In an arena of one thread, use_parallelism(true) starts no thread either (the factorization
  // included) ...
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        tbb::task_arena arena(1);
        arena.execute([] { exit_with_new_threads(FAS::parameters::use_parallelism(true)); });
      },
      testing::ExitedWithCode(0), "");

  // ... and the field is called from the calling thread only.
  std::mutex mutex;
  std::set<std::thread::id> callers;
  auto field = [&](const Point& p) {
    std::lock_guard<std::mutex> lock(mutex);
    callers.insert(std::this_thread::get_id());
    return point_source(p);
  };
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0.2), Vector(0.3, 0, 1), 1.0, 1.0, 8000);
  tbb::task_arena arena(1);
  arena.execute([&] {
    FAS::Flow_aligned_deformation<Mesh, decltype(field)> deformation(tm, field, FAS::Alignment::ORTHOGONAL,
                                                                     FAS::parameters::use_parallelism(true));
    deformation.step();
  });
  EXPECT_EQ(callers, std::set<std::thread::id>{std::this_thread::get_id()});
}
#endif

} // namespace test_Flow_aligned_deformation_resources
