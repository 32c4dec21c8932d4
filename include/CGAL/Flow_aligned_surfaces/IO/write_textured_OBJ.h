// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A textured surface for renderers other than ParaView: Wavefront OBJ with one texture
// coordinate per vertex (`vt u v`, faces `f i/i j/j k/k`), its material file (MTL, `map_Kd`
// naming the texture) and the texture itself as PNG, all three beside each other:
//
//   stem.obj  ->  mtllib stem.mtl  ->  map_Kd stem.png

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_TEXTURED_OBJ_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_TEXTURED_OBJ_H

#include <CGAL/Flow_aligned_surfaces/IO/write_PNG.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/error_output.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/write_file_atomically.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Writes `tm` with the per-vertex texture coordinates `uv_map` as the Wavefront OBJ file
`filename`, the material file beside it (the same name with the extension `.mtl`) and
`texture` as PNG beside it (extension `.png`), which the material names in `map_Kd`.

Texture coordinates are written as they are (textures repeat, so they may leave
\f$ [0, 1] \f$); one that is not finite is written as `0 0` (such faces are the masked ones of
`compute_flow_texture_mask()`).  Each file is written beside its name and renamed over it when
complete.  The MTL and the PNG are replaced only if they are this OBJ's, written by an earlier
call for the same `filename`: a file of these names that is not (a texture of the user's, say)
makes the function return `false` with its name, before anything is written.  When the PNG cannot be written (no libpng: see `write_PNG()`), the OBJ and the MTL
are still written and the function returns `false` with the reason.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam UVMap a model of `ReadablePropertyMap` with the vertices as key type and
`std::array<double, 2>` as value type, e.g. filled by `compute_flow_texture_coordinates()`
\tparam NamedParameters a sequence of named parameters

\param filename the OBJ file (`.obj`)
\param tm the mesh (any polygon mesh)
\param uv_map the texture coordinates of the vertices
\param texture the texture
\param np optional named parameters: `vertex_point_map`, `vertex_index_map` as in
       `normalized_flux()`, `stream_precision` (significant digits, default 17) and
       `error_message` (where the reason of a failure goes, `FAS::parameters::error_message()`;
       default: no message)

\returns `true` if the three files were written; `false` otherwise, with the reason in the
string of `error_message` when it is given.
\sa `write_PNG()`, `write_VTP()`, `compute_flow_texture_coordinates()`
*/
template <class TriangleMesh, class UVMap, class NamedParameters = parameters::Default_named_parameters>
bool write_textured_OBJ(const std::string& filename, const TriangleMesh& tm, UVMap uv_map,
                        const Texture_image& texture,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);
  const std::filesystem::path obj(filename);
  const std::filesystem::path mtl = std::filesystem::path(obj).replace_extension(".mtl");
  const std::filesystem::path png = std::filesystem::path(obj).replace_extension(".png");
  std::string* const error = internal::error_output(np);
  auto fail = [&](const std::string& reason) {
    if (error)
      *error = "write_textured_OBJ: " + reason;
    return false;
  };

  // The MTL and the PNG are files the caller did not name: one that exists is replaced only if it
  // is this OBJ's, that is, if the MTL beside it is one that an earlier call wrote for this OBJ.
  const std::string mtl_first_line = "# flow texture of " + obj.filename().string();
  const bool mtl_exists = std::filesystem::exists(mtl), png_exists = std::filesystem::exists(png);
  if (mtl_exists || png_exists) {
    std::string line;
    if (mtl_exists) {
      std::ifstream is(mtl);
      std::getline(is, line);
    }
    if (line != mtl_first_line) {
      const std::filesystem::path& other = mtl_exists ? mtl : png;
      return fail(other.string() + " exists and is not the texture file of " + obj.filename().string() +
                  " written by an earlier write_textured_OBJ(); nothing was written (move it away or "
                  "choose another name for the OBJ)");
    }
  }

  std::string reason;
  if (!internal::write_file_atomically(mtl.string(), reason, [&](std::ostream& os) {
        os << mtl_first_line << "\nnewmtl flow_texture\n"
           << "Ka 1 1 1\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd " << png.filename().string() << "\n";
      }))
    return fail(mtl.string() + ": " + reason);

  const auto ordered_vertices = Flow_aligned_surfaces::internal::vertices_in_index_order(tm, vim);
  if (!internal::write_file_atomically(obj.string(), reason, [&](std::ostream& os) {
        os.precision(precision);
        os << "mtllib " << mtl.filename().string() << "\n";
        for (auto v : ordered_vertices) {
          const auto& p = get(vpm, v);
          os << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' '
             << CGAL::to_double(p.z()) << '\n';
        }
        for (auto v : ordered_vertices) {
          const std::array<double, 2> uv = get(uv_map, v);
          const bool finite = std::isfinite(uv[0]) && std::isfinite(uv[1]);
          os << "vt " << (finite ? uv[0] : 0.0) << ' ' << (finite ? uv[1] : 0.0) << '\n';
        }
        os << "usemtl flow_texture\n";
        for (auto f : faces(tm)) {
          os << 'f';
          for (auto v : vertices_around_face(halfedge(f, tm), tm)) {
            const auto i = get(vim, v) + 1;
            os << ' ' << i << '/' << i;
          }
          os << '\n';
        }
      }))
    return fail(obj.string() + ": " + reason);

  std::string png_error;
  if (!write_PNG(png.string(), texture, &png_error))
    return fail(png_error + " (" + obj.filename().string() + " and " + mtl.filename().string() +
                " were written)");
  return true;
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_TEXTURED_OBJ_H
