// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The velocity and mask array names that the named parameters `array_name` and
// `mask_array_name` give, each either given or not: read by the file readers and by the fields
// that wrap a VTK data set.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_ARRAY_NAMES_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_ARRAY_NAMES_H

#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <optional>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// The value of the string parameter `Tag` of `np`, or nothing if `np` does not set it.
template <class Tag, class NamedParameters>
std::optional<std::string> string_parameter(const NamedParameters& np)
{
  if constexpr (parameters::is_default_parameter<NamedParameters, Tag>::value)
    return std::nullopt;
  else
    return std::string(parameters::get_parameter(np, Tag()));
}

/// The velocity and mask array names that the named parameters give; unset where not given.
struct Array_names {
  std::optional<std::string> array, mask;
  /// the velocity array's name, or null if not given
  const std::string* array_name() const { return array ? &*array : nullptr; }
  /// the mask array's name, or null if not given
  const std::string* mask_name() const { return mask ? &*mask : nullptr; }
};

template <class NamedParameters>
Array_names array_names(const NamedParameters& np)
{
  return Array_names{string_parameter<internal_np::array_name_t>(np),
                     string_parameter<internal_np::mask_array_name_t>(np)};
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_ARRAY_NAMES_H
