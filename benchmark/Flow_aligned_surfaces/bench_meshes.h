// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test meshes of the unstructured benchmarks: a structured block of n^3 cubes whose nodes are
// graded along each axis (cell sizes growing by a factor ~3 across the block), rotated about a
// skew axis, and jittered by up to 0.15 of the local cell size at the interior nodes, so that
// the cells are general (non-parallelepiped, non-planar-faced) hexahedra, not axis-aligned
// boxes.  Written either as n^3 VTK hexahedra or as 6 n^3 tetrahedra (each cube split along
// its main diagonal, a conforming Kuhn triangulation).  Query points are given in the block's
// parameters u in [0, n]^3 and mapped by the trilinear map of the cube containing them, so they
// are inside the mesh; "coherent" streams are many short random paths with steps of 0.1 cell.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_BENCHMARK_BENCH_MESHES_H
#define CGAL_FLOW_ALIGNED_SURFACES_BENCHMARK_BENCH_MESHES_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace fas_bench {

struct Block_mesh {
  int n = 0;
  std::vector<double> points; // x, y, z per node
  std::vector<float> vectors; // a smooth velocity per node
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<unsigned char> types;
};

inline int node_index(int n, int i, int j, int k)
{
  return i + (n + 1) * (j + (n + 1) * k);
}

// The node (i, j, k) of the block of n^3 cubes over about [0, 1]^3.
inline std::array<double, 3> block_node(int n, int i, int j, int k)
{
  auto graded = [n](int i) { // sizes grow by e^1.1 ~ 3 from one end to the other
    const double a = 1.1;
    return (std::exp(a * double(i) / n) - 1.) / (std::exp(a) - 1.);
  };
  double x[3] = {graded(i), graded(j), graded(k)};
  const int ijk[3] = {i, j, k};
  // Deterministic jitter of interior nodes by up to 0.15 of the local cell size.
  std::uint64_t h = std::uint64_t(node_index(n, i, j, k)) * 0x9E3779B97F4A7C15ull + 12345;
  for (int a = 0; a < 3; ++a) {
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    const double r = double(h % 1000003) / 1000003. * 2. - 1.;
    if (ijk[a] > 0 && ijk[a] < n && i > 0 && i < n && j > 0 && j < n && k > 0 && k < n)
      x[a] += 0.15 * r * (graded(ijk[a] + 1) - graded(ijk[a]));
  }
  // Rotation by 0.5 rad about the axis (1, 2, 3) / sqrt(14).
  const double ax[3] = {1. / std::sqrt(14.), 2. / std::sqrt(14.), 3. / std::sqrt(14.)};
  const double c = std::cos(0.5), s = std::sin(0.5);
  const double d = ax[0] * x[0] + ax[1] * x[1] + ax[2] * x[2];
  const double cr[3] = {ax[1] * x[2] - ax[2] * x[1], ax[2] * x[0] - ax[0] * x[2],
                        ax[0] * x[1] - ax[1] * x[0]};
  std::array<double, 3> r;
  for (int a = 0; a < 3; ++a)
    r[a] = x[a] * c + cr[a] * s + ax[a] * d * (1. - c);
  return r;
}

const int hex_corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

