// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow fields of a parsed legacy VTK file: the velocity and mask arrays chosen among the
// point data and decoded, the grid coordinates, points and cells (either form of CELLS), and
// the three fields built from them; and the frame of the public readers (named parameters in,
// `false` + message out).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_LEGACY_VTK_LEGACY_FIELDS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_LEGACY_VTK_LEGACY_FIELDS_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_legacy/VTK_legacy_parser.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/remove_masked_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/structured_grid_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/voxels_as_hexahedra.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/vtk_cell_types.h>
#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

inline std::string describe_arrays(const std::vector<VTK_legacy_array>& arrays)
{
  std::string r;
  for (const VTK_legacy_array& a : arrays) {
    if (!a.point_data)
      continue;
    if (!r.empty())
      r += ", ";
    r += "'" + a.name + "' (" + a.kind + " " + a.type + ", " + std::to_string(a.components) + " component" +
         (a.components == 1 ? "" : "s") + ")";
  }
  return r.empty() ? std::string("none") : r;
}

// The node arrays of a parsed file: the velocity (3 floats per node) and the mask (empty when
// there is none), decoded and checked.
struct VTK_legacy_node_data {
  std::vector<float> values;
  std::vector<unsigned char> flags;
  std::string mask_name;
};

// Chooses the velocity and mask arrays among the point data (by name, else the first VECTORS,
// else the first 3-component array; the mask named `inside` by default) and decodes them.
inline VTK_legacy_node_data read_node_data(VTK_legacy_parser& parser, const std::string* array_name,
                                           const std::string* mask_name)
{
  const VTK_legacy_array* velocity = nullptr;
  const VTK_legacy_array* mask = nullptr;
  for (const VTK_legacy_array& a : parser.arrays) {
    if (!a.point_data)
      continue;
    if (array_name != nullptr) {
      if (velocity == nullptr && a.name == *array_name)
        velocity = &a;
    }
    else if (a.components == 3 && a.type != "bit" &&
             (velocity == nullptr || (velocity->kind != "VECTORS" && a.kind == "VECTORS"))) {
      velocity = &a; // the first VECTORS array, else the first 3-component array
    }
    if (mask == nullptr && a.name == (mask_name ? *mask_name : std::string("inside")))
      mask = &a;
  }
  const std::string present = " (the point data arrays are: " + describe_arrays(parser.arrays) + ")";
  if (velocity == nullptr) {
    if (array_name != nullptr)
      parser.fail_file("there is no point data array named '" + *array_name + "'" + present);
    parser.fail_file("there is no 3-component point data array to read as the velocity" + present);
  }
  if (velocity->components != 3 || velocity->type == "bit")
    parser.fail_file("the point data array '" + velocity->name + "' has " +
                     std::to_string(velocity->components) + " components of type " + velocity->type +
                     "; a velocity needs 3 numbers per node");
  if (mask_name != nullptr && !mask_name->empty() && mask == nullptr)
    parser.fail_file("there is no point data array named '" + *mask_name + "' for the mask" + present);
  if (mask != nullptr && (mask->components != 1 || mask->type == "bit"))
    parser.fail_file("the mask array '" + mask->name + "' has " + std::to_string(mask->components) +
                     " components of type " + mask->type + "; a mask needs 1 number per node (" +
                     std::to_string(parser.nodes) + " values)");
  if (mask == velocity)
    mask = nullptr;
  for (const VTK_legacy_array* a : {velocity, mask})
    if (a != nullptr && a->tuples != parser.nodes)
      parser.fail_file(std::string(a == mask ? "the mask array '" : "the velocity array '") + a->name +
                       "' has " + std::to_string(a->tuples) + " tuples but the grid (" +
                       parser.size_source() + ") has " + std::to_string(parser.nodes) + " nodes");

  VTK_legacy_node_data d;
  const std::size_t nodes = parser.nodes;
  if (mask != nullptr) {
    d.mask_name = mask->name;
    reserve_huge_pages(d.flags, nodes);
    d.flags.resize(nodes);
    // By value: a byte store through d.flags[i], or through a captured reference, could alias
    // the pointer, which would then be reloaded per value.
    unsigned char* flags = d.flags.data();
    auto check = [&, flags](std::size_t i, double v, std::size_t offset, std::size_t line) {
      flags[i] = checked_mask_flag(
          v, mask->name, [&] { return "node " + std::to_string(i); },
          [&](const std::string& what) { parser.fail_at(offset, line, what); });
    };
    const auto b = parser.binary_values(*mask);
    // Binary: decoded as a run; only a NaN, which the run reports, goes through `check`.
    if (!parser.binary || decode_checked_flags(b.type, b.order, b.data, nodes, flags))
      parser.decode(*mask, check);
  }
  reserve_huge_pages(d.values, 3 * nodes);
  d.values.resize(3 * nodes);
  float* values = d.values.data();
  auto check = [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    values[i] = checked_velocity_component(
        v, i, [&] { return d.flags.empty() || d.flags[i / 3] != 0; }, !d.flags.empty(), velocity->name,
        "node", [&] { return parser.node_name(i / 3); },
        [&](const std::string& what) { parser.fail_at(offset, line, what); });
  };
  // A solid node's value is never interpolated: one with a non-finite component is stored as
  // zero, as the grid fields' constructors do (and the cells field, which refuses non-finite
  // values, gets the same).
  auto zero_bad_solid_nodes = [&](std::size_t first_node, std::size_t end_node) {
    for (std::size_t node = first_node; node < end_node && node < d.flags.size(); ++node) {
      float* c = values + 3 * node;
      if (d.flags[node] == 0 && !(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        c[0] = c[1] = c[2] = 0.f;
    }
  };
  if (parser.binary) {
    // Decoded and range-checked straight into the result, in parallel blocks; the values of the
    // (rare) blocks holding a non-finite or too large value are then checked one by one in file
    // order, so the message names the first bad value at a fluid node, as in the ASCII case.
    const auto b = parser.binary_values(*velocity);
    for (std::size_t block :
         decode_checked_floats(b.type, b.order, b.data, 3 * nodes, values, [&](std::size_t i, double v) {
           check(i, v, b.begin + i * b.size, 0);
           return values[i];
         })) {
      const std::size_t begin = block * checked_block_size;
      zero_bad_solid_nodes(begin / 3, (begin + checked_block_size + 2) / 3);
    }
  }
  else {
    parser.decode(*velocity, check);
    zero_bad_solid_nodes(0, nodes);
  }
  return d;
}

// The values of a geometry array (coordinates or points) as Real (double, or float for an
// array of floats, which are exact), each finite.
template <class Real = double>
std::vector<Real> decode_reals(VTK_legacy_parser& parser, const VTK_legacy_array& a)
{
  std::vector<Real> r;
  reserve_huge_pages(r, a.components * a.tuples);
  r.resize(a.components * a.tuples);
  parser.decode(a, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    if (!std::isfinite(v)) {
      std::ostringstream msg;
      msg << a.kind << ": ";
      if (a.components == 3)
        msg << "coordinate " << i % 3 << " of point " << i / 3;
      else
        msg << "value " << i;
      msg << " is " << v << "; expected a finite number";
      parser.fail_at(offset, line, msg.str());
    }
    r[i] = static_cast<Real>(v);
  });
  return r;
}

// The node coordinates along each axis of a STRUCTURED_POINTS or RECTILINEAR_GRID dataset.
inline std::array<std::vector<double>, 3> grid_coordinates(VTK_legacy_parser& parser)
{
  std::array<std::vector<double>, 3> x;
  for (int a = 0; a < 3; ++a) {
    if (parser.dataset == "RECTILINEAR_GRID") {
      x[a] = decode_reals(parser, *parser.coordinates[a]);
      continue;
    }
    x[a].resize(parser.dimensions[a]);
    for (std::size_t i = 0; i < x[a].size(); ++i) // the formula of Regular_grid_flow_field_3
      x[a][i] = parser.origin[a] + static_cast<double>(i) * parser.spacing[a];
  }
  return x;
}

// The cells of an UNSTRUCTURED_GRID with the 32-bit indices that `Unstructured_flow_field_3`
// keeps, so that they move into the field without a narrowing copy (for a real mesh of 2e5
// hexahedra, 18 MB fewer pages to touch).
struct Unstructured_grid_cells {
  typedef Flow_aligned_surfaces::internal::Cell_point_location::Index Index;
  std::vector<Index> connectivity, offsets;
  std::vector<unsigned char> cell_types;
};

// Calls `f(values, m)` on the `count` values of a binary array decoded as doubles, in blocks
// that stay in the L1 cache, until `f` returns false; returns whether it never did.
template <class F>
bool for_each_binary_block(const VTK_legacy_parser::Binary_values& b, std::size_t count, const F& f)
{
  constexpr std::size_t block_size = 1024;
  double block[block_size];
  for (std::size_t i0 = 0; i0 < count; i0 += block_size) {
    const std::size_t m = count - i0 < block_size ? count - i0 : block_size;
    decode_binary_numbers(b.type, b.order, b.data + i0 * b.size, m, block);
    if (!f(static_cast<const double*>(block), m))
      return false;
  }
  return true;
}

// The cells of a binary file (either form of CELLS) checked as `read_unstructured_cells()`
// checks them, in tight loops over decoded blocks without the per-value bookkeeping that a
// message needs: a real mesh's cells load several times faster.  Returns false at the first
// value the checks refuse, with `r` incomplete; the caller then decodes the values again, one
// by one, to say where and why.
inline bool decode_valid_binary_cells(const VTK_legacy_parser& parser, const std::vector<int>& points_per_cell,
                                      Unstructured_grid_cells& r)
{
  typedef Unstructured_grid_cells::Index Index;
  const std::size_t nc = parser.cells;
  const double np = static_cast<double>(parser.nodes);
  const auto point_index = [np](double v) {
    return v >= 0. && v < np && v == static_cast<double>(static_cast<std::int64_t>(v));
  };
  // Huge pages where the system gives them: a first touch per 2 MiB instead of per 4 KiB.
  reserve_huge_pages(r.offsets, nc + 1);
  r.offsets.assign(nc + 1, 0);
  if (parser.cell_list) {
    const VTK_legacy_array& list = *parser.cell_list;
    reserve_huge_pages(r.connectivity, list.tuples - nc); // nc <= list.tuples, checked by pass 1
    r.connectivity.resize(list.tuples - nc);
    std::size_t cell = 0, left = 0, k = 0;   // the current cell, its points still to read
    const bool valid = for_each_binary_block(parser.binary_values(list), list.tuples, [&](const double* v, std::size_t m) {
      for (std::size_t j = 0; j < m; ++j) {
        if (left == 0) {
          if (cell == nc || v[j] != points_per_cell[cell])
            return false;
          left = static_cast<std::size_t>(points_per_cell[cell]);
        }
        else {
          if (k == r.connectivity.size() || !point_index(v[j]))
            return false;
          r.connectivity[k++] = static_cast<Index>(v[j]);
          if (--left == 0)
            r.offsets[++cell] = static_cast<Index>(k);
        }
      }
      return true;
    });
    return valid && cell == nc;
  }
  const VTK_legacy_array& offsets = *parser.offsets;
  const VTK_legacy_array& connectivity = *parser.connectivity;
  std::size_t i = 0;
  const bool valid_offsets = for_each_binary_block(parser.binary_values(offsets), nc + 1, [&](const double* v, std::size_t m) {
    for (std::size_t j = 0; j < m; ++j, ++i) {
      const double previous = i == 0 ? 0. : static_cast<double>(r.offsets[i - 1]);
      if (i == 0 ? v[j] != 0. : v[j] - previous != points_per_cell[i - 1])
        return false;
      r.offsets[i] = static_cast<Index>(v[j]);
    }
    return true;
  });
  if (!valid_offsets || static_cast<std::size_t>(r.offsets[nc]) != connectivity.tuples)
    return false;
  reserve_huge_pages(r.connectivity, connectivity.tuples);
  r.connectivity.resize(connectivity.tuples);
  Index* out = r.connectivity.data();
  return for_each_binary_block(parser.binary_values(connectivity), connectivity.tuples, [&](const double* v, std::size_t m) {
    for (std::size_t j = 0; j < m; ++j) {
      if (!point_index(v[j]))
        return false;
      *out++ = static_cast<Index>(v[j]);
    }
    return true;
  });
}

// The messages of the value-by-value decoding of an UNSTRUCTURED_GRID's cells: the checked
// point index at a value, and a cell's name.
struct Unstructured_cell_checks {
  VTK_legacy_parser& parser;
  const Unstructured_grid_cells& r;

  Unstructured_grid_cells::Index point_index(std::size_t cell, double v, std::size_t offset, std::size_t line) const
  {
    const std::size_t np = parser.nodes;
    if (!(v >= 0. && v < static_cast<double>(np) && v == std::floor(v)))
      parser.fail_at(offset, line,
                     "cell " + std::to_string(cell) + " has the point index " + number_string(v) +
                         "; expected an index in [0, " + std::to_string(np) + ") (POINTS " +
                         std::to_string(np) + ")");
    return static_cast<Unstructured_grid_cells::Index>(v);
  }
  std::string cell_name(std::size_t cell) const
  {
    return "cell " + std::to_string(cell) + " (" + vtk_cell_type_name(r.cell_types[cell]) + ")";
  }
};

// The cell types into r, and each cell's number of points; a type the field does not hold is
// refused, naming the cell.
inline std::vector<int> read_cell_types(VTK_legacy_parser& parser, Unstructured_grid_cells& r)
{
  std::vector<int> points_per_cell(parser.cells);
  r.cell_types.resize(parser.cells);
  parser.decode(*parser.cell_types, [&](std::size_t i, double t, std::size_t offset, std::size_t line) {
    int n = 0;
    const char* name = vtk_cell_type_name(t, &n);
    if (n == 0)
      parser.fail_at(offset, line,
                     "cell " + std::to_string(i) + " has VTK type " + number_string(t) + " (" + name +
                         "); supported: 10 (VTK_TETRA), 11 (VTK_VOXEL), 12 (VTK_HEXAHEDRON), 13 (VTK_WEDGE), "
                         "14 (VTK_PYRAMID)");
    r.cell_types[i] = static_cast<unsigned char>(t);
    points_per_cell[i] = n;
  });
  return points_per_cell;
}

// Legacy form of CELLS, value by value: per cell, its number of points, then their indices.
inline void decode_cell_list(VTK_legacy_parser& parser, const std::vector<int>& points_per_cell,
                             Unstructured_grid_cells& r)
{
  const Unstructured_cell_checks check{parser, r};
  const std::size_t nc = parser.cells;
  const VTK_legacy_array& list = *parser.cell_list;
  const std::string cells_line = "CELLS " + std::to_string(nc) + " " + std::to_string(list.tuples);
  r.offsets.reserve(nc + 1);
  r.offsets.push_back(0);
  r.connectivity.reserve(list.tuples - nc); // nc <= list.tuples, checked by pass 1
  std::size_t cell = 0, left = 0;           // the current cell and its points still to read
  parser.decode(list, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    if (left == 0) {
      if (cell == nc)
        parser.fail_at(offset, line,
                       cells_line + ": the " + std::to_string(nc) + " cells end after " + std::to_string(i) +
                           " values, not " + std::to_string(list.tuples));
      if (v != points_per_cell[cell])
        parser.fail_at(offset, line,
                       check.cell_name(cell) + " lists " + number_string(v) + " points; expected " +
                           std::to_string(points_per_cell[cell]));
      left = static_cast<std::size_t>(points_per_cell[cell]);
      return;
    }
    r.connectivity.push_back(check.point_index(cell, v, offset, line));
    if (--left == 0) {
      r.offsets.push_back(static_cast<Unstructured_grid_cells::Index>(r.connectivity.size()));
      ++cell;
    }
  });
  if (cell != nc)
    parser.fail_at(list.header, list.header_line,
                   cells_line + ": the values end inside cell " + std::to_string(cell) + " of " +
                       std::to_string(nc) + " (wrong count)");
}

