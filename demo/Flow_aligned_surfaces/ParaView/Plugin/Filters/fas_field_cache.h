// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The velocity fields this process has built, shared by every filter that samples the same
// piece.  Building a field costs as much as a filter's own work on unstructured cells (the cell
// hierarchy of 185,000 hexahedra: about 40 ms), and the five filters of a chain sample the same
// input.  ParaView hands a filter its input in a data object that the pipeline refreshes before
// each update: the object's modification time changes between a filter's RequestInformation and
// its RequestData, while its points, cells and arrays stay the same objects.  So a field is
// found again by what it is built from: the geometry and every point and cell array, each by
// object and modification time (a new object or a modified one gets a later time, so a key is
// never reused for other values), with the velocity selection and the whole image's extent.
// The cache holds its fields weakly: a field lives as long as a filter holds it.

#ifndef FAS_FIELD_CACHE_H
#define FAS_FIELD_CACHE_H

#include "fas_paraview_support.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace fas_paraview {

/// What a velocity field is built from, as `make_velocity_field()` reads it.
struct Field_source {
  std::string array_name;
  int association = 0;
  std::vector<std::uint64_t> stamps; ///< the objects read (address, modification time) and the image's values

  bool operator<(const Field_source& o) const
  {
    return std::tie(array_name, association, stamps) < std::tie(o.array_name, o.association, o.stamps);
  }
};

namespace field_cache_detail {

inline void add_object(std::vector<std::uint64_t>& stamps, vtkObject* object)
{
  stamps.push_back(std::uint64_t(reinterpret_cast<std::uintptr_t>(object)));
  stamps.push_back(object != nullptr ? std::uint64_t(object->GetMTime()) : 0);
}

inline void add_values(std::vector<std::uint64_t>& stamps, const double* values, int n)
{
  for (int i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, values + i, sizeof bits);
    stamps.push_back(bits);
  }
}

inline void add_arrays(std::vector<std::uint64_t>& stamps, vtkFieldData* data)
{
  stamps.push_back(std::uint64_t(data->GetNumberOfArrays()));
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    add_object(stamps, data->GetAbstractArray(a));
}

// The geometry of an image, an unstructured grid or, for any other data set, the data object
// itself (its modification time covers everything it holds).
inline void add_geometry(std::vector<std::uint64_t>& stamps, vtkDataSet* data_set)
{
  if (auto* image = vtkImageData::SafeDownCast(data_set)) {
    stamps.push_back(1);
    const int* extent = image->GetExtent();
    for (int i = 0; i < 6; ++i)
      stamps.push_back(std::uint64_t(std::int64_t(extent[i])));
    add_values(stamps, image->GetOrigin(), 3);
    add_values(stamps, image->GetSpacing(), 3);
    add_values(stamps, image->GetDirectionMatrix()->GetData(), 9);
  }
  else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data_set)) {
    stamps.push_back(2);
    add_object(stamps, grid->GetPoints());
    if (grid->GetPoints() != nullptr)
      add_object(stamps, grid->GetPoints()->GetData());
    add_object(stamps, grid->GetCells());
    add_object(stamps, grid->GetCellTypesArray());
    add_object(stamps, grid->GetFaces());
    add_object(stamps, grid->GetFaceLocations());
  }
  else {
    stamps.push_back(3);
    add_object(stamps, data_set);
  }
}

} // namespace field_cache_detail

/// What `make_velocity_field(data_set, selection, whole_extent)` reads.
inline Field_source field_source(vtkDataSet* data_set, const Velocity_selection& selection, const int* whole_extent)
{
  using namespace field_cache_detail;
  Field_source source{ selection.name, selection.association, {} };
  std::vector<std::uint64_t>& s = source.stamps;
  add_geometry(s, data_set);
  add_arrays(s, data_set->GetPointData());
  add_arrays(s, data_set->GetCellData());
  s.push_back(whole_extent != nullptr ? 1 : 0);
  if (whole_extent != nullptr)
    for (int i = 0; i < 6; ++i)
      s.push_back(std::uint64_t(std::int64_t(whole_extent[i])));
  return source;
}

/// The fields built so far on this process and still held by a filter.
class Field_cache {
public:
  /// `make_velocity_field(data_set, selection, whole_extent)`, or the field built before from the
  /// same objects; `built` says which.  \throws std::invalid_argument as `make_velocity_field()` does.
  static std::shared_ptr<const Velocity_field> field(vtkDataSet* data_set, const Velocity_selection& selection,
                                                     const int* whole_extent, bool& built)
  {
    built = true;
    if (data_set == nullptr)
      return std::make_shared<const Velocity_field>(make_velocity_field(data_set, selection, whole_extent));
    Field_cache& cache = instance();
    Field_source source = field_source(data_set, selection, whole_extent);
    std::lock_guard<std::mutex> lock(cache.m_mutex);
    cache.forget_expired();
    if (auto found = cache.m_fields.find(source); found != cache.m_fields.end())
      if (std::shared_ptr<const Velocity_field> field = found->second.lock()) {
        built = false;
        return field;
      }
    auto field = std::make_shared<const Velocity_field>(make_velocity_field(data_set, selection, whole_extent));
    cache.m_fields[std::move(source)] = field;
    return field;
  }

private:
  static Field_cache& instance()
  {
    static Field_cache cache;
    return cache;
  }

  void forget_expired()
  {
    for (auto i = m_fields.begin(); i != m_fields.end();)
      i = i->second.expired() ? m_fields.erase(i) : std::next(i);
  }

  std::mutex m_mutex;
  std::map<Field_source, std::weak_ptr<const Velocity_field>> m_fields;
};

} // namespace fas_paraview

#endif // FAS_FIELD_CACHE_H
