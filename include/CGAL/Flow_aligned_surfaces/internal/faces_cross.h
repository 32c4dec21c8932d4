// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether two triangles of a manifold triangle mesh intersect beyond the vertex or the edge they
// share, with exact predicates: the test `CGAL::Polygon_mesh_processing::self_intersections()`
// applies to each pair of faces whose boxes meet, here on vertex indices, so that the guard of
// `grow_boundary()` can choose the pairs (each with a new face) instead of sorting all boxes.
// - No shared vertex: the triangles intersect.
// - One shared vertex: the edge opposite it in either triangle meets the other triangle (the
//   intersection of two triangles through a common vertex leaves one of them through that edge).
// - One shared edge: the triangles are coplanar and fold onto each other (their third vertices on
//   the same side of the edge).
// - Three: the same triangle twice.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FACES_CROSS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FACES_CROSS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Whether the faces with vertex indices `f` and `g` intersect beyond what they share; `point(v)`
/// returns vertex v's position as an `Epick::Point_3`.  Neither face may be degenerate (collinear).
template <class Index, class PointOf>
bool faces_cross(const std::array<Index, 3>& f, const std::array<Index, 3>& g, const PointOf& point)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  int shared = 0, fi = 0, gi = 0; // the number of shared vertices, the last one's places
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[j]) {
        ++shared;
        fi = i;
        gi = j;
      }
  const K::Point_3 f0 = point(f[0]), f1 = point(f[1]), f2 = point(f[2]);
  const K::Point_3 g0 = point(g[0]), g1 = point(g[1]), g2 = point(g[2]);
  switch (shared) {
  case 0:
    return CGAL::do_intersect(K::Triangle_3(f0, f1, f2), K::Triangle_3(g0, g1, g2));
  case 1: {
    // Most pairs of a fan are told apart by boxes, before the exact test.
    const K::Segment_3 f_opposite(point(f[(fi + 1) % 3]), point(f[(fi + 2) % 3]));
    const K::Segment_3 g_opposite(point(g[(gi + 1) % 3]), point(g[(gi + 2) % 3]));
    const CGAL::Bbox_3 f_box = f0.bbox() + f1.bbox() + f2.bbox(), g_box = g0.bbox() + g1.bbox() + g2.bbox();
    return (CGAL::do_overlap(f_box, g_opposite.bbox()) &&
            CGAL::do_intersect(K::Triangle_3(f0, f1, f2), g_opposite)) ||
           (CGAL::do_overlap(g_box, f_opposite.bbox()) &&
            CGAL::do_intersect(K::Triangle_3(g0, g1, g2), f_opposite));
  }
  case 2: {
    // The vertex of each face off the shared edge (p, q).
    int f_apex = 0, g_apex = 0;
    for (int i = 0; i < 3; ++i) {
      if (f[i] != g[0] && f[i] != g[1] && f[i] != g[2])
        f_apex = i;
      if (g[i] != f[0] && g[i] != f[1] && g[i] != f[2])
        g_apex = i;
    }
    const K::Point_3 p = point(f[(f_apex + 1) % 3]), q = point(f[(f_apex + 2) % 3]);
    const K::Point_3 a = point(f[f_apex]), b = point(g[g_apex]);
    return CGAL::coplanar(p, q, a, b) && CGAL::coplanar_orientation(p, q, a, b) == CGAL::POSITIVE;
  }
  default:
    return true;
  }
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FACES_CROSS_H
