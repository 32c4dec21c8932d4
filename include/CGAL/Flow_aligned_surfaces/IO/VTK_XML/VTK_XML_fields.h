// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow fields of a VTK XML data set, read without VTK: the velocity and mask chosen among
// the point arrays and decoded, an image as a uniform grid (no rotation), a rectilinear grid
// as one, any data set as cells (a structured grid or image as its hexahedra, cells touching a
// solid point left out), and the steps of a ParaView data collection (.pvd).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_FIELDS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_FIELDS_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/VTK_XML_data_set.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/remove_masked_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/structured_grid_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/uniform_grid_reading.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/voxels_as_hexahedra.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/vtk_cell_types.h>
#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

inline std::string describe_VTK_XML_arrays(const std::vector<VTK_XML_array>& arrays)
{
  std::string r;
  for (const VTK_XML_array& a : arrays)
    r += (r.empty() ? "'" : ", '") + a.name + "' (" + a.type_name + ", " + std::to_string(a.components) +
         " component" + (a.components == 1 ? "" : "s") + ")";
  return r.empty() ? std::string("none") : r;
}

/// The velocity and mask arrays among the point data, chosen as documented.
struct VTK_XML_point_arrays {
  std::vector<VTK_XML_array> arrays;
  const VTK_XML_array* velocity = nullptr;
  const VTK_XML_array* mask = nullptr;
};

inline const VTK_XML_array* find_VTK_XML_array(const std::vector<VTK_XML_array>& arrays, const std::string& name)
{
  for (const VTK_XML_array& a : arrays)
    if (a.name == name)
      return &a;
  return nullptr;
}

// The velocity: the named array, else the active vectors if they have 3 components, else the
// first 3-component array.
inline const VTK_XML_array* choose_velocity(const VTK_XML_data_set& f, const std::vector<VTK_XML_array>& arrays,
                                            const XML_element* point_data, const std::string* array_name,
                                            const std::string& present)
{
  if (array_name != nullptr) {
    const VTK_XML_array* a = find_VTK_XML_array(arrays, *array_name);
    if (a == nullptr)
      f.doc.fail_file("there is no point data array named '" + *array_name + "'" + present);
    return a;
  }
  const std::string* active = point_data ? point_data->attribute("Vectors") : nullptr;
  const VTK_XML_array* a = active ? find_VTK_XML_array(arrays, *active) : nullptr;
  if (a != nullptr && a->components == 3 && a->numeric)
    return a;
  for (const VTK_XML_array& b : arrays)
    if (b.components == 3 && b.numeric)
      return &b;
  f.doc.fail_file("there is no 3-component point data array to read as the velocity" + present);
}

inline VTK_XML_point_arrays choose_point_arrays(const VTK_XML_data_set& f, const std::string* array_name,
                                                const std::string* mask_name)
{
  VTK_XML_point_arrays r;
  const XML_element* point_data = f.doc.child(*f.piece, "PointData");
  r.arrays = f.arrays(point_data);
  const std::string present = " (the point data arrays are: " + describe_VTK_XML_arrays(r.arrays) + ")";
  r.velocity = choose_velocity(f, r.arrays, point_data, array_name, present);
  if (!r.velocity->numeric)
    f.decoder.fail(*r.velocity, "holds " + r.velocity->type_name + ", not numbers; a velocity needs 3 numbers per point");
  if (r.velocity->components != 3)
    f.doc.fail_file("the point data array '" + r.velocity->name + "' has " + std::to_string(r.velocity->components) +
                    " components; a velocity needs 3 numbers per point");
  const std::string mask = mask_name ? *mask_name : std::string("inside");
  if (!mask.empty()) {
    r.mask = find_VTK_XML_array(r.arrays, mask);
    if (r.mask == nullptr && mask_name != nullptr)
      f.doc.fail_file("there is no point data array named '" + mask + "' for the mask" + present);
    if (r.mask != nullptr && (r.mask->components != 1 || !r.mask->numeric))
      f.doc.fail_file("the mask array '" + mask + "' has " + std::to_string(r.mask->components) +
                      " components of type " + r.mask->type_name + "; a mask needs 1 number per point");
  }
  for (const VTK_XML_array* a : {r.velocity, r.mask}) {
    const std::size_t tuples = a ? VTK_XML_count(f.doc, *a->element, "NumberOfTuples", f.points) : f.points;
    if (tuples != f.points)
      f.decoder.fail(*a, "has NumberOfTuples=\"" + std::to_string(tuples) + "\" but the data set has " +
                             std::to_string(f.points) + " points");
  }
  return r;
}

