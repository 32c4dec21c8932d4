// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point location in the cells of `Unstructured_flow_field_3` (see its documentation for the
// method and its costs): the mesh arrays, a bounding volume hierarchy over the cells (a complete
// binary tree of float boxes, 8 cells per leaf), and the walk from the cell that answered the
// previous query of the same thread, through face neighbours found in the hierarchy and kept in
// a per-thread cache.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CELL_POINT_LOCATION_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CELL_POINT_LOCATION_H

#include <CGAL/Flow_aligned_surfaces/internal/cell_shape_functions.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// The cells of an unstructured mesh and where each point is among them.  The owner fills the
// mesh arrays, each checked (sizes, cell types, point indices, finite coordinates), then calls
// `build()`.
class Cell_point_location {
public:
  // Point indices and positions in `connectivity`.
  typedef std::int32_t Index;

  // A cell containing a point, the tree node (a leaf) holding the cell, and where in the cell.
  struct Hit : Cell_parametric_point {
    std::size_t cell = 0, leaf = 0;
  };

  // The mesh.  The points: exactly one of the two is not empty (float_points also when there
  // is none).  offsets: number of cells + 1 entries.
  std::vector<float> float_points;
  std::vector<double> double_points;
  std::vector<Index> connectivity, offsets;
  std::vector<unsigned char> cell_types;
  // The bounding box of the points; empty (no point is in it) until `build()`.
  double bbox[6] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

  // The box of the points and the hierarchy.
  void build() { build_hierarchy(*this); }

  // The points if they are floats, else null.
  const std::vector<float>* float_points_or_null() const
  {
    return double_points.empty() ? &float_points : nullptr;
  }

  // Whether a cell contains x, with the hit: the walk from the thread's hint, else the hierarchy.
  bool find(const double* x, Hit& hit) const
  {
    const Cell_point_location& s = *this;
    // Written so that NaN coordinates fail too.
    if (!(x[0] >= s.bbox[0] && x[0] <= s.bbox[3] && x[1] >= s.bbox[1] && x[1] <= s.bbox[4] &&
          x[2] >= s.bbox[2] && x[2] <= s.bbox[5]))
      return false;
    static thread_local Walk_caches caches;
    Walk_cache& w = caches.of(s.id);
    const auto try_any = [&](std::size_t c, std::size_t node) {
      if (!try_cell(s, c, x, hit))
        return false;
      hit.leaf = node;
      return true;
    };
    // The walk, else the hierarchy, nearest to the hint first.
    const bool found =
        w.has_hint ? walk(s, x, hit, w) || search_from(s, w.leaf, x, try_any) : search(s, 0, x, try_any);
    if (!found)
      return false;
    smallest_cell_on_shared_faces(s, x, hit);
    w.has_hint = true;
    w.cell = hit.cell;
    w.leaf = hit.leaf;
    return true;
  }

  // Makes `hit`, a cell containing x, the answer that does not depend on the queries before it
  // (on the thread's hint): on a shared face the cell of smallest index among those containing
  // x.  Every inversion starts at the cell's parametric centre (the last bits of Newton's
  // method depend on where it starts), so a field gives the same sample at a point whatever
  // order, thread or process asks for it.
  static void smallest_cell_on_shared_faces(const Cell_point_location& s, const double* x, Hit& hit)
  {
    if (in_reference_cell(s.cell_types[hit.cell], hit.xi, -cell_interior_margin))
      return;
    search(s, 0, x, [&](std::size_t c, std::size_t node) {
      Hit other;
      if (c < hit.cell && try_cell(s, c, x, other)) {
        other.leaf = node;
        hit = other;
      }
      return false; // every cell whose box holds x
    });
  }

  // Whether cell c contains x (its box first), with the hit.
  static bool try_cell(const Cell_point_location& s, std::size_t c, const double* x, Hit& hit)
  {
    double X[8][3], b[6];
    const int n = gather(s, c, X);
    cell_points_box(X, n, b);
    if (!in_cell_box(b, x) || !invert_cell_map(s.cell_types[c], X, n, x, hit))
      return false;
    hit.cell = c;
    return true;
  }

