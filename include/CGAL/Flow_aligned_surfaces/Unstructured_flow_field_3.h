// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A model of `FlowField_3` on an unstructured mesh of tetrahedra, hexahedra, wedges and pyramids
// (VTK cell types 10, 12, 13, 14 with VTK's vertex orderings) with velocities at the points:
// v(p) = sum_i N_i(xi) v_i, where xi solves x(xi) = sum_i N_i(xi) X_i = p in the cell containing
// p (isoparametric interpolation: linear on tetrahedra, trilinear on hexahedra), and
// std::nullopt where no cell contains p.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_UNSTRUCTURED_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_UNSTRUCTURED_FLOW_FIELD_3_H

#include <CGAL/Bbox_3.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// A velocity field given at the points of an unstructured mesh of tetrahedra, hexahedra,
/// wedges and pyramids and interpolated with the cells' shape functions, a model of
/// `FlowField_3`.
///
/// The mesh is given as VTK stores an `UNSTRUCTURED_GRID`: point coordinates, the cells'
/// point indices (`connectivity`), where each cell starts in it (`offsets`) and the VTK cell
/// types, with VTK's vertex ordering for each type:
/// - `10` tetrahedron `0 1 2 3`: linear interpolation (exact for linear fields);
/// - `12` hexahedron: `0 1 2 3` one quadrilateral face in order, `4 5 6 7` the points joined to
///   them by the four remaining edges: trilinear (isoparametric) interpolation;
/// - `13` wedge: triangle `0 1 2`, triangle `3 4 5`, edges `0-3`, `1-4`, `2-5`;
/// - `14` pyramid: quadrilateral base `0 1 2 3` in order, apex `4`.
///
/// A point is located by a walk from the cell that answered the previous query of the same
/// thread on the same field (the hint), for the coherent queries that integration and
/// deformation make, and else with a bounding volume hierarchy: a complete binary tree of
/// float boxes (rounded outwards) whose leaves hold 8 cells each, built top down by splitting
/// the cells at the median of their bounding boxes' centres along the longest axis.  The walk
/// inverts the hint cell's map at `p` (Newton's method from the previous parametric position);
/// if `p` is outside, it crosses the face through which the parametric point leaves the
/// reference cell the most into the cell sharing that face, and so on, for at most 8 cells.
/// It gives up at the mesh boundary, on a cell whose inversion diverges, and when `p` is not
/// in the box of the hint leaf's grandparent in the tree (about 32 cells around the hint);
/// then the hierarchy is searched from the hint's leaf upwards (its leaf, then the sibling
/// subtrees on the way to the root), so that a query near the hint stays near the bottom of
/// the tree.  A cell contains `p` when the Newton inversion of its isoparametric map converges
/// and the parametric coordinates lie in the reference cell up to `1e-10` (so that points on
/// shared faces and on the mesh boundary are inside; points outside the bounding box of the
/// points never are).  On a face shared by two conforming cells (the same points) both give the
/// same value, up to rounding; a quadrilateral face against two triangles is not conforming
/// (the walk does not cross it, the hierarchy still finds the cell beyond).  Degenerate cells
/// (zero volume) contain no point.
///
/// The face neighbours are not stored: the walk finds the cell beyond a face in the hierarchy
/// (among the cells of the leaves whose box holds the face's centroid, nearest to the current
/// cell's leaf first, the first that holds all the face's points) and remembers it in a
/// per-thread cache of 1024 cells (direct-mapped by cell index, 53 KB per thread, each face's
/// neighbour looked for on the first crossing).  The hint and the cache are `thread_local`,
/// keyed by a number that identifies the field's shared storage (never reused within the
/// process): `operator()` is `const` and safe to call from several threads at once (a TBB
/// loop, for instance), a copy shares the cache key of its original, and a thread alternating
/// between two fields starts both afresh at each switch.  Whatever the hint and the cache say
/// is checked before it is used (the cell must contain `p`, a neighbour must hold the face's
/// points), so a stale entry costs time, never a wrong answer.
///
/// Memory: the arrays as given (points in the precision given, 32-bit indices), plus 4 bytes
/// per cell for the cells' order in the leaves and 2 float boxes (48 bytes) per leaf, about 10
/// bytes per cell in all; and per thread that queries the field, the 53 KB cache.  Copies share
/// the arrays and the hierarchy (through `std::shared_ptr`), so copying a field is cheap.  A
/// query performs no allocation.
///
/// \tparam GeomTraits a model of `Kernel`; the coordinates are converted to `double` with
///         `CGAL::to_double()`.
///
/// \sa `Regular_grid_flow_field_3`
template <typename GeomTraits>
class Unstructured_flow_field_3 {
public:
  /// \name Types
  /// @{

  /// The geometric traits.
  typedef GeomTraits Geom_traits;
  /// The number type.
  typedef typename GeomTraits::FT FT;
  /// The point type.
  typedef typename GeomTraits::Point_3 Point_3;
  /// The vector type.
  typedef typename GeomTraits::Vector_3 Vector_3;
  /// The type of point indices in `connectivity` and of positions in `offsets`: meshes have
  /// fewer than 2^31 points and connectivity entries.
  typedef std::int32_t Index;

  /// The supported VTK cell types.
  enum Cell_type : unsigned char {
    TETRA = 10,      ///< VTK_TETRA, 4 points
    HEXAHEDRON = 12, ///< VTK_HEXAHEDRON, 8 points
    WEDGE = 13,      ///< VTK_WEDGE, 6 points
    PYRAMID = 14     ///< VTK_PYRAMID, 5 points
  };

