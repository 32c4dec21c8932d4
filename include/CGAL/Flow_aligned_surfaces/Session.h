// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The data model of an interactive session (Section 4 of the paper): the initial patch and the
// user's operations in order (iterations, translations, rotations, growing, saves).
// `IO/read_session.h` reads it from a text file; `replay_session()` carries it out.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_SESSION_H
#define CGAL_FLOW_ALIGNED_SURFACES_SESSION_H

#include <CGAL/Flow_aligned_surfaces/Alignment.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesRef
/// The initial surface of a session: a planar rectangle or a disk, as `make_planar_patch()` and
/// `make_disk_patch()` build them.
struct Session_patch {
  /// The kind of initial surface.
  enum class Shape {
    PLANAR, ///< `patch planar ...`: a rectangle
    DISK    ///< `patch disk ...`: a disk
  };
  Shape shape = Shape::PLANAR;               ///< rectangle or disk
  std::array<double, 3> center{{0, 0, 0}};   ///< the center of the patch
  std::array<double, 3> normal{{0, 0, 1}};   ///< the normal of its plane (not necessarily unit)
  double width = 1;                          ///< the rectangle's first side (planar)
  double height = 1;                         ///< the rectangle's second side (planar)
  double radius = 1;                         ///< the disk's radius (disk)
  std::size_t target_number_of_faces = 1000; ///< the number of faces asked of the patch builder
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// One operation of a session, as one line of the file gives it.
struct Session_operation {
  /// What the operation does.
  enum class Kind {
    ITERATE,   ///< `iterate N` or `iterate until-converged [N]`
    TRANSLATE, ///< `translate dx dy dz`
    ROTATE,    ///< `rotate ax ay az angle` (degrees, about the centroid of the surface's vertices)
    GROW,      ///< `grow distance [dx dy dz | across-flow]`
    SAVE       ///< `save path`
  };
  /// Which part of the boundary `grow` offsets.
  enum class Growth {
    WHOLE_BOUNDARY, ///< `grow d`
    DIRECTION,      ///< `grow d dx dy dz`: the part facing `vector`
    ACROSS_FLOW     ///< `grow d across-flow`: across the flow, for tangential surfaces
  };
  Kind kind = Kind::ITERATE; ///< what the operation does
  std::size_t line = 0;      ///< the line of the file (1 = first)
  /// `ITERATE`: the number of iterations, or the largest one when `until_converged`.
  std::size_t number_of_iterations = 0;
  bool until_converged = false; ///< `ITERATE`: stop at the first converged iteration
  std::array<double, 3> vector{
      {0, 0, 0}};      ///< `TRANSLATE`: the move; `ROTATE`: the axis; `GROW`: the direction
  double angle = 0;    ///< `ROTATE`: the angle in radians (the file gives degrees)
  double distance = 0; ///< `GROW`: the offset distance
  Growth growth = Growth::WHOLE_BOUNDARY; ///< `GROW`: which part of the boundary
  std::string path;                       ///< `SAVE`: the file name, as written in the session
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// A session read by `read_session()`: where it takes place and what the user did.
struct Session {
  std::string flow;                            ///< the `flow` line's argument, empty if there is none
  Alignment alignment = Alignment::TANGENTIAL; ///< the `alignment` line's argument (default tangential)
  Session_patch patch;                         ///< the `patch` line: the initial surface
  std::vector<Session_operation> operations;   ///< the operations, in the order of the file
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_SESSION_H
