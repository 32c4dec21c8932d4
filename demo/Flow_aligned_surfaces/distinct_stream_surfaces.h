// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One stream surface (or path surface) per distinct seed curve.  Seed curves taken on a flow-
// tangential surface (the iso-contours of its tangential parametrization) all lie on the same
// stream surface, up to the
// surface's alignment error (the paper, Section 5: "Stream surfaces seeded from curves in
// approximately flow-tangential surfaces coincide locally"); integrating each would give the same
// surface several times, drawn on top of itself.  So the curves are integrated in order, and a
// curve is skipped as lying on a surface already integrated when
//
//   more than half of its points are within `tolerance` of that surface
//
// (distance to its triangles, by an AABB tree).  The tolerance is half the front spacing h by
// default: the integrated surface resolves nothing finer, while distinct curves on a flow-
// orthogonal surface (iso-contours of r a fraction of the patch apart) lie far outside it.
// Stream surfaces: forward and backward halves as one mesh (Integration_direction::BOTH),
// arc-length time lines.  Path surfaces (unsteady flows): forward from their release time.

#ifndef FAS_DEMO_DISTINCT_STREAM_SURFACES_H
#define FAS_DEMO_DISTINCT_STREAM_SURFACES_H

#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fas_demo {

/// The stream surfaces of `integrate_distinct_stream_surfaces()`, all in one mesh.
template <class Mesh>
struct Distinct_stream_surfaces {
  Mesh mesh; ///< every surface, with the vertex maps "v:u", "v:t" and "v:seed"
  /// Per seed curve: the index of the curve whose surface it was found on (itself when it was
  /// integrated), or nothing when it was not integrated (fewer than two points, or the
  /// integrator refused it: the reason is in `skipped_reasons`).
  std::vector<std::optional<std::size_t>> surface_of;
  std::vector<std::string> skipped_reasons; ///< one line per curve the integrator refused
  /// The number of surfaces integrated.
  std::size_t number_of_surfaces() const
  {
    std::size_t n = 0;
    for (std::size_t i = 0; i < surface_of.size(); ++i)
      n += surface_of[i] == i ? 1 : 0;
    return n;
  }
};

/// The fraction of `curve`'s points within `tolerance` of the triangles `faces` of `tm`.
template <class Mesh, class Polyline>
double fraction_of_points_near(const Mesh& tm, const std::vector<typename Mesh::Face_index>& faces,
                               const Polyline& curve, double tolerance)
{
  using Point = typename Mesh::Point;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  if (faces.empty() || curve.empty())
    return 0;
  Tree tree(faces.begin(), faces.end(), tm);
  tree.accelerate_distance_queries();
  std::size_t near = 0;
  for (const Point& p : curve)
    near += tree.squared_distance(p) <= tolerance * tolerance ? 1 : 0;
  return double(near) / double(curve.size());
}

