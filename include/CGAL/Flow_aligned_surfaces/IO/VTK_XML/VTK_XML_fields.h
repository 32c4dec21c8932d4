// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow fields of a VTK XML data set read by VTK: the velocity and mask chosen among the
// point arrays and checked, an image as a uniform grid (no rotation), any data set with cells
// as cells (a structured grid or image as its hexahedra, cells touching a solid point left
// out), and the steps of a ParaView data collection (.pvd).
//
// Needs VTK: link the target CGAL::Flow_aligned_surfaces_VTK.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_FIELDS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_FIELDS_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/VTK_XML_reader.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/remove_masked_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/structured_grid_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/voxels_as_hexahedra.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

// The velocity and mask of the point data, chosen as documented, as floats and fluid flags.
// `where(i)` names point i in messages.
template <class Where>
void read_VTK_point_arrays(const VTK_XML_context& c, vtkDataSet* ds, const std::string* array_name,
                           const std::string* mask_name, const Where& where, std::vector<float>& values,
                           std::vector<unsigned char>& flags)
{
  vtkPointData* pd = ds->GetPointData();
  const std::size_t n = static_cast<std::size_t>(ds->GetNumberOfPoints());
  const std::string present = " (the point data arrays are: " + describe_VTK_arrays(pd) + ")";
  vtkDataArray* velocity = nullptr;
  if (array_name != nullptr) {
    vtkAbstractArray* a = pd->GetAbstractArray(array_name->c_str());
    if (a == nullptr)
      c.fail("there is no point data array named '" + *array_name + "'" + present);
    velocity = vtkDataArray::SafeDownCast(a);
    if (velocity == nullptr)
      c.fail("the point data array '" + *array_name + "' holds " + a->GetDataTypeAsString() +
             ", not numbers; a velocity needs 3 numbers per point");
  }
  else {
    velocity = pd->GetVectors();
    for (int i = 0;
         i < pd->GetNumberOfArrays() && (velocity == nullptr || velocity->GetNumberOfComponents() != 3); ++i)
      velocity = pd->GetArray(i);
    if (velocity == nullptr || velocity->GetNumberOfComponents() != 3)
      c.fail("there is no 3-component point data array to read as the velocity" + present);
  }
  const std::string velocity_name = velocity->GetName() ? velocity->GetName() : "";
  if (velocity->GetNumberOfComponents() != 3)
    c.fail("the point data array '" + velocity_name + "' has " +
           std::to_string(velocity->GetNumberOfComponents()) +
           " components; a velocity needs 3 numbers per point");

  vtkDataArray* mask = nullptr;
  const std::string mask_array = mask_name ? *mask_name : std::string("inside");
  if (!mask_array.empty()) {
    vtkAbstractArray* a = pd->GetAbstractArray(mask_array.c_str());
    if (a == nullptr && mask_name != nullptr)
      c.fail("there is no point data array named '" + mask_array + "' for the mask" + present);
    if (a != nullptr) {
      mask = vtkDataArray::SafeDownCast(a);
      if (mask == nullptr || mask->GetNumberOfComponents() != 1)
        c.fail("the mask array '" + mask_array + "' has " + std::to_string(a->GetNumberOfComponents()) +
               " components of type " + a->GetDataTypeAsString() + "; a mask needs 1 number per point");
    }
  }
  for (vtkDataArray* a : {velocity, mask})
    if (a != nullptr && static_cast<std::size_t>(a->GetNumberOfTuples()) != n)
      c.fail(std::string(a == mask ? "the mask array '" : "the velocity array '") +
             (a->GetName() ? a->GetName() : "") + "' has " + std::to_string(a->GetNumberOfTuples()) +
             " tuples but the data set has " + std::to_string(n) + " points");

  std::vector<unsigned char> f;
  if (mask != nullptr) {
    f.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      f[i] = Flow_aligned_surfaces::IO::internal::checked_mask_flag(
          mask->GetComponent(static_cast<vtkIdType>(i), 0), mask_array, [&] { return "point " + where(i); },
          [&](const std::string& what) { c.fail(what); });
  }
  std::vector<float> v(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    double x[3];
    velocity->GetTuple(static_cast<vtkIdType>(i), x);
    for (int d = 0; d < 3; ++d) {
      const float s = Flow_aligned_surfaces::IO::internal::checked_velocity_component(
          x[d], std::size_t(d), [&] { return f.empty() || f[i] != 0; }, !f.empty(), velocity_name, "point",
          [&] { return "point " + where(i); }, [&](const std::string& what) { c.fail(what); });
      // Solid points' values are never interpolated; the fields' constructors want them finite.
      v[3 * i + d] = std::isnan(s) ? 0.f : s;
    }
  }
  values = std::move(v);
  flags = std::move(f);
}

