// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the main job puts its patches in a flow read from a file when the user did not say: near
// the flow's main feature and tilted off the flow, so that a first run shows a real deformation
// (a patch in uniform flow that already contains it converges in two iterations and shows
// nothing).  The field is sampled on a lattice of about 40^3 points over its box:
// - the obstacle is where the flow is not defined (the `inside` mask says solid, or a cell-data
//   hole) at lattice points away from the box's faces (the outer 10% of each side, where the
//   channel's walls are, are left out); its centre and extent are those of these points;
// - without such points, the feature is the lattice point of largest vorticity |curl v|
//   (central differences on the lattice), also away from the box's faces (a lid-driven
//   cavity's largest vorticity is in the corners of its lid, where nothing can be placed).
// The mean flow direction d is the mean of the sampled velocities.  The orthogonal patch goes
// downstream of the obstacle (its centre moved along d by the obstacle's half extent and one
// patch size: the wake), the tangential one beside it (moved across d by the same amount, on
// the side with more room); both at the vorticity maximum when there is no obstacle.  Each is
// then tilted by `tilt` off its aligned orientation at that point: the tangential normal
// (d x the obstacle's axis, the lattice axis along which it fills most of the lattice, or v x z)
// turned towards v, the orthogonal normal (v) turned
// away from it.  A centre where the flow is not defined is moved towards the box's centre.

#ifndef FAS_DEMO_FEATURE_PLACEMENT_H
#define FAS_DEMO_FEATURE_PLACEMENT_H

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel/global_functions.h>

#include <CGAL/Flow_aligned_surfaces/internal/batched_sampling.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace fas_demo {

/// Where `place_near_feature()` puts the patches, and why (for the program's output).
template <class Point, class Vector>
struct Feature_placement {
  Point tangential_center, orthogonal_center;
  Vector tangential_normal, orthogonal_normal;
  bool found_obstacle = false;   ///< an obstacle (no-flow region inside the box), else the vorticity maximum
  Point feature;                 ///< the obstacle's centre, or the point of largest vorticity
  std::array<double, 3> extent{}; ///< the obstacle's extent along x, y, z (0 without obstacle)
  std::string description;       ///< one sentence for the user
};

/// The values of `field` at `points`: one call of `field.sample(points)` when the field answers
/// batches (the concept's optional operation: a field whose pieces live on several processes
/// answers them in one exchange), else one query per point.
template <class Field, class Point>
auto values_at(const Field& field, const std::vector<Point>& points)
{
  if constexpr (CGAL::Flow_aligned_surfaces::internal::has_batch_sampling_v<Field, Point>)
    return field.sample(points);
  else {
    std::vector<decltype(field(points.front()))> values;
    values.reserve(points.size());
    for (const Point& p : points)
      values.push_back(field(p));
    return values;
  }
}

/// The n^3 lattice points (i, j, k) in the order they are sampled: a walk from each point to a
/// lattice neighbour, fastest along the axis of the smallest step (back and forth, row after row,
/// layer after layer), so that each query of a field that starts from its previous answer (the
/// walk of `Unstructured_flow_field_3`) starts next to it.
inline std::vector<std::array<int, 3>> lattice_walk(int n, const std::array<double, 3>& step)
{
  std::array<int, 3> axis{0, 1, 2}; // fastest first
  std::stable_sort(axis.begin(), axis.end(),
                   [&](int a, int b) { return step[std::size_t(a)] < step[std::size_t(b)]; });
  std::vector<std::array<int, 3>> visits;
  visits.reserve(std::size_t(n) * n * n);
  const auto there_and_back = [n](int u, int pass) { return pass % 2 == 0 ? u : n - 1 - u; };
  for (int slow = 0; slow < n; ++slow)
    for (int u = 0; u < n; ++u) {
      const int middle = there_and_back(u, slow);
      for (int v = 0; v < n; ++v) {
        std::array<int, 3> c;
        c[std::size_t(axis[2])] = slow;
        c[std::size_t(axis[1])] = middle;
        c[std::size_t(axis[0])] = there_and_back(v, slow * n + u);
        visits.push_back(c);
      }
    }
  return visits;
}

