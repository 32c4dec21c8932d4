// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's pictures of a surface through VTK's OpenGL renderer, off screen, as PNG: the surface
// coloured by a per-face scalar (e.g. the normalized flux, blue 0 -> red 1, grey where
// undefined), or textured, the texture blended to its mean colour by a per-face mask b,
//
//   shown = (1 - b) * texture(u, v) + b * mean(texture),
//
// drawn as a textured layer and, on top of it (polygon offset), a layer of the mean colour with
// opacity b; polylines (seed curves, stream lines) on top.  Needs the demo's CMake target
// fas_demo_rendering (VTK RenderingOpenGL2, IOImage, X11).  Without an X display a private Xvfb
// is started (virtual_display.h); without either, nothing is rendered and the reason is returned.
// Rendering is an application's business, so it lives here and not in the library, whose
// public headers (flow_texture.h for the textures and masks) are all it uses.

#ifndef FAS_DEMO_RENDER_SURFACE_PNG_H
#define FAS_DEMO_RENDER_SURFACE_PNG_H

#include "surface_rendering.h"
#include "virtual_display.h"
#include "vtk_polydata_of_mesh.h"
#include "write_then_rename.h"

#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2)
VTK_MODULE_INIT(vtkRenderingFreeType)

namespace fas_demo {

namespace detail {

inline vtkSmartPointer<vtkPolyDataMapper> make_mapper(vtkPolyData* polydata)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(polydata);
  mapper->ScalarVisibilityOff();
  return mapper;
}

inline vtkSmartPointer<vtkActor> make_actor(vtkPolyDataMapper* mapper)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.35);
  actor->GetProperty()->SetDiffuse(0.65);
  actor->GetProperty()->SetSpecular(0);
  return actor;
}

inline vtkSmartPointer<vtkImageData> make_vtk_image(const CGAL::Flow_aligned_surfaces::Texture_image& t)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(int(t.width), int(t.height), 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* bytes = static_cast<unsigned char*>(image->GetScalarPointer());
  for (std::size_t i = 0; i < t.pixels.size(); ++i) // VTK's rows run bottom up too
    bytes[i] = (unsigned char)std::lround(
        255 * std::clamp(std::isnan(t.pixels[i]) ? 0.0f : t.pixels[i], 0.0f, 1.0f));
  return image;
}

/// Textures `actor` (which draws `surface`) by `texture` at one (u, v) per point of `surface`
/// (non-finite coordinates map to 0).
inline void set_texture(vtkActor* actor, vtkPolyData* surface,
                        const CGAL::Flow_aligned_surfaces::Texture_image& texture,
                        const std::vector<std::array<double, 2>>& texture_coordinates)
{
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetName("texture_coordinates");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(vtkIdType(texture_coordinates.size()));
  for (std::size_t i = 0; i < texture_coordinates.size(); ++i) {
    const auto& t = texture_coordinates[i];
    const bool finite = std::isfinite(t[0]) && std::isfinite(t[1]);
    tcoords->SetTuple2(vtkIdType(i), finite ? t[0] : 0.0, finite ? t[1] : 0.0);
  }
  surface->GetPointData()->SetTCoords(tcoords);
  auto vtk_texture = vtkSmartPointer<vtkTexture>::New();
  vtk_texture->SetInputData(make_vtk_image(texture));
  vtk_texture->RepeatOn();
  vtk_texture->InterpolateOn();
  actor->SetTexture(vtk_texture);
  actor->GetProperty()->SetColor(1, 1, 1);
}

/// The layer that blends a textured surface (`points`, `polys`) to the texture's mean colour:
/// that colour with opacity b per face, pulled in front of the textured layer; null when no b is
/// positive.
inline vtkSmartPointer<vtkActor> make_mask_layer(vtkPoints* points, vtkCellArray* polys,
                                                 const CGAL::Flow_aligned_surfaces::Texture_image& texture,
                                                 const std::vector<double>& face_mask)
{
  bool any_mask = false;
  for (double b : face_mask)
    any_mask = any_mask || !(b <= 0);
  if (!any_mask)
    return nullptr;
  const std::array<double, 3> mean = texture.mean_color();
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(vtkIdType(face_mask.size()));
  for (std::size_t j = 0; j < face_mask.size(); ++j) {
    const double b = std::isnan(face_mask[j]) ? 1.0 : std::clamp(face_mask[j], 0.0, 1.0);
    colors->SetTuple4(vtkIdType(j), std::lround(255 * mean[0]), std::lround(255 * mean[1]),
                      std::lround(255 * mean[2]), std::lround(255 * b));
  }
  auto layer = vtkSmartPointer<vtkPolyData>::New();
  layer->SetPoints(points);
  layer->SetPolys(polys);
  layer->GetCellData()->SetScalars(colors);
  auto layer_mapper = make_mapper(layer);
  layer_mapper->ScalarVisibilityOn();
  layer_mapper->SetScalarModeToUseCellData();
  layer_mapper->SetColorModeToDirectScalars();
  layer_mapper->SetResolveCoincidentTopologyToPolygonOffset();
  layer_mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2, -2);
  return make_actor(layer_mapper);
}