// File version 5.1, value by value: OFFSETS (cells + 1 of them) and CONNECTIVITY.
inline void decode_offsets_and_connectivity(VTK_legacy_parser& parser, const std::vector<int>& points_per_cell,
                                            Unstructured_grid_cells& r)
{
  typedef Unstructured_grid_cells::Index Index;
  const Unstructured_cell_checks check{parser, r};
  const std::size_t nc = parser.cells;
  const VTK_legacy_array& offsets = *parser.offsets;
  const VTK_legacy_array& connectivity = *parser.connectivity;
  r.offsets.resize(nc + 1);
  parser.decode(offsets, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    if (i == 0 && v != 0.)
      parser.fail_at(offset, line, "OFFSETS[0] is " + number_string(v) + "; expected 0");
    if (i > 0) {
      const double previous = static_cast<double>(r.offsets[i - 1]);
      if (v - previous != points_per_cell[i - 1])
        parser.fail_at(offset, line,
                       check.cell_name(i - 1) + " has OFFSETS " + number_string(previous) + " and " +
                           number_string(v) + ", so " + number_string(v - previous) + " points; expected " +
                           std::to_string(points_per_cell[i - 1]));
    }
    if (i == nc && v != static_cast<double>(connectivity.tuples))
      parser.fail_at(offset, line,
                     "the last offset is " + number_string(v) + " but CONNECTIVITY has " +
                         std::to_string(connectivity.tuples) + " values; expected them equal");
    r.offsets[i] = static_cast<Index>(v);
  });
  r.connectivity.resize(connectivity.tuples);
  parser.decode(connectivity, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    const std::size_t cell = static_cast<std::size_t>(
        std::upper_bound(r.offsets.begin(), r.offsets.end(), static_cast<Index>(i)) - r.offsets.begin() - 1);
    r.connectivity[i] = check.point_index(cell, v, offset, line);
  });
}

