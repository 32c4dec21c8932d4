// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks that every reader makes on the node values it decodes, one value at a time: a
// mask value m becomes the fluid flag [m != 0] (a NaN is an error), and a velocity component v
// is stored as the 32-bit float v if v is finite and |v| <= FLT_MAX (else an error at a fluid
// node, and NaN at a solid node, whose value is never interpolated).  The messages name the
// array, the node and the value.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_NODE_VALUE_CHECKS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_NODE_VALUE_CHECKS_H

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Node `i` of a grid of `n[0] x n[1] x n[2]` nodes (x fastest) in messages: "i = (x, y, z)".
inline std::string grid_node_string(const std::array<std::size_t, 3>& n, std::size_t i)
{
  return std::to_string(i) + " = (" + std::to_string(i % n[0]) + ", " + std::to_string((i / n[0]) % n[1]) +
         ", " + std::to_string(i / (n[0] * n[1])) + ")";
}

/// The fluid flag of the value `m` of the mask `name`; a NaN calls `fail(message)` (which does
/// not return), `where()` naming the node ("node 5").
template <class Where, class Fail>
unsigned char checked_mask_flag(double m, const std::string& name, const Where& where, const Fail& fail)
{
  if (std::isnan(m))
    fail("the mask '" + name + "' is NaN at " + where());
  return m != 0. ? 1 : 0;
}

/// The float stored for `v`, the value `i` of the velocity `name` (component `i % 3` of its
/// node), at a node that is fluid or not (`fluid()`): `v` if it is finite and fits in a float;
/// else NaN at a solid node (the caller decides what a solid node holds) and `fail(message)`
/// (which does not return) at a fluid node, with `where()` naming the node ("node 5 = (2, 1, 0)")
/// and, if the grid has a mask (`masked`), the words "at a fluid `kind`".  The common case costs
/// one comparison: the node, its mask and the component are looked at only for a bad value.
template <class Is_fluid, class Where, class Fail>
float checked_velocity_component(double v, std::size_t i, const Is_fluid& fluid, bool masked,
                                 const std::string& name, const char* kind, const Where& where,
                                 const Fail& fail)
{
  // False for NaN and infinities too.
  if (std::fabs(v) <= static_cast<double>((std::numeric_limits<float>::max)()))
    return static_cast<float>(v);
  if (fluid()) {
    std::ostringstream msg;
    msg << "the velocity '" << name << "' at " << where() << ", component " << i % 3 << ", is " << v
        << (std::isfinite(v) ? ", which does not fit in a 32-bit float" : "; expected a finite number");
    if (masked)
      msg << " at a fluid " << kind;
    fail(msg.str());
  }
  return std::numeric_limits<float>::quiet_NaN();
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_NODE_VALUE_CHECKS_H
