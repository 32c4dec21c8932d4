// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's scene pictures (scene_rendering.h) through VTK's OpenGL renderer, off screen, as
// PNG: each view in its own viewport side by side under the same camera, lit by a light kit
// (key, fill and back lights, as ParaView's default), with specular highlights; the surfaces with
// face scalars coloured blue to red with a colour bar titled by the array's name; the obstacle
// as VTK's flying-edges contour of where the flow is defined, smoothed and closed.  Needs the demo's CMake target
// fas_demo_rendering; the display and the PNG writing are those of render_surface_PNG.h.

#ifndef FAS_DEMO_RENDER_SCENE_PNG_H
#define FAS_DEMO_RENDER_SCENE_PNG_H

#include "render_surface_PNG.h"
#include "scene_rendering.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>


namespace fas_demo {

namespace detail {

inline vtkSmartPointer<vtkLookupTable> make_blue_to_red(const std::array<double, 2>& range)
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetHueRange(0.667, 0.0);
  table->SetTableRange(range[0], range[1]);
  table->SetBelowRangeColor(0.6, 0.6, 0.6, 1);
  table->UseBelowRangeColorOn();
  table->Build();
  return table;
}

// Adds the actors of `s` to `renderer`: the surface, and for a textured one its mask layer.
inline void add_scene_surface(vtkRenderer* renderer, const Scene_surface& s, vtkLookupTable* table)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const auto& p : s.points)
    points->InsertNextPoint(p.data());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : s.triangles) {
    const vtkIdType ids[3] = {vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2])};
    polys->InsertNextCell(3, ids);
  }
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetPolys(polys);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->ScalarVisibilityOff();
  if (s.face_scalars.size() == s.triangles.size() && !s.face_scalars.empty()) {
    auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
    scalars->SetNumberOfTuples(vtkIdType(s.face_scalars.size()));
    for (std::size_t j = 0; j < s.face_scalars.size(); ++j)
      scalars->SetValue(vtkIdType(j), std::isfinite(s.face_scalars[j]) && s.face_scalars[j] >= 0
                                          ? s.face_scalars[j]
                                          : -1e300);
    polydata->GetCellData()->SetScalars(scalars);
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetScalarModeToUseCellData();
    mapper->ScalarVisibilityOn();
  }
  const bool textured = s.texture != nullptr && s.texture_coordinates.size() == s.points.size();
  auto actor = vtkSmartPointer<vtkActor>::New();
  if (textured) // the coordinates travel with the points through the normals' filter
    set_texture(actor, polydata, *s.texture, s.texture_coordinates);
  // Smooth shading: point normals (flat faces, unconnected sides, consistent orientation).
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(polydata);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->Update();
  mapper->SetInputConnection(normals->GetOutputPort());
  if (s.opacity < 1) { // behind an opaque surface it coincides with (a stream surface through its seeding surface)
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(2, 2);
  }
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  if (!textured)
    property->SetColor(s.color[0], s.color[1], s.color[2]);
  property->SetOpacity(s.opacity);
  property->SetAmbient(0.2);
  property->SetDiffuse(0.8);
  property->SetSpecular(0.25);
  property->SetSpecularPower(30);
  if (s.edges) {
    property->EdgeVisibilityOn();
    property->SetEdgeColor(0.3, 0.3, 0.3);
  }
  renderer->AddActor(actor);
  if (textured && s.face_mask.size() == s.triangles.size())
    if (const vtkSmartPointer<vtkActor> layer = make_mask_layer(points, polys, *s.texture, s.face_mask))
      renderer->AddActor(layer);
}

inline vtkSmartPointer<vtkActor> make_scene_lines_actor(const Scene_lines& l)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& polyline : l.polylines) {
    std::vector<vtkIdType> ids;
    for (const auto& p : polyline)
      ids.push_back(points->InsertNextPoint(p.data()));
    if (ids.size() >= 2)
      lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
  }
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetLines(lines);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(polydata);
  mapper->ScalarVisibilityOff();
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-4, -4);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(l.color[0], l.color[1], l.color[2]);
  actor->GetProperty()->SetLineWidth(float(l.width));
  actor->GetProperty()->LightingOff();
  return actor;
}

} // namespace detail

