// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The order in which the triangular sweeps of a supernodal Cholesky factor visit its
// supernodes, split into independent subtrees of the elimination tree so that they can run on
// several threads.
//
// A supernode updates only its ancestors.  The tree is cut at its top (the "top" supernodes,
// few: the separators of a fill-reducing ordering) into subtrees of about equal work, packed
// into a fixed number of groups.  Forward sweep: the groups, heaviest first, each on the next
// free thread, each writing its updates of the top rows into a private buffer, then the buffers
// added in group order and the top swept; backward sweep: the top first, then the groups in the
// same way.  The cut and the order of every addition are fixed by the factor alone, so the
// result is the same bit for bit on one thread or many.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_ELIMINATION_SUBTREES_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_ELIMINATION_SUBTREES_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#endif

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

class Elimination_subtrees {
public:
  /// The number of groups of subtrees: enough to keep a few threads busy, few enough that the
  /// top stays small.
  static constexpr int number_of_groups = 4;

  /// No supernodes.
  Elimination_subtrees() = default;

  /// The supernodes of a CHOLMOD supernodal factor: `super` (first column of each supernode, size
  /// nsuper + 1), `pi` (offsets of their row lists in `rows`).  A factor whose supernodes are not
  /// in postorder or whose row lists are not sorted is swept in sequence.
  Elimination_subtrees(int nsuper, const int* super, const int* pi, const int* rows)
      : m_nsuper(nsuper), m_super(super), m_pi(pi), m_rows(rows)
  {
    cut();
  }

  /// Whether the sweeps are split into groups (else they visit every supernode in sequence).
  bool is_split() const { return !m_groups.empty(); }

  /// Whether `forward()` and `backward()` run the groups on the threads of the caller's TBB arena.
  void use_parallelism(bool parallel) { m_parallel = parallel; }

  /// The forward sweep over the interleaved right-hand side `z` (`width` values of `Scalar`,
  /// double or float, per row):
  /// `visit(s, target, split, group)` processes supernode s, adding its updates of the rows at
  /// positions [split, nrows) of its row list to `target` instead of `z` (split < 0: all to `z`);
  /// `group` (in [0, number_of_groups]) tells the visits that may run at the same time apart.
  template <class Scalar, class Visit>
  void forward(Scalar* z, int width, const Visit& visit) const
  {
    if (!is_split()) {
      for (int s = 0; s < m_nsuper; ++s)
        visit(s, z, -1, 0);
      return;
    }
    const std::size_t n = std::size_t(m_super[m_nsuper]) * std::size_t(width);
    std::vector<std::vector<Scalar>>& private_rows = std::get<std::vector<std::vector<Scalar>>>(m_private);
    private_rows.resize(m_groups.size());
    for_each_group([&](std::size_t g) {
      std::vector<Scalar>& buffer = private_rows[g];
      if (buffer.size() != n)
        buffer.assign(n, Scalar(0));
      for (int column : m_top_columns)
        std::fill_n(buffer.data() + std::size_t(column) * width, width, Scalar(0));
      for (const Range& range : m_groups[g])
        for (int s = range.first; s <= range.last; ++s)
          visit(s, buffer.data(), m_split[s], int(g) + 1);
    });
    for (const std::vector<Scalar>& buffer : private_rows)
      for (int column : m_top_columns)
        for (int c = 0; c < width; ++c)
          z[std::size_t(column) * width + c] += buffer[std::size_t(column) * width + c];
    for (int s : m_top)
      visit(s, z, -1, 0);
  }

  /// The backward sweep: `visit(s, group)` for every supernode, each after all its ancestors.
  template <class Visit>
  void backward(const Visit& visit) const
  {
    if (!is_split()) {
      for (int s = m_nsuper - 1; s >= 0; --s)
        visit(s, 0);
      return;
    }
    for (auto s = m_top.rbegin(); s != m_top.rend(); ++s)
      visit(*s, 0);
    for_each_group([&](std::size_t g) {
      for (auto range = m_groups[g].rbegin(); range != m_groups[g].rend(); ++range)
        for (int s = range->last; s >= range->first; --s)
          visit(s, int(g) + 1);
    });
  }

  /// The share of the work (stored entries) in the top, swept on one thread.
  double top_fraction() const { return m_top_fraction; }

private:
  // A subtree: the supernodes [first, last] of a postordered tree, last its root.
  struct Range {
    int first, last;
  };

