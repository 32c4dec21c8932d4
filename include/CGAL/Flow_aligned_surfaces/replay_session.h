// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Replays an interactive session (Section 4 of the paper) on a `Flow_aligned_deformation`:
// the iterations, rigid moves and growing steps of an `Session`, in order, recording the
// normalized flux and the largest requested rotation of every iteration (the curves of the
// paper's Figure 6, where every user operation makes a "flux spike" that the following
// iterations remove).  The replay is deterministic: the same session on the same surface and
// flow gives the same records, bit for bit, when the deformation runs sequentially.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_REPLAY_SESSION_H
#define CGAL_FLOW_ALIGNED_SURFACES_REPLAY_SESSION_H

#include <CGAL/Flow_aligned_surfaces/Alignment.h>
#include <CGAL/Flow_aligned_surfaces/Session.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesRef
/// One iteration of a replayed session.
struct Session_iteration {
  std::size_t line = 0;    ///< the session line of the `iterate` operation that made it
  Iteration_report report; ///< its report (`report.iteration` counts from 1 over the session)
  /// The moves applied since the previous iteration, as the session names them, separated by
  /// spaces (`"translate rotate"`), empty if there were none: the cause of a flux spike.
  std::string moves_before;
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// What `replay_session()` did.
struct Session_replay_report {
  std::vector<Session_iteration> iterations; ///< every iteration, in order
  std::vector<Growth_report> growths;        ///< every `grow`, in order
  Normalized_flux final_normalized_flux;     ///< f_n of the surface after the last operation
};

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Replays the operations of `session` on `deformation`.

`iterate N` performs `N` iterations (`step()`); `iterate until-converged N` iterates until an
iteration converges, at most `N` times; `translate` and `rotate` call the rigid moves (the
rotation is about the centroid of the surface's vertices); `grow` calls
`Flow_aligned_deformation::grow()` with the whole boundary, `FAS::parameters::growth_direction()`
or `FAS::parameters::across_flow()`; `save` calls `save(operation)`, which typically writes
`deformation.mesh()` to a file named after `operation.path`.

The session's set-up lines (`flow`, `alignment`, `patch`) are not used here: they describe how
to build `deformation`, which the caller does (the example `replay_session.cpp` shows how).

\tparam Deformation a `Flow_aligned_deformation`
\tparam Save a callable `void(const Session_operation&)`

\throws std::invalid_argument if an operation is refused (for instance growing a surface that
        has no boundary in the given direction); the message starts with the session's line
        (`"session line 12: ..."`), and the surface stays as the operations before left it.
*/
template <class Deformation, class Save>
Session_replay_report replay_session(Deformation& deformation, const Session& session, const Save& save)
{
  using Vector_3 = typename Deformation::Vector_3;
  using Op = Session_operation;
  Session_replay_report result;
  std::string moves;
  auto vector = [](const Op& op) { return Vector_3(op.vector[0], op.vector[1], op.vector[2]); };
  auto add_move = [&moves](const char* name) {
    if (!moves.empty())
      moves += ' ';
    moves += name;
  };
  for (const Op& op : session.operations) {
    try {
      switch (op.kind) {
      case Op::Kind::ITERATE:
        for (std::size_t i = 0; i < op.number_of_iterations; ++i) {
          Session_iteration iteration;
          iteration.line = op.line;
          iteration.report = deformation.step();
          iteration.moves_before = std::move(moves);
          moves.clear();
          result.iterations.push_back(iteration);
          if (op.until_converged && iteration.report.converged)
            break;
        }
        break;
      case Op::Kind::TRANSLATE:
        deformation.translate(vector(op));
        add_move("translate");
        break;
      case Op::Kind::ROTATE:
        deformation.rotate(vector(op), op.angle);
        add_move("rotate");
        break;
      case Op::Kind::GROW:
        if (op.growth == Op::Growth::DIRECTION)
          result.growths.push_back(deformation.grow(op.distance, parameters::growth_direction(vector(op))));
        else if (op.growth == Op::Growth::ACROSS_FLOW)
          result.growths.push_back(deformation.grow(op.distance, parameters::across_flow(true)));
        else
          result.growths.push_back(deformation.grow(op.distance));
        add_move("grow");
        break;
      case Op::Kind::SAVE:
        save(op);
        break;
      }
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("session line " + std::to_string(op.line) + ": " + e.what());
    }
  }
  result.final_normalized_flux = deformation.current_normalized_flux();
  return result;
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_REPLAY_SESSION_H
