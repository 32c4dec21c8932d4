// The Poisson operators of Section 3 against closed forms: gradients of linear
// functions, the cotangent formula, and the identities L = G^T A G, D G = L.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Poisson_operators {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace FAS = CGAL::Flow_aligned_surfaces;
namespace FASI = CGAL::Flow_aligned_surfaces::internal;

struct Curved_patch {
  FASI::Positions x;
  FASI::Mesh_arrays arrays;
  FASI::Poisson_operators ops;
};

// A disk patch bent onto a paraboloid, so that the faces are not coplanar.
Curved_patch make_curved_patch(std::size_t faces)
{
  Mesh tm;
  FAS::make_disk_patch(tm, K::Point_3(0.1, -0.2, 0.3), K::Vector_3(0.2, 0.1, 1), 1.0, faces);
  for (auto v : tm.vertices()) {
    const K::Point_3 p = tm.point(v);
    tm.point(v) = K::Point_3(p.x(), p.y(), p.z() + 0.3 * (p.x() * p.x() - 0.5 * p.y() * p.y()));
  }
  Curved_patch patch;
  const auto vim = get(CGAL::vertex_index, tm);
  patch.x = FASI::read_positions(FASI::vertices_in_index_order(tm, vim), tm.points());
  patch.arrays = FASI::make_mesh_arrays(tm, vim, get(CGAL::face_index, tm));
  patch.ops =
      std::get<FASI::Poisson_operators>(FASI::make_poisson_operators(patch.x, patch.arrays.face_vertices));
  return patch;
}

TEST(PoissonOperators, GradientOfLinearFunctionIsExactProjection)
{
  const Curved_patch patch = make_curved_patch(400);
  const Eigen::Vector3d g(0.7, -1.3, 2.1);
  const Eigen::VectorXd u = patch.x * g; // u(x) = g . x
  const Eigen::VectorXd grad = patch.ops.G * u;
  for (std::size_t j = 0; j < patch.arrays.face_vertices.size(); ++j) {
    const auto& f = patch.arrays.face_vertices[j];
    const Eigen::Vector3d a = patch.x.row(f[0]), b = patch.x.row(f[1]), c = patch.x.row(f[2]);
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    // The surface gradient of a linear function is its gradient projected into the face plane.
    const Eigen::Vector3d expected = g - n * n.dot(g);
    const Eigen::Vector3d got = grad.segment<3>(3 * Eigen::Index(j));
    EXPECT_LT((got - expected).norm(), 1e-10 * g.norm()) << "face " << j;
  }
}

TEST(PoissonOperators, LaplacianIsSymmetricPositiveSemiDefiniteAndAnnihilatesConstants)
{
  const Curved_patch patch = make_curved_patch(200);
  const Eigen::MatrixXd l = Eigen::MatrixXd(patch.ops.L);
  EXPECT_LT((l - l.transpose()).cwiseAbs().maxCoeff(), 1e-12 * l.cwiseAbs().maxCoeff());
  EXPECT_LT((l * Eigen::VectorXd::Ones(l.rows())).cwiseAbs().maxCoeff(), 1e-12 * l.cwiseAbs().maxCoeff());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(l);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-10 * eigen.eigenvalues().maxCoeff());
  // Exactly one zero eigenvalue on a connected patch.
  EXPECT_GT(eigen.eigenvalues()(1), 1e-8 * eigen.eigenvalues().maxCoeff());
}

TEST(PoissonOperators, LaplacianEqualsCotangentFormula)
{
  const Curved_patch patch = make_curved_patch(300);
  // L_ik = -1/2 (cot alpha + cot beta) for the angles opposite edge ik (Pinkall-Polthier).
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(patch.x.rows(), patch.x.rows());
  for (const auto& f : patch.arrays.face_vertices)
    for (int corner = 0; corner < 3; ++corner) {
      const Eigen::Index o = f[corner], i = f[(corner + 1) % 3], k = f[(corner + 2) % 3];
      const Eigen::Vector3d e1 = patch.x.row(i) - patch.x.row(o), e2 = patch.x.row(k) - patch.x.row(o);
      const double cot = e1.dot(e2) / e1.cross(e2).norm();
      expected(i, k) -= 0.5 * cot;
      expected(k, i) -= 0.5 * cot;
      expected(i, i) += 0.5 * cot;
      expected(k, k) += 0.5 * cot;
    }
  EXPECT_LT((Eigen::MatrixXd(patch.ops.L) - expected).cwiseAbs().maxCoeff(),
            1e-10 * expected.cwiseAbs().maxCoeff());
}