/// The velocities and fluid flags of the points of `f`; `name(i)` names point i in messages.
template <class Point_name>
Node_values read_VTK_XML_point_values(const VTK_XML_data_set& f, const std::string* array_name,
                                      const std::string* mask_name, const Point_name& name)
{
  const VTK_XML_point_arrays a = choose_point_arrays(f, array_name, mask_name);
  const VTK_XML_values velocity = f.decoder.values(*a.velocity, f.points);
  if (a.mask == nullptr)
    return decode_node_values(f.cursor, f.points, velocity.array, nullptr, "point", name);
  const VTK_XML_values mask = f.decoder.values(*a.mask, f.points);
  return decode_node_values(f.cursor, f.points, velocity.array, &mask.array, "point", name);
}

/// The values of an array as doubles (geometry and cells), `check(i, v)` called on each.
template <class Check>
std::vector<double> read_VTK_XML_doubles(const VTK_XML_data_set& f, const VTK_XML_array& a, std::size_t tuples,
                                         const Check& check)
{
  const VTK_XML_values v = f.decoder.values(a, tuples);
  std::vector<double> r(tuples * a.components);
  if (!v.array.ascii)
    decode_binary_numbers(v.array.type, v.array.order, reinterpret_cast<const unsigned char*>(v.array.bytes.data()),
                          r.size(), r.data());
  else
    decode_grid_array(f.cursor, v.array, [&](std::size_t i, double x, std::size_t, std::size_t) { r[i] = x; });
  for (std::size_t i = 0; i < r.size(); ++i)
    check(i, r[i]);
  return r;
}

/// The coordinates of the points of an array of 3 components, each finite.
inline std::vector<double> read_VTK_XML_points(const VTK_XML_data_set& f, const VTK_XML_array& a)
{
  if (a.components != 3)
    f.decoder.fail(a, "holds points of " + std::to_string(a.components) + " components; points need 3 coordinates");
  return read_VTK_XML_doubles(f, a, f.points, [&](std::size_t i, double x) {
    if (!std::isfinite(x))
      f.decoder.fail(a, "has the non-finite coordinate " + std::to_string(i % 3) + " at point " +
                            std::to_string(i / 3));
  });
}

/// The image's first point and spacing, refused if rotated.
struct VTK_XML_image_geometry {
  std::array<double, 3> first, spacing;
};

inline VTK_XML_image_geometry read_VTK_XML_image_geometry(const VTK_XML_data_set& f)
{
  const XML_element& image = *f.data_set;
  const std::vector<double> origin =
      image.attribute("Origin") ? VTK_XML_numbers(f.doc, image, "Origin", 3) : std::vector<double>(3, 0.);
  const std::vector<double> spacing =
      image.attribute("Spacing") ? VTK_XML_numbers(f.doc, image, "Spacing", 3) : std::vector<double>(3, 1.);
  if (image.attribute("Direction")) {
    const std::vector<double> m = VTK_XML_numbers(f.doc, image, "Direction", 9);
    for (int k = 0; k < 9; ++k)
      if (m[std::size_t(k)] != (k % 4 == 0 ? 1. : 0.)) {
        std::ostringstream msg;
        msg << "the image has the Direction matrix (";
        for (int i = 0; i < 9; ++i)
          msg << (i ? " " : "") << m[std::size_t(i)];
        msg << "), which is not the identity: rotated images are not supported";
        f.doc.fail_element(image, msg.str());
      }
  }
  VTK_XML_image_geometry g;
  for (int a = 0; a < 3; ++a) {
    g.spacing[a] = spacing[std::size_t(a)];
    // The grid's origin is the piece's first point, which its extent may move off the origin.
    g.first[a] = origin[std::size_t(a)] + f.first_index[a] * spacing[std::size_t(a)];
  }
  return g;
}

inline void check_VTK_XML_grid_dimensions(const VTK_XML_data_set& f)
{
  const std::array<std::size_t, 3>& d = f.dimensions;
  if (d[0] < 2 || d[1] < 2 || d[2] < 2)
    f.doc.fail_element(*f.piece, "the " + std::string(f.type == "ImageData" ? "image" : "grid") + " has " +
                                     std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
                                     std::to_string(d[2]) +
                                     " points; a grid needs at least 2 points along each axis (2D and 1D data "
                                     "sets are not supported)");
}

