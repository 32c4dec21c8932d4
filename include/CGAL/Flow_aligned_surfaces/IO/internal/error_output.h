// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The string that the named parameter `error_message` gives the readers and writers for the
// reason of a failure, or null when the caller wants no message.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_ERROR_OUTPUT_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_ERROR_OUTPUT_H

#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

template <class NamedParameters>
std::string* error_output(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::error_message_t()),
                                      static_cast<std::string*>(nullptr));
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_ERROR_OUTPUT_H
