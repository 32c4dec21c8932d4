// The same flow alignment on every model of FaceListGraph the design names:
// CGAL::Surface_mesh, CGAL::Polyhedron_3 with and without vertex/face ids (the latter
// through CGAL's dynamic index maps) and an OpenMesh TriMesh.  The algorithm works on
// arrays in index order, and every mesh type gets its vertices and faces in the order
// make_planar_patch creates them, so the results must agree with Surface_mesh's to
// rounding.

#ifdef FAS_HAVE_OPENMESH
// OpenMesh's PropertyT<VectorT>::push_back() (every add_vertex) copies a default-constructed,
// deliberately uninitialized VectorT; GCC reports it at -O2 inside <new_allocator.h>, where
// only a pragma that precedes the standard headers reaches it.
// Pushed here and popped after the includes, so that it reaches no file compiled after this
// one in a unity batch.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#ifdef FAS_HAVE_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/Mesh/Traits.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#if defined(FAS_HAVE_OPENMESH) && defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_mesh_types {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

using Surface_mesh = CGAL::Surface_mesh<Point>;
using Polyhedron_with_ids = CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3>;
using Polyhedron = CGAL::Polyhedron_3<K>;

// How a test reaches the points of a mesh type: the named parameters to pass to every
// call (none for the CGAL types, whose internal vertex point map holds K::Point_3).
template <class Mesh>
struct Mesh_access {
  static auto np(Mesh&) { return CGAL::parameters::default_values(); }
  static auto vpm(Mesh& tm) { return get(CGAL::vertex_point, tm); }
  static auto read_vpm(const Mesh& tm) { return get(CGAL::vertex_point, tm); }
};

#ifdef FAS_HAVE_OPENMESH
// OpenMesh with double points.  CGAL's own OpenMesh vertex point map rounds every point it
// writes to float (properties_OpenMesh.h casts to float before building the OpenMesh point,
// whatever its scalar), so the double mesh goes through this map instead.
using OpenMesh_double = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;
// OpenMesh's default TriMesh: float points, CGAL's default vertex point map.
using OpenMesh_float = OpenMesh::TriMesh_ArrayKernelT<>;

class OpenMesh_point_map {
public:
  using key_type = boost::graph_traits<OpenMesh_double>::vertex_descriptor;
  using value_type = Point;
  using reference = Point;
  using category = boost::read_write_property_map_tag;

  OpenMesh_point_map() = default;
  explicit OpenMesh_point_map(const OpenMesh_double& tm) : m_tm(const_cast<OpenMesh_double*>(&tm)) {}

  friend Point get(const OpenMesh_point_map& map, key_type v)
  {
    const OpenMesh::Vec3d& p = map.m_tm->point(v);
    return Point(p[0], p[1], p[2]);
  }
  friend void put(const OpenMesh_point_map& map, key_type v, const Point& p)
  {
    map.m_tm->set_point(v, OpenMesh::Vec3d(p.x(), p.y(), p.z()));
  }

private:
  OpenMesh_double* m_tm = nullptr;
};

template <>
struct Mesh_access<OpenMesh_double> {
  static auto np(OpenMesh_double& tm) { return CGAL::parameters::vertex_point_map(OpenMesh_point_map(tm)); }
  static OpenMesh_point_map vpm(OpenMesh_double& tm) { return OpenMesh_point_map(tm); }
  static OpenMesh_point_map read_vpm(const OpenMesh_double& tm) { return OpenMesh_point_map(tm); }
};
#endif

// The positions of `tm` in vertex iteration order.
template <class Mesh>
std::vector<std::array<double, 3>> positions(const Mesh& tm)
{
  const auto vpm = Mesh_access<Mesh>::read_vpm(tm);
  std::vector<std::array<double, 3>> result;
  for (auto v : vertices(tm)) {
    const Point p = get(vpm, v);
    result.push_back({p.x(), p.y(), p.z()});
  }
  return result;
}

double largest_distance(const std::vector<std::array<double, 3>>& a,
                        const std::vector<std::array<double, 3>>& b)
{
  double largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    largest = (std::max)(largest, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1], a[i][2] - b[i][2]));
  return largest;
}

// One alignment problem: a planar patch, a flow and a target.
struct Problem {
  Point center;
  Vector normal;
  double size;
  std::size_t faces;
  FAS::Alignment alignment;
};

