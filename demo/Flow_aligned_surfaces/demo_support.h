// What the demo's programs share: the kernel and mesh types, the built-in flows by name, a
// flow read from a data file, and the surface files a user opens in ParaView (PLY, and VTP
// with the velocity at the vertices and the normalized flux of every face).

#ifndef FAS_DEMO_DEMO_SUPPORT_H
#define FAS_DEMO_DEMO_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/Sampled_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>

#include "surface_rendering.h"
#include "write_polydata_VTP.h"
#ifdef FAS_DEMO_HAVE_RENDERING
#include "render_surface_PNG.h"
#endif

#include <CGAL/Surface_mesh/IO/PLY.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace fas_demo {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

// Every flow behind one type, so that the deformation is compiled once.
using Flow = std::function<std::optional<Vector>(const Point&)>;

/// A number in a CSV file, or an empty field for no value.
inline std::string csv_field(const std::optional<double>& x)
{
  std::ostringstream os;
  os.precision(17);
  if (x)
    os << *x;
  return os.str();
}

/// The names that `make_built_in_flow()` knows, for usage messages.
inline const char* built_in_flow_names()
{
  return "cylinder|point-source|sphere|helical|hill|burgers|abc|tornado";
}

/// A built-in analytic flow by name, or nothing for an unknown name.
inline std::optional<Flow> make_built_in_flow(const std::string& name)
{
  if (name == "cylinder") // potential flow past a cylinder of radius 1 along z
    return Flow(FAS::Cylinder_potential_flow<Kernel>(1.0, 1.0));
  if (name == "point-source")
    return Flow(FAS::Point_source_flow<Kernel>(Point(0, 0, 0), 1.0));
  if (name == "sphere")
    return Flow(FAS::Sphere_potential_flow<Kernel>(1.0, 1.0));
  if (name == "helical")
    return Flow(FAS::Helical_flow<Kernel>(0.5));
  if (name == "hill")
    return Flow(FAS::Hill_spherical_vortex<Kernel>(1.0, 1.0));
  if (name == "burgers")
    return Flow(FAS::Burgers_vortex<Kernel>());
  if (name == "abc")
    return Flow(FAS::ABC_flow<Kernel>());
  if (name == "tornado")
    return Flow(FAS::Crawfis_tornado<Kernel>());
  return std::nullopt;
}

/// Calls `read(np)` with the demo's options of the readers: the reason of a failure in `error`,
/// large binary arrays decoded on all cores, and the velocity array `array` (empty: the file's
/// first vector array).
template <class Read>
bool read_with_demo_options(const Read& read, const std::string& array, std::string& error)
{
  const auto parallel = FAS::parameters::use_parallelism(true);
  return array.empty()
             ? read(FAS::parameters::error_message(&error, parallel))
             : read(FAS::parameters::error_message(&error, FAS::parameters::array_name(array, parallel)));
}

/// The flow of a data file (any format `IO::read_flow_field()` reads), the velocity array named
/// `array` (empty: the first vector array); prints the reason and returns nothing on failure.
inline std::optional<FAS::Sampled_flow_field_3<Kernel>> read_data_field(const std::string& file,
                                                                        const std::string& array)
{
  FAS::Sampled_flow_field_3<Kernel> field;
  std::string error;
  if (!read_with_demo_options([&](const auto& np) { return FAS::IO::read_flow_field(file, field, np); },
                              array, error)) {
    std::cerr << "error: " << error << "\n";
    return std::nullopt;
  }
  return field;
}

/// The normalized flux of each face of `tm` in `flow`, by face index.
inline std::vector<double> face_fluxes(const Mesh& tm, const Flow& flow)
{
  std::vector<double> values(tm.number_of_faces());
  FAS::compute_face_normalized_flux(
      tm, flow, boost::make_iterator_property_map(values.begin(), get(CGAL::face_index, tm)));
  return values;
}

/// The velocity of `flow` at each vertex of `tm`, 3 values per vertex by vertex index (0 where
/// the flow is not defined).
inline std::vector<double> vertex_velocities(const Mesh& tm, const Flow& flow)
{
  std::vector<double> values;
  for (auto v : tm.vertices()) {
    const auto sample = flow(tm.point(v));
    const Vector w = sample ? *sample : Vector(0, 0, 0);
    values.insert(values.end(), {w.x(), w.y(), w.z()});
  }
  return values;
}