  // The cells sharing a face with cell `cell` (conforming faces with exactly the same points),
  // in the order of the cell's faces.
  std::vector<std::size_t> face_neighbours(std::size_t cell) const
  {
    const Cell_point_location& s = *this;
    double X[8][3];
    gather(s, cell, X);
    std::vector<std::size_t> r;
    for (int f = 0; f < number_of_cell_faces(s.cell_types[cell]); ++f) {
      std::size_t d, leaf;
      if (find_neighbour(s, cell, f, X, 0, d, leaf))
        r.push_back(d);
    }
    return r;
  }

private:
  // Cells per leaf of the hierarchy: 8 is ~10 bytes per cell in all (order + boxes) and a
  // leaf's cells are about a 2 x 2 x 2 block, which usually holds the next cell of a coherent
  // query.
  static constexpr std::size_t leaf_size = 8;

  // The hierarchy.  order: the cells in the order of the leaves; leaf l (in
  // left-to-right order) holds order[leaf_size l, leaf_size (l + 1)).  The 2 L - 1 nodes of
  // the tree over the L leaves are a complete binary tree in heap order (children of i at
  // 2 i + 1 and 2 i + 2; the leaves are the nodes L - 1 ... 2 L - 2; those on the deepest
  // level, from first_deepest on, are the leftmost); node_box: 6 floats per node, xmin,
  // ymin, zmin, xmax, ymax, zmax, rounded outwards.
  std::vector<Index> order;
  std::size_t leaves = 0, first_deepest = 0;
  std::vector<float> node_box;
  // Unique among the meshes of the process (never reused, unlike an address): the key of
  // the threads' walk caches.
  std::uint64_t id = new_storage_id();

  // What a thread keeps between its queries of one field: the hint and the face neighbours
  // met by its walks, in a direct-mapped cache indexed by cell (a cell evicts the one that
  // had its slot).  Everything it holds is tried before it is trusted (the hint cell must
  // contain the point, a neighbour must share the face), so a stale entry costs time only.
  struct Walk_cache {
    static constexpr std::size_t slots = 1024; // 52 bytes each: 53 KB
    struct Slot {
      Index cell = -1;
      Index neighbour[6]; // -2: not looked for yet; -1: none (a boundary face)
      Index leaf[6];      // the leaf node holding the neighbour
    };
    std::uint64_t owner = 0; // the field storage's `id`; 0: none
    bool has_hint = false;
    std::size_t cell = 0, leaf = 0; // the hint: the last cell found, its leaf node
    Slot slot[slots];

    void reset(std::uint64_t id)
    {
      owner = id;
      has_hint = false;
      for (Slot& e : slot)
        e.cell = -1;
    }
    Slot& of(std::size_t c)
    {
      Slot& e = slot[c % slots];
      if (e.cell != Index(c)) {
        e.cell = Index(c);
        for (int f = 0; f < 6; ++f)
          e.neighbour[f] = -2;
      }
      return e;
    }
  };
  // A thread's walk caches of the last fields it queried, so that a thread alternating between
  // a few fields (an unsteady field interpolating between two time steps' meshes) keeps the
  // hint and the neighbours of each: 4 caches, 212 KB per thread.
  struct Walk_caches {
    static constexpr std::size_t fields = 4;
    Walk_cache cache[fields];
    std::size_t next = 0; // the cache to reuse for the next new field: the oldest

    Walk_cache& of(std::uint64_t id)
    {
      for (Walk_cache& w : cache)
        if (w.owner == id)
          return w;
      Walk_cache& w = cache[next];
      next = (next + 1) % fields;
      w.reset(id);
      return w;
    }
  };

  // Cells a walk visits before the hierarchy takes over.
  static constexpr int max_walk_steps = 8;

  static std::uint64_t new_storage_id()
  {
    static std::atomic<std::uint64_t> last(0);
    return ++last;
  }

  // The points of cell c as doubles, X[i] = point i of the cell; returns their number.  The
  // precision of the storage is chosen once per cell visit.
  static int gather(const Cell_point_location& s, std::size_t c, double (*X)[3])
  {
    const int n = number_of_cell_points(s.cell_types[c]);
    const Index* v = s.connectivity.data() + s.offsets[c];
    if (s.double_points.empty())
      gather_cell_points(s.float_points, v, n, X);
    else
      gather_cell_points(s.double_points, v, n, X);
    return n;
  }