// Orthogonal in a point source: the patch becomes a piece of a sphere.
const Problem orthogonal_problem{Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 1000,
                                 FAS::Alignment::ORTHOGONAL};
// Tangential in the helical flow: the patch becomes a piece of a cylinder around z.
const Problem tangential_problem{Point(1.0, 0.2, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 1000,
                                 FAS::Alignment::TANGENTIAL};

struct Outcome {
  std::vector<std::array<double, 3>> initial, final;
  std::size_t number_of_vertices = 0, number_of_faces = 0;
  FAS::Alignment_report report;
  double measured_flux = 0; // normalized_flux() of the final surface
};

template <class Mesh, class Flow>
Outcome solve(const Problem& problem, const Flow& flow)
{
  Mesh tm;
  FAS::make_planar_patch(tm, problem.center, problem.normal, problem.size, problem.size, problem.faces,
                         Mesh_access<Mesh>::np(tm));
  Outcome outcome;
  outcome.number_of_vertices = num_vertices(tm);
  outcome.number_of_faces = num_faces(tm);
  outcome.initial = positions(tm);
  outcome.report = FAS::align_to_flow(tm, flow, problem.alignment, Mesh_access<Mesh>::np(tm));
  outcome.final = positions(tm);
  outcome.measured_flux = FAS::normalized_flux(tm, flow, Mesh_access<Mesh>::np(tm)).value.value();
  return outcome;
}

// Checks that the reference run did something worth comparing: it met its flux target and
// moved the patch by much more than the comparison tolerance.
void expect_meaningful_reference(const Problem& problem, const Outcome& reference)
{
  ASSERT_GT(reference.number_of_faces, problem.faces / 2);
  EXPECT_TRUE(reference.report.converged);
  if (problem.alignment == FAS::Alignment::ORTHOGONAL)
    EXPECT_GE(reference.report.normalized_flux.value.value(), 0.995);
  else
    EXPECT_LE(reference.report.normalized_flux.value.value(), 0.01);
  EXPECT_GT(largest_distance(reference.initial, reference.final), 1e-2 * problem.size);
}

void expect_same_outcome(const Problem& problem, const Outcome& reference, const Outcome& other,
                         double tolerance)
{
  ASSERT_EQ(other.number_of_vertices, reference.number_of_vertices);
  ASSERT_EQ(other.number_of_faces, reference.number_of_faces);
  ASSERT_EQ(other.initial.size(), reference.initial.size());
  // make_planar_patch creates the same points in the same order on every mesh type.
  EXPECT_EQ(largest_distance(other.initial, reference.initial), 0.0);
  EXPECT_EQ(other.report.number_of_iterations, reference.report.number_of_iterations);
  EXPECT_EQ(other.report.converged, reference.report.converged);
  EXPECT_NEAR(other.report.normalized_flux.value.value(), reference.report.normalized_flux.value.value(),
              tolerance);
  EXPECT_NEAR(other.measured_flux, reference.measured_flux, tolerance);
  EXPECT_LE(largest_distance(other.final, reference.final), tolerance * problem.size);
}

template <class Mesh>
class MeshTypes : public ::testing::Test {
};

using Mesh_types = ::testing::Types<Polyhedron_with_ids, Polyhedron
#ifdef FAS_HAVE_OPENMESH
                                    ,
                                    OpenMesh_double
#endif
                                    >;
TYPED_TEST_SUITE(MeshTypes, Mesh_types);

TYPED_TEST(MeshTypes, OrthogonalAlignmentInPointSourceMatchesSurfaceMesh)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const Outcome reference = solve<Surface_mesh>(orthogonal_problem, source);
  expect_meaningful_reference(orthogonal_problem, reference);
  expect_same_outcome(orthogonal_problem, reference, solve<TypeParam>(orthogonal_problem, source), 1e-9);
}

TYPED_TEST(MeshTypes, TangentialAlignmentInHelicalFlowMatchesSurfaceMesh)
{
  const FAS::Helical_flow<K> helix(0.5);
  const Outcome reference = solve<Surface_mesh>(tangential_problem, helix);
  expect_meaningful_reference(tangential_problem, reference);
  expect_same_outcome(tangential_problem, reference, solve<TypeParam>(tangential_problem, helix), 1e-9);
}

