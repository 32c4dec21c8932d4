// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the demo's scene pictures show (render_scene_PNG.h), the way the paper's Figures 4, 5 and 8
// show the method: several surfaces and line sets in one 3D scene seen by an oblique camera, one
// of them coloured by a named array with a colour bar, the obstacle (the contour of where the
// flow is defined, sampled on a lattice), the outline of the domain, and one or more views side
// by side (the initial patch beside the aligned one).  Plain data without VTK, like
// surface_rendering.h.

#ifndef FAS_DEMO_SCENE_RENDERING_H
#define FAS_DEMO_SCENE_RENDERING_H

#include "surface_rendering.h"

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace fas_demo {

/// A triangle surface of a scene: textured when `texture` is given (the paper's Figure 8), else
/// coloured by `face_scalars` through the picture's colour map when they are given, else in
/// `color`.
struct Scene_surface {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<double> face_scalars; ///< one per triangle, or empty
  /// The texture, with one (u, v) per point in `texture_coordinates`, blended per triangle to its
  /// mean colour by `face_mask` (b in [0, 1]; empty: not blended).
  std::shared_ptr<const CGAL::Flow_aligned_surfaces::Texture_image> texture;
  std::vector<std::array<double, 2>> texture_coordinates;
  std::vector<double> face_mask;
  std::array<double, 3> color{0.8, 0.8, 0.8};
  double opacity = 1;
  bool edges = false; ///< draw the triangles' edges (a wireframe over the surface)
};

/// Polylines of a scene (seed curves, stream lines, the domain's outline).
struct Scene_lines {
  std::vector<std::vector<std::array<double, 3>>> polylines;
  std::array<double, 3> color{0.05, 0.05, 0.05};
  double width = 2; ///< pixels
};

/// Where the flow is defined, sampled on a regular lattice: the obstacle is drawn as the
/// contour at 1/2 of `defined` (1: defined, 0: not).
struct Flow_domain_lattice {
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<int, 3> dimensions{0, 0, 0}; ///< points along x, y, z
  std::vector<double> defined;            ///< x fastest
};

/// One view of a picture: what it shows and its title (drawn at its top).
struct Scene_view {
  std::vector<Scene_surface> surfaces;
  std::vector<Scene_lines> lines;
  std::string title;
};

/// The share of a scene picture's height that its colour bar's strip takes, below the views.
constexpr double scene_bar_strip = 0.12;

/// A scene picture: its views side by side under one camera, the colour map of the surfaces'
/// face scalars with a colour bar titled `scalar_name`, and the obstacle in every view.
struct Scene_picture {
  std::size_t width = 1200;
  std::size_t height = 800;
  std::vector<Scene_view> views;
  std::string scalar_name;                  ///< the colour bar's title (empty: no colour bar)
  std::array<double, 2> scalar_range{0, 1}; ///< blue to red
  Flow_domain_lattice obstacle;             ///< no obstacle when empty
  /// The box of the domain's outline the views draw (xmin, xmax, ymin, ymax, zmin, zmax), for
  /// the other views of the scene (ParaView's).
  std::array<double, 6> outline_bounds{0, 0, 0, 0, 0, 0};
  std::array<double, 3> obstacle_color{0.72, 0.72, 0.76};
  std::array<double, 3> background{1, 1, 1};
  Render_camera camera;
};

} // namespace fas_demo

#endif // FAS_DEMO_SCENE_RENDERING_H