// Writes what `window` shows to `filename` as PNG, beside it first and renamed over it when
// complete, so that a reader never sees half a picture; `reason` says why not.
inline bool write_window_PNG(vtkRenderWindow* window, const std::string& filename, std::string& reason)
{
  const auto fail = [&](const std::string& why) {
    reason = why;
    return false;
  };
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto png = vtkSmartPointer<vtkPNGWriter>::New();
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* encoded = png->GetResult();
  if (encoded == nullptr || encoded->GetNumberOfValues() == 0)
    return fail("VTK's PNG writer produced nothing");
  // Written beside `filename` and renamed over it, so that a reader never sees half a picture.
  std::string why;
  if (!write_stream_then_rename(filename, why, [&](std::ostream& os) {
        os.write(reinterpret_cast<const char*>(encoded->GetPointer(0)),
                 std::streamsize(encoded->GetNumberOfValues()));
      }))
    return fail("cannot write the picture: " + why);
  return true;
}

} // namespace detail

/* Renders `tm` as `what` describes through VTK's OpenGL renderer, off screen, and writes
the picture to `filename` as PNG.

Coloured by `face_scalars` (blue to red), or textured by `texture` at `texture_coordinates`
with the texture blended per face to its mean colour by `face_mask`, lit by VTK's head light;
`polylines` are drawn on top.  The picture's texture follows the surface, so two views of the
same surface show the same texture at the same surface points (unlike screen-space LIC).

Rendering needs an X display for OpenGL: when `DISPLAY` is unset or does not open, a private
`Xvfb` is started once per process (stopped at exit; `FAS_NO_XVFB=1` in the environment
forbids it).  When neither works, nothing is rendered and the function returns `false` with
the reason, so a program can go on writing its other files.  The PNG is written beside
`filename` and renamed over it when complete.

`tm` is any polygon mesh (a model of `FaceListGraph`); `np` may hold `vertex_point_map`,
`vertex_index_map` and `face_index_map` as in `normalized_flux()`; `error`, if not null,
receives the reason of a failure.

Returns `true` if the picture was written; `false` if an array of `what` has the wrong size,
a size is zero, there is no display, or the file could not be written.
*/
template <class TriangleMesh,
          class NamedParameters = CGAL::Flow_aligned_surfaces::parameters::Default_named_parameters>
