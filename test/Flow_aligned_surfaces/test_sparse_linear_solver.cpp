// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameter `sparse_linear_solver`, with the solver of a build without CHOLMOD
// (Eigen's SimplicialLDLT): the deformation (`align_to_flow()`), its growth
// (`Flow_aligned_deformation::grow()`, which factors the grown surface anew) and the two
// parametrizations give the surfaces and maps of the default solver, to 1e-9 of the diameter.
// (The free `grow_boundary()` factors nothing.)  Without CHOLMOD both sides are Eigen's, and the
// comparison only checks that the parameter is accepted.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/SparseCholesky>

#include "planar_patch_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace test_sparse_linear_solver {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Simplicial = CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>;

// The tolerance of every comparison, relative to the diameter of the surface: the two solvers
// round differently (about 1e-16 of a solution), and the iterations do not amplify it this much.
constexpr double tolerance = 1e-9;

using fas_test::diameter;
using fas_test::planar_patch;

// The largest distance between the vertices of two meshes of the same connectivity.
double largest_distance(const Mesh& a, const Mesh& b)
{
  EXPECT_EQ(a.number_of_vertices(), b.number_of_vertices());
  double largest = 0;
  for (Vertex v : a.vertices())
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(a.point(v), b.point(v))));
  return largest;
}


TEST(SparseLinearSolver, DefaultIsCholmodsWhenFoundElseEigens)
{
  using Default = FAS::internal::Default_sparse_linear_solver::Solver;
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
  EXPECT_TRUE((std::is_same<Default, FAS::internal::Cholmod_LDLT_swept>::value));
#else
  EXPECT_TRUE((std::is_same<Default, Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>::value));
#endif
}

template <class Flow>
void expect_the_default_solvers_alignment(const Mesh& start, const Flow& flow, FAS::Alignment alignment)
{
  Mesh by_default = start, simplicial = start;
  const FAS::Alignment_report a = FAS::align_to_flow(by_default, flow, alignment);
  const FAS::Alignment_report b =
      FAS::align_to_flow(simplicial, flow, alignment, CGAL::parameters::sparse_linear_solver(Simplicial()));
  EXPECT_TRUE(a.converged);
  EXPECT_EQ(a.converged, b.converged);
  EXPECT_EQ(a.number_of_iterations, b.number_of_iterations);
  EXPECT_LT(largest_distance(by_default, simplicial), tolerance * diameter(by_default));
}

TEST(SparseLinearSolver, AlignToFlowGivesTheDefaultSolversSurface)
{
  expect_the_default_solvers_alignment(planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 3000),
                                       FAS::Point_source_flow<K>(Point(0, 0, 0), 1.0),
                                       FAS::Alignment::ORTHOGONAL);
  expect_the_default_solvers_alignment(planar_patch(Point(1.0, 0.2, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 3000),
                                       FAS::Helical_flow<K>(0.5), FAS::Alignment::TANGENTIAL);
}

TEST(SparseLinearSolver, GrowingGivesTheDefaultSolversSurface)
{
  using Flow = FAS::Point_source_flow<K>;
  const Flow source(Point(0, 0, 0), 1.0);
  Mesh by_default, simplicial;
  FAS::make_disk_patch(by_default, Point(0.1, 0.2, 2.0), Vector(0.2, 0.1, 1.0), 0.5, 1000);
  simplicial = by_default;
  FAS::Flow_aligned_deformation<Mesh, Flow> a(by_default, source, FAS::Alignment::ORTHOGONAL);
  FAS::Flow_aligned_deformation<Mesh, Flow, CGAL::Default, CGAL::Default, Simplicial> b(
      simplicial, source, FAS::Alignment::ORTHOGONAL);
  a.run();
  b.run();
  const FAS::Growth_report grown_a = a.grow(0.1), grown_b = b.grow(0.1);
  EXPECT_EQ(grown_a.number_of_new_faces, grown_b.number_of_new_faces);
  const FAS::Alignment_report after_a = a.run(), after_b = b.run();
  EXPECT_TRUE(after_a.converged);
  EXPECT_EQ(after_a.number_of_iterations, after_b.number_of_iterations);
  ASSERT_EQ(by_default.number_of_faces(), simplicial.number_of_faces());
  EXPECT_LT(largest_distance(by_default, simplicial), tolerance * diameter(by_default));
}

// Runs `parametrize` (a call of parametrize_tangential() or parametrize_orthogonal() with the
// named parameters it is given) with the default solver and with Eigen's; r and s agree.
template <class Parametrize>
void expect_the_default_solvers_maps(const Mesh& tm, const Parametrize& parametrize)
{
  Mesh copy = tm;
  auto r = copy.add_property_map<Vertex, double>("v:r", 0.).first;
  auto s = copy.add_property_map<Vertex, double>("v:s", 0.).first;
  auto r_simplicial = copy.add_property_map<Vertex, double>("v:r_simplicial", 0.).first;
  auto s_simplicial = copy.add_property_map<Vertex, double>("v:s_simplicial", 0.).first;
  ASSERT_TRUE(parametrize(copy, r, s, CGAL::parameters::default_values()));
  ASSERT_TRUE(
      parametrize(copy, r_simplicial, s_simplicial, CGAL::parameters::sparse_linear_solver(Simplicial())));
  double largest = 0, range = 0;
  for (Vertex v : copy.vertices()) {
    largest = (std::max)({largest, std::abs(r[v] - r_simplicial[v]), std::abs(s[v] - s_simplicial[v])});
    range = (std::max)({range, std::abs(r[v]), std::abs(s[v])});
  }
  EXPECT_GT(range, 0.);
  EXPECT_LT(largest, tolerance * diameter(copy));
}

TEST(SparseLinearSolver, ParametrizationsGiveTheDefaultSolversMaps)
{
  const FAS::Helical_flow<K> helix(0.5);
  const Mesh tm = planar_patch(Point(1.0, 0.2, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 3000);
  expect_the_default_solvers_maps(tm, [&](const Mesh& m, auto r, auto s, const auto& np) {
    return FAS::parametrize_tangential(m, helix, r, s, np);
  });
  expect_the_default_solvers_maps(tm, [&](const Mesh& m, auto r, auto s, const auto& np) {
    return FAS::parametrize_orthogonal(m, helix, r, s, np);
  });
}

} // namespace

} // namespace test_sparse_linear_solver