// Each face keeps its stiffness K_j = A_j grad^T grad as three numbers (its rows sum to zero);
// its entries and its product with a matrix are those of the dense K_j built from the closed-form
// gradients, and each off-diagonal entry is -cot/2 of the angle opposite its edge.
TEST(PoissonOperators, FaceStiffnessIsTheDenseStiffnessOfTheGradients)
{
  const Curved_patch patch = make_curved_patch(300);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (const FASI::Reference_face& face : patch.ops.faces) {
    const Eigen::Vector3d a = patch.x.row(face.vertices[0]).transpose(), b = patch.x.row(face.vertices[1]).transpose(),
                          c = patch.x.row(face.vertices[2]).transpose();
    const auto t = FASI::triangle_gradients(a, b, c);
    ASSERT_TRUE(t);
    const Eigen::Matrix3d dense = t->area * t->gradients.transpose() * t->gradients;
    const double scale = dense.cwiseAbs().maxCoeff();
    Eigen::Matrix3d entries;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        entries(i, k) = face.stiffness(i, k);
    EXPECT_LE((entries - dense).cwiseAbs().maxCoeff(), 1e-13 * scale);
    const std::array<Eigen::Vector3d, 3> p = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d e1 = p[std::size_t((i + 1) % 3)] - p[std::size_t(i)];
      const Eigen::Vector3d e2 = p[std::size_t((i + 2) % 3)] - p[std::size_t(i)];
      EXPECT_NEAR(face.edge_stiffness[std::size_t(i)], -0.5 * e1.dot(e2) / e1.cross(e2).norm(), 1e-13 * scale);
    }
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i)
      m(i / 3, i % 3) = uniform(random);
    EXPECT_LE((face.times_stiffness(m) - dense * m).cwiseAbs().maxCoeff(), 1e-13 * scale);
  }
}

// L is assembled column by column without triplets; it must be the matrix that
// Eigen's setFromTriplets() makes of the faces' stiffness matrices, entry for entry and bit for
// bit (the same sums in the same order), also with the vertices in a random order and on a mesh
// of two components with a boundary.  Fails if an entry is missing, duplicated, misplaced or
// summed in another order.
TEST(PoissonOperators, LaplacianIsTheTripletAssemblyOfTheFaceStiffnesses)
{
  Mesh tm;
  FAS::make_disk_patch(tm, K::Point_3(0.1, -0.2, 0.3), K::Vector_3(0.2, 0.1, 1), 1.0, 300);
  FAS::make_planar_patch(tm, K::Point_3(3, 0, 0), K::Vector_3(1, 1, 1), 1.0, 0.5, 200);
  for (auto v : tm.vertices()) {
    const K::Point_3 p = tm.point(v);
    tm.point(v) = K::Point_3(p.x(), p.y(), p.z() + 0.3 * (p.x() * p.x() - 0.5 * p.y() * p.y()));
  }
  std::vector<std::size_t> order(num_vertices(tm));
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(18));
  auto vim = tm.add_property_map<Mesh::Vertex_index, std::size_t>("v:shuffled").first;
  for (auto v : tm.vertices())
    vim[v] = order[std::size_t(v)];
  const FASI::Positions x = FASI::read_positions(FASI::vertices_in_index_order(tm, vim), tm.points());
  const FASI::Mesh_arrays arrays = FASI::make_mesh_arrays(tm, vim, get(CGAL::face_index, tm));
  ASSERT_EQ(arrays.number_of_components, 2u);
  const auto ops =
      std::get<FASI::Poisson_operators>(FASI::make_poisson_operators(x, arrays.face_vertices, FASI::Operators_asked::stiffness));

  std::vector<Eigen::Triplet<double>> triplets;
  for (const FASI::Reference_face& face : ops.faces)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        triplets.emplace_back(face.vertices[i], face.vertices[k], face.stiffness(i, k));
  Eigen::SparseMatrix<double> expected(x.rows(), x.rows());
  expected.setFromTriplets(triplets.begin(), triplets.end());

  ASSERT_TRUE(ops.L.isCompressed());
  ASSERT_EQ(ops.L.nonZeros(), expected.nonZeros());
  for (Eigen::Index c = 0; c <= x.rows(); ++c)
    ASSERT_EQ(ops.L.outerIndexPtr()[c], expected.outerIndexPtr()[c]) << "column " << c;
  for (Eigen::Index k = 0; k < expected.nonZeros(); ++k) {
    EXPECT_EQ(ops.L.innerIndexPtr()[k], expected.innerIndexPtr()[k]) << "entry " << k;
    EXPECT_EQ(ops.L.valuePtr()[k], expected.valuePtr()[k]) << "entry " << k;
  }
}