/// `lattice` padded by `pad` samples on every side with 1 (the flow defined) and smoothed by a
/// Gaussian of standard deviation one sample (separable, truncated at 3): its contour at 1/2 is
/// smooth where the samples' 0/1 steps would draw stairs, and closed where the obstacle leaves
/// the lattice (capped on the lattice's box, where the scene's outline is), instead of ending
/// in an open rim.
inline Flow_domain_lattice padded_smoothed_lattice(const Flow_domain_lattice& lattice, int pad = 4)
{
  Flow_domain_lattice out;
  const std::array<int, 3> n = lattice.dimensions;
  for (std::size_t a = 0; a < 3; ++a) {
    out.dimensions[a] = n[a] + 2 * pad;
    out.spacing[a] = lattice.spacing[a];
    out.origin[a] = lattice.origin[a] - pad * lattice.spacing[a];
  }
  const std::array<int, 3> d = out.dimensions;
  const auto index = [&d](int i, int j, int k) {
    return std::size_t(i) + std::size_t(d[0]) * (std::size_t(j) + std::size_t(d[1]) * std::size_t(k));
  };
  out.defined.assign(std::size_t(d[0]) * std::size_t(d[1]) * std::size_t(d[2]), 1.0);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        out.defined[index(i + pad, j + pad, k + pad)] =
            lattice.defined[std::size_t(i) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * std::size_t(k))];
  constexpr int radius = 3;
  std::array<double, 2 * radius + 1> weights{};
  double sum = 0;
  for (int t = -radius; t <= radius; ++t)
    sum += weights[std::size_t(t + radius)] = std::exp(-0.5 * t * t);
  for (double& w : weights)
    w /= sum;
  std::vector<double> next(out.defined.size());
  for (int axis = 0; axis < 3; ++axis) { // one axis at a time; beyond the padding, 1 (the flow)
    for (int k = 0; k < d[2]; ++k)
      for (int j = 0; j < d[1]; ++j)
        for (int i = 0; i < d[0]; ++i) {
          double value = 0;
          for (int t = -radius; t <= radius; ++t) {
            std::array<int, 3> q{i, j, k};
            q[std::size_t(axis)] += t;
            const bool inside = q[std::size_t(axis)] >= 0 && q[std::size_t(axis)] < d[std::size_t(axis)];
            value += weights[std::size_t(t + radius)] * (inside ? out.defined[index(q[0], q[1], q[2])] : 1.0);
          }
          next[index(i, j, k)] = value;
        }
    out.defined.swap(next);
  }
  return out;
}

/// The obstacle of a scene: the contour at 1/2 of where the flow is defined on `lattice`,
/// padded and smoothed (`padded_smoothed_lattice()`; VTK's flying edges, with normals).
inline vtkSmartPointer<vtkPolyData> obstacle_polydata(const Flow_domain_lattice& sampled)
{
  const Flow_domain_lattice lattice = padded_smoothed_lattice(sampled);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(lattice.origin.data());
  image->SetSpacing(lattice.spacing.data());
  image->SetDimensions(lattice.dimensions[0], lattice.dimensions[1], lattice.dimensions[2]);
  auto values = vtkSmartPointer<vtkDoubleArray>::New();
  values->SetName("defined");
  values->SetNumberOfTuples(vtkIdType(lattice.defined.size()));
  for (std::size_t i = 0; i < lattice.defined.size(); ++i)
    values->SetValue(vtkIdType(i), lattice.defined[i]);
  image->GetPointData()->SetScalars(values);
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputData(image);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOn();
  contour->ComputeScalarsOff();
  contour->Update();
  return contour->GetOutput();
}

namespace detail {

inline vtkSmartPointer<vtkActor> make_obstacle_actor(const Flow_domain_lattice& lattice,
                                                     const std::array<double, 3>& color)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(obstacle_polydata(lattice));
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(20);
  return actor;
}

} // namespace detail