// The image's dimensions, checked to be a 3D grid without rotation.
inline std::array<std::size_t, 3> checked_image_dimensions(const VTK_XML_context& c, vtkImageData* image)
{
  int d[3];
  image->GetDimensions(d);
  std::array<std::size_t, 3> n;
  for (int a = 0; a < 3; ++a) {
    if (d[a] < 2)
      c.fail("the image has " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
             std::to_string(d[2]) +
             " points; a grid needs at least 2 points along each axis (2D and 1D images are not supported)");
    n[a] = static_cast<std::size_t>(d[a]);
  }
  if (vtkMatrix3x3* m = image->GetDirectionMatrix()) {
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col)
        if (m->GetElement(r, col) != (r == col ? 1. : 0.)) {
          std::ostringstream msg;
          msg << "the image has the Direction matrix (";
          for (int k = 0; k < 9; ++k)
            msg << (k ? " " : "") << m->GetElement(k / 3, k % 3);
          msg << "), which is not the identity: rotated images are not supported";
          c.fail(msg.str());
        }
  }
  return n;
}

template <class K>
Regular_grid_flow_field_3<K> read_VTK_XML_grid(const VTK_XML_context& c, const std::string* array_name,
                                               const std::string* mask_name)
{
  check_readable(c);
  if (!VTK_can_read<vtkXMLImageDataReader>(c.file))
    c.fail("this is " + VTK_XML_kind(c.file) +
           "; a Regular_grid_flow_field_3 is read from a VTK XML ImageData file (.vti)");
  vtkSmartPointer<vtkDataSet> ds = run_VTK_reader<vtkXMLImageDataReader>(c);
  vtkImageData* image = vtkImageData::SafeDownCast(ds);
  const std::array<std::size_t, 3> n = checked_image_dimensions(c, image);
  std::vector<float> values;
  std::vector<unsigned char> flags;
  read_VTK_point_arrays(
      c, ds, array_name, mask_name,
      [&n](std::size_t i) { return Flow_aligned_surfaces::IO::internal::grid_node_string(n, i); }, values,
      flags);
  // The grid's origin is the image's first point, which the extent may move off VTK's origin.
  double first[3], spacing[3];
  image->GetPoint(0, first);
  image->GetSpacing(spacing);
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  return Flow_aligned_surfaces::IO::internal::construct_field<Regular_grid_flow_field_3<K>>(
      [&](const std::string& what) { c.fail(what); }, Point_3(first[0], first[1], first[2]),
      Vector_3(spacing[0], spacing[1], spacing[2]), n, std::move(values), std::move(flags));
}

// The cells of the data set as VTK arrays, with the velocity and the mask; cells touching a
// solid point are dropped.
// The coordinates of the np points of ds, x, y, z per point, as Real.
template <class Real>
std::vector<Real> VTK_point_coordinates(vtkDataSet* ds, std::size_t np)
{
  std::vector<Real> r(3 * np);
  double x[3];
  for (std::size_t i = 0; i < np; ++i) {
    ds->GetPoint(static_cast<vtkIdType>(i), x);
    for (int a = 0; a < 3; ++a)
      r[3 * i + a] = static_cast<Real>(x[a]);
  }
  return r;
}

