// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pieces of the demo's scene pictures (scene_rendering.h) made from the demo's meshes, lines
// and flows: a mesh as a scene surface, polylines as a line set, a box's outline, where a flow
// is defined on a lattice (the obstacle's contour), and the oblique camera of the paper's
// figures: looking down at the scene's box from the front left, so that surfaces aligned with
// the flow show their bending instead of their face.

#ifndef FAS_DEMO_SCENE_ASSEMBLY_H
#define FAS_DEMO_SCENE_ASSEMBLY_H

#include "scene_rendering.h"
#include "write_polydata_VTP.h"
#ifdef FAS_DEMO_HAVE_RENDERING
#include "render_scene_PNG.h"
#endif

#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace fas_demo {

/// `tm` (a triangle mesh) as a scene surface coloured by `face_scalars` (one per face in the
/// order of the face index map, or empty) or in `color`.
template <class Mesh>
Scene_surface to_scene_surface(const Mesh& tm, std::vector<double> face_scalars, std::array<double, 3> color,
                               double opacity = 1)
{
  Scene_surface s;
  const auto vim = get(CGAL::vertex_index, tm);
  s.points.resize(num_vertices(tm));
  for (auto v : vertices(tm)) {
    const auto& p = get(CGAL::vertex_point, tm, v);
    s.points[get(vim, v)] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  for (auto f : faces(tm)) {
    std::array<std::size_t, 3> t{};
    int k = 0;
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      if (k < 3)
        t[std::size_t(k++)] = get(vim, v);
    s.triangles.push_back(t);
  }
  s.face_scalars = std::move(face_scalars);
  s.color = color;
  s.opacity = opacity;
  return s;
}

/// Polylines of points of a CGAL kernel as a line set.
template <class Polyline>
Scene_lines to_scene_lines(const std::vector<Polyline>& polylines, std::array<double, 3> color, double width)
{
  Scene_lines l;
  for (const Polyline& line : polylines) {
    l.polylines.emplace_back();
    for (const auto& p : line)
      l.polylines.back().push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  l.color = color;
  l.width = width;
  return l;
}

/// The twelve edges of `box`, thin and grey.
inline Scene_lines box_outline(const CGAL::Bbox_3& box)
{
  Scene_lines l;
  const double x[2] = {box.xmin(), box.xmax()}, y[2] = {box.ymin(), box.ymax()}, z[2] = {box.zmin(), box.zmax()};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      l.polylines.push_back({{x[0], y[a], z[b]}, {x[1], y[a], z[b]}});
      l.polylines.push_back({{x[a], y[0], z[b]}, {x[a], y[1], z[b]}});
      l.polylines.push_back({{x[a], y[b], z[0]}, {x[a], y[b], z[1]}});
    }
  l.color = {0.45, 0.45, 0.45};
  l.width = 1.5;
  return l;
}

/// `box` grown by `fraction` of its size on every side.
inline CGAL::Bbox_3 expanded(const CGAL::Bbox_3& box, double fraction)
{
  const double dx = fraction * (box.xmax() - box.xmin()), dy = fraction * (box.ymax() - box.ymin()),
               dz = fraction * (box.zmax() - box.zmin());
  return CGAL::Bbox_3(box.xmin() - dx, box.ymin() - dy, box.zmin() - dz, box.xmax() + dx, box.ymax() + dy,
                      box.zmax() + dz);
}

/// The intersection of two overlapping boxes.
inline CGAL::Bbox_3 box_intersection(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b)
{
  return CGAL::Bbox_3(std::max(a.xmin(), b.xmin()), std::max(a.ymin(), b.ymin()), std::max(a.zmin(), b.zmin()),
                      std::min(a.xmax(), b.xmax()), std::min(a.ymax(), b.ymax()), std::min(a.zmax(), b.zmax()));
}

/// Where `flow` (returning an optional vector) is defined over `box`, on a lattice of spacing
/// (longest side) / `n`: 1 where it has a finite value, 0 elsewhere.
template <class Point, class Flow>
Flow_domain_lattice sample_flow_domain(const Flow& flow, const CGAL::Bbox_3& box, int n)
{
  Flow_domain_lattice lattice;
  const std::array<double, 3> lo{box.xmin(), box.ymin(), box.zmin()}, hi{box.xmax(), box.ymax(), box.zmax()};
  const double h = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / n;
  if (!(h > 0))
    return lattice;
  for (int a = 0; a < 3; ++a) {
    lattice.origin[std::size_t(a)] = lo[std::size_t(a)];
    lattice.spacing[std::size_t(a)] = h;
    lattice.dimensions[std::size_t(a)] = std::max(2, int(std::ceil((hi[std::size_t(a)] - lo[std::size_t(a)]) / h)) + 1);
  }
  const auto& d = lattice.dimensions;
  lattice.defined.reserve(std::size_t(d[0]) * std::size_t(d[1]) * std::size_t(d[2]));
  bool any_undefined = false;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i) {
        const auto v = flow(Point(lo[0] + i * h, lo[1] + j * h, lo[2] + k * h));
        const bool defined = v && std::isfinite(v->x()) && std::isfinite(v->y()) && std::isfinite(v->z());
        lattice.defined.push_back(defined ? 1 : 0);
        any_undefined = any_undefined || !defined;
      }
  if (!any_undefined) // no obstacle in the box
    lattice = Flow_domain_lattice();
  return lattice;
}