template <class K>
Regular_grid_flow_field_3<K> read_VTK_XML_grid(const std::string& file, const std::string* array_name,
                                               const std::string* mask_name)
{
  const VTK_XML_data_set f("read_VTK_XML_flow_field", file, {"ImageData"},
                           "a Regular_grid_flow_field_3 is read from a VTK XML ImageData file (.vti)");
  check_VTK_XML_grid_dimensions(f);
  const VTK_XML_image_geometry g = read_VTK_XML_image_geometry(f);
  Node_values d = read_VTK_XML_point_values(f, array_name, mask_name,
                                            [&](std::size_t i) { return grid_node_string(f.dimensions, i); });
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  return construct_field<Regular_grid_flow_field_3<K>>(
      [&](const std::string& what) { f.doc.fail_file(what); }, Flow_aligned_surfaces::internal::Node_values_checked(),
      Point_3(g.first[0], g.first[1], g.first[2]), Vector_3(g.spacing[0], g.spacing[1], g.spacing[2]), f.dimensions,
      std::move(d.values), std::move(d.flags));
}

/// The node coordinates along each axis of an image or a rectilinear grid.
inline std::array<std::vector<double>, 3> read_VTK_XML_axes(const VTK_XML_data_set& f)
{
  std::array<std::vector<double>, 3> x;
  if (f.type == "ImageData") {
    const VTK_XML_image_geometry g = read_VTK_XML_image_geometry(f);
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = 0; i < f.dimensions[a]; ++i) // the formula of Regular_grid_flow_field_3
        x[a].push_back(g.first[a] + static_cast<double>(i) * g.spacing[a]);
    return x;
  }
  const std::vector<VTK_XML_array> axes = f.arrays(&f.piece_child("Coordinates"));
  if (axes.size() != 3)
    f.doc.fail_element(f.piece_child("Coordinates"), "holds " + std::to_string(axes.size()) +
                                                         " DataArray elements; expected 3 (x, y, z)");
  for (int a = 0; a < 3; ++a) {
    const VTK_XML_array& c = axes[std::size_t(a)];
    if (c.components != 1)
      f.decoder.fail(c, "has " + std::to_string(c.components) + " components; a coordinate axis has 1");
    x[a] = read_VTK_XML_doubles(f, c, f.dimensions[a], [&](std::size_t i, double v) {
      if (!std::isfinite(v))
        f.decoder.fail(c, "has the non-finite coordinate " + std::to_string(v) + " at index " + std::to_string(i));
    });
  }
  return x;
}

template <class K>
Rectilinear_grid_flow_field_3<K> read_VTK_XML_rectilinear(const std::string& file, const std::string* array_name,
                                                          const std::string* mask_name)
{
  const VTK_XML_data_set f("read_VTK_XML_flow_field", file, {"RectilinearGrid", "ImageData"},
                           "a Rectilinear_grid_flow_field_3 is read from a VTK XML RectilinearGrid (.vtr) or "
                           "ImageData (.vti) file");
  check_VTK_XML_grid_dimensions(f);
  // The values first: their bytes bound the number of points before the axes are allocated.
  Node_values d = read_VTK_XML_point_values(f, array_name, mask_name,
                                            [&](std::size_t i) { return grid_node_string(f.dimensions, i); });
  std::array<std::vector<double>, 3> x = read_VTK_XML_axes(f);
  return construct_field<Rectilinear_grid_flow_field_3<K>>(
      [&](const std::string& what) { f.doc.fail_file(what); }, Flow_aligned_surfaces::internal::Node_values_checked(),
      std::move(x), std::move(d.values), std::move(d.flags));
}

/// The `Cells` array named `name` of an unstructured grid.
inline const VTK_XML_array& VTK_XML_cell_array(const VTK_XML_data_set& f, const std::vector<VTK_XML_array>& arrays,
                                               const std::string& name)
{
  const VTK_XML_array* a = find_VTK_XML_array(arrays, name);
  if (a == nullptr)
    f.doc.fail_element(f.piece_child("Cells"), "there is no DataArray named '" + name + "' (the arrays are: " +
                                                    describe_VTK_XML_arrays(arrays) + ")");
  if (a->components != 1)
    f.decoder.fail(*a, "has " + std::to_string(a->components) + " components; expected 1");
  return *a;
}