/// See the file's comment.  `field(p)` returns an optional vector; `box` is its domain; `size`
/// the patch size; `tilt` radians; `center`: both patches there (only tilted), instead of near the
/// feature.  Returns nothing when no lattice point has a flow.
template <class Point, class Vector, class Field>
std::optional<Feature_placement<Point, Vector>> place_near_feature(const Field& field, const CGAL::Bbox_3& box,
                                                                   double size, double tilt,
                                                                   const std::optional<Point>& center = {})
{
  constexpr int n = 40;
  const std::array<double, 3> lo{box.xmin(), box.ymin(), box.zmin()}, hi{box.xmax(), box.ymax(), box.zmax()};
  std::array<double, 3> step;
  for (int a = 0; a < 3; ++a)
    step[a] = (hi[a] - lo[a]) / (n - 1);
  const auto point = [&](int i, int j, int k) {
    return Point(lo[0] + i * step[0], lo[1] + j * step[1], lo[2] + k * step[2]);
  };
  const auto index = [&](int i, int j, int k) { return (std::size_t(k) * n + j) * n + i; };
  const std::vector<std::array<int, 3>> visits = lattice_walk(n, step);
  std::vector<Point> lattice;
  lattice.reserve(visits.size());
  for (const std::array<int, 3>& c : visits)
    lattice.push_back(point(c[0], c[1], c[2]));
  const auto visited = values_at(field, lattice);
  std::vector<typename decltype(visited)::value_type> values(visited.size());
  for (std::size_t m = 0; m < visits.size(); ++m)
    values[index(visits[m][0], visits[m][1], visits[m][2])] = visited[m];
  std::vector<std::optional<Vector>> samples(lattice.size());
  Vector mean(0, 0, 0);
  std::size_t defined = 0;
  std::array<double, 3> obstacle_lo{hi}, obstacle_hi{lo}, obstacle_sum{0, 0, 0};
  std::size_t obstacle_points = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Point p = point(i, j, k);
        std::optional<Vector> v = values[index(i, j, k)];
        if (v && !(std::isfinite(v->x()) && std::isfinite(v->y()) && std::isfinite(v->z())))
          v.reset();
        samples[index(i, j, k)] = v;
        if (v) {
          mean = mean + *v;
          ++defined;
          continue;
        }
        const int away = n / 10; // the outer 10% of each side: walls, not obstacles
        const bool inner = std::min({i, j, k}) >= away && std::max({i, j, k}) < n - away;
        if (!inner)
          continue;
        const std::array<double, 3> c{p.x(), p.y(), p.z()};
        for (int a = 0; a < 3; ++a) {
          obstacle_lo[a] = std::min(obstacle_lo[a], c[a]);
          obstacle_hi[a] = std::max(obstacle_hi[a], c[a]);
          obstacle_sum[a] += c[a];
        }
        ++obstacle_points;
      }
  if (defined == 0 || mean.squared_length() == 0)
    return std::nullopt;
  const Vector d = mean / std::sqrt(mean.squared_length());

  Feature_placement<Point, Vector> result;
  std::ostringstream why;
  why.precision(4);
  if (obstacle_points > 0) {
    result.found_obstacle = true;
    result.feature = Point(obstacle_sum[0] / obstacle_points, obstacle_sum[1] / obstacle_points,
                           obstacle_sum[2] / obstacle_points);
    for (int a = 0; a < 3; ++a)
      result.extent[a] = obstacle_hi[a] - obstacle_lo[a] + step[a];
    why << "near the obstacle (the region without flow centred at " << result.feature << ", "
        << result.extent[0] << " x " << result.extent[1] << " x " << result.extent[2] << ")";
  }
  else { // the lattice point of largest |curl v|
    double largest = -1;
    const int away = n / 10; // not in the walls' boundary layers (a lid's corner is singular)
    for (int k = away; k < n - away; ++k)
      for (int j = away; j < n - away; ++j)
        for (int i = away; i < n - away; ++i) {
          const auto &xm = samples[index(i - 1, j, k)], &xp = samples[index(i + 1, j, k)],
                     &ym = samples[index(i, j - 1, k)], &yp = samples[index(i, j + 1, k)],
                     &zm = samples[index(i, j, k - 1)], &zp = samples[index(i, j, k + 1)];
          if (!xm || !xp || !ym || !yp || !zm || !zp)
            continue;
          const Vector dx = (*xp - *xm) / (2 * step[0]), dy = (*yp - *ym) / (2 * step[1]),
                       dz = (*zp - *zm) / (2 * step[2]);
          const Vector curl(dy.z() - dz.y(), dz.x() - dx.z(), dx.y() - dy.x());
          if (curl.squared_length() > largest) {
            largest = curl.squared_length();
            result.feature = point(i, j, k);
          }
        }
    if (largest < 0)
      result.feature = point(n / 2, n / 2, n / 2);
    why << "at the largest vorticity (|curl v| = " << std::sqrt(std::max(largest, 0.0)) << " at " << result.feature
        << ")";
  }

  // The obstacle's axis: the lattice axis along which it fills most of the inner lattice (a
  // cylinder between two walls fills it along its axis, whatever its diameter), else z; the
  // first in that order that is not along the mean flow.
  const std::array<Vector, 3> axes{Vector(1, 0, 0), Vector(0, 1, 0), Vector(0, 0, 1)};
  std::array<int, 3> order{2, 0, 1};
  if (result.found_obstacle) {
    const auto filled = [&](int a) { return result.extent[std::size_t(a)] / ((n - 2 * (n / 10)) * step[std::size_t(a)]); };
    order = {0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return filled(a) > filled(b); });
  }
  Vector axis = axes[std::size_t(order[0])], across = CGAL::cross_product(d, axis);
  for (int a = 1; a < 3 && across.squared_length() < 0.01; ++a)
    across = CGAL::cross_product(d, axis = axes[std::size_t(order[std::size_t(a)])]);
  across = across / std::sqrt(across.squared_length());
  const auto half_extent_along = [&](const Vector& u) {
    return 0.5 * (std::abs(u.x()) * result.extent[0] + std::abs(u.y()) * result.extent[1] +
                  std::abs(u.z()) * result.extent[2]);
  };
  // Inside the box, with a flow: moved towards the box's centre until it has one.
  const Point box_center((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
  const auto settle = [&](Point p) {
    for (int a = 0; a < 3; ++a) { // keep the patch's middle half a size inside each face (when it fits)
      const double margin = std::min(size / 2, (hi[a] - lo[a]) / 2);
      const double c = std::clamp(a == 0 ? p.x() : a == 1 ? p.y() : p.z(), lo[a] + margin, hi[a] - margin);
      p = Point(a == 0 ? c : p.x(), a == 1 ? c : p.y(), a == 2 ? c : p.z());
    }
    for (int s = 0; s < 20 && !field(p); ++s)
      p = p + 0.1 * (box_center - p);
    return p;
  };
  const auto room = [&](const Point& p) { // distance to the box along `across`, both ways
    const std::array<double, 3> c{p.x(), p.y(), p.z()}, u{across.x(), across.y(), across.z()};
    double plus = 1e300, minus = 1e300;
    for (int a = 0; a < 3; ++a)
      if (std::abs(u[a]) > 1e-12) {
        const double t_hi = (hi[a] - c[a]) / u[a], t_lo = (lo[a] - c[a]) / u[a];
        plus = std::min(plus, std::max(t_hi, t_lo));
        minus = std::min(minus, -std::min(t_hi, t_lo));
      }
    return plus >= minus ? 1.0 : -1.0;
  };
  const double side_offset = half_extent_along(across) + 0.6 * size;
  result.tangential_center = settle(result.feature + room(result.feature) * side_offset * across);
  result.orthogonal_center = settle(result.feature - (half_extent_along(d) + size) * d);
  if (center) {
    result.tangential_center = result.orthogonal_center = *center;
    why.str("");
    why << "at the given centre";
  }

  const auto unit = [](const Vector& v) { return v / std::sqrt(v.squared_length()); };
  const auto flow_at = [&](const Point& p) {
    const auto v = field(p);
    return v && v->squared_length() > 0 ? unit(*v) : d;
  };
  // Tangential: the aligned normal v x axis turned by `tilt` towards v.
  const Vector vt = flow_at(result.tangential_center);
  Vector nt = CGAL::cross_product(vt, axis);
  if (nt.squared_length() < 1e-6)
    nt = CGAL::cross_product(vt, across);
  nt = unit(nt);
  result.tangential_normal = std::cos(tilt) * nt + std::sin(tilt) * vt;
  // Orthogonal: v turned by `tilt` away from itself (towards `across`).
  const Vector vo = flow_at(result.orthogonal_center);
  Vector w = across - (across * vo) * vo;
  if (w.squared_length() < 1e-6)
    w = CGAL::cross_product(vo, axis);
  w = unit(w);
  result.orthogonal_normal = std::cos(tilt) * vo + std::sin(tilt) * w;
  why << ", tilted " << std::lround(tilt * 180 / 3.141592653589793) << " degrees off the flow";
  result.description = why.str();
  return result;
}

} // namespace fas_demo

#endif // FAS_DEMO_FEATURE_PLACEMENT_H
