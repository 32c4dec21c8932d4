// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the demo's pictures show (render_surface_PNG.h): the camera and the surface's colouring,
// texture, mask and polylines.  Plain data without VTK, so that the demo's programs describe
// their pictures the same way whether or not they were built with VTK's rendering.

#ifndef FAS_DEMO_SURFACE_RENDERING_H
#define FAS_DEMO_SURFACE_RENDERING_H

#include <CGAL/Flow_aligned_surfaces/flow_texture.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fas_demo {

/// A camera of `render_surface_PNG()`: where it is, where it looks, which way is up, and the
/// projection: parallel when `parallel_scale` > 0 (half the picture's height in world units),
/// else perspective with the vertical `view_angle` (degrees).
struct Render_camera {
  std::array<double, 3> position{0, 0, 1};    ///< the eye
  std::array<double, 3> focal_point{0, 0, 0}; ///< the point at the picture's center
  std::array<double, 3> view_up{0, 1, 0};     ///< up in the picture (orthogonalized)
  double parallel_scale = 0;                  ///< > 0: parallel projection
  double view_angle = 30;                     ///< perspective only
};

/// What `render_surface_PNG()` draws.  Every member is optional; an empty surface colouring
/// gives a light grey surface.
struct Surface_rendering {
  std::size_t width = 800;  ///< picture width, pixels
  std::size_t height = 600; ///< picture height, pixels
  /// One value per face (in the order of the face index map), coloured blue (`scalar_range[0]`)
  /// to red (`scalar_range[1]`); a negative or non-finite value is grey (undefined, as the
  /// -1 of `compute_face_normalized_flux()`).  Ignored when `texture` is set.
  std::vector<double> face_scalars;
  std::array<double, 2> scalar_range{0, 1}; ///< the values of the two ends of the colour map
  /// The name of what `face_scalars` holds: a colour bar with this title is drawn (empty: none).
  std::string scalar_bar_title;
  /// The texture, with one (u, v) per vertex in `texture_coordinates` (order of the
  /// vertex index map; non-finite ones are drawn as (0, 0) and should be masked).
  const CGAL::Flow_aligned_surfaces::Texture_image* texture = nullptr;
  std::vector<std::array<double, 2>> texture_coordinates; ///< per vertex
  /// Per face, b in [0, 1] of `compute_flow_texture_mask()`; empty: no mask.
  std::vector<double> face_mask;
  /// Polylines drawn over the surface (seed curves, stream lines).
  std::vector<std::vector<std::array<double, 3>>> polylines;
  std::array<double, 3> polyline_color{0.05, 0.05, 0.05}; ///< their colour
  double polyline_width = 3;                              ///< their width, pixels
  std::array<double, 3> background{1, 1, 1};              ///< the background colour
  /// The camera; none: looking along -z at the whole surface (VTK's `ResetCamera()`).
  std::optional<Render_camera> camera;
};

} // namespace fas_demo

#endif // FAS_DEMO_SURFACE_RENDERING_H