// The interactive class too: a step, a rigid move and a run, with the vertex point map given
// explicitly and the index maps left to their defaults.
TYPED_TEST(MeshTypes, InteractiveDeformationWithRigidMoveMatchesSurfaceMesh)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const auto run = [&source](auto& tm) {
    using Mesh = std::remove_reference_t<decltype(tm)>;
    using Vpm = decltype(Mesh_access<Mesh>::vpm(tm));
    FAS::make_planar_patch(tm, Point(0, 0.1, 1.5), Vector(0.2, -0.3, 1.0), 0.8, 0.8, 500,
                           CGAL::parameters::vertex_point_map(Mesh_access<Mesh>::vpm(tm)));
    FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>, Vpm> deformation(
        tm, source, FAS::Alignment::ORTHOGONAL,
        CGAL::parameters::vertex_point_map(Mesh_access<Mesh>::vpm(tm)));
    deformation.step();
    deformation.rotate(Vector(1, 0, 0), 0.3);
    const FAS::Alignment_report report = deformation.run();
    EXPECT_TRUE(report.converged);
    EXPECT_GE(report.normalized_flux.value.value(), 0.995);
    EXPECT_EQ(deformation.number_of_factorizations(), 1u);
    return positions(tm);
  };
  Surface_mesh reference_mesh;
  TypeParam mesh;
  const auto reference = run(reference_mesh);
  const auto other = run(mesh);
  ASSERT_EQ(other.size(), reference.size());
  EXPECT_LE(largest_distance(other, reference), 1e-9 * 0.8);
}

// The seeding stages of Section 5 on an aligned orthogonal surface: the free orthogonal
// parametrization and geodesic distance, the deformation's own parametrization (with its
// factorization), iso-contours of r and seed points, with the index maps left to their
// defaults and dynamic property maps for the outputs.
struct Seeding_outcome {
  std::vector<double> r, s, shared_r, shared_s, distance;
  std::vector<std::array<double, 3>> contour_points, seed_points;
  std::size_t number_of_contours = 0;
};

template <class Mesh>
Seeding_outcome seed(const FAS::Point_source_flow<K>& source)
{
  using Vpm = decltype(Mesh_access<Mesh>::vpm(std::declval<Mesh&>()));
  Mesh tm;
  const auto np = CGAL::parameters::vertex_point_map(Mesh_access<Mesh>::vpm(tm));
  FAS::make_planar_patch(tm, Point(0, 0.1, 1.5), Vector(0.2, -0.3, 1.0), 0.8, 0.8, 800, np);
  FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>, Vpm> deformation(
      tm, source, FAS::Alignment::ORTHOGONAL, np);
  deformation.run();
  auto r = get(CGAL::dynamic_vertex_property_t<double>(), tm),
       s = get(CGAL::dynamic_vertex_property_t<double>(), tm),
       shared_r = get(CGAL::dynamic_vertex_property_t<double>(), tm),
       shared_s = get(CGAL::dynamic_vertex_property_t<double>(), tm),
       distance = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  FAS::parametrize_orthogonal(tm, source, r, s,
                              FAS::parameters::angle(0.3, FAS::parameters::normalized(true, np)));
  deformation.parametrize_orthogonal(shared_r, shared_s,
                                     FAS::parameters::angle(0.3, FAS::parameters::normalized(true)));
  FAS::compute_geodesic_distance(tm, *vertices(tm).begin(), distance, np);
  std::vector<std::vector<Point>> contours;
  FAS::extract_iso_contours(tm, r, std::vector<double>{-0.2, 0.0, 0.2}, std::back_inserter(contours), np);
  std::vector<Point> seeds;
  FAS::sample_seed_points(tm, 0.1, std::back_inserter(seeds), np);

  Seeding_outcome outcome;
  for (auto v : vertices(tm)) {
    outcome.r.push_back(get(r, v));
    outcome.s.push_back(get(s, v));
    outcome.shared_r.push_back(get(shared_r, v));
    outcome.shared_s.push_back(get(shared_s, v));
    outcome.distance.push_back(get(distance, v));
  }
  outcome.number_of_contours = contours.size();
  for (const auto& contour : contours)
    for (const Point& p : contour)
      outcome.contour_points.push_back({p.x(), p.y(), p.z()});
  for (const Point& p : seeds)
    outcome.seed_points.push_back({p.x(), p.y(), p.z()});
  return outcome;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    largest = (std::max)(largest, std::abs(a[i] - b[i]));
  return largest;
}