/// The oblique camera of the scene pictures: looking at the centre of `focus` from the left
/// and above, from the side of y's sign `side` (direction (-1, 0.9 side, 0.75) from it, z up:
/// upstream enough for a patch across the flow to show its face),
/// far enough for the box to fill a view of aspect `aspect` (width / height).
inline Render_camera oblique_camera(const CGAL::Bbox_3& focus, double aspect, double side = -1)
{
  const std::array<double, 3> c{(focus.xmin() + focus.xmax()) / 2, (focus.ymin() + focus.ymax()) / 2,
                                (focus.zmin() + focus.zmax()) / 2};
  const double diagonal = std::sqrt(CGAL::square(focus.xmax() - focus.xmin()) +
                                    CGAL::square(focus.ymax() - focus.ymin()) +
                                    CGAL::square(focus.zmax() - focus.zmin()));
  const double view_angle = 30;
  const double distance = 0.5 * diagonal / std::tan(view_angle / 2 * 3.141592653589793 / 180) /
                          std::min(1.0, aspect);
  const std::array<double, 3> dir{-1.0, side < 0 ? -0.9 : 0.9, 0.75};
  const double length = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  Render_camera camera;
  for (int a = 0; a < 3; ++a)
    camera.position[std::size_t(a)] = c[std::size_t(a)] + distance * dir[std::size_t(a)] / length;
  camera.focal_point = c;
  camera.view_up = {0, 0, 1};
  camera.view_angle = view_angle;
  return camera;
}

/// One stage of `scene` in a picture of its own: `view` with the scene's obstacle, domain
/// outline and camera, the colour bar of `scalar_name` over `scalar_range` in its strip below
/// (empty name: no bar, and no strip).  Its view is the size of one of the scene's, so that the
/// camera frames the stage as the scene frames it and the stage pictures can be compared with
/// each other and with the scene.
inline Scene_picture stage_picture(const Scene_picture& scene, Scene_view view,
                                   const std::string& scalar_name, const std::array<double, 2>& scalar_range)
{
  const auto& b = scene.outline_bounds;
  view.lines.push_back(box_outline(CGAL::Bbox_3(b[0], b[2], b[4], b[1], b[3], b[5])));
  Scene_picture stage;
  stage.width = scene.width / std::max<std::size_t>(1, scene.views.size());
  const bool scene_bar = !scene.scalar_name.empty(), stage_bar = !scalar_name.empty();
  const double view_height = double(scene.height) * (scene_bar ? 1 - scene_bar_strip : 1);
  stage.height = std::size_t(std::lround(view_height / (stage_bar ? 1 - scene_bar_strip : 1)));
  stage.views.push_back(std::move(view));
  stage.scalar_name = scalar_name;
  stage.scalar_range = scalar_range;
  stage.obstacle = scene.obstacle;
  stage.outline_bounds = scene.outline_bounds;
  stage.obstacle_color = scene.obstacle_color;
  stage.background = scene.background;
  stage.camera = scene.camera;
  return stage;
}

/// Renders `picture` to `path`; prints why and returns false when it cannot (no VTK rendering
/// in the build, no display).
inline bool write_scene_picture(const std::filesystem::path& path, const Scene_picture& picture)
{
#ifdef FAS_DEMO_HAVE_RENDERING
  std::string error;
  if (render_scene_PNG(path.string(), picture, &error))
    return true;
  std::cerr << "pictures not written: " << error << "\n";
#else
  (void)picture;
  std::cerr << "pictures not written: " << path.string()
            << ": built without VTK rendering and X11 (the demo's target fas_demo_rendering)\n";
#endif
  return false;
}

/// Writes the obstacle of `picture` (the contour of its lattice) to `path` as VTP, for
/// ParaView; returns false with the reason in `error` when it cannot (a build without VTK's
/// rendering and XML I/O: `error` says so), true without writing when there is no obstacle.
inline bool write_obstacle_VTP(const std::filesystem::path& path, const Scene_picture& picture, std::string& error)
{
  if (picture.obstacle.defined.empty())
    return true;
#if defined(FAS_DEMO_HAVE_RENDERING) && defined(CGAL_FLOW_ALIGNED_SURFACES_USE_VTK)
  return detail::write_VTK_polydata(path.string(), obstacle_polydata(picture.obstacle), error);
#else
  error = path.string() + " not written: built without VTK's rendering and XML I/O";
  return false;
#endif
}

} // namespace fas_demo

#endif // FAS_DEMO_SCENE_ASSEMBLY_H