/// Writes `tm` to `path` as VTP (binary when built with VTK, write_polydata_VTP.h), with the
/// velocity at the vertices, the per-face flux (the active scalars) and the `extra` vertex arrays.
inline bool write_surface_VTP(const std::filesystem::path& path, const Mesh& tm, const Flow& flow,
                              std::vector<FAS::IO::Data_array> extra = {})
{
  std::string error;
  extra.insert(extra.begin(), {"velocity", 3, vertex_velocities(tm, flow)});
  const bool vtp = write_mesh_VTP(path.string(), tm, extra, {{"normalized_flux", 1, face_fluxes(tm, flow)}},
                                  Active_scalars{"", "normalized_flux"}, &error);
  if (!vtp)
    std::cerr << "error: " << error << "\n";
  return vtp;
}

/// Writes `stem`.ply and `stem`.vtp (with the velocity and the per-face normalized flux).
inline bool write_surface(const std::filesystem::path& stem, const Mesh& tm, const Flow& flow)
{
  if (!CGAL::IO::write_PLY(stem.string() + ".ply", tm, CGAL::parameters::stream_precision(17))) {
    std::cerr << "error: cannot write " << stem.string() << ".ply\n";
    return false;
  }
  return write_surface_VTP(stem.string() + ".vtp", tm, flow);
}

/// Renders `what` of `tm` into the PNG `path`, seen obliquely (50 degrees off the surface's mean
/// normal) unless `what` has a camera; prints why and returns false when it cannot (no
/// VTK rendering in the build, no display): the other files of a program do not depend on it.
inline bool write_picture(const std::filesystem::path& path, const Mesh& tm, const Surface_rendering& what)
{
#ifdef FAS_DEMO_HAVE_RENDERING
  std::string error;
  Surface_rendering facing = what;
  if (!facing.camera && !tm.is_empty()) { // look at the surface along its area-weighted mean normal
    Vector normal(0, 0, 0);
    Vector sum(0, 0, 0);
    double area = 0;
    for (auto f : tm.faces()) {
      const auto h = tm.halfedge(f);
      const Point &a = tm.point(tm.source(h)), &b = tm.point(tm.target(h)),
                  &c = tm.point(tm.target(tm.next(h)));
      const Vector n = CGAL::cross_product(b - a, c - a) / 2;
      normal = normal + n;
      const double face_area = std::sqrt(n.squared_length());
      sum = sum + face_area * ((a - CGAL::ORIGIN) + (b - CGAL::ORIGIN) + (c - CGAL::ORIGIN)) / 3;
      area += face_area;
    }
    const CGAL::Bbox_3 box = CGAL::bbox_3(tm.points().begin(), tm.points().end());
    const double diagonal =
        std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                  CGAL::square(box.zmax() - box.zmin()));
    const double length = std::sqrt(normal.squared_length());
    if (area > 0 && length > 1e-3 * area) { // a surface that faces some way (not a closed one)
      const Point center = CGAL::ORIGIN + sum / area;
      const Vector up = std::abs(normal.z()) < 0.9 * length ? Vector(0, 0, 1) : Vector(0, 1, 0);
      // Oblique: 50 degrees off the normal, about the picture's vertical and towards the top, so
      // that a bent surface shows its bending instead of its face.
      const Vector n = normal / length;
      Vector side = CGAL::cross_product(up, n);
      side = side / std::sqrt(side.squared_length());
      const double off = 50 * CGAL_PI / 180;
      const Vector direction = std::cos(off) * n + std::sin(off) * (0.8 * side + 0.6 * up);
      const Point eye = center + 2 * diagonal * direction / std::sqrt(direction.squared_length());
      facing.camera = Render_camera{
          {eye.x(), eye.y(), eye.z()}, {center.x(), center.y(), center.z()}, {up.x(), up.y(), up.z()}, 0, 30};
    }
  }
  if (render_surface_PNG(path.string(), tm, facing, CGAL::parameters::default_values(), &error))
    return true;
  std::cerr << "pictures not written: " << error << "\n";
#else
  (void)tm;
  (void)what;
  std::cerr << "pictures not written: " << path.string()
            << ": built without VTK rendering and X11 (the demo's target fas_demo_rendering)\n";
#endif
  return false;
}