TYPED_TEST(MeshTypes, SeedingStagesMatchSurfaceMesh)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const Seeding_outcome reference = seed<Surface_mesh>(source);
  const Seeding_outcome other = seed<TypeParam>(source);
  // The reference is meaningful: r spans the contour values, three contours cross the patch,
  // the distance grows to the far corner, and the shared factorization agrees with the free one.
  ASSERT_FALSE(reference.r.empty());
  EXPECT_LT(*std::min_element(reference.r.begin(), reference.r.end()), -0.2);
  EXPECT_GT(*std::max_element(reference.r.begin(), reference.r.end()), 0.2);
  EXPECT_EQ(reference.number_of_contours, 3u);
  EXPECT_GT(*std::max_element(reference.distance.begin(), reference.distance.end()), 0.8);
  EXPECT_LE(largest_difference(reference.shared_r, reference.r), 1e-3);
  EXPECT_GT(reference.seed_points.size(), 20u);

  ASSERT_EQ(other.r.size(), reference.r.size());
  EXPECT_LE(largest_difference(other.r, reference.r), 1e-9);
  EXPECT_LE(largest_difference(other.s, reference.s), 1e-9);
  EXPECT_LE(largest_difference(other.shared_r, reference.shared_r), 1e-9);
  EXPECT_LE(largest_difference(other.shared_s, reference.shared_s), 1e-9);
  EXPECT_LE(largest_difference(other.distance, reference.distance), 1e-9);
  EXPECT_EQ(other.number_of_contours, reference.number_of_contours);
  ASSERT_EQ(other.contour_points.size(), reference.contour_points.size());
  EXPECT_LE(largest_distance(other.contour_points, reference.contour_points), 1e-9);
  ASSERT_EQ(other.seed_points.size(), reference.seed_points.size());
  EXPECT_LE(largest_distance(other.seed_points, reference.seed_points), 1e-9);
}

#ifdef FAS_HAVE_OPENMESH
// OpenMesh's default TriMesh stores float points, and CGAL's default vertex point map for it
// converts to K::Point_3 and back: the package works through it unchanged, to float precision.
// The reference is a Surface_mesh run on the same patch rounded to float, since the face the
// deformation anchors (the one nearest the barycenter) is a tie on this symmetric patch that
// the rounding decides, and the anchor moves the final surface by 0.6% of the patch size.
TEST(MeshTypesOpenMesh, DefaultFloatTriMeshAlignsThroughCGALsVertexPointMap)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const Problem& problem = orthogonal_problem;
  OpenMesh_float tm;
  FAS::make_planar_patch(tm, problem.center, problem.normal, problem.size, problem.size, problem.faces);
  Surface_mesh reference;
  FAS::make_planar_patch(reference, problem.center, problem.normal, problem.size, problem.size,
                         problem.faces);
  const auto initial = positions(tm);
  ASSERT_EQ(initial.size(), num_vertices(reference));
  // The reference starts from the float-rounded points, read back from OpenMesh (a float cast
  // written in this loop was compiled away for two of three coordinates by GCC 12.2 at -O2).
  // Half a float ulp is at most 2.4e-7 per coordinate below 4.
  EXPECT_LE(largest_distance(initial, positions(reference)), 5e-7);
  std::size_t i = 0;
  for (auto v : reference.vertices()) {
    reference.point(v) = Point(initial[i][0], initial[i][1], initial[i][2]);
    ++i;
  }

  const FAS::Alignment_report expected = FAS::align_to_flow(reference, source, problem.alignment);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, source, problem.alignment);
  EXPECT_TRUE(report.converged);
  EXPECT_GE(report.normalized_flux.value.value(), 0.995);
  EXPECT_EQ(report.number_of_iterations, expected.number_of_iterations);
  EXPECT_NEAR(FAS::normalized_flux(tm, source).value.value(),
              FAS::normalized_flux(reference, source).value.value(), 1e-6);
  ASSERT_GT(largest_distance(initial, positions(reference)), 1e-2 * problem.size);
  // Every iteration rounds the coordinates (about 2) to float, 1.2e-7 each.
  EXPECT_LE(largest_distance(positions(tm), positions(reference)), 1e-5 * problem.size);
}
#endif

} // namespace

} // namespace test_mesh_types
