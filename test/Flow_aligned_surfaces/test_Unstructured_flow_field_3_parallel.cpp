// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unstructured_flow_field_3 under a TBB parallel_for, as the deformation calls it: coherent
// paths through 16^3 jittered hexahedra and 6 * 10^3 tetrahedra (more cells than a thread's
// walk cache holds), one path per task so that every thread's walk switches between paths,
// must give the linear field the mesh carries, and the same values (to rounding) as the same
// queries made one after the other on one thread.  Also the face neighbours that the walk
// uses, against the cube indices they must be.

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include "jittered_cube_mesh.h"
#include "test_kernel.h"
#include "skip_without_tool.h"

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Unstructured_flow_field_3_parallel {

namespace {

using namespace fas_test;
typedef FAS::Unstructured_flow_field_3<K> Field;

// Paths of 120 points 0.3 cell apart (n cubes per axis), turning slowly, bouncing off the
// cube's faces a little inside them.
std::vector<std::array<double, 3>> paths(int n, int count)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> start(0.05, 0.95);
  std::normal_distribution<double> g(0., 1.);
  std::vector<std::array<double, 3>> r;
  for (int p = 0; p < count; ++p) {
    std::array<double, 3> x = {start(rng), start(rng), start(rng)}, d = {g(rng), g(rng), g(rng)};
    for (int s = 0; s < 120; ++s) {
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int a = 0; a < 3; ++a) {
        x[a] += 0.3 / n * d[a] / len;
        if (x[a] < 0.01 || x[a] > 0.99) {
          x[a] = x[a] < 0.01 ? 0.01 : 0.99;
          d[a] = -d[a];
        }
        d[a] += 0.2 * g(rng);
      }
      r.push_back(x);
    }
  }
  return r;
}

void check_parallel(int n, bool tetrahedra)
{
#ifndef CGAL_LINKED_WITH_TBB
  (void)n;
  (void)tetrahedra;
  FAS_SKIP_WITHOUT_TOOL("built without TBB (CGAL_LINKED_WITH_TBB is not defined)");
#else
  const Field field = jittered_cube_field(n, tetrahedra, 7);
  const int count = 400;
  const std::vector<std::array<double, 3>> x = paths(n, count);
  std::vector<std::optional<Field::Vector_3>> serial(x.size()), parallel(x.size());
  for (std::size_t q = 0; q < x.size(); ++q)
    serial[q] = field(Point_3(x[q][0], x[q][1], x[q][2]));
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 1), [&](const tbb::blocked_range<int>& r) {
    for (int p = r.begin(); p < r.end(); ++p)
      for (std::size_t q = 120 * std::size_t(p); q < 120 * std::size_t(p + 1); ++q)
        parallel[q] = field(Point_3(x[q][0], x[q][1], x[q][2]));
  });
  for (std::size_t q = 0; q < x.size(); ++q) {
    ASSERT_TRUE(serial[q] && parallel[q]) << "query " << q;
    const std::array<double, 3> e = linear_field(x[q].data());
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR((*parallel[q])[a], e[a], 1e-5) << "query " << q; // the node values are floats
      EXPECT_NEAR((*parallel[q])[a], (*serial[q])[a], 1e-12) << "query " << q;
    }
  }
#endif
}

TEST(UnstructuredFlowField3Parallel, TBBQueriesOnHexahedra)
{
  check_parallel(16, false);
}

TEST(UnstructuredFlowField3Parallel, TBBQueriesOnTetrahedra)
{
  check_parallel(10, true);
}

TEST(UnstructuredFlowField3Parallel, FaceNeighboursOfJitteredHexahedra)
{
  // Faces in VTK order: x = 0, x = 1, y = 0, y = 1, z = 0, z = 1 of the cube; the boundary
  // faces have none.
  const int n = 5;
  const Field field = jittered_cube_field(n, false, 13);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::vector<std::size_t> expected;
        const int ijk[3] = {i, j, k};
        for (int a = 0; a < 3; ++a)
          for (int side : {-1, 1}) {
            int m[3] = {i, j, k};
            m[a] += side;
            if (ijk[a] + side >= 0 && ijk[a] + side < n)
              expected.push_back(std::size_t(m[0] + n * (m[1] + n * m[2])));
          }
        EXPECT_EQ(field.face_neighbours(std::size_t(i + n * (j + n * k))), expected)
            << i << " " << j << " " << k;
      }
}

} // namespace

} // namespace test_Unstructured_flow_field_3_parallel
