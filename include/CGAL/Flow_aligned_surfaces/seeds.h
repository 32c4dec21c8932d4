// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Seed structures on a surface (Section 5 of the paper):
//
//   sample_seed_points:  a set S of points of the surface with |p - q| >= spacing for p != q in S
//                        (Euclidean), greedy over candidates drawn uniformly by area, ~30 per
//                        spacing^2 of area, so that S is close to maximal (every point of the
//                        surface within about `spacing` of S): seeds for stream lines;
//   project_polyline:    a user-drawn polyline P mapped to x -> argmin_{y in tm} |x - y| after
//                        densifying it to steps of h/4, then resampled at arc length h along
//                        the projected curve and projected again: the "drawn" seed curve.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_SEEDS_H
#define CGAL_FLOW_ALIGNED_SURFACES_SEEDS_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Points accepted so far, bucketed in cubes of side `spacing`, so that a candidate is compared
/// with the points of its 27 neighbouring cubes only.
class Spaced_point_set {
public:
  explicit Spaced_point_set(double spacing) : m_spacing(spacing) {}

  /// Adds `p` if no point of the set is closer than the spacing; returns whether it did.
  bool insert_if_far(const Eigen::Vector3d& p)
  {
    const std::array<std::int64_t, 3> c = cell(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto found = m_cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (found == m_cells.end())
            continue;
          for (std::size_t i : found->second)
            if ((m_points[i] - p).squaredNorm() < m_spacing * m_spacing)
              return false;
        }
    m_cells[key(c)].push_back(m_points.size());
    m_points.push_back(p);
    return true;
  }

