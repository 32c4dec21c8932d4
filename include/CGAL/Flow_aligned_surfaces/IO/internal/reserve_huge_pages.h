// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reserves room for n elements in a std::vector and asks the system to back it with huge pages
// (2 MiB on x86-64 and most ARM64 Linux systems) where it can: for a reader's result arrays of
// tens of MB, the first touch then faults once per 2 MiB instead of once per 4 KiB.  The vector
// keeps the standard allocator, so the field classes take it by move, and a system without
// transparent huge pages (or with them disabled) just gets the reserve.  With TBB, the pages of
// a large reserve are faulted in (zeroed by the kernel) on all cores.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_RESERVE_HUGE_PAGES_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_RESERVE_HUGE_PAGES_H

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// `v.reserve(n)`; then, if the reserved bytes span at least one aligned huge page, advises
/// `MADV_HUGEPAGE` on the aligned huge pages inside them (an advice only: a refusal changes
/// nothing, and pages touched before are merely candidates for the kernel's collapsing).
template <class T>
void reserve_huge_pages(std::vector<T>& v, std::size_t n)
{
  v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge_page = std::uintptr_t(2) << 20;
  const std::uintptr_t b = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (b + huge_page - 1) & ~(huge_page - 1);
  const std::uintptr_t last = (b + v.capacity() * sizeof(T)) & ~(huge_page - 1);
  if (first < last)
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#if defined(MADV_POPULATE_WRITE) && defined(CGAL_LINKED_WITH_TBB)
  // The kernel zeroes each new page at its first touch: 10-25 ms per 100 MB, which would come
  // on one core (in the caller's `resize()`).  Faulting the huge pages in ahead, on all cores,
  // does it in parallel; the advice neither writes nor changes the contents of pages already
  // present.  Small reserves are not worth the threads.
  const std::size_t pages = first < last ? (last - first) / huge_page : 0;
  if (pages >= 4)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pages),
                      [first](const tbb::blocked_range<std::size_t>& r) {
                        ::madvise(reinterpret_cast<void*>(first + r.begin() * huge_page),
                                  r.size() * huge_page, MADV_POPULATE_WRITE);
                      });
#endif
#endif
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_RESERVE_HUGE_PAGES_H