/// The cells of an unstructured grid in the form of `Unstructured_flow_field_3`, with every
/// type, point count and point index checked.
inline Structured_grid_cells read_VTK_XML_cells(const VTK_XML_data_set& f)
{
  const std::size_t nc = f.cells, np = f.points;
  if (nc == 0)
    f.doc.fail_element(*f.piece, "the unstructured grid has no cells");
  const std::vector<VTK_XML_array> arrays = f.arrays(&f.piece_child("Cells"));
  const VTK_XML_array& types = VTK_XML_cell_array(f, arrays, "types");
  const VTK_XML_array& offsets = VTK_XML_cell_array(f, arrays, "offsets");
  const VTK_XML_array& connectivity = VTK_XML_cell_array(f, arrays, "connectivity");
  // The types first: their bytes bound the number of cells before anything is allocated from it.
  const std::vector<double> type_values = read_VTK_XML_doubles(f, types, nc, [](std::size_t, double) {});
  Structured_grid_cells r;
  std::vector<int> points_per_cell(nc);
  r.cell_types.resize(nc);
  for (std::size_t i = 0; i < nc; ++i) {
    const double t = type_values[i];
    int n = 0;
    const char* name = vtk_cell_type_name(t, &n);
    if (n == 0)
      f.decoder.fail(types, "gives cell " + std::to_string(i) + " the VTK cell type " + number_string(t) + " (" +
                                name +
                                "); supported are 10 (VTK_TETRA), 11 (VTK_VOXEL), 12 (VTK_HEXAHEDRON), 13 "
                                "(VTK_WEDGE) and 14 (VTK_PYRAMID)");
    r.cell_types[i] = static_cast<unsigned char>(t);
    points_per_cell[i] = n;
  }
  r.offsets.resize(nc + 1, 0);
  read_VTK_XML_doubles(f, offsets, nc, [&](std::size_t i, double v) {
    const double previous = static_cast<double>(r.offsets[i]);
    if (v - previous != points_per_cell[i])
      f.decoder.fail(offsets, "gives cell " + std::to_string(i) + " (" + vtk_cell_type_name(r.cell_types[i]) + ") " +
                                  number_string(v - previous) + " points; expected " +
                                  std::to_string(points_per_cell[i]));
    r.offsets[i + 1] = static_cast<std::int64_t>(v);
  });
  const std::size_t n = static_cast<std::size_t>(r.offsets.back());
  r.connectivity.resize(n);
  const std::vector<double> ids = read_VTK_XML_doubles(f, connectivity, n, [&](std::size_t i, double v) {
    if (!(v >= 0. && v < static_cast<double>(np) && v == std::floor(v)))
      f.decoder.fail(connectivity, "holds the point index " + number_string(v) + " at " + std::to_string(i) +
                                       "; expected an index in [0, " + std::to_string(np) + ")");
  });
  for (std::size_t i = 0; i < n; ++i)
    r.connectivity[i] = static_cast<std::int64_t>(ids[i]);
  voxels_as_hexahedra(r.cell_types, r.offsets, r.connectivity);
  return r;
}

/// The points, velocities, mask and cells of a data set, as `Unstructured_flow_field_3` takes them.
struct VTK_XML_cell_data {
  Node_values nodes;
  std::vector<double> points;
  bool float_points = true;
  Structured_grid_cells cells;
};

/// The current piece of `f` as cells.
inline VTK_XML_cell_data read_VTK_XML_piece_cells(const VTK_XML_data_set& f, const std::string* array_name,
                                                  const std::string* mask_name)
{
  const bool structured = f.type != "UnstructuredGrid";
  if (structured)
    check_VTK_XML_grid_dimensions(f);
  VTK_XML_cell_data r;
  r.nodes = read_VTK_XML_point_values(f, array_name, mask_name, [&](std::size_t i) {
    return structured ? grid_node_string(f.dimensions, i) : std::to_string(i);
  });
  if (f.type == "UnstructuredGrid" || f.type == "StructuredGrid") {
    const std::vector<VTK_XML_array> p = f.arrays(&f.piece_child("Points"));
    if (p.empty())
      f.doc.fail_element(f.piece_child("Points"), "holds no DataArray");
    r.float_points = p.front().type == Binary_type::FLOAT32;
    r.points = read_VTK_XML_points(f, p.front());
  }
  else {
    r.float_points = false;
    const std::array<std::vector<double>, 3> x = read_VTK_XML_axes(f);
    r.points.reserve(3 * f.points);
    for (double z : x[2])
      for (double y : x[1])
        for (double xi : x[0])
          r.points.insert(r.points.end(), {xi, y, z});
  }
  r.cells = structured ? structured_grid_cells(f.dimensions) : read_VTK_XML_cells(f);
  return r;
}

