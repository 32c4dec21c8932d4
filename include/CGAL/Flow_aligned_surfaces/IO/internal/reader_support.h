// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The frame that every public flow-field reader puts around its parser: the array names of
// the named parameters (`array_name`, `mask_array_name`, each either given or not), the
// translation of the internal `Read_error` (and of `std::bad_alloc`) into `false` + message
// with the output untouched and the message where `error_message` says, and the threads a
// reader may use (`use_parallelism`).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_READER_SUPPORT_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_READER_SUPPORT_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/error_output.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/internal/array_names.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

// The array names of the named parameters, shared with the fields that read them
// (`VTK_flow_field_3`).
using Flow_aligned_surfaces::internal::Array_names;
using Flow_aligned_surfaces::internal::array_names;

/// `Field(args...)`; a `std::invalid_argument` by which the constructor refuses values that
/// the reader did not check itself becomes `fail(its message)`, which throws a `Read_error`
/// naming the file.
template <class Field, class Fail, class... Args>
Field construct_field(const Fail& fail, Args&&... args)
{
  try {
    return Field(std::forward<Args>(args)...);
  } catch (const std::invalid_argument& e) {
    fail(std::string(e.what()));
    throw;
  }
}

/// Whether `np` asks for `use_parallelism(true)`: the readers then decode binary arrays on all
/// the threads of the caller's TBB arena; by default they run on the calling thread only.
template <class NamedParameters>
bool reads_in_parallel(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::use_parallelism_t()), false);
}

/// Runs `read()` (which returns the field or throws `Read_error`) and assigns its result to
/// `field` (a field, or anything assignable from one); on failure leaves `field` untouched,
/// writes the reason to the string of `np`'s `error_message` (if any) and returns `false`.
/// `reader` and `filename` name the message about a lack of memory.  Unless `np` asks for
/// `use_parallelism`, `read()` runs in a TBB arena of one thread, so that its parallel loops
/// start no thread the caller did not ask for.
template <class Field, class NamedParameters, class Read>
bool read_into(const std::string& reader, const std::string& filename, Field& field,
               const NamedParameters& np, const Read& read)
{
  std::string* const error = error_output(np);
  const bool parallel = reads_in_parallel(np);
  try {
#ifdef CGAL_LINKED_WITH_TBB
    if (!parallel) {
      tbb::task_arena calling_thread_only(1);
      calling_thread_only.execute([&] { field = read(); });
      return true;
    }
#else
    (void)parallel;
#endif
    field = read();
    return true;
  } catch (const Read_error& e) {
    if (error)
      *error = e.what();
  } catch (const std::bad_alloc&) {
    if (error)
      *error = reader + ": " + filename + ": not enough memory for the field";
  }
  return false;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_READER_SUPPORT_H