  /// A read-only view of the point coordinates, `x, y, z` per point, in the precision they were
  /// given in (exactly one of `float_data()` and `double_data()` is not null).
  class Point_coordinates {
  public:
    /// three times the number of points
    std::size_t size() const
    {
      return m_float_points != nullptr ? m_float_points->size() : m_double_points->size();
    }
    /// coordinate `i % 3` of point `i / 3`, converted to `double`
    double operator[](std::size_t i) const
    {
      return m_float_points != nullptr ? double((*m_float_points)[i]) : (*m_double_points)[i];
    }
    /// the coordinates if they were given as `float`, else null
    const float* float_data() const { return m_float_points != nullptr ? m_float_points->data() : nullptr; }
    /// the coordinates if they were given as `double`, else null
    const double* double_data() const
    {
      return m_float_points != nullptr ? nullptr : m_double_points->data();
    }

  private:
    friend class Unstructured_flow_field_3;
    Point_coordinates(const std::vector<float>* f, const std::vector<double>* d)
        : m_float_points(f), m_double_points(d)
    {
    }
    const std::vector<float>* m_float_points;
    const std::vector<double>* m_double_points;
  };
  /// @}

  /// \name Creation
  /// @{

  /// creates the field from the arrays of a VTK unstructured grid.
  ///
  /// \tparam Real `float` or `double`: the points are kept in this precision (the
  ///         interpolation computes in `double`)
  ///
  /// \param points the coordinates, `x, y, z` per point
  /// \param connectivity the point indices of all cells, cell after cell
  /// \param offsets where each cell starts in `connectivity`: either `number_of_cells + 1`
  ///        entries starting with `0` and ending with `connectivity.size()` (VTK's
  ///        `vtkCellArray` and legacy `OFFSETS`), or `number_of_cells` entries giving where
  ///        each cell ends (the `offsets` array of `.vtu` files)
  /// \param cell_types one VTK cell type per cell, each one of `Cell_type`
  /// \param vectors the velocities, `x, y, z` per point
  ///
  /// All the arrays are kept as given (moved into the shared storage): pass them with
  /// `std::move()` to avoid copies.
  ///
  /// \throws std::invalid_argument naming the faulty argument and index, with the expected and
  ///         actual values, if there is no cell, a size is wrong, there are 2^31 points or
  ///         connectivity entries or more, an offset decreases, a cell has the wrong number of
  ///         points for its type, a point index is out of range, a cell type is not supported,
  ///         or a coordinate or velocity is not finite.
  template <typename Real>
  Unstructured_flow_field_3(std::vector<Real> points, std::vector<Index> connectivity,
                            std::vector<Index> offsets, std::vector<unsigned char> cell_types,
                            std::vector<float> vectors)
  {
    static_assert(std::is_same<Real, float>::value || std::is_same<Real, double>::value,
                  "points must hold float or double coordinates");
    auto s = std::make_shared<Storage>();
    validate_and_store(*s, std::move(points), std::move(connectivity), std::move(offsets),
                       std::move(cell_types), std::move(vectors));
    build_hierarchy(*s);
    m_storage = std::move(s);
  }

  /// creates the field from 64-bit `connectivity` and `offsets` (VTK's `vtkIdType`), converted
  /// to `Index`; otherwise as the constructor above.
  /// \tparam Real `float` or `double`
  /// \tparam Int `std::int64_t` (a template parameter only so that braced lists of indices
  ///         choose the constructor above)
  /// \throws std::invalid_argument as above, and if an entry does not fit in `Index`.
  template <typename Real, typename Int,
            typename std::enable_if<std::is_same<Int, std::int64_t>::value, int>::type = 0>
  Unstructured_flow_field_3(std::vector<Real> points, const std::vector<Int>& connectivity,
                            const std::vector<Int>& offsets, std::vector<unsigned char> cell_types,
                            std::vector<float> vectors)
      : Unstructured_flow_field_3(std::move(points), narrow(connectivity, "connectivity"),
                                  narrow(offsets, "offsets"), std::move(cell_types), std::move(vectors))
  {
  }

  /// @}

  /// \name Evaluation
  /// @{