void expect_same_operators(const FASI::Poisson_operators& got, const FASI::Poisson_operators& expected)
{
  ASSERT_EQ(got.faces.size(), expected.faces.size());
  for (std::size_t j = 0; j < expected.faces.size(); ++j) {
    ASSERT_EQ(got.faces[j].vertices, expected.faces[j].vertices) << "face " << j;
    ASSERT_EQ(got.faces[j].area, expected.faces[j].area) << "face " << j;
    ASSERT_EQ(got.faces[j].edge_stiffness, expected.faces[j].edge_stiffness) << "face " << j;
  }
  ASSERT_EQ(got.face_areas, expected.face_areas);
  ASSERT_TRUE(got.L.isCompressed());
  ASSERT_EQ(got.L.rows(), expected.L.rows());
  ASSERT_EQ(got.L.cols(), expected.L.cols());
  ASSERT_EQ(got.L.nonZeros(), expected.L.nonZeros());
  for (Eigen::Index c = 0; c <= expected.L.cols(); ++c)
    ASSERT_EQ(got.L.outerIndexPtr()[c], expected.L.outerIndexPtr()[c]) << "column " << c;
  for (Eigen::Index k = 0; k < expected.L.nonZeros(); ++k) {
    ASSERT_EQ(got.L.innerIndexPtr()[k], expected.L.innerIndexPtr()[k]) << "entry " << k;
    ASSERT_EQ(got.L.valuePtr()[k], expected.L.valuePtr()[k]) << "entry " << k;
  }
}

// After grow_boundary() (new vertices and faces after the old ones), the old operators extended
// by extend_poisson_operators() are those made from scratch on the grown mesh, to the last bit,
// three times in a row (the first extension reallocates, the next ones work in place in the
// room the first left).  The old vertices are numbered in a random order, so that columns
// without new entries lie between columns with some and must be moved.  Fails if a column is
// misplaced while moving, an entry is lost or added twice in the merge, or the sums are made in
// another order.
TEST(PoissonOperators, ExtendedOperatorsOfAGrownMeshAreTheOperatorsOfTheWholeMesh)
{
  Mesh tm;
  FAS::make_disk_patch(tm, K::Point_3(0.1, -0.2, 0.3), K::Vector_3(0.2, 0.1, 1), 1.0, 300);
  std::vector<std::size_t> order(num_vertices(tm));
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(18));
  auto vim = tm.add_property_map<Mesh::Vertex_index, std::size_t>("v:order").first;
  for (auto v : tm.vertices())
    vim[v] = std::size_t(v) < order.size() ? order[std::size_t(v)] : std::size_t(v);
  const auto fim = get(CGAL::face_index, tm);
  auto positions = [&] { return FASI::read_positions(FASI::vertices_in_index_order(tm, vim), tm.points()); };
  FASI::Mesh_arrays arrays = FASI::make_mesh_arrays(tm, vim, fim);
  auto ops = std::get<FASI::Poisson_operators>(
      FASI::make_poisson_operators(positions(), arrays.face_vertices, FASI::Operators_asked::stiffness));
  for (int round = 0; round < 3; ++round) {
    const std::size_t old_faces = num_faces(tm), old_vertices = num_vertices(tm);
    FAS::grow_boundary(tm, 0.1);
    ASSERT_GT(num_faces(tm), old_faces);
    ASSERT_GT(num_vertices(tm), old_vertices);
    for (auto v : tm.vertices()) // Surface_mesh numbers the new vertices after the old ones
      if (std::size_t(v) >= old_vertices)
        vim[v] = std::size_t(v);
    arrays = FASI::make_mesh_arrays(tm, vim, fim);
    const FASI::Positions x = positions();
    ASSERT_FALSE(FASI::extend_poisson_operators(ops, x, arrays.face_vertices));
    const auto expected =
        std::get<FASI::Poisson_operators>(FASI::make_poisson_operators(x, arrays.face_vertices, FASI::Operators_asked::stiffness));
    expect_same_operators(ops, expected);
  }
}