  // f(g) for every group; in parallel, each thread takes the heaviest group not yet taken
  // whenever it is free.  The groups' work is uneven when the cut stops at the top's share
  // (at 3.2e5 faces the four hold 36, 33, 10 and 11 % of the work); splitting the range of
  // groups in halves gave both heavy ones to one thread (SOLVE 1.4x faster on two threads than
  // on one, against 1.7x this way; RESULTS.md, "The solver").  The order does not change
  // the result: each group writes its own rows and its own buffer.
  template <class Function>
  void for_each_group(const Function& f) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if (m_parallel) {
      std::atomic<std::size_t> next(0);
      const int threads = (std::min)(tbb::this_task_arena::max_concurrency(), int(m_groups.size()));
      tbb::parallel_for(0, threads, [&](int) {
        for (std::size_t k = next++; k < m_heaviest_first.size(); k = next++)
          f(m_heaviest_first[k]);
      });
      return;
    }
#endif
    for (std::size_t g = 0; g < m_groups.size(); ++g)
      f(g);
  }

  int rows_of(int s) const { return m_pi[s + 1] - m_pi[s]; }
  int columns_of(int s) const { return m_super[s + 1] - m_super[s]; }

  void cut()
  {
    const int ns = m_nsuper;
    if (ns < 2 * number_of_groups)
      return;
    // The parent of each supernode: the supernode of its first row below its own columns.
    std::vector<int> super_of_column(static_cast<std::size_t>(m_super[ns]));
    for (int s = 0; s < ns; ++s)
      std::fill(super_of_column.begin() + m_super[s], super_of_column.begin() + m_super[s + 1], s);
    std::vector<int> parent(ns, -1), first(ns), size(ns);
    std::vector<double> work(ns), subtree_work(ns);
    std::vector<std::vector<int>> children(ns);
    std::vector<int> roots;
    for (int s = 0; s < ns; ++s) {
      const int k = columns_of(s), nrows = rows_of(s);
      const int* row = m_rows + m_pi[s];
      if (!std::is_sorted(row, row + nrows))
        return;
      work[s] = double(k) * nrows - double(k) * (k - 1) / 2;
      if (nrows > k) {
        parent[s] = super_of_column[row[k]];
        if (parent[s] <= s)
          return; // not a postordered elimination tree
        children[parent[s]].push_back(s);
      }
      else
        roots.push_back(s);
    }
    // Postorder: the descendants of s are [first[s], s].
    for (int s = 0; s < ns; ++s) {
      first[s] = s;
      size[s] = 1;
      subtree_work[s] = work[s];
      for (int c : children[s]) {
        first[s] = (std::min)(first[s], first[c]);
        size[s] += size[c];
        subtree_work[s] += subtree_work[c];
      }
      if (s - first[s] + 1 != size[s])
        return;
    }
    const double total = std::accumulate(work.begin(), work.end(), 0.);

    // Cut the heaviest subtree until the groups balance: its root goes to the top.
    std::vector<int> candidates = roots, top;
    double top_work = 0;
    std::vector<std::vector<int>> packed;
    std::vector<double> load;
    for (;;) {
      std::sort(candidates.begin(), candidates.end(),
                [&](int a, int b) { return subtree_work[a] > subtree_work[b] || (subtree_work[a] == subtree_work[b] && a < b); });
      packed.assign(number_of_groups, {});
      load.assign(number_of_groups, 0.);
      for (int c : candidates) {
        const std::size_t g = std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
        packed[g].push_back(c);
        load[g] += subtree_work[c];
      }
      const double largest = *std::max_element(load.begin(), load.end());
      const double mean = (total - top_work) / number_of_groups;
      if (largest <= 1.05 * mean)
        break;
      const int heaviest = candidates.front();
      if (children[heaviest].empty() || top_work + work[heaviest] > 0.1 * total)
        break;
      candidates.erase(candidates.begin());
      top.push_back(heaviest);
      top_work += work[heaviest];
      candidates.insert(candidates.end(), children[heaviest].begin(), children[heaviest].end());
    }
    if (top.empty())
      return;

    std::sort(top.begin(), top.end());
    m_top = top;
    m_top_fraction = top_work / total;
    for (int s : m_top)
      for (int column = m_super[s]; column < m_super[s + 1]; ++column)
        m_top_columns.push_back(column);
    m_split.assign(ns, -1);
    m_groups.clear();
    for (std::vector<int>& group : packed) {
      std::sort(group.begin(), group.end());
      std::vector<Range> ranges;
      for (int root : group) {
        ranges.push_back(Range{first[root], root});
        const int end_column = m_super[root + 1];
        for (int s = first[root]; s <= root; ++s) {
          const int* row = m_rows + m_pi[s];
          m_split[s] = int(std::lower_bound(row, row + rows_of(s), end_column) - row);
        }
      }
      m_groups.push_back(std::move(ranges));
    }
    m_heaviest_first.resize(m_groups.size());
    std::iota(m_heaviest_first.begin(), m_heaviest_first.end(), std::size_t(0));
    std::stable_sort(m_heaviest_first.begin(), m_heaviest_first.end(),
                     [&](std::size_t a, std::size_t b) { return load[a] > load[b]; });
  }

  int m_nsuper = 0;
  const int *m_super = nullptr, *m_pi = nullptr, *m_rows = nullptr;
  std::vector<int> m_top;         // the supernodes above the groups, in increasing order
  std::vector<int> m_top_columns; // their columns
  std::vector<std::vector<Range>> m_groups;
  std::vector<std::size_t> m_heaviest_first; // the groups by decreasing work
  std::vector<int> m_split; // per supernode of a group: first position of a row outside its subtree
  double m_top_fraction = 0;
  bool m_parallel = false;
  // The groups' private copies of the rows, in double or in float.
  mutable std::tuple<std::vector<std::vector<double>>, std::vector<std::vector<float>>> m_private;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_ELIMINATION_SUBTREES_H