  static void cell_box(const Cell_point_location& s, std::size_t c, double* b)
  {
    double X[8][3];
    cell_points_box(X, gather(s, c, X), b);
  }

  static bool in_node_box(const Cell_point_location& s, std::size_t node, const double* x)
  {
    const float* b = s.node_box.data() + 6 * node;
    return x[0] >= b[0] && x[0] <= b[3] && x[1] >= b[1] && x[1] <= b[4] && x[2] >= b[2] && x[2] <= b[5];
  }

  // Tree node of leaf l (left to right), and back; the cells of a leaf (positions in order).
  static std::size_t leaf_node(const Cell_point_location& s, std::size_t l)
  {
    const std::size_t deepest = 2 * s.leaves - 1 - s.first_deepest;
    return l < deepest ? s.first_deepest + l : s.leaves - 1 + (l - deepest);
  }
  static std::size_t leaf_rank(const Cell_point_location& s, std::size_t node)
  {
    const std::size_t deepest = 2 * s.leaves - 1 - s.first_deepest;
    return node >= s.first_deepest ? node - s.first_deepest : deepest + (node - (s.leaves - 1));
  }
  static std::size_t leaf_begin(const Cell_point_location& s, std::size_t node)
  {
    return leaf_size * leaf_rank(s, node);
  }
  static std::size_t leaf_end(const Cell_point_location& s, std::size_t node)
  {
    return (std::min)(leaf_begin(s, node) + leaf_size, s.order.size());
  }

  static std::size_t leftmost_leaf(const Cell_point_location& s, std::size_t node)
  {
    while (node < s.leaves - 1)
      node = 2 * node + 1;
    return node;
  }
  static std::size_t rightmost_leaf(const Cell_point_location& s, std::size_t node)
  {
    while (node < s.leaves - 1)
      node = 2 * node + 2;
    return node;
  }

  // A cell and the centre of its box, as the tree's partitions move them.
  struct Centred_cell {
    float centre[3];
    Index cell;
  };

  // f(i) for i in [0, n): on all cores with TBB.
  template <class F>
  static void for_each_in_range(std::size_t n, const F& f)
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&f](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i)
        f(i);
    });
#else
    for (std::size_t i = 0; i < n; ++i)
      f(i);
#endif
  }

  // Orders the cells of the subtree of `node` (an inner node) so that each of its inner nodes
  // splits its cells at the median of the longest axis of their centres; the two subtrees of
  // a node of many cells are ordered concurrently with TBB.
  static void split_subtree(const Cell_point_location& s, std::size_t node, std::vector<Centred_cell>& cells)
  {
    if (node >= s.leaves - 1)
      return;
    const std::size_t first = leaf_size * leaf_rank(s, leftmost_leaf(s, node));
    const std::size_t middle = leaf_size * leaf_rank(s, leftmost_leaf(s, 2 * node + 2));
    const std::size_t last = (std::min)(leaf_size * (leaf_rank(s, rightmost_leaf(s, node)) + 1), cells.size());
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
      lo[a] = hi[a] = cells[first].centre[a];
    for (std::size_t k = first; k < last; ++k)
      for (int a = 0; a < 3; ++a) {
        lo[a] = (std::min)(lo[a], cells[k].centre[a]);
        hi[a] = (std::max)(hi[a], cells[k].centre[a]);
      }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis])
        axis = a;
    std::nth_element(cells.begin() + std::ptrdiff_t(first), cells.begin() + std::ptrdiff_t(middle),
                     cells.begin() + std::ptrdiff_t(last),
                     [axis](const Centred_cell& u, const Centred_cell& v) { return u.centre[axis] < v.centre[axis]; });
#ifdef CGAL_LINKED_WITH_TBB
    if (last - first >= 16384) {
      tbb::parallel_invoke([&] { split_subtree(s, 2 * node + 1, cells); },
                           [&] { split_subtree(s, 2 * node + 2, cells); });
      return;
    }
