// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A field that integrates ahead, seen by work that takes turns with its caller (Taking_turns.h):
// what the field's own process alone decides (`sample_here()`) is answered at once, on the
// work's thread; a batch, which may exchange with other processes, is asked of the caller, who
// runs it between its own exchanges.  The work has no `integrate_ahead_meanwhile()`: the caller's
// first rounds are the only ones the other processes work through meanwhile.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FIELD_IN_TURNS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FIELD_IN_TURNS_H

#include <CGAL/Flow_aligned_surfaces/internal/Taking_turns.h>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

template <class FlowField>
struct Field_in_turns {
  const FlowField* field;
  Taking_turns* turns;

  // The call operators are there for the traits that tell a steady field from an unsteady one;
  // the algorithms sample a field that answers batches through `sample()` and `sample_here()`.
  template <class... Args>
  auto operator()(Args&&... args) const -> decltype((*field)(std::forward<Args>(args)...))
  {
    return turns->ask(Taking_turns::Request::EXCHANGE, [&] { return (*field)(std::forward<Args>(args)...); });
  }

  template <class... Args>
  auto sample(Args&&... args) const -> decltype(field->sample(std::forward<Args>(args)...))
  {
    return turns->ask(Taking_turns::Request::EXCHANGE,
                      [&] { return field->sample(std::forward<Args>(args)...); });
  }

  // Every `samples_per_turn` samples answered at once end the work's turn: enough that handing
  // the turn over and back (13 µs on a 2-core virtual machine) costs little, few enough that the
  // caller goes on soon after the other processes have done their part (about 0.2 ms of samples
  // in unstructured cells, 0.05 ms in an image).
  template <class... Args>
  auto sample_here(Args&&... args) const -> decltype(field->sample_here(std::forward<Args>(args)...))
  {
    if (++answered_here % samples_per_turn == 0)
      turns->ask(Taking_turns::Request::LOCAL, [] {});
    return field->sample_here(std::forward<Args>(args)...);
  }

  static constexpr std::size_t samples_per_turn = 1024;
  mutable std::size_t answered_here = 0;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FIELD_IN_TURNS_H