// The cells of an UNSTRUCTURED_GRID (either form of CELLS) in the form of
// `Unstructured_flow_field_3`, with every type, point count and point index checked: binary
// files in blocks, and value by value where those checks refuse a value (or in ASCII files),
// to say where and why.
inline Unstructured_grid_cells read_unstructured_cells(VTK_legacy_parser& parser)
{
  const std::size_t nc = parser.cells, np = parser.nodes;
  const std::size_t indices = parser.cell_list ? parser.cell_list->tuples - nc : parser.connectivity->tuples;
  const std::size_t most = static_cast<std::size_t>((std::numeric_limits<Unstructured_grid_cells::Index>::max)());
  if (np > most || indices > most)
    parser.fail_file("the grid has " + std::to_string(np) + " points and " + std::to_string(indices) +
                     " point indices in its cells; Unstructured_flow_field_3 holds at most " + std::to_string(most) +
                     " of each (32-bit indices)");
  Unstructured_grid_cells r;
  const std::vector<int> points_per_cell = read_cell_types(parser, r);
  if (!parser.binary || !decode_valid_binary_cells(parser, points_per_cell, r)) {
    r.offsets.clear();
    r.connectivity.clear();
    if (parser.cell_list)
      decode_cell_list(parser, points_per_cell, r);
    else
      decode_offsets_and_connectivity(parser, points_per_cell, r);
  }
  voxels_as_hexahedra(r.cell_types, r.offsets, r.connectivity);
  return r;
}