  /// returns the interpolated velocity at `p`, or `std::nullopt` if no cell contains `p`.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    Hit hit;
    if (!find(x, hit))
      return std::nullopt;
    return interpolate(hit);
  }

  /// returns the index of a cell containing `p`, or `std::nullopt` if there is none.  Where
  /// several cells contain `p` (on shared faces), which one is returned depends on the hint.
  std::optional<std::size_t> locate(const Point_3& p) const
  {
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    Hit hit;
    if (!find(x, hit))
      return std::nullopt;
    return hit.cell;
  }

  /// returns the velocity at `p` interpolated in cell `cell`, or `std::nullopt` if that cell
  /// does not contain `p`.  On a face shared by two cells, both give the same value up to
  /// rounding (for conforming faces).
  /// \pre `cell < number_of_cells()`
  std::optional<Vector_3> evaluate_in_cell(std::size_t cell, const Point_3& p) const
  {
    CGAL_precondition(cell < number_of_cells());
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    Hit hit;
    if (!try_cell(*m_storage, cell, x, hit))
      return std::nullopt;
    return interpolate(hit);
  }

  /// @}

  /// \name Access
  /// @{

  /// the number of points
  std::size_t number_of_points() const { return m_storage->vectors.size() / 3; }
  /// the number of cells
  std::size_t number_of_cells() const { return m_storage->cell_types.size(); }
  /// the bounding box of the points
  Bbox_3 bbox() const
  {
    const double* b = m_storage->bbox;
    return Bbox_3(b[0], b[1], b[2], b[3], b[4], b[5]);
  }
  /// the point coordinates, `x, y, z` per point, in the precision given to the constructor
  Point_coordinates points() const
  {
    return Point_coordinates(float_points(*m_storage), &m_storage->double_points);
  }
  /// the velocities, `x, y, z` per point
  const std::vector<float>& vectors() const { return m_storage->vectors; }
  /// the point indices of all cells, cell after cell
  const std::vector<Index>& connectivity() const { return m_storage->connectivity; }
  /// the `number_of_cells() + 1` positions in `connectivity()` where the cells start, the last
  /// one being `connectivity().size()` (whichever form was given to the constructor)
  const std::vector<Index>& offsets() const { return m_storage->offsets; }
  /// the VTK cell types
  const std::vector<unsigned char>& cell_types() const { return m_storage->cell_types; }
  /// the cells sharing a face with cell `cell` (conforming faces with exactly the same points),
  /// in the order of the cell's faces; computed on each call (from the hierarchy, as the walk
  /// does, but without its cache).
  /// \pre `cell < number_of_cells()`
  std::vector<std::size_t> face_neighbours(std::size_t cell) const
  {
    CGAL_precondition(cell < number_of_cells());
    const Storage& s = *m_storage;
    double X[8][3];
    gather(s, cell, X);
    std::vector<std::size_t> r;
    for (int f = 0; f < number_of_faces(s.cell_types[cell]); ++f) {
      std::size_t d, leaf;
      if (find_neighbour(s, cell, f, X, 0, d, leaf))
        r.push_back(d);
    }
    return r;
  }

  /// @}