bool render_surface_PNG(const std::string& filename, const TriangleMesh& tm, const Surface_rendering& what,
                        const NamedParameters& np = CGAL::parameters::default_values(),
                        std::string* error = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto fail = [&](const std::string& reason) {
    if (error)
      *error = "render_surface_PNG: " + filename + ": " + reason;
    return false;
  };
  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  if (what.width == 0 || what.height == 0 || what.width > 16384 || what.height > 16384)
    return fail("width and height must be in [1, 16384] (got " + std::to_string(what.width) + " x " +
                std::to_string(what.height) + ")");
  if (!what.face_scalars.empty() && what.face_scalars.size() != nf)
    return fail("face_scalars has " + std::to_string(what.face_scalars.size()) + " values for " +
                std::to_string(nf) + " faces");
  if (!what.face_mask.empty() && what.face_mask.size() != nf)
    return fail("face_mask has " + std::to_string(what.face_mask.size()) + " values for " +
                std::to_string(nf) + " faces");
  if (what.texture != nullptr &&
      (what.texture_coordinates.size() != nv || what.texture->width == 0 || what.texture->height == 0 ||
       what.texture->pixels.size() != 3 * what.texture->width * what.texture->height))
    return fail("the texture is empty or inconsistent, or texture_coordinates has " +
                std::to_string(what.texture_coordinates.size()) + " values for " + std::to_string(nv) +
                " vertices");
  std::string reason;
  if (!ensure_display(reason))
    return fail(reason);

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const vtkSmartPointer<vtkPolyData> surface = vtk_polydata_of_mesh(tm, vpm, vim, fim);
  vtkPoints* points = surface->GetPoints();
  vtkCellArray* polys = surface->GetPolys();

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(what.background[0], what.background[1], what.background[2]);
  auto mapper = detail::make_mapper(surface);
  auto actor = detail::make_actor(mapper);
  renderer->AddActor(actor);
  if (what.texture != nullptr) {
    detail::set_texture(actor, surface, *what.texture, what.texture_coordinates);
    if (const vtkSmartPointer<vtkActor> layer =
            detail::make_mask_layer(points, polys, *what.texture, what.face_mask))
      renderer->AddActor(layer);
  }
  else if (!what.face_scalars.empty()) {
    auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
    scalars->SetName("face_scalars");
    scalars->SetNumberOfTuples(vtkIdType(nf));
    for (std::size_t j = 0; j < nf; ++j) {
      const double s = what.face_scalars[j];
      scalars->SetValue(vtkIdType(j), std::isfinite(s) && s >= 0 ? s : -1e300);
    }
    surface->GetCellData()->SetScalars(scalars);
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetHueRange(0.667, 0.0);
    table->SetTableRange(what.scalar_range[0], what.scalar_range[1]);
    table->SetBelowRangeColor(0.6, 0.6, 0.6, 1);
    table->UseBelowRangeColorOn();
    table->Build();
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetScalarModeToUseCellData();
    mapper->ScalarVisibilityOn();
    if (!what.scalar_bar_title.empty()) {
      auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
      bar->SetLookupTable(table);
      bar->SetTitle(what.scalar_bar_title.c_str());
      bar->SetNumberOfLabels(5);
      bar->SetOrientationToHorizontal();
      bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
      bar->GetPositionCoordinate()->SetValue(0.5, 0.02);
      bar->SetWidth(0.46);
      bar->SetHeight(0.13);
      for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
        text->SetColor(0.1, 0.1, 0.1);
        text->ShadowOff();
        text->ItalicOff();
      }
      renderer->AddActor2D(bar);
    }
  }
  else
    actor->GetProperty()->SetColor(0.85, 0.85, 0.85);

  if (!what.polylines.empty()) {
    auto line_points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& polyline : what.polylines) {
      std::vector<vtkIdType> ids;
      for (const auto& p : polyline)
        ids.push_back(line_points->InsertNextPoint(p.data()));
      if (ids.size() >= 2)
        lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
    }
    auto curves = vtkSmartPointer<vtkPolyData>::New();
    curves->SetPoints(line_points);
    curves->SetLines(lines);
    auto curve_mapper = detail::make_mapper(curves);
    curve_mapper->SetResolveCoincidentTopologyToPolygonOffset();
    curve_mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-4, -4);
    auto curve_actor = vtkSmartPointer<vtkActor>::New();
    curve_actor->SetMapper(curve_mapper);
    curve_actor->GetProperty()->SetColor(what.polyline_color[0], what.polyline_color[1],
                                         what.polyline_color[2]);
    curve_actor->GetProperty()->SetLineWidth(float(what.polyline_width));
    curve_actor->GetProperty()->LightingOff();
    renderer->AddActor(curve_actor);
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  if (what.camera) {
    camera->SetPosition(what.camera->position.data());
    camera->SetFocalPoint(what.camera->focal_point.data());
    camera->SetViewUp(what.camera->view_up.data());
    camera->OrthogonalizeViewUp();
    if (what.camera->parallel_scale > 0) {
      camera->ParallelProjectionOn();
      camera->SetParallelScale(what.camera->parallel_scale);
    }
    else
      camera->SetViewAngle(what.camera->view_angle);
    renderer->ResetCameraClippingRange();
  }
  else
    renderer->ResetCamera();

  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->SetSize(int(what.width), int(what.height));
  window->Render();
  if (!detail::write_window_PNG(window, filename, reason))
    return fail(reason);
  return true;
}

} // namespace fas_demo

#endif // FAS_DEMO_RENDER_SURFACE_PNG_H