TEST(PoissonOperators, DivergenceOfGradientIsLaplacian)
{
  const Curved_patch patch = make_curved_patch(300);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd u(patch.x.rows());
  for (Eigen::Index i = 0; i < u.size(); ++i)
    u[i] = uniform(rng);
  const Eigen::VectorXd lhs = patch.ops.D * (patch.ops.G * u);
  const Eigen::VectorXd rhs = patch.ops.L * u;
  EXPECT_LT((lhs - rhs).cwiseAbs().maxCoeff(), 1e-10 * rhs.cwiseAbs().maxCoeff());
  // L = G^T A G as matrices.
  const Eigen::MatrixXd gtag =
      Eigen::MatrixXd(patch.ops.G.transpose()) * patch.ops.area_matrix() * Eigen::MatrixXd(patch.ops.G);
  EXPECT_LT((gtag - Eigen::MatrixXd(patch.ops.L)).cwiseAbs().maxCoeff(), 1e-10 * gtag.cwiseAbs().maxCoeff());
}

// D, assembled column by column, is Eigen's product G^T A to the last bit, with the same
// entries in the same places, on a mesh whose faces list their vertices in every cyclic order
// (face j rotated by j mod 3); asked for the divergence alone, the same D and no G.
TEST(PoissonOperators, DivergenceIsTheProductOfTheGradientTransposedAndTheAreas)
{
  const Curved_patch patch = make_curved_patch(300);
  std::vector<std::array<Eigen::Index, 3>> faces = patch.arrays.face_vertices;
  std::set<std::array<bool, 2>> orders; // (fv[0] < fv[1], fv[1] < fv[2]) of the faces
  for (std::size_t j = 0; j < faces.size(); ++j) {
    std::rotate(faces[j].begin(), faces[j].begin() + std::ptrdiff_t(j % 3), faces[j].end());
    orders.insert({faces[j][0] < faces[j][1], faces[j][1] < faces[j][2]});
  }
  ASSERT_GE(orders.size(), 3u);
  const auto all = std::get<FASI::Poisson_operators>(FASI::make_poisson_operators(patch.x, faces));
  const Eigen::SparseMatrix<double> product = all.G.transpose() * all.area_matrix();
  const auto same_bits = [&product](const Eigen::SparseMatrix<double>& d) {
    if (d.rows() != product.rows() || d.cols() != product.cols() || d.nonZeros() != product.nonZeros())
      return false;
    for (Eigen::Index k = 0; k <= d.cols(); ++k)
      if (d.outerIndexPtr()[k] != product.outerIndexPtr()[k])
        return false;
    for (Eigen::Index e = 0; e < d.nonZeros(); ++e)
      if (d.innerIndexPtr()[e] != product.innerIndexPtr()[e] ||
          std::memcmp(&d.valuePtr()[e], &product.valuePtr()[e], sizeof(double)) != 0)
        return false;
    return true;
  };
  EXPECT_TRUE(same_bits(all.D));
  const auto divergence_only = std::get<FASI::Poisson_operators>(
      FASI::make_poisson_operators(patch.x, faces, FASI::Operators_asked::divergence));
  EXPECT_TRUE(same_bits(divergence_only.D));
  EXPECT_EQ(divergence_only.G.nonZeros(), 0);
}

TEST(PoissonOperators, AreasSumToSurfaceArea)
{
  Mesh tm;
  FAS::make_planar_patch(tm, K::Point_3(1, 2, 3), K::Vector_3(1, 1, 1), 2.0, 0.5, 500);
  const auto vim = get(CGAL::vertex_index, tm);
  const auto x = FASI::read_positions(FASI::vertices_in_index_order(tm, vim), tm.points());
  const auto arrays = FASI::make_mesh_arrays(tm, vim, get(CGAL::face_index, tm));
  const auto ops = std::get<FASI::Poisson_operators>(FASI::make_poisson_operators(x, arrays.face_vertices));
  EXPECT_NEAR(ops.face_areas.sum(), 1.0, 1e-12);
}

TEST(PoissonOperators, DegenerateFaceIsReported)
{
  FASI::Positions x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0;
  const auto built = FASI::make_poisson_operators(x, {{0, 1, 3}, {0, 1, 2}});
  ASSERT_TRUE(std::holds_alternative<FASI::Degenerate_face>(built));
  EXPECT_EQ(std::get<FASI::Degenerate_face>(built).face, 1u);
}

} // namespace

} // namespace test_Poisson_operators