private:
  // Parametric tolerance of the inside test: dimensionless, far above the rounding of a Newton
  // solution (~1e-15 for well-shaped cells) so that a point on a shared face is inside both
  // cells, and far below any distance that matters for sampling a flow.
  static constexpr double inside_tolerance = 1e-10;
  // Cells per leaf of the hierarchy: 8 is ~10 bytes per cell in all (order + boxes) and a
  // leaf's cells are about a 2 x 2 x 2 block, which usually holds the next cell of a coherent
  // query.
  static constexpr std::size_t leaf_size = 8;

  struct Storage {
    // The points: exactly one of the two is not empty (float_points also when there is none).
    std::vector<float> float_points;
    std::vector<double> double_points;
    std::vector<float> vectors;
    std::vector<Index> connectivity, offsets;
    std::vector<unsigned char> cell_types;
    double bbox[6];
    // The hierarchy.  order: the cells in the order of the leaves; leaf l (in
    // left-to-right order) holds order[leaf_size l, leaf_size (l + 1)).  The 2 L - 1 nodes of
    // the tree over the L leaves are a complete binary tree in heap order (children of i at
    // 2 i + 1 and 2 i + 2; the leaves are the nodes L - 1 ... 2 L - 2; those on the deepest
    // level, from first_deepest on, are the leftmost); node_box: 6 floats per node, xmin,
    // ymin, zmin, xmax, ymax, zmax, rounded outwards.
    std::vector<Index> order;
    std::size_t leaves = 0, first_deepest = 0;
    std::vector<float> node_box;
    // Unique among the fields of the process (never reused, unlike an address): the key of
    // the threads' walk caches.
    std::uint64_t id = new_storage_id();
  };

  struct Hit {
    std::size_t cell = 0, leaf = 0; // leaf: the tree node holding the cell
    int n = 0;
    double N[8];
    double xi[3]; // the parametric coordinates of the point in the cell
  };

  // What a thread keeps between its queries of one field: the hint and the face neighbours
  // met by its walks, in a direct-mapped cache indexed by cell (a cell evicts the one that
  // had its slot).  Everything it holds is tried before it is trusted (the hint cell must
  // contain the point, a neighbour must share the face), so a stale entry costs time only.
  struct Walk_cache {
    static constexpr std::size_t slots = 1024; // 52 bytes each: 53 KB per thread
    struct Slot {
      Index cell = -1;
      Index neighbour[6]; // -2: not looked for yet; -1: none (a boundary face)
      Index leaf[6];      // the leaf node holding the neighbour
    };
    std::uint64_t owner = 0; // the field storage's `id`; 0: none
    bool has_hint = false;
    std::size_t cell = 0, leaf = 0; // the hint: the last cell found, its leaf node
    double xi[3];                   // where the last query was found in `cell`: Newton's start
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
  // Cells a walk visits before the hierarchy takes over.
  static constexpr int max_walk_steps = 8;

  static std::uint64_t new_storage_id()
  {
    static std::atomic<std::uint64_t> last(0);
    return ++last;
  }

  static const std::vector<float>* float_points(const Storage& s)
  {
    return s.double_points.empty() ? &s.float_points : nullptr;
  }

  static const char* type_name(unsigned char t)
  {
    switch (t) {
    case TETRA:
      return "tetrahedron";
    case HEXAHEDRON:
      return "hexahedron";
    case WEDGE:
      return "wedge";
    case PYRAMID:
      return "pyramid";
    default:
      return "unsupported";
    }
  }

  static int points_of(unsigned char t)
  {
    switch (t) {
    case TETRA:
      return 4;
    case HEXAHEDRON:
      return 8;
    case WEDGE:
      return 6;
    case PYRAMID:
      return 5;
    default:
      return 0;
    }
  }

  static int number_of_faces(unsigned char t) { return t == TETRA ? 4 : t == HEXAHEDRON ? 6 : 5; }

  // The local point indices of face f of a cell of type t (VTK's numbering), a triangle padded
  // with -1 at the end.  Hexahedron: faces r = 0, r = 1, s = 0, s = 1, t = 0, t = 1; tetrahedron:
  // s = 0, r + s + t = 1, r = 0, t = 0; wedge: t = 0, t = 1, s = 0, r + s = 1, r = 0; pyramid:
  // t = 0, s = 0, r = 1, s = 1, r = 0 (see `exit_face()`).
  static const std::array<int, 4>& face_points(unsigned char t, int f)
  {
    static const std::array<int, 4> tet[4] = {{0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}, {0, 2, 1, -1}};
    static const std::array<int, 4> hex[6] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                              {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
    static const std::array<int, 4> wedge[5] = {
        {0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
    static const std::array<int, 4> pyramid[5] = {
        {0, 3, 2, 1}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};
    return (t == TETRA ? tet : t == HEXAHEDRON ? hex : t == WEDGE ? wedge : pyramid)[f];
  }

  // The point indices of face f of cell c, sorted, a triangle padded with -1 in front: the
  // same for the two cells sharing the face.
  static std::array<Index, 4> face_key(const Storage& s, std::size_t c, int f)
  {
    const std::array<int, 4>& local = face_points(s.cell_types[c], f);
    const Index* v = s.connectivity.data() + s.offsets[c];
    std::array<Index, 4> key;
    for (int k = 0; k < 4; ++k)
      key[k] = local[k] < 0 ? Index(-1) : v[local[k]];
    std::sort(key.begin(), key.end());
    return key;
  }

  // The face of a cell of type t through which the parametric point xi (outside the reference
  // cell) leaves it the most: the face whose defining inequality xi violates by the largest
  // amount, or -1 if it violates none.
  static int exit_face(unsigned char t, const double* xi)
  {
    const double r = xi[0], s = xi[1], u = xi[2];
    double violation[6];
    int n = 0;
    switch (t) {
    case TETRA:
      n = 4, violation[0] = -s, violation[1] = r + s + u - 1., violation[2] = -r, violation[3] = -u;
      break;
    case HEXAHEDRON:
      n = 6, violation[0] = -r, violation[1] = r - 1., violation[2] = -s, violation[3] = s - 1.,
      violation[4] = -u, violation[5] = u - 1.;
      break;
    case WEDGE:
      n = 5, violation[0] = -u, violation[1] = u - 1., violation[2] = -s, violation[3] = r + s - 1.,
      violation[4] = -r;
      break;
    default: // PYRAMID; above the apex (t > 1) there is no face
      n = 5, violation[0] = -u, violation[1] = -s, violation[2] = r - 1., violation[3] = s - 1.,
      violation[4] = -r;
    }
    int best = -1;
    double largest = inside_tolerance;
    for (int f = 0; f < n; ++f)
      if (violation[f] > largest) // false for NaN
        largest = violation[f], best = f;
    return best;
  }

  [[noreturn]] static void fail(const std::string& what)
  {
    throw std::invalid_argument("Unstructured_flow_field_3: " + what);
  }

  static constexpr std::size_t max_entries = std::size_t((std::numeric_limits<Index>::max)());

  static std::vector<Index> narrow(const std::vector<std::int64_t>& a, const char* name)
  {
    std::ostringstream msg;
    if (a.size() > max_entries) {
      msg << name << ".size() is " << a.size() << "; at most " << max_entries << " entries are supported";
      fail(msg.str());
    }
    std::vector<Index> r(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i] < (std::numeric_limits<Index>::min)() || a[i] > (std::numeric_limits<Index>::max)()) {
        msg << name << "[" << i << "] is " << a[i] << "; expected a value below 2^31 (32-bit indices)";
        fail(msg.str());
      }
      r[i] = static_cast<Index>(a[i]);
    }
    return r;
  }

  template <typename Real>
  static void validate_and_store(Storage& s, std::vector<Real> points, std::vector<Index> connectivity,
                                 std::vector<Index> offsets, std::vector<unsigned char> cell_types,
                                 std::vector<float> vectors)
  {
    std::ostringstream msg;
    if (points.size() % 3 != 0) {
      msg << "points.size() is " << points.size() << "; expected a multiple of 3 (x, y, z per point)";
      fail(msg.str());
    }
    const std::size_t np = points.size() / 3;
    if (np > max_entries) {
      msg << "there are " << np << " points; at most " << max_entries << " are supported (32-bit indices)";
      fail(msg.str());
    }
    if (connectivity.size() > max_entries) {
      msg << "connectivity.size() is " << connectivity.size() << "; at most " << max_entries
          << " entries are supported (32-bit offsets)";
      fail(msg.str());
    }
    if (vectors.size() != points.size()) {
      msg << "vectors.size() is " << vectors.size() << " but there are " << np << " points; expected "
          << points.size() << " (x, y, z per point)";
      fail(msg.str());
    }
    const std::size_t nc = cell_types.size();
    if (nc == 0)
      fail("cell_types is empty; expected at least one cell");
    if (offsets.size() == nc) {
      offsets.insert(offsets.begin(), Index(0)); // .vtu form: the ends of the cells
    }
    else if (offsets.size() != nc + 1) {
      msg << "offsets.size() is " << offsets.size() << " but cell_types.size() is " << nc << "; expected "
          << nc + 1 << " (starts and the end) or " << nc << " (ends)";
      fail(msg.str());
    }
    else if (offsets[0] != 0) {
      msg << "offsets[0] is " << offsets[0] << "; expected 0";
      fail(msg.str());
    }
    if (offsets.back() != static_cast<Index>(connectivity.size())) {
      msg << "the last offset is " << offsets.back() << " but connectivity.size() is " << connectivity.size()
          << "; expected them equal";
      fail(msg.str());
    }
    for (std::size_t c = 0; c < nc; ++c) {
      const int n = points_of(cell_types[c]);
      if (n == 0) {
        msg << "cell_types[" << c << "] is " << int(cell_types[c])
            << "; expected 10 (tetrahedron), 12 (hexahedron), 13 (wedge) or 14 (pyramid)";
        fail(msg.str());
      }
      if (std::int64_t(offsets[c + 1]) - std::int64_t(offsets[c]) != n) {
        msg << "cell " << c << " (a " << type_name(cell_types[c]) << ") has offsets[" << c
            << "] = " << offsets[c] << " and offsets[" << c + 1 << "] = " << offsets[c + 1] << ", so "
            << std::int64_t(offsets[c + 1]) - std::int64_t(offsets[c]) << " points; expected " << n;
        fail(msg.str());
      }
    }
    for (std::size_t i = 0; i < connectivity.size(); ++i) {
      if (connectivity[i] < 0 || static_cast<std::size_t>(connectivity[i]) >= np) {
        msg << "connectivity[" << i << "] is " << connectivity[i] << "; expected a point index in [0, " << np
            << ")";
        fail(msg.str());
      }
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!std::isfinite(points[i])) {
        msg << "points[" << i << "] (coordinate " << i % 3 << " of point " << i / 3 << ") is " << points[i]
            << "; expected a finite number";
        fail(msg.str());
      }
    }
    for (std::size_t i = 0; i < vectors.size(); ++i) {
      if (!std::isfinite(vectors[i])) {
        msg << "vectors[" << i << "] (component " << i % 3 << " at point " << i / 3 << ") is " << vectors[i]
            << "; expected a finite number";
        fail(msg.str());
      }
    }
    store_points(s, std::move(points));
    s.vectors = std::move(vectors);
    s.connectivity = std::move(connectivity);
    s.offsets = std::move(offsets);
    s.cell_types = std::move(cell_types);
  }

  static void store_points(Storage& s, std::vector<float> points) { s.float_points = std::move(points); }
  static void store_points(Storage& s, std::vector<double> points)
  {
    if (points.empty())
      return; // no point (so no cell either: refused before)
    s.double_points = std::move(points);
  }

  // The points of cell c as doubles, X[i] = point i of the cell; returns their number.  The
  // precision of the storage is chosen once per cell visit.
  template <typename T>
  static void gather(const std::vector<T>& points, const Index* v, int n, double (*X)[3])
  {
    for (int i = 0; i < n; ++i) {
      const T* x = points.data() + 3 * static_cast<std::size_t>(v[i]);
      X[i][0] = static_cast<double>(x[0]);
      X[i][1] = static_cast<double>(x[1]);
      X[i][2] = static_cast<double>(x[2]);
    }
  }

  static int gather(const Storage& s, std::size_t c, double (*X)[3])
  {
    const int n = points_of(s.cell_types[c]);
    const Index* v = s.connectivity.data() + s.offsets[c];
    if (s.double_points.empty())
      gather(s.float_points, v, n, X);
    else
      gather(s.double_points, v, n, X);
    return n;
  }

  // The bounding box of the n points X, enlarged by the inside tolerance (relative to the cell
  // size), so that the box never rejects a point the exact test accepts.
  static void points_box(const double (*X)[3], int n, double* b)
  {
    for (int a = 0; a < 3; ++a) {
      double lo = X[0][a], hi = X[0][a];
      for (int i = 1; i < n; ++i) {
        lo = (std::min)(lo, X[i][a]);
        hi = (std::max)(hi, X[i][a]);
      }
      const double pad = 1e-8 * (hi - lo) + 1e-300;
      b[a] = lo - pad;
      b[a + 3] = hi + pad;
    }
  }

  static void cell_box(const Storage& s, std::size_t c, double* b)
  {
    double X[8][3];
    points_box(X, gather(s, c, X), b);
  }

  static bool in_box(const double* b, const double* x)
  {
    return x[0] >= b[0] && x[0] <= b[3] && x[1] >= b[1] && x[1] <= b[4] && x[2] >= b[2] && x[2] <= b[5];
  }

  static bool in_node_box(const Storage& s, std::size_t node, const double* x)
  {
    const float* b = s.node_box.data() + 6 * node;
    return x[0] >= b[0] && x[0] <= b[3] && x[1] >= b[1] && x[1] <= b[4] && x[2] >= b[2] && x[2] <= b[5];
  }

  // Tree node of leaf l (left to right), and back; the cells of a leaf (positions in order).
  static std::size_t leaf_node(const Storage& s, std::size_t l)
  {
    const std::size_t deepest = 2 * s.leaves - 1 - s.first_deepest;
    return l < deepest ? s.first_deepest + l : s.leaves - 1 + (l - deepest);
  }
  static std::size_t leaf_rank(const Storage& s, std::size_t node)
  {
    const std::size_t deepest = 2 * s.leaves - 1 - s.first_deepest;
    return node >= s.first_deepest ? node - s.first_deepest : deepest + (node - (s.leaves - 1));
  }
  static std::size_t leaf_begin(const Storage& s, std::size_t node) { return leaf_size * leaf_rank(s, node); }
  static std::size_t leaf_end(const Storage& s, std::size_t node)
  {
    return (std::min)(leaf_begin(s, node) + leaf_size, s.order.size());
  }

  static std::size_t leftmost_leaf(const Storage& s, std::size_t node)
  {
    while (node < s.leaves - 1)
      node = 2 * node + 1;
    return node;
  }
  static std::size_t rightmost_leaf(const Storage& s, std::size_t node)
  {
    while (node < s.leaves - 1)
      node = 2 * node + 2;
    return node;
  }

  static void build_hierarchy(Storage& s)
  {
    const std::size_t nc = s.cell_types.size();
    const double inf = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      s.bbox[a] = inf;
      s.bbox[a + 3] = -inf;
    }
    const Point_coordinates x(float_points(s), &s.double_points);
    for (std::size_t i = 0; i < x.size(); ++i) {
      s.bbox[i % 3] = (std::min)(s.bbox[i % 3], x[i]);
      s.bbox[i % 3 + 3] = (std::max)(s.bbox[i % 3 + 3], x[i]);
    }
    // The cells' box centres, then the tree top down: each node's cells split at the median
    // of the longest axis of their centres, the left part holding as many leaves as the left
    // subtree of the complete tree has (a kd-tree of boxes in the implicit layout).
    std::vector<float> centre(3 * nc);
    for (std::size_t c = 0; c < nc; ++c) {
      double b[6];
      cell_box(s, c, b);
      for (int a = 0; a < 3; ++a)
        centre[3 * c + a] = static_cast<float>(0.5 * (b[a] + b[a + 3]));
    }
    s.order.resize(nc);
    for (std::size_t c = 0; c < nc; ++c)
      s.order[c] = static_cast<Index>(c);
    s.leaves = (nc + leaf_size - 1) / leaf_size;
    const std::size_t nodes = 2 * s.leaves - 1;
    s.first_deepest = 0;
    while (2 * s.first_deepest + 1 < nodes)
      s.first_deepest = 2 * s.first_deepest + 1;
    std::vector<std::size_t> todo(1, 0);
    while (!todo.empty()) {
      const std::size_t node = todo.back();
      todo.pop_back();
      if (node >= s.leaves - 1)
        continue;
      const std::size_t first = leaf_size * leaf_rank(s, leftmost_leaf(s, node));
      const std::size_t middle = leaf_size * leaf_rank(s, leftmost_leaf(s, 2 * node + 2));
      const std::size_t last = (std::min)(leaf_size * (leaf_rank(s, rightmost_leaf(s, node)) + 1), nc);
      float lo[3], hi[3];
      for (int a = 0; a < 3; ++a)
        lo[a] = hi[a] = centre[3 * std::size_t(s.order[first]) + a];
      for (std::size_t k = first; k < last; ++k)
        for (int a = 0; a < 3; ++a) {
          lo[a] = (std::min)(lo[a], centre[3 * std::size_t(s.order[k]) + a]);
          hi[a] = (std::max)(hi[a], centre[3 * std::size_t(s.order[k]) + a]);
        }
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (hi[a] - lo[a] > hi[axis] - lo[axis])
          axis = a;
      std::nth_element(s.order.begin() + std::ptrdiff_t(first), s.order.begin() + std::ptrdiff_t(middle),
                       s.order.begin() + std::ptrdiff_t(last), [&](Index u, Index v) {
                         return centre[3 * std::size_t(u) + axis] < centre[3 * std::size_t(v) + axis];
                       });
      todo.push_back(2 * node + 1);
      todo.push_back(2 * node + 2);
    }
    centre = std::vector<float>();
    s.node_box.assign(6 * nodes, 0.f);
    const float finf = std::numeric_limits<float>::infinity();
    for (std::size_t node = s.leaves - 1; node < nodes; ++node) {
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
    }
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
  static bool search(const Storage& s, std::size_t root, const double* x, const Accept& accept)
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
  static bool search_from(const Storage& s, std::size_t start, const double* x, const Accept& accept)
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
  static bool find_neighbour(const Storage& s, std::size_t c, int f, const double (*X)[3], std::size_t start,
                             std::size_t& d, std::size_t& leaf)
  {
    const std::array<int, 4>& local = face_points(s.cell_types[c], f);
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
      const int n = points_of(s.cell_types[e]);
      for (int k = 0; k < m; ++k)
        if (std::find(w, w + n, P[k]) == w + n)
          return false;
      d = e;
      leaf = node;
      return true;
    });
  }

  // Shape functions N and their derivatives dN/d(r, s, t) at xi, in VTK's conventions.
  static int shape(unsigned char type, const double* xi, double* N, double (*dN)[3])
  {
    const double r = xi[0], s = xi[1], t = xi[2];
    switch (type) {
    case TETRA: {
      const double n[4] = {1. - r - s - t, r, s, t};
      const double d[4][3] = {{-1., -1., -1.}, {1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}};
      for (int i = 0; i < 4; ++i) {
        N[i] = n[i];
        for (int a = 0; a < 3; ++a)
          dN[i][a] = d[i][a];
      }
      return 4;
    }
    case HEXAHEDRON: {
      // Corner i has parameters (r_i, s_i, t_i) with VTK's ordering.
      static const int rc[8] = {0, 1, 1, 0, 0, 1, 1, 0}, sc[8] = {0, 0, 1, 1, 0, 0, 1, 1},
                       tc[8] = {0, 0, 0, 0, 1, 1, 1, 1};
      for (int i = 0; i < 8; ++i) {
        const double fr = rc[i] ? r : 1. - r, fs = sc[i] ? s : 1. - s, ft = tc[i] ? t : 1. - t;
        const double gr = rc[i] ? 1. : -1., gs = sc[i] ? 1. : -1., gt = tc[i] ? 1. : -1.;
        N[i] = fr * fs * ft;
        dN[i][0] = gr * fs * ft;
        dN[i][1] = fr * gs * ft;
        dN[i][2] = fr * fs * gt;
      }
      return 8;
    }
    case WEDGE: {
      const double l[3] = {1. - r - s, r, s};
      const double dl[3][2] = {{-1., -1.}, {1., 0.}, {0., 1.}};
      for (int i = 0; i < 3; ++i) {
        N[i] = l[i] * (1. - t);
        N[i + 3] = l[i] * t;
        dN[i][0] = dl[i][0] * (1. - t);
        dN[i][1] = dl[i][1] * (1. - t);
        dN[i][2] = -l[i];
        dN[i + 3][0] = dl[i][0] * t;
        dN[i + 3][1] = dl[i][1] * t;
        dN[i + 3][2] = l[i];
      }
      return 6;
    }
    default: { // PYRAMID, VTK's vtkPyramid::InterpolationFunctions
      const double rm = 1. - r, sm = 1. - s, tm = 1. - t;
      N[0] = rm * sm * tm;
      N[1] = r * sm * tm;
      N[2] = r * s * tm;
      N[3] = rm * s * tm;
      N[4] = t;
      const double d[5][3] = {{-sm * tm, -rm * tm, -rm * sm},
                              {sm * tm, -r * tm, -r * sm},
                              {s * tm, r * tm, -r * s},
                              {-s * tm, rm * tm, -rm * s},
                              {0., 0., 1.}};
      for (int i = 0; i < 5; ++i)
        for (int a = 0; a < 3; ++a)
          dN[i][a] = d[i][a];
      return 5;
    }
    }
  }

  static bool in_reference_cell(unsigned char type, const double* xi)
  {
    const double e = inside_tolerance;
    const double r = xi[0], s = xi[1], t = xi[2];
    const bool t_ok = t >= -e && t <= 1. + e;
    switch (type) {
    case TETRA:
      return r >= -e && s >= -e && t >= -e && r + s + t <= 1. + e;
    case WEDGE:
      return r >= -e && s >= -e && r + s <= 1. + e && t_ok;
    default:
      return r >= -e && r <= 1. + e && s >= -e && s <= 1. + e && t_ok;
    }
  }

  // Inverts the map x(xi) = p of the cell of type `type` with points X by Newton's method from
  // `start` (in the reference cell) or else from the cell's parametric center.  Returns whether
  // it converged and xi is in the reference cell, with the shape function values and xi in hit;
  // else, if `estimate` is not null, stores there the last iterate (exact where the iteration
  // converged outside the reference cell, NaN or huge where it diverged), for the walk.
  static bool invert(unsigned char type, const double (*X)[3], int n, const double* p, Hit& hit,
                     const double* start = nullptr, double* estimate = nullptr)
  {
    double size = 0.;
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        size = (std::max)(size, std::abs(X[i][a] - X[0][a]));
    double xi[3];
    switch (type) {
    case TETRA:
      xi[0] = xi[1] = xi[2] = 0.25;
      break;
    case WEDGE:
      xi[0] = xi[1] = 1. / 3.;
      xi[2] = 0.5;
      break;
    case PYRAMID:
      xi[0] = xi[1] = 0.5;
      xi[2] = 0.25;
      break;
    default:
      xi[0] = xi[1] = xi[2] = 0.5;
    }
    if (start != nullptr && type != TETRA) // linear maps need no start
      for (int a = 0; a < 3; ++a)
        xi[a] = start[a];
    auto reject = [&] {
      if (estimate != nullptr)
        for (int a = 0; a < 3; ++a)
          estimate[a] = xi[a];
      return false;
    };
    double N[8], dN[8][3];
    // Linear cells converge in one step; the trilinear map in a few for reasonable cells.  The
    // cap bounds the cost of points that are far outside a cell (in its bounding box only).
    const int max_iterations = type == TETRA ? 1 : 12;
    bool converged = false;
    for (int it = 0; it < max_iterations; ++it) {
      shape(type, xi, N, dN);
      double res[3] = {p[0], p[1], p[2]};
      double J[3][3] = {{0., 0., 0.}, {0., 0., 0.}, {0., 0., 0.}};
      for (int i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
          res[a] -= N[i] * X[i][a];
          for (int b = 0; b < 3; ++b)
            J[a][b] += X[i][a] * dN[i][b];
        }
      const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
      if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
        break;
      // Cramer's rule for J d = res.
      double d[3];
      for (int b = 0; b < 3; ++b) {
        double M[3][3];
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 3; ++c)
            M[a][c] = c == b ? res[a] : J[a][c];
        d[b] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
               det;
      }
      double step = 0.;
      for (int a = 0; a < 3; ++a) {
        xi[a] += d[a];
        step = (std::max)(step, std::abs(d[a]));
      }
      if (!(step < 1e3)) // diverging: far outside the cell
        break;
      // Newton's error after a step of size h is about C h^2 (C: the map's second derivatives
      // over its first, O(1) in parametric units for usable cells), so after a step below 1e-8
      // xi is as accurate as rounding allows, without one more step to see it.  A
      // tetrahedron's map is affine: one step solves it.
      if (step < 1e-8 || type == TETRA) {
        converged = true;
        break;
      }
      if (it >= 3) {
        // Far from the reference cell after a few steps: p is not in this cell.
        bool far = false;
        for (int a = 0; a < 3; ++a)
          far = far || xi[a] < -0.5 || xi[a] > 1.5;
        if (far)
          return reject();
      }
    }
    if (!converged) {
      // Accept when the residual is at rounding level (the step criterion can miss it near
      // the pyramid's apex, where the map is singular).
      shape(type, xi, N, dN);
      double err = 0.;
      for (int a = 0; a < 3; ++a) {
        double x = 0.;
        for (int i = 0; i < n; ++i)
          x += N[i] * X[i][a];
        err = (std::max)(err, std::abs(x - p[a]));
      }
      if (!(err <= 1e-12 * size))
        return reject();
    }
    if (type == PYRAMID && xi[2] >= 1. - 1e-8) {
      // At the apex r and s are undetermined and irrelevant.
      xi[0] = (std::min)((std::max)(xi[0], 0.), 1.);
      xi[1] = (std::min)((std::max)(xi[1], 0.), 1.);
    }
    if (!in_reference_cell(type, xi))
      return reject();
    hit.n = shape(type, xi, hit.N, dN);
    for (int a = 0; a < 3; ++a)
      hit.xi[a] = xi[a];
    return true;
  }

  // Whether cell c contains x (its box first), with the hit.
  static bool try_cell(const Storage& s, std::size_t c, const double* x, Hit& hit,
                       const double* start = nullptr)
  {
    double X[8][3], b[6];
    const int n = gather(s, c, X);
    points_box(X, n, b);
    if (!in_box(b, x) || !invert(s.cell_types[c], X, n, x, hit, start))
      return false;
    hit.cell = c;
    return true;
  }

  Vector_3 interpolate(const Hit& hit) const
  {
    double r[3] = {0., 0., 0.};
    const Storage& s = *m_storage;
    const Index* c = s.connectivity.data() + s.offsets[hit.cell];
    for (int i = 0; i < hit.n; ++i) {
      const float* v = s.vectors.data() + 3 * static_cast<std::size_t>(c[i]);
      for (int d = 0; d < 3; ++d)
        r[d] += hit.N[i] * static_cast<double>(v[d]);
    }
    return Vector_3(FT(r[0]), FT(r[1]), FT(r[2]));
  }

  // The walk from the hint's cell: invert the cell's map at x; if x is outside, cross the face
  // through which the parametric point leaves the cell (`exit_face()`) into the neighbour
  // sharing it (from the thread's cache, else found in the hierarchy and cached), and again,
  // for at most `max_walk_steps` cells.  Gives up (false) at the boundary, on a cell whose map
  // diverges, or when x is not in the box of the hint leaf's grandparent (about 32 cells).
  static bool walk(const Storage& s, const double* x, Hit& hit, Walk_cache& w)
  {
    std::size_t c = w.cell, leaf = w.leaf, near = leaf;
    for (int up = 0; up < 2 && near != 0; ++up)
      near = (near - 1) / 2;
    if (!in_node_box(s, near, x))
      return false;
    const double* start = w.xi;
    for (int step = 0;; ++step) {
      double X[8][3], xi[3], b[6];
      const int n = gather(s, c, X);
      if (invert(s.cell_types[c], X, n, x, hit, start, xi)) {
        points_box(X, n, b);
        if (!in_box(b, x)) // as try_cell(): points outside the cell's box are not in it
          return false;
        hit.cell = c;
        hit.leaf = leaf;
        return true;
      }
      const int f = exit_face(s.cell_types[c], xi);
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
      start = nullptr;
    }
  }

  bool find(const double* x, Hit& hit) const
  {
    const Storage& s = *m_storage;
    // Written so that NaN coordinates fail too.
    if (!(x[0] >= s.bbox[0] && x[0] <= s.bbox[3] && x[1] >= s.bbox[1] && x[1] <= s.bbox[4] &&
          x[2] >= s.bbox[2] && x[2] <= s.bbox[5]))
      return false;
    static thread_local Walk_cache w;
    if (w.owner != s.id)
      w.reset(s.id);
    const auto try_any = [&](std::size_t c, std::size_t node) {
      if (!try_cell(s, c, x, hit))
        return false;
      hit.leaf = node;
      return true;
    };
    // The walk, else the hierarchy, nearest to the hint first.
    const bool found =
        w.has_hint ? walk(s, x, hit, w) || search_from(s, w.leaf, x, try_any) : search(s, 0, x, try_any);
    if (found) {
      w.has_hint = true;
      w.cell = hit.cell;
      w.leaf = hit.leaf;
      for (int a = 0; a < 3; ++a)
        w.xi[a] = hit.xi[a];
    }
    return found;
  }

  std::shared_ptr<const Storage> m_storage;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_UNSTRUCTURED_FLOW_FIELD_3_H
