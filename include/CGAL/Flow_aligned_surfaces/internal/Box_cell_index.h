// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which of many boxes a few small boxes can meet: the small boxes bucketed by the cells of a
// uniform grid as large as the largest of them, the occupied cells in an open-addressing hash
// table (cells far apart may share a slot: that only adds boxes to test), each slot listing the
// boxes that reach its cells.  A query box then looks at the slots of the cells it covers and
// tests the boxes listed there, each once.  The guard of `grow_boundary()` asks this of every face of the
// surface against the few hundred faces of the new strip: a query costs a few probes, where
// CGAL's box intersection would sort the whole surface, and a node-based hash set one
// allocation-chasing lookup per cell.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BOX_CELL_INDEX_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BOX_CELL_INDEX_H

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

class Box_cell_index {
  using Index = std::uint32_t; // boxes, entries and queries: a few thousand of each in a growth

public:
  /// Indexes `boxes` (kept by reference: they must outlive the index).
  explicit Box_cell_index(const std::vector<CGAL::Bbox_3>& boxes) : m_boxes(boxes)
  {
    for (const CGAL::Bbox_3& b : boxes) {
      m_all += b;
      for (int i = 0; i < 3; ++i)
        m_cell = (std::max)(m_cell, b.max(i) - b.min(i));
    }
    m_cell = m_cell > 0 ? m_cell : 1;
    std::size_t incidences = 0;
    for (const CGAL::Bbox_3& b : boxes)
      incidences += std::size_t(cell_range(b).count());
    std::size_t capacity = 16;
    while (capacity < 2 * incidences)
      capacity *= 2;
    m_mask = capacity - 1;
    m_keys.assign(capacity, empty_key);
    // Counted, then listed from each slot's end down (a box whose cells share a slot is listed
    // there twice: the queries skip what they tested already).
    m_first.assign(capacity + 1, 0);
    for_each_slot_of_boxes([&](std::size_t slot, std::size_t) { ++m_first[slot]; });
    for (std::size_t s = 1; s < capacity; ++s)
      m_first[s] += m_first[s - 1]; // the end of slot s
    m_first[capacity] = m_first[capacity - 1];
    m_listed.resize(m_first[capacity]);
    for_each_slot_of_boxes([&](std::size_t slot, std::size_t j) { m_listed[--m_first[slot]] = Index(j); });
    m_visited.assign(boxes.size(), 0);
  }

  /// Calls `f(j)` once for every indexed box `j` that meets `query` (closed boxes), in no
  /// particular order, until `f` returns true; returns whether it did.
  template <class F>
  bool find_meeting(const CGAL::Bbox_3& query, const F& f)
  {
    if (!CGAL::do_overlap(query, m_all))
      return false;
    ++m_query;
    auto visit = [&](std::size_t j) {
      if (m_visited[j] == m_query)
        return false;
      m_visited[j] = m_query;
      return CGAL::do_overlap(query, m_boxes[j]) && f(j);
    };
    const Cell_range r = cell_range(query);
    if (r.count() > 64) { // a box much larger than the indexed ones: all of them are tested
      for (std::size_t j = 0; j < m_boxes.size(); ++j)
        if (visit(j))
          return true;
      return false;
    }
    for (std::int64_t i = r.lo[0]; i <= r.hi[0]; ++i)
      for (std::int64_t j = r.lo[1]; j <= r.hi[1]; ++j)
        for (std::int64_t k = r.lo[2]; k <= r.hi[2]; ++k) {
          const std::size_t slot = find(key(i, j, k));
          if (slot != not_found)
            for (std::size_t e = m_first[slot]; e < m_first[slot + 1]; ++e)
              if (visit(m_listed[e]))
                return true;
        }
    return false;
  }

  /// Whether `query` meets (closed boxes) one of the indexed boxes.
  bool meets_any(const CGAL::Bbox_3& query)
  {
    return find_meeting(query, [](std::size_t) { return true; });
  }

private:
  static constexpr std::int64_t empty_key = INT64_MIN;
  static constexpr std::size_t not_found = std::size_t(-1);

  struct Cell_range {
    std::int64_t lo[3], hi[3];
    std::int64_t count() const { return (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1); }
  };

  Cell_range cell_range(const CGAL::Bbox_3& b) const
  {
    Cell_range r;
    for (int i = 0; i < 3; ++i) {
      r.lo[i] = std::int64_t(std::floor(b.min(i) / m_cell));
      r.hi[i] = std::int64_t(std::floor(b.max(i) / m_cell));
    }
    return r;
  }

  static std::int64_t key(std::int64_t i, std::int64_t j, std::int64_t k)
  {
    const std::int64_t h = (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
    return h == empty_key ? 0 : h;
  }

  std::size_t slot_of(std::int64_t key) const
  {
    return std::size_t((std::uint64_t(key) * 0x9E3779B97F4A7C15ull) >> 20) & m_mask;
  }

  std::size_t find(std::int64_t key) const
  {
    for (std::size_t s = slot_of(key);; s = (s + 1) & m_mask) {
      if (m_keys[s] == key)
        return s;
      if (m_keys[s] == empty_key)
        return not_found;
    }
  }

  std::size_t insert(std::int64_t key)
  {
    std::size_t s = slot_of(key);
    while (m_keys[s] != key && m_keys[s] != empty_key)
      s = (s + 1) & m_mask;
    m_keys[s] = key;
    return s;
  }

  // Calls f(slot, box) for every box and every cell it reaches.
  template <class F>
  void for_each_slot_of_boxes(const F& f)
  {
    for (std::size_t b = 0; b < m_boxes.size(); ++b) {
      const Cell_range r = cell_range(m_boxes[b]);
      for (std::int64_t i = r.lo[0]; i <= r.hi[0]; ++i)
        for (std::int64_t j = r.lo[1]; j <= r.hi[1]; ++j)
          for (std::int64_t k = r.lo[2]; k <= r.hi[2]; ++k)
            f(insert(key(i, j, k)), b);
    }
  }

  const std::vector<CGAL::Bbox_3>& m_boxes;
  CGAL::Bbox_3 m_all;
  double m_cell = 0;
  std::size_t m_mask = 0;
  std::vector<std::int64_t> m_keys;
  std::vector<Index> m_first, m_listed; // slot s lists m_listed[m_first[s]], ... before m_first[s + 1]
  std::vector<Index> m_visited;         // the last query that tested each box
  Index m_query = 0;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BOX_CELL_INDEX_H