// Reads the file and builds the field; throw Read_error with the message.
template <class K>
Regular_grid_flow_field_3<K> read_VTK_legacy_grid(const std::string& filename, const std::string* array_name,
                                                  const std::string* mask_name)
{
  VTK_legacy_parser parser(filename, File_contents(filename, "read_VTK_flow_field"));
  parser.parse({"STRUCTURED_POINTS"}, "Regular_grid_flow_field_3");
  VTK_legacy_node_data d = read_node_data(parser, array_name, mask_name);
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  return construct_field<Regular_grid_flow_field_3<K>>(
      parser.file_failure(), Flow_aligned_surfaces::internal::Node_values_checked(),
      Point_3(parser.origin[0], parser.origin[1], parser.origin[2]),
      Vector_3(parser.spacing[0], parser.spacing[1], parser.spacing[2]), parser.dimensions,
      std::move(d.values), std::move(d.flags));
}

template <class K>
Rectilinear_grid_flow_field_3<K> read_VTK_legacy_rectilinear(const std::string& filename,
                                                             const std::string* array_name,
                                                             const std::string* mask_name)
{
  VTK_legacy_parser parser(filename, File_contents(filename, "read_VTK_flow_field"));
  parser.parse({"STRUCTURED_POINTS", "RECTILINEAR_GRID"}, "Rectilinear_grid_flow_field_3");
  VTK_legacy_node_data d = read_node_data(parser, array_name, mask_name);
  std::array<std::vector<double>, 3> x = grid_coordinates(parser);
  return construct_field<Rectilinear_grid_flow_field_3<K>>(
      parser.file_failure(), Flow_aligned_surfaces::internal::Node_values_checked(), std::move(x),
      std::move(d.values), std::move(d.flags));
}

