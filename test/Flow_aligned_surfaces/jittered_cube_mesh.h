// The mesh of the walk tests: the unit cube in n^3 cubes whose interior nodes are jittered by up
// to 0.2 cell, as VTK hexahedra or as Kuhn's 6 tetrahedra per cube (conforming), carrying the
// linear field v(p) = A p + b that both interpolations reproduce exactly (up to the rounding
// of the node values to floats).  Cube (i, j, k) is cell i + n (j + n k) (times 6 plus the
// tetrahedron's rank for tetrahedra).

#ifndef FAS_TEST_JITTERED_CUBE_MESH_H
#define FAS_TEST_JITTERED_CUBE_MESH_H

#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <array>
#include <random>
#include <vector>

namespace fas_test {

inline std::array<double, 3> linear_field(const double* x)
{
  return {{1. + 2. * x[0] - x[1] + 0.5 * x[2], -3. + x[0] + 4. * x[1] - 2. * x[2],
           0.25 - x[0] + x[1] + 3. * x[2]}};
}

inline FAS::Unstructured_flow_field_3<K> jittered_cube_field(int n, bool tetrahedra, unsigned seed)
{
  typedef FAS::Unstructured_flow_field_3<K>::Index Index;
  static const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  static const int kuhn[6][4] = {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 4, 5, 6},
                                 {0, 4, 7, 6}, {0, 3, 7, 6}, {0, 3, 2, 6}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2 / n, 0.2 / n);
  std::vector<double> points;
  std::vector<float> vectors;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const int ijk[3] = {i, j, k};
        double x[3];
        for (int a = 0; a < 3; ++a)
          x[a] = double(ijk[a]) / n + (ijk[a] > 0 && ijk[a] < n ? jitter(rng) : 0.);
        points.insert(points.end(), x, x + 3);
        for (double c : linear_field(x))
          vectors.push_back(static_cast<float>(c));
      }
  std::vector<Index> connectivity, offsets{0};
  std::vector<unsigned char> types;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Index h[8];
        for (int q = 0; q < 8; ++q)
          h[q] = (i + corner[q][0]) + (n + 1) * ((j + corner[q][1]) + (n + 1) * (k + corner[q][2]));
        if (tetrahedra) {
          for (const auto& t : kuhn) {
            for (int q : t)
              connectivity.push_back(h[q]);
            offsets.push_back(static_cast<Index>(connectivity.size()));
            types.push_back(10);
          }
        }
        else {
          connectivity.insert(connectivity.end(), h, h + 8);
          offsets.push_back(static_cast<Index>(connectivity.size()));
          types.push_back(12);
        }
      }
  return FAS::Unstructured_flow_field_3<K>(points, connectivity, offsets, types, vectors);
}

} // namespace fas_test

#endif // FAS_TEST_JITTERED_CUBE_MESH_H