/// What the picture of `tm` coloured by the normalized flux of its faces shows, with `lines` (seed
/// curves, stream lines) drawn on it.
inline Surface_rendering flux_with_polylines(const Mesh& tm, const Flow& flow,
                                             const std::vector<std::vector<Point>>& lines)
{
  Surface_rendering what;
  what.face_scalars = face_fluxes(tm, flow);
  what.scalar_bar_title = "normalized_flux";
  for (const std::vector<Point>& line : lines) {
    what.polylines.emplace_back();
    for (const Point& p : line)
      what.polylines.back().push_back({p.x(), p.y(), p.z()});
  }
  return what;
}

/// The LIC-like texture of the paper's Section 6 on a stream surface: the noise texture, mapped by
/// the surface's unnormalized tangential parametrization r, s (texture coordinates per vertex, in
/// vertex index order) and blended to its mean colour by the mask b per face (face index order).
struct Flow_texture_of_mesh {
  FAS::Texture_image texture = FAS::make_noise_texture(128, 128, 24, 1);
  std::vector<std::array<double, 2>> texture_coordinates;
  std::vector<double> face_mask;
};

/// The flow texture of `tm` in `flow` with `scale` texture repeats per unit of r, or, when `scale`
/// is not positive, -`scale` repeats over the range of r.  \throws what
/// `parametrize_tangential()` throws (no usable flow on the surface).
inline Flow_texture_of_mesh flow_texture_of_mesh(const Mesh& tm, const Flow& flow, double scale)
{
  Mesh copy = tm;
  auto r = copy.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
  auto s = copy.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
  auto uv = copy.add_property_map<Mesh::Vertex_index, std::array<double, 2>>("v:uv").first;
  auto mask = copy.add_property_map<Mesh::Face_index, double>("f:mask", 1).first;
  FAS::parametrize_tangential(copy, flow, r, s, FAS::parameters::normalized(false));
  if (!(scale > 0))
    scale = scale < 0 ? FAS::flow_texture_scale(copy, r, -scale) : 1;
  FAS::compute_flow_texture_coordinates(copy, r, s, uv, scale);
  FAS::compute_flow_texture_mask(copy, flow, r, mask);
  Flow_texture_of_mesh result;
  result.texture_coordinates.resize(copy.number_of_vertices());
  result.face_mask.resize(copy.number_of_faces());
  for (auto v : copy.vertices())
    result.texture_coordinates[v.idx()] = uv[v];
  for (auto f : copy.faces())
    result.face_mask[f.idx()] = mask[f];
  return result;
}

/// The orthogonal surface of the seeding programs: a tilted disk of `faces` triangles beside the
/// point source `flow`, aligned orthogonally (it becomes a piece of a sphere about the source);
/// returns the alignment's report.
inline FAS::Alignment_report make_orthogonal_disk(Mesh& tm, const FAS::Point_source_flow<Kernel>& flow,
                                                  std::size_t faces)
{
  FAS::make_disk_patch(tm, Point(0, 0, 1), Vector(0.3, 0, 1), 0.6, faces);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::ORTHOGONAL);
  std::cout << "aligned: flux " << report.normalized_flux << " after " << report.number_of_iterations
            << " iterations\n";
  return report;
}

/// Seed curves that cross the flow, the way of the paper's Figure 4 (top): a disk patch is
/// aligned tangentially to the flow (a piece of stream surface), parametrized tangentially, and
/// the iso-contours of its r (along the flow) are the seed curves.
struct Tangential_seed_curves {
  Mesh surface;                           ///< the aligned patch
  FAS::Alignment_report alignment;        ///< how well it is aligned
  std::vector<std::vector<Point>> curves; ///< the iso-contours of r
};

/// The seed curves of a disk of `faces` triangles at `center` with `normal` and `radius`, aligned
/// tangentially to `flow`: `number_of_curves` evenly spaced iso-contours of r.
inline Tangential_seed_curves make_tangential_seed_curves(const Flow& flow, const Point& center,
                                                          const Vector& normal, double radius,
                                                          std::size_t faces, std::size_t number_of_curves)
{
  Tangential_seed_curves seeds;
  Mesh& tm = seeds.surface;
  FAS::make_disk_patch(tm, center, normal, radius, faces);
  seeds.alignment = FAS::align_to_flow(tm, flow, FAS::Alignment::TANGENTIAL);
  auto r = tm.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
  auto s = tm.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
  FAS::parametrize_tangential(tm, flow, r, s);
  FAS::extract_iso_contours(tm, r, FAS::evenly_spaced_iso_values(tm, r, number_of_curves),
                            std::back_inserter(seeds.curves));
  return seeds;
}

} // namespace fas_demo

#endif // FAS_DEMO_DEMO_SUPPORT_H