/// Appends piece `b` (the current piece of `f`) to the pieces `a` read before it: its point
/// indices shift by the points before it.
inline void append_VTK_XML_piece(const VTK_XML_data_set& f, VTK_XML_cell_data& a, VTK_XML_cell_data b)
{
  if (a.points.empty()) {
    a = std::move(b);
    return;
  }
  if (a.nodes.flags.empty() != b.nodes.flags.empty())
    f.doc.fail_element(*f.piece, std::string("this piece has ") + (b.nodes.flags.empty() ? "no mask" : "a mask") +
                                     " but the pieces before it " + (b.nodes.flags.empty() ? "have one" : "have none"));
  const std::int64_t points_before = static_cast<std::int64_t>(a.points.size() / 3);
  const std::int64_t indices_before = static_cast<std::int64_t>(a.cells.connectivity.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  a.float_points = a.float_points && b.float_points;
  a.nodes.values.insert(a.nodes.values.end(), b.nodes.values.begin(), b.nodes.values.end());
  a.nodes.flags.insert(a.nodes.flags.end(), b.nodes.flags.begin(), b.nodes.flags.end());
  for (std::int64_t i : b.cells.connectivity)
    a.cells.connectivity.push_back(i + points_before);
  for (std::size_t c = 1; c < b.cells.offsets.size(); ++c)
    a.cells.offsets.push_back(b.cells.offsets[c] + indices_before);
  a.cells.cell_types.insert(a.cells.cell_types.end(), b.cells.cell_types.begin(), b.cells.cell_types.end());
}

template <class K>
Unstructured_flow_field_3<K> read_VTK_XML_cells(const std::string& file, const std::string* array_name,
                                                const std::string* mask_name)
{
  VTK_XML_data_set f("read_VTK_XML_flow_field", file,
                     {"UnstructuredGrid", "StructuredGrid", "RectilinearGrid", "ImageData"},
                     "an Unstructured_flow_field_3 is read from a VTK XML UnstructuredGrid (.vtu), "
                     "StructuredGrid (.vts), RectilinearGrid (.vtr) or ImageData (.vti) file");
  // The pieces of an unstructured grid, concatenated (empty ones skipped).
  VTK_XML_cell_data d;
  for (std::size_t i = 0; i < f.pieces.size(); ++i) {
    if (f.type == "UnstructuredGrid")
      f.select_piece(i);
    if (f.points != 0)
      append_VTK_XML_piece(f, d, read_VTK_XML_piece_cells(f, array_name, mask_name));
  }
  Structured_grid_cells& cells = d.cells;
  const std::size_t all_cells = cells.cell_types.size();
  if (!d.nodes.flags.empty() &&
      remove_masked_cells(d.nodes.flags, cells.connectivity, cells.offsets, cells.cell_types) == 0)
    f.doc.fail_file("every one of the " + std::to_string(all_cells) +
                    " cells touches a solid point of the mask (no fluid cell is left)");
  const auto refused = [&](const std::string& what) { f.doc.fail_file(what); };
  // Float points stay float in the field (they were decoded as doubles, exactly).
  if (d.float_points)
    return construct_field<Unstructured_flow_field_3<K>>(refused, std::vector<float>(d.points.begin(), d.points.end()),
                                                         std::move(cells.connectivity), std::move(cells.offsets),
                                                         std::move(cells.cell_types), std::move(d.nodes.values));
  return construct_field<Unstructured_flow_field_3<K>>(refused, std::move(d.points), std::move(cells.connectivity),
                                                       std::move(cells.offsets), std::move(cells.cell_types),
                                                       std::move(d.nodes.values));
}

template <class Field>
struct VTK_XML_field_reader;

template <class K>
struct VTK_XML_field_reader<Regular_grid_flow_field_3<K>> {
  static Regular_grid_flow_field_3<K> read(const std::string& file, const std::string* a, const std::string* m)
  {
    return read_VTK_XML_grid<K>(file, a, m);
  }
};

template <class K>
struct VTK_XML_field_reader<Rectilinear_grid_flow_field_3<K>> {
  static Rectilinear_grid_flow_field_3<K> read(const std::string& file, const std::string* a, const std::string* m)
  {
    return read_VTK_XML_rectilinear<K>(file, a, m);
  }
};

template <class K>
struct VTK_XML_field_reader<Unstructured_flow_field_3<K>> {
  static Unstructured_flow_field_3<K> read(const std::string& file, const std::string* a, const std::string* m)
  {
    return read_VTK_XML_cells<K>(file, a, m);
  }
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_FIELDS_H