/// Integrates the surface of every seed curve of `seeds` that does not lie on a surface
/// integrated before it (see the file's comment) by `integrate_stream_surface(field, curve, mesh,
/// parameters(u, t))`: `parameters` gives the named parameters for the vertex maps u and t.
/// `tolerance` is the distance of a curve to a surface below which it lies on it.
template <class Mesh, class Field, class Polyline, class Parameters>
Distinct_stream_surfaces<Mesh> integrate_distinct_surfaces(const Field& field,
                                                           const std::vector<Polyline>& seeds,
                                                           double tolerance, const Parameters& parameters)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  using Face = typename Mesh::Face_index;
  using Vertex = typename Mesh::Vertex_index;
  Distinct_stream_surfaces<Mesh> result;
  Mesh& mesh = result.mesh;
  auto u = mesh.template add_property_map<Vertex, double>("v:u", 0).first;
  auto t = mesh.template add_property_map<Vertex, double>("v:t", 0).first;
  auto seed_id = mesh.template add_property_map<Vertex, double>("v:seed", -1).first;
  const auto np = parameters(u, t);
  std::vector<std::vector<Face>> faces_of; // per seed curve (empty unless integrated)
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    result.surface_of.emplace_back();
    faces_of.emplace_back();
    if (seeds[i].size() < 2)
      continue;
    for (std::size_t j = 0; j < i && !result.surface_of[i]; ++j)
      if (result.surface_of[j] == j && fraction_of_points_near(mesh, faces_of[j], seeds[i], tolerance) > 0.5)
        result.surface_of[i] = j;
    if (result.surface_of[i])
      continue;
    const std::size_t first_vertex = mesh.number_of_vertices(), first_face = mesh.number_of_faces();
    try {
      FAS::integrate_stream_surface(field, seeds[i], mesh, np);
    } catch (const std::exception& e) { // a degenerate contour: skip it, say why
      result.skipped_reasons.push_back("seed curve " + std::to_string(i) + " skipped: " + e.what());
      continue;
    }
    // The surface mesh numbers new elements after the old ones (nothing is ever removed here).
    for (std::size_t v = first_vertex; v < mesh.number_of_vertices(); ++v)
      seed_id[Vertex(typename Mesh::size_type(v))] = double(i);
    for (std::size_t f = first_face; f < mesh.number_of_faces(); ++f)
      faces_of[i].push_back(Face(typename Mesh::size_type(f)));
    result.surface_of[i] = i;
  }
  return result;
}

/// The stream surfaces of the distinct seed curves of `seeds` in the steady `flow`, forward and
/// backward as one mesh, with front spacing `spacing` and arc-length time lines up to
/// `max_length` each way; `tolerance` <= 0: half the spacing.  Every vertex carries its seed
/// parameter u, its signed time-line parameter t (< 0 on the backward half) and the index of its
/// seed curve.
template <class Mesh, class Flow, class Polyline>
Distinct_stream_surfaces<Mesh>
integrate_distinct_stream_surfaces(const Flow& flow, const std::vector<Polyline>& seeds, double spacing,
                                   double max_length, double tolerance = 0)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  return integrate_distinct_surfaces<Mesh>(
      flow, seeds, tolerance > 0 ? tolerance : spacing / 2, [&](auto u, auto t) {
        return FAS::parameters::front_spacing(
            spacing, FAS::parameters::arc_length_time_lines(
                         true, FAS::parameters::max_length(
                                   max_length, FAS::parameters::integration_direction(
                                                   FAS::Integration_direction::BOTH,
                                                   FAS::parameters::seed_parameter_map(
                                                       u, FAS::parameters::integration_time_map(t))))));
      });
}

/// The path surfaces of the distinct seed curves of `seeds` in the unsteady `flow` (called with
/// `(p, t)`), released at `start_time` and integrated forward for `duration`, with front spacing
/// `spacing`; a curve is on a surface when most of it is within half the spacing (the seed curves
/// of a surface tangential to the flow at the start time lie on one path surface near their
/// start).  Every vertex carries u, t (the time since the release) and the index of its seed
/// curve as the stream surfaces do, and its time `start_time` + t ("v:time").
template <class Mesh, class UnsteadyFlow, class Polyline>
Distinct_stream_surfaces<Mesh>
integrate_distinct_path_surfaces(const UnsteadyFlow& flow, const std::vector<Polyline>& seeds, double spacing,
                                 double start_time, double duration)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  Distinct_stream_surfaces<Mesh> result =
      integrate_distinct_surfaces<Mesh>(flow, seeds, spacing / 2, [&](auto u, auto t) {
        return FAS::parameters::front_spacing(
            spacing, FAS::parameters::start_time(
                         start_time, FAS::parameters::max_time(
                                         duration, FAS::parameters::seed_parameter_map(
                                                       u, FAS::parameters::integration_time_map(t)))));
      });
  using Vertex = typename Mesh::Vertex_index;
  const auto t = result.mesh.template property_map<Vertex, double>("v:t").first;
  auto time = result.mesh.template add_property_map<Vertex, double>("v:time", start_time).first;
  for (Vertex v : result.mesh.vertices())
    time[v] = start_time + t[v];
  return result;
}

} // namespace fas_demo

#endif // FAS_DEMO_DISTINCT_STREAM_SURFACES_H