template <class K>
Unstructured_flow_field_3<K> read_VTK_XML_cells(const VTK_XML_context& c, const std::string* array_name,
                                                const std::string* mask_name)
{
  // vtkIdType here; the field's constructor narrows to its 32-bit Index (and says so if it cannot).
  typedef std::int64_t Index;
  check_readable(c);
  vtkSmartPointer<vtkDataSet> ds;
  std::optional<std::array<std::size_t, 3>> structured;
  if (VTK_can_read<vtkXMLUnstructuredGridReader>(c.file)) {
    ds = run_VTK_reader<vtkXMLUnstructuredGridReader>(c);
  }
  else if (VTK_can_read<vtkXMLStructuredGridReader>(c.file)) {
    ds = run_VTK_reader<vtkXMLStructuredGridReader>(c);
    int d[3];
    vtkStructuredGrid::SafeDownCast(ds)->GetDimensions(d);
    for (int a = 0; a < 3; ++a)
      if (d[a] < 2)
        c.fail("the structured grid has " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
               std::to_string(d[2]) + " points; it needs at least 2 points along each axis");
    structured = {{std::size_t(d[0]), std::size_t(d[1]), std::size_t(d[2])}};
  }
  else if (VTK_can_read<vtkXMLImageDataReader>(c.file)) {
    ds = run_VTK_reader<vtkXMLImageDataReader>(c);
    structured = checked_image_dimensions(c, vtkImageData::SafeDownCast(ds));
  }
  else {
    c.fail("this is " + VTK_XML_kind(c.file) +
           "; an Unstructured_flow_field_3 is read from a VTK XML UnstructuredGrid (.vtu), StructuredGrid "
           "(.vts) or ImageData (.vti) file");
  }

  const std::size_t np = static_cast<std::size_t>(ds->GetNumberOfPoints());
  std::vector<float> values;
  std::vector<unsigned char> flags;
  if (structured)
    read_VTK_point_arrays(
        c, ds, array_name, mask_name,
        [&](std::size_t i) { return Flow_aligned_surfaces::IO::internal::grid_node_string(*structured, i); },
        values, flags);
  else
    read_VTK_point_arrays(
        c, ds, array_name, mask_name, [](std::size_t i) { return std::to_string(i); }, values, flags);

  std::vector<Index> connectivity, offsets;
  std::vector<unsigned char> types;
  if (structured) {
    Flow_aligned_surfaces::IO::internal::Structured_grid_cells cells =
        Flow_aligned_surfaces::IO::internal::structured_grid_cells(*structured);
    connectivity = std::move(cells.connectivity);
    offsets = std::move(cells.offsets);
    types = std::move(cells.cell_types);
  }
  else {
    vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(ds);
    const vtkIdType nc = grid->GetNumberOfCells();
    if (nc == 0)
      c.fail("the unstructured grid has no cells");
    offsets.reserve(static_cast<std::size_t>(nc) + 1);
    types.reserve(static_cast<std::size_t>(nc));
    offsets.push_back(0);
    for (vtkIdType cell = 0; cell < nc; ++cell) {
      const int type = grid->GetCellType(cell);
      if (type != VTK_TETRA && type != VTK_VOXEL && type != VTK_HEXAHEDRON && type != VTK_WEDGE &&
          type != VTK_PYRAMID) {
        const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
        c.fail("cell " + std::to_string(cell) + " has the VTK cell type " + std::to_string(type) + " (" +
               (name ? name : "unknown") +
               "); supported are 10 (tetrahedron), 11 (voxel), 12 (hexahedron), 13 (wedge) and 14 (pyramid)");
      }
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      grid->GetCellPoints(cell, n, ids);
      connectivity.insert(connectivity.end(), ids, ids + n);
      offsets.push_back(static_cast<Index>(connectivity.size()));
      types.push_back(static_cast<unsigned char>(type));
    }
    Flow_aligned_surfaces::IO::internal::voxels_as_hexahedra(types, offsets, connectivity);
  }

  const std::size_t cells = types.size();
  if (!flags.empty() &&
      Flow_aligned_surfaces::IO::internal::remove_masked_cells(flags, connectivity, offsets, types) == 0)
    c.fail("every one of the " + std::to_string(cells) +
           " cells touches a solid point of the mask (no fluid cell is left)");
  const auto refused = [&](const std::string& what) { c.fail(what); };
  // The points in the file's precision (float points stay float in the field).
  vtkPointSet* point_set = vtkPointSet::SafeDownCast(ds);
  if (point_set != nullptr && point_set->GetPoints() != nullptr &&
      point_set->GetPoints()->GetDataType() == VTK_FLOAT)
    return Flow_aligned_surfaces::IO::internal::construct_field<Unstructured_flow_field_3<K>>(
        refused, VTK_point_coordinates<float>(ds, np), std::move(connectivity), std::move(offsets),
        std::move(types), std::move(values));
  return Flow_aligned_surfaces::IO::internal::construct_field<Unstructured_flow_field_3<K>>(
      refused, VTK_point_coordinates<double>(ds, np), std::move(connectivity), std::move(offsets),
      std::move(types), std::move(values));
}