#endif
    split_subtree(s, 2 * node + 1, cells);
    split_subtree(s, 2 * node + 2, cells);
  }

  static void build_hierarchy(Cell_point_location& s)
  {
    const std::size_t nc = s.cell_types.size();
    const double inf = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      s.bbox[a] = inf;
      s.bbox[a + 3] = -inf;
    }
    const auto enclose = [&s](const auto& points) {
      for (std::size_t i = 0; i < points.size(); ++i) {
        s.bbox[i % 3] = (std::min)(s.bbox[i % 3], double(points[i]));
        s.bbox[i % 3 + 3] = (std::max)(s.bbox[i % 3 + 3], double(points[i]));
      }
    };
    if (s.double_points.empty())
      enclose(s.float_points);
    else
      enclose(s.double_points);
    // The cells' box centres, then the tree top down: each node's cells split at the median
    // of the longest axis of their centres, the left part holding as many leaves as the left
    // subtree of the complete tree has (a kd-tree of boxes in the implicit layout).  The centres
    // move with their cells, so that the partitions read them in order; with TBB the centres,
    // the subtrees and the leaves' boxes are computed on all cores (the same tree as on one).
    std::vector<Centred_cell> cells(nc);
    for_each_in_range(nc, [&](std::size_t c) {
      double b[6];
      cell_box(s, c, b);
      for (int a = 0; a < 3; ++a)
        cells[c].centre[a] = static_cast<float>(0.5 * (b[a] + b[a + 3]));
      cells[c].cell = static_cast<Index>(c);
    });
    s.leaves = (nc + leaf_size - 1) / leaf_size;
    const std::size_t nodes = 2 * s.leaves - 1;
    s.first_deepest = 0;
    while (2 * s.first_deepest + 1 < nodes)
      s.first_deepest = 2 * s.first_deepest + 1;
    split_subtree(s, 0, cells);
    s.order.resize(nc);
    for (std::size_t k = 0; k < nc; ++k)
      s.order[k] = cells[k].cell;
    cells = std::vector<Centred_cell>();
    s.node_box.assign(6 * nodes, 0.f);
    const float finf = std::numeric_limits<float>::infinity();
    for_each_in_range(s.leaves, [&](std::size_t leaf) {
      const std::size_t node = s.leaves - 1 + leaf;
      double u[6] = {inf, inf, inf, -inf, -inf, -inf};
      for (std::size_t k = leaf_begin(s, node); k < leaf_end(s, node); ++k) {
        double b[6];
        cell_box(s, std::size_t(s.order[k]), b);
        for (int a = 0; a < 3; ++a) {
          u[a] = (std::min)(u[a], b[a]);
          u[a + 3] = (std::max)(u[a + 3], b[a + 3]);
        }
      }
      for (int a = 0; a < 3; ++a) { // rounded outwards: the float box holds the double one
        s.node_box[6 * node + a] = std::nextafter(static_cast<float>(u[a]), -finf);
        s.node_box[6 * node + a + 3] = std::nextafter(static_cast<float>(u[a + 3]), finf);
      }
    });
    for (std::size_t node = s.leaves - 1; node-- > 0;) {
      float* b = s.node_box.data() + 6 * node;
      const float* l = s.node_box.data() + 6 * (2 * node + 1); // the children, l and r
      const float* r = l + 6;
      for (int a = 0; a < 3; ++a) {
        b[a] = (std::min)(l[a], r[a]);
        b[a + 3] = (std::max)(l[a + 3], r[a + 3]);
      }
    }
  }

  // Calls accept(cell, leaf node) for the cells of the leaves of the subtree of `root` whose
  // boxes contain x, until it returns true; returns whether it did.
  template <typename Accept>
  static bool search(const Cell_point_location& s, std::size_t root, const double* x, const Accept& accept)
  {
    // The tree is complete, so its depth is below 64 for any size_t number of cells, and the
    // stack holds at most one pending sibling per level.
    std::size_t stack[64];
    int top = 0;
    stack[top++] = root;
    while (top > 0) {
      const std::size_t node = stack[--top];
      if (!in_node_box(s, node, x))
        continue;
      if (node >= s.leaves - 1) {
        for (std::size_t k = leaf_begin(s, node); k < leaf_end(s, node); ++k)
          if (accept(std::size_t(s.order[k]), node))
            return true;
        continue;
      }
      stack[top++] = 2 * node + 2;
      stack[top++] = 2 * node + 1;
    }
    return false;
  }

  // The same over the whole tree, nearest to the tree node `start` first: its subtree, then
  // the siblings' subtrees on the way up to the root (every cell once).
  template <typename Accept>
  static bool search_from(const Cell_point_location& s, std::size_t start, const double* x,
                          const Accept& accept)
  {
    if (search(s, start, x, accept))
      return true;
    for (std::size_t node = start; node != 0; node = (node - 1) / 2)
      if (search(s, node % 2 == 1 ? node + 1 : node - 1, x, accept))
        return true;
    return false;
  }

  // The cell d sharing face f of cell c (whose points are X), that is, holding all the face's
  // points, and the leaf holding d; searched among the cells whose leaf box contains the
  // face's centroid (as d's box does), nearest to the tree node `start` first.  Returns false
  // on the boundary.
  static bool find_neighbour(const Cell_point_location& s, std::size_t c, int f, const double (*X)[3],
                             std::size_t start, std::size_t& d, std::size_t& leaf)
  {
    const std::array<int, 4>& local = cell_face_points(s.cell_types[c], f);
    const int m = local[3] < 0 ? 3 : 4;
    const Index* v = s.connectivity.data() + s.offsets[c];
    Index P[4];
    double centroid[3] = {0., 0., 0.};
    for (int k = 0; k < m; ++k) {
      P[k] = v[local[k]];
      for (int a = 0; a < 3; ++a)
        centroid[a] += X[local[k]][a] / m;
    }
    return search_from(s, start, centroid, [&](std::size_t e, std::size_t node) {
      if (e == c)
        return false;
      const Index* w = s.connectivity.data() + s.offsets[e];
      const int n = number_of_cell_points(s.cell_types[e]);
      for (int k = 0; k < m; ++k)
        if (std::find(w, w + n, P[k]) == w + n)
          return false;
      d = e;
      leaf = node;
      return true;
    });
  }

  // The walk from the hint's cell: invert the cell's map at x; if x is outside, cross the face
  // through which the parametric point leaves the cell (`cell_exit_face()`) into the neighbour
  // sharing it (from the thread's cache, else found in the hierarchy and cached), and again,
  // for at most `max_walk_steps` cells.  Gives up (false) at the boundary, on a cell whose map
  // diverges, or when x is not in the box of the hint leaf's grandparent (about 32 cells).
  static bool walk(const Cell_point_location& s, const double* x, Hit& hit, Walk_cache& w)
  {
    std::size_t c = w.cell, leaf = w.leaf, near = leaf;
    for (int up = 0; up < 2 && near != 0; ++up)
      near = (near - 1) / 2;
    if (!in_node_box(s, near, x))
      return false;
    for (int step = 0;; ++step) {
      double X[8][3], xi[3], b[6];
      const int n = gather(s, c, X);
      if (invert_cell_map(s.cell_types[c], X, n, x, hit, xi)) {
        cell_points_box(X, n, b);
        if (!in_cell_box(b, x)) // as try_cell(): points outside the cell's box are not in it
          return false;
        hit.cell = c;
        hit.leaf = leaf;
        return true;
      }
      const int f = cell_exit_face(s.cell_types[c], xi);
      if (f < 0 || step + 1 == max_walk_steps)
        return false;
      typename Walk_cache::Slot& e = w.of(c);
      if (e.neighbour[f] == -2) {
        std::size_t d, d_leaf;
        const bool found = find_neighbour(s, c, f, X, leaf, d, d_leaf);
        e.neighbour[f] = found ? Index(d) : Index(-1);
        e.leaf[f] = found ? Index(d_leaf) : Index(-1);
      }
      if (e.neighbour[f] < 0)
        return false;
      c = std::size_t(e.neighbour[f]);
      leaf = std::size_t(e.leaf[f]);
    }
  }
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CELL_POINT_LOCATION_H