  const std::vector<Eigen::Vector3d>& points() const { return m_points; }

private:
  std::array<std::int64_t, 3> cell(const Eigen::Vector3d& p) const
  {
    return {std::int64_t(std::floor(p.x() / m_spacing)), std::int64_t(std::floor(p.y() / m_spacing)),
            std::int64_t(std::floor(p.z() / m_spacing))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    // 21 bits per coordinate: the cells of a surface that needs fewer than 5e7 candidates fit.
    const auto bits = [](std::int64_t x) { return std::uint64_t(x) & ((std::uint64_t(1) << 21) - 1); };
    return bits(c[0]) | (bits(c[1]) << 21) | (bits(c[2]) << 42);
  }

  double m_spacing;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
  std::vector<Eigen::Vector3d> m_points;
};

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes points of `tm` spread evenly over it, no two closer than `spacing` (Euclidean
distance), to `out`: seeds for stream lines on an orthogonal surface (the paper's Figure 5).

Candidates are drawn uniformly by area (about 30 per `spacing`² of area) with a seeded random
generator and accepted greedily when they keep the spacing, so that the result is close to a
maximal Poisson-disk sample: every point of `tm` lies within about `spacing` of a seed, and the
number of seeds is about `0.7 area / spacing²`.  The same input and seed give the same points.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam OutputIterator an output iterator accepting `Point_3`
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param spacing the smallest distance between two seeds
\param out receives the seeds
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random generator}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map, geom_traits}
    \cgalParamDescription{as in `normalized_flux()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the output iterator past the last seed.
\throws std::invalid_argument if `spacing` is not positive and finite, or so small that the
surface would need more than 5e7 candidates, or if `tm` is empty, not a valid manifold triangle
mesh or has a coordinate that is not finite; nothing is written then.
\sa `project_polyline()`, `extract_iso_contours()`
*/
template <class TriangleMesh, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator sample_seed_points(const TriangleMesh& tm, double spacing, OutputIterator out,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::string caller = "sample_seed_points";
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw std::invalid_argument(caller + ": spacing must be positive and finite (got " +
                                std::to_string(spacing) + ")");
  const auto [vpm, gt] = internal::checked_mesh_input(tm, np, caller + ": tm");
  const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const internal::Positions x = internal::read_positions(internal::vertices_in_index_order(tm, vim), vpm);
  internal::check_finite_positions(x, caller + ": tm");
  const auto face_vertices = internal::make_mesh_arrays(tm, vim, fim).face_vertices;

  std::vector<double> cumulative_area(face_vertices.size());
  double area = 0;
  for (std::size_t j = 0; j < face_vertices.size(); ++j) {
    const auto& fv = face_vertices[j];
    area += 0.5 * (x.row(fv[1]) - x.row(fv[0])).cross(x.row(fv[2]) - x.row(fv[0])).norm();
    cumulative_area[j] = area;
  }
  const double candidates = std::ceil(30 * area / (spacing * spacing));
  if (!(candidates <= 5e7))
    throw std::invalid_argument(caller + ": spacing " + std::to_string(spacing) +
                                " is too small for the area " + std::to_string(area) +
                                " of tm (more than 5e7 candidates)");

  CGAL::Random random(seed);
  internal::Spaced_point_set accepted(spacing);
  for (std::size_t k = 0; k < std::size_t(candidates); ++k) {
    const double target = random.get_double(0, area);
    const std::size_t j =
        (std::min)(std::size_t(std::upper_bound(cumulative_area.begin(), cumulative_area.end(), target) -
                               cumulative_area.begin()),
                   face_vertices.size() - 1);
    double u = random.get_double(), v = random.get_double();
    if (u + v > 1) { // reflect into the triangle: uniform by area
      u = 1 - u;
      v = 1 - v;
    }
    const auto& fv = face_vertices[j];
    const Eigen::Vector3d a = x.row(fv[0]), b = x.row(fv[1]), c = x.row(fv[2]);
    accepted.insert_if_far(a + u * (b - a) + v * (c - a));
  }
  const auto construct_point = gt.construct_point_3_object();
  for (const Eigen::Vector3d& p : accepted.points())
    *out++ = construct_point(p.x(), p.y(), p.z());
  return out;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Projects the polyline `polyline` onto `tm` (each point to its closest point of `tm`) and
resamples it, writing the points of the resulting polyline on `tm` to `out`: a "drawn" seed
curve (the paper's Figure 4).

The input is first densified to steps of `h/4`, \f$ h \f$ the resampling step, and projected;
the projected curve is then resampled at arc length \f$ h \f$ from its first point, with its
last point kept, and each sample projected again.  The first and last points are the
projections of the first and last input points, so a closed polyline stays closed.  Parts of the
input far from `tm` project onto its closest border.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam PointRange a range of `Point_3`
\tparam OutputIterator an output iterator accepting `Point_3`
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param polyline the points of the polyline
\param out receives the points of the projected polyline
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{resampling_step}
    \cgalParamDescription{`FAS::parameters::resampling_step()`: \f$ h \f$}
    \cgalParamType{`double`}
    \cgalParamDefault{the mean edge length of `tm`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map, geom_traits}
    \cgalParamDescription{as in `normalized_flux()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the output iterator past the last point.
\throws std::invalid_argument if `polyline` is empty or has a coordinate that is not finite, if
`resampling_step` is not positive and finite, or if `tm` is empty, not a valid manifold triangle
mesh or has a coordinate that is not finite; nothing is written then.
\sa `sample_seed_points()`, `extract_iso_contours()`
*/
template <class TriangleMesh, class PointRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator project_polyline(const TriangleMesh& tm, const PointRange& polyline, OutputIterator out,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Point_3 = typename Geom_traits::Point_3;
  const std::string caller = "project_polyline";
  const auto [vpm, gt] = internal::checked_mesh_input(tm, np, caller + ": tm");

  std::vector<Eigen::Vector3d> input;
  for (const auto& p : polyline) {
    input.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if (!input.back().allFinite())
      throw std::invalid_argument(caller + ": polyline: point " + std::to_string(input.size() - 1) +
                                  " has a coordinate that is not finite");
  }
  if (input.empty())
    throw std::invalid_argument(caller + ": polyline: it has no point");
  double step = 0;
  if constexpr (parameters::is_default_parameter<NamedParameters, internal_np::resampling_step_t>::value) {
    for (auto e : edges(tm))
      step += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(halfedge(e, tm), tm)),
                                                               get(vpm, target(halfedge(e, tm), tm)))));
    step /= double(num_edges(tm));
  }
  else
    step = get_parameter(np, internal_np::resampling_step_t());
  if (!(step > 0) || !std::isfinite(step))
    throw std::invalid_argument(caller + ": resampling_step must be positive and finite (got " +
                                std::to_string(step) + ")");

  using Primitive =
      CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, std::remove_const_t<decltype(vpm)>>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Geom_traits, Primitive>>;
  Tree tree(faces(tm).first, faces(tm).second, tm, vpm);
  tree.accelerate_distance_queries();
  const auto construct_point = gt.construct_point_3_object();
  const auto project = [&](const Eigen::Vector3d& p) {
    const Point_3 q = tree.closest_point(construct_point(p.x(), p.y(), p.z()));
    return Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
  };

  std::vector<Eigen::Vector3d> projected{project(input.front())};
  for (std::size_t i = 1; i < input.size(); ++i) {
    const double pieces = std::ceil((input[i] - input[i - 1]).norm() / (step / 4));
    // A segment longer than 1e7 steps would ask for memory the user did not mean to spend.
    if (!(pieces <= 1e7))
      throw std::invalid_argument(caller + ": polyline: segment " + std::to_string(i - 1) +
                                  " is more than 2.5e6 resampling steps long");
    for (std::size_t k = 1; k <= std::size_t(pieces); ++k)
      projected.push_back(project(input[i - 1] + (double(k) / pieces) * (input[i] - input[i - 1])));
  }

  std::vector<Eigen::Vector3d> resampled{projected.front()};
  double carried = 0; // arc length since the last sample
  for (std::size_t i = 1; i < projected.size(); ++i) {
    const Eigen::Vector3d& a = projected[i - 1];
    const double length = (projected[i] - a).norm();
    double at = step - carried; // arc length along this segment of the next sample
    for (; at < length; at += step)
      resampled.push_back(project(a + (at / length) * (projected[i] - a)));
    carried = length - (at - step);
  }
  if (projected.size() > 1) {
    // The last point ends the curve; a sample within a hundredth of a step of it is replaced.
    if (resampled.size() > 1 && (resampled.back() - projected.back()).norm() < 0.01 * step)
      resampled.pop_back();
    resampled.push_back(projected.back());
  }
  for (const Eigen::Vector3d& p : resampled)
    *out++ = construct_point(p.x(), p.y(), p.z());
  return out;
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_SEEDS_H