inline Block_mesh make_block_mesh(int n, bool tetrahedra)
{
  Block_mesh m;
  m.n = n;
  const std::size_t nodes = std::size_t(n + 1) * (n + 1) * (n + 1);
  m.points.reserve(3 * nodes); // exact sizes, as a reader makes them
  m.vectors.reserve(3 * nodes);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const std::array<double, 3> x = block_node(n, i, j, k);
        m.points.insert(m.points.end(), x.begin(), x.end());
        m.vectors.push_back(float(std::sin(3. * x[1]) + x[2]));
        m.vectors.push_back(float(std::cos(2. * x[2]) - x[0]));
        m.vectors.push_back(float(0.5 + x[0] * x[1]));
      }
  const std::size_t cells = std::size_t(n) * n * n * (tetrahedra ? 6 : 1);
  m.connectivity.reserve(cells * (tetrahedra ? 4 : 8));
  m.offsets.reserve(cells + 1);
  m.types.reserve(cells);
  m.offsets.push_back(0);
  // Kuhn's 6 tetrahedra of a cube: 0 -> e_a -> e_a + e_b -> (1, 1, 1), as hex corner numbers.
  static const int kuhn[6][4] = {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 4, 5, 6},
                                 {0, 4, 7, 6}, {0, 3, 7, 6}, {0, 3, 2, 6}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::int64_t h[8];
        for (int q = 0; q < 8; ++q)
          h[q] = node_index(n, i + hex_corner[q][0], j + hex_corner[q][1], k + hex_corner[q][2]);
        if (tetrahedra) {
          for (const auto& t : kuhn) {
            for (int q : t)
              m.connectivity.push_back(h[q]);
            m.offsets.push_back(std::int64_t(m.connectivity.size()));
            m.types.push_back(10);
          }
        }
        else {
          m.connectivity.insert(m.connectivity.end(), h, h + 8);
          m.offsets.push_back(std::int64_t(m.connectivity.size()));
          m.types.push_back(12);
        }
      }
  return m;
}

// The position of the block parameters u in [0, n]^3 (trilinear in the cube containing u).
inline std::array<double, 3> block_position(const Block_mesh& m, const double* u)
{
  int c[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    c[a] = (std::min)(m.n - 1, (std::max)(0, int(std::floor(u[a]))));
    t[a] = u[a] - c[a];
  }
  std::array<double, 3> x = {{0., 0., 0.}};
  for (int q = 0; q < 8; ++q) {
    const double w = (hex_corner[q][0] ? t[0] : 1. - t[0]) * (hex_corner[q][1] ? t[1] : 1. - t[1]) *
                     (hex_corner[q][2] ? t[2] : 1. - t[2]);
    const double* p = m.points.data() + 3 * node_index(m.n, c[0] + hex_corner[q][0], c[1] + hex_corner[q][1],
                                                       c[2] + hex_corner[q][2]);
    for (int a = 0; a < 3; ++a)
      x[a] += w * p[a];
  }
  return x;
}

// `paths` random paths of `steps` points each, 0.1 cell apart, direction turning slowly;
// consecutive in the result (path after path).
inline std::vector<std::array<double, 3>> coherent_queries(const Block_mesh& m, std::size_t paths,
                                                           std::size_t steps)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> start(0.5, m.n - 0.5);
  std::normal_distribution<double> g(0., 1.);
  std::vector<std::array<double, 3>> r;
  r.reserve(paths * steps);
  for (std::size_t p = 0; p < paths; ++p) {
    double u[3] = {start(rng), start(rng), start(rng)}, d[3] = {g(rng), g(rng), g(rng)};
    for (std::size_t s = 0; s < steps; ++s) {
      r.push_back(block_position(m, u));
      double len = 0.;
      for (int a = 0; a < 3; ++a) {
        d[a] += 0.2 * g(rng);
        len += d[a] * d[a];
      }
      len = std::sqrt(len);
      for (int a = 0; a < 3; ++a) {
        d[a] /= len;
        u[a] += 0.1 * d[a];
        if (u[a] < 0.01 || u[a] > m.n - 0.01) { // reflect at the block's faces
          d[a] = -d[a];
          u[a] += 0.2 * d[a];
        }
      }
    }
  }
  return r;
}

inline std::vector<std::array<double, 3>> random_queries(const Block_mesh& m, std::size_t count)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0., m.n);
  std::vector<std::array<double, 3>> r;
  r.reserve(count);
  for (std::size_t q = 0; q < count; ++q) {
    const double x[3] = {u(rng), u(rng), u(rng)};
    r.push_back(block_position(m, x));
  }
  return r;
}

} // namespace fas_bench

#endif // CGAL_FLOW_ALIGNED_SURFACES_BENCHMARK_BENCH_MESHES_H