template <class Field>
struct VTK_XML_field_reader;

template <class K>
struct VTK_XML_field_reader<Regular_grid_flow_field_3<K>> {
  static Regular_grid_flow_field_3<K> read(const VTK_XML_context& c, const std::string* a,
                                           const std::string* m)
  {
    return read_VTK_XML_grid<K>(c, a, m);
  }
};

template <class K>
struct VTK_XML_field_reader<Unstructured_flow_field_3<K>> {
  static Unstructured_flow_field_3<K> read(const VTK_XML_context& c, const std::string* a,
                                           const std::string* m)
  {
    return read_VTK_XML_cells<K>(c, a, m);
  }
};

// The steps of a .pvd file: (time, file, byte offset of the DataSet element), in file order.
struct PVD_step {
  double time;
  std::string file;
  long long byte;
};

inline std::vector<PVD_step> read_PVD_steps(const VTK_XML_context& c)
{
  check_readable(c);
  vtkSmartPointer<vtkXMLDataParser> parser = vtkSmartPointer<vtkXMLDataParser>::New();
  const vtkSmartPointer<VTK_error_observer> messages = vtkSmartPointer<VTK_error_observer>::New();
  messages->watch(parser);
  parser->SetFileName(c.file.c_str());
  const int parsed = parser->Parse();
  if (!parsed || messages->has_errors() || parser->GetRootElement() == nullptr)
    c.fail("VTK cannot parse it as XML: " +
           (messages->has_errors() ? messages->errors() : std::string("no root element")));
  vtkXMLDataElement* root = parser->GetRootElement();
  const char* type = root->GetAttribute("type");
  if (std::string(root->GetName() ? root->GetName() : "") != "VTKFile" || type == nullptr ||
      std::string(type) != "Collection")
    c.fail(std::string("the root element is <") + (root->GetName() ? root->GetName() : "") + " type=\"" +
           (type ? type : "") + "\">; a ParaView data collection has <VTKFile type=\"Collection\">");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (collection == nullptr)
    c.fail("the VTKFile element has no <Collection> element");
  const std::filesystem::path folder = std::filesystem::path(c.file).parent_path();
  std::vector<PVD_step> steps;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    if (std::string(e->GetName() ? e->GetName() : "") != "DataSet")
      continue;
    const std::string where = "byte " + std::to_string(e->GetXMLByteIndex()) + ": DataSet element " +
                              std::to_string(steps.size()) + ": ";
    const char* timestep = e->GetAttribute("timestep");
    const char* file = e->GetAttribute("file");
    if (timestep == nullptr)
      c.fail(where + "no timestep attribute");
    if (file == nullptr || *file == '\0')
      c.fail(where + "no file attribute");
    char* end = nullptr;
    const double t = std::strtod(timestep, &end);
    if (end == timestep || *end != '\0' || !std::isfinite(t))
      c.fail(where + "the timestep '" + Flow_aligned_surfaces::IO::internal::printable(timestep) +
             "' is not a finite number");
    std::filesystem::path path(file);
    if (path.is_relative())
      path = folder / path;
    steps.push_back(PVD_step{t, path.string(), static_cast<long long>(e->GetXMLByteIndex())});
  }
  if (steps.empty())
    c.fail("the Collection holds no DataSet element");
  return steps;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_FIELDS_H