template <class K>
Unstructured_flow_field_3<K> read_VTK_legacy_cells(const std::string& filename, const std::string* array_name,
                                                   const std::string* mask_name)
{
  VTK_legacy_parser parser(filename, File_contents(filename, "read_VTK_flow_field"));
  parser.parse({"UNSTRUCTURED_GRID", "STRUCTURED_GRID", "RECTILINEAR_GRID", "STRUCTURED_POINTS"},
               "Unstructured_flow_field_3");
  VTK_legacy_node_data d = read_node_data(parser, array_name, mask_name);
  // Float points stay float in the field.
  const bool float_points = (parser.dataset == "UNSTRUCTURED_GRID" || parser.dataset == "STRUCTURED_GRID") &&
                            parser.points && parser.points->type == "float";
  std::vector<double> points;
  std::vector<float> points_as_floats;
  if (float_points)
    points_as_floats = decode_reals<float>(parser, *parser.points);
  else if (parser.dataset == "UNSTRUCTURED_GRID" || parser.dataset == "STRUCTURED_GRID")
    points = decode_reals(parser, *parser.points);
  // The cells without the masked ones, and the field.
  const auto field = [&](auto cells) {
    const std::size_t all_cells = cells.cell_types.size();
    if (!d.flags.empty() &&
        remove_masked_cells(d.flags, cells.connectivity, cells.offsets, cells.cell_types) == 0)
      parser.fail_file("every one of the " + std::to_string(all_cells) +
                       " cells touches a solid node of the mask '" + d.mask_name + "'; no cell is left");
    if (float_points)
      return construct_field<Unstructured_flow_field_3<K>>(
          parser.file_failure(), std::move(points_as_floats), std::move(cells.connectivity),
          std::move(cells.offsets), std::move(cells.cell_types), std::move(d.values));
    return construct_field<Unstructured_flow_field_3<K>>(
        parser.file_failure(), std::move(points), std::move(cells.connectivity), std::move(cells.offsets),
        std::move(cells.cell_types), std::move(d.values));
  };
  if (parser.dataset == "UNSTRUCTURED_GRID")
    return field(read_unstructured_cells(parser));
  if (parser.dataset != "STRUCTURED_GRID") {
    const std::array<std::vector<double>, 3> x = grid_coordinates(parser);
    points.reserve(3 * parser.nodes);
    for (double z : x[2])
      for (double y : x[1])
        for (double xi : x[0])
          points.insert(points.end(), {xi, y, z});
  }
  return field(structured_grid_cells(parser.dimensions));
}

// The public functions' common part: the named parameters, and the errors made `false` + message
// with `field` untouched.
template <class Field, class NamedParameters, class Read>
bool read_VTK_legacy(const std::string& filename, Field& field, const NamedParameters& np, const Read& read)
{
  const Array_names names = array_names(np);
  return read_into("read_VTK_flow_field", filename, field, np,
                   [&] { return read(filename, names.array_name(), names.mask_name()); });
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_LEGACY_VTK_LEGACY_FIELDS_H