/// Renders `picture` (scene_rendering.h) off screen and writes it to `filename` as PNG; returns
/// false with the reason in `error` (no display, sizes out of range, a write failure).
inline bool render_scene_PNG(const std::string& filename, const Scene_picture& picture, std::string* error)
{
  const auto fail = [&](const std::string& reason) {
    if (error)
      *error = "render_scene_PNG: " + filename + ": " + reason;
    return false;
  };
  if (picture.views.empty() || picture.width == 0 || picture.height == 0 || picture.width > 16384 ||
      picture.height > 16384)
    return fail("no view, or a size outside [1, 16384]");
  const auto& lattice = picture.obstacle;
  if (std::size_t(std::max(0, lattice.dimensions[0])) * std::size_t(std::max(0, lattice.dimensions[1])) *
          std::size_t(std::max(0, lattice.dimensions[2])) !=
      lattice.defined.size())
    return fail("the obstacle's lattice has " + std::to_string(lattice.defined.size()) +
                " values for its dimensions");
  std::string reason;
  if (!ensure_display(reason))
    return fail(reason);

  const auto table = detail::make_blue_to_red(picture.scalar_range);
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0); // depth peeling (translucent surfaces) needs it off; FXAA smooths the edges
  window->SetSize(int(picture.width), int(picture.height));
  const double n = double(picture.views.size());
  // The colour bar in a strip of its own below the views: over a view it hid the surfaces.
  const bool bar = !picture.scalar_name.empty();
  const double strip = bar ? scene_bar_strip : 0;
  if (bar) {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(0, 0, 1, strip);
    renderer->SetBackground(picture.background[0], picture.background[1], picture.background[2]);
    auto actor = vtkSmartPointer<vtkScalarBarActor>::New();
    actor->SetLookupTable(table);
    actor->SetTitle(picture.scalar_name.c_str());
    actor->SetNumberOfLabels(5);
    actor->SetLabelFormat("%.2g");
    actor->SetOrientationToHorizontal();
    actor->SetTextPositionToPrecedeScalarBar();
    // At least 480 pixels wide, centred: narrower, as 0.4 of a one-view picture, its labels ran
    // into each other.
    const double bar_width = std::max(0.4, std::min(0.8, 480.0 / double(picture.width)));
    actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    actor->GetPositionCoordinate()->SetValue((1 - bar_width) / 2, 0.05);
    actor->SetWidth(bar_width);
    actor->SetHeight(0.9);
    for (vtkTextProperty* text : {actor->GetTitleTextProperty(), actor->GetLabelTextProperty()}) {
      text->SetColor(0.1, 0.1, 0.1);
      text->ShadowOff();
      text->ItalicOff();
    }
    renderer->AddActor2D(actor);
    window->AddRenderer(renderer);
  }
  for (std::size_t i = 0; i < picture.views.size(); ++i) {
    const Scene_view& view = picture.views[i];
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(i / n, strip, (i + 1) / n, 1);
    renderer->SetBackground(picture.background[0], picture.background[1], picture.background[2]);
    renderer->SetUseDepthPeeling(1);
    renderer->SetMaximumNumberOfPeels(8);
    renderer->UseFXAAOn();
    for (const Scene_surface& s : view.surfaces)
      detail::add_scene_surface(renderer, s, table);
    for (const Scene_lines& l : view.lines)
      renderer->AddActor(detail::make_scene_lines_actor(l));
    if (!lattice.defined.empty())
      renderer->AddActor(detail::make_obstacle_actor(lattice, picture.obstacle_color));
    if (!view.title.empty()) {
      auto title = vtkSmartPointer<vtkTextActor>::New();
      title->SetInput(view.title.c_str());
      title->GetTextProperty()->SetFontSize(int(picture.height / 32));
      title->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
      title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
      title->GetPositionCoordinate()->SetValue(0.03, 0.93);
      renderer->AddActor2D(title);
    }
    auto lights = vtkSmartPointer<vtkLightKit>::New();
    lights->AddLightsToRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(picture.camera.position.data());
    camera->SetFocalPoint(picture.camera.focal_point.data());
    camera->SetViewUp(picture.camera.view_up.data());
    camera->OrthogonalizeViewUp();
    camera->SetViewAngle(picture.camera.view_angle);
    renderer->ResetCameraClippingRange();
    window->AddRenderer(renderer);
  }
  window->Render();
  if (!detail::write_window_PNG(window, filename, reason))
    return fail(reason);
  return true;
}

} // namespace fas_demo

#endif // FAS_DEMO_RENDER_SCENE_PNG_H
