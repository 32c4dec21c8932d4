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

#include <CGAL/Flow_aligned_surfaces/internal/Cell_point_location.h>
#include <CGAL/Flow_aligned_surfaces/internal/cell_shape_functions.h>

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
/// the cells at the median of their bounding boxes' centres along the longest axis (by the
/// constructor, with TBB on the threads of the caller's arena: the same tree).  The walk
/// inverts the hint cell's map at `p` (Newton's method from the cell's parametric centre; a
/// hexahedron's steps from the eight coefficients of its trilinear map as a polynomial; one
/// step where the map is affine: a tetrahedron, and a hexahedron whose bilinear and trilinear
/// coefficients are at rounding level, a parallelepiped, as most cells of a block-structured
/// mesh are);
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
/// per-thread cache of 1024 cells (direct-mapped by cell index, 53 KB, each face's neighbour
/// looked for on the first crossing).  The hint and the cache are `thread_local`, keyed by a
/// number that identifies the field's shared storage (never reused within the process), and a
/// thread keeps them for the last 4 fields it queried (212 KB per thread): `operator()` is
/// `const` and safe to call from several threads at once (a TBB loop, for instance), a copy
/// shares the cache key of its original, and a thread alternating between the fields of two
/// time steps (as `Unsteady_flow_field_3` does at a time between them) walks in each from its
/// own hint; a fifth field takes over the oldest of the four.  Whatever the hint and the cache say
/// is checked before it is used (the cell must contain `p`, a neighbour must hold the face's
/// points), so a stale entry costs time, never a wrong answer.  Nor a different one: the
/// answer at `p` does not depend on the queries before it.  Where several cells contain `p`
/// (within `1e-9` of a shared face in parametric coordinates) the cell of smallest index gives
/// the value, and a cell's map is always inverted from its parametric centre (Newton's last
/// bits depend on where it starts), so the same point gets the same sample, bit for bit, from
/// any thread, in any order, in any process.
///
/// Memory: the arrays as given (points in the precision given, 32-bit indices), plus 4 bytes
/// per cell for the cells' order in the leaves and 2 float boxes (48 bytes) per leaf, about 10
/// bytes per cell in all; and per thread that queries the field, its 53 KB cache.  Copies share
/// the arrays and the hierarchy (through `std::shared_ptr`), so copying a field is cheap.  A
/// query performs no allocation.
///
/// \tparam GeomTraits a model of `Kernel`; the coordinates are converted to `double` with
///         `CGAL::to_double()`.
///
/// \cgalModels `FlowField_3`
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

  /// creates an empty field: no point, no cell, `std::nullopt` everywhere, `bbox()` the empty
  /// `Bbox_3()`.  It is what a reader such as `IO::read_VTK_flow_field()` fills.
  Unstructured_flow_field_3() : m_storage(std::make_shared<const Storage>()) {}

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
    s->cells.build();
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
    Hit hit;
    if (!find(p, hit))
      return std::nullopt;
    return interpolate(hit);
  }

  /// returns the index of a cell containing `p`, or `std::nullopt` if there is none.  Where
  /// several cells contain `p` (on shared faces), the one of smallest index.
  std::optional<std::size_t> locate(const Point_3& p) const
  {
    Hit hit;
    if (!find(p, hit))
      return std::nullopt;
    return hit.cell;
  }

  /// returns whether `p` lies in the interior of a cell, farther than `1e-9` inside its
  /// reference cell (ten times the inside test's tolerance): then no other cell of a conforming
  /// mesh contains `p`, nor does a cell of another piece of a conforming partition of the mesh
  /// (the pieces of a mesh distributed over processes), so that the value at `p` is this cell's.
  /// False on and near the cells' faces and outside the mesh.
  bool is_in_cell_interior(const Point_3& p) const
  {
    Hit hit;
    return find(p, hit) &&
           internal::in_reference_cell(cell_types()[hit.cell], hit.xi, -internal::cell_interior_margin);
  }

  /// returns the velocity at `p` interpolated in cell `cell`, or `std::nullopt` if that cell
  /// does not contain `p`.  On a face shared by two cells, both give the same value up to
  /// rounding (for conforming faces).
  /// \pre `cell < number_of_cells()`
  std::optional<Vector_3> evaluate_in_cell(std::size_t cell, const Point_3& p) const
  {
    CGAL_precondition(cell < number_of_cells());
    Hit hit;
    if (!internal::Cell_point_location::try_cell(m_storage->cells, cell, coordinates(p).data(), hit))
      return std::nullopt;
    return interpolate(hit);
  }

  /// @}

  /// \name Access
  /// @{

  /// the number of points
  std::size_t number_of_points() const { return m_storage->vectors.size() / 3; }
  /// the number of cells
  std::size_t number_of_cells() const { return m_storage->cells.cell_types.size(); }
  /// the bounding box of the points
  Bbox_3 bbox() const
  {
    const double* b = m_storage->cells.bbox;
    return Bbox_3(b[0], b[1], b[2], b[3], b[4], b[5]);
  }
  /// the point coordinates, `x, y, z` per point, in the precision given to the constructor
  Point_coordinates points() const
  {
    return Point_coordinates(m_storage->cells.float_points_or_null(), &m_storage->cells.double_points);
  }
  /// the velocities, `x, y, z` per point
  const std::vector<float>& vectors() const { return m_storage->vectors; }
  /// the point indices of all cells, cell after cell
  const std::vector<Index>& connectivity() const { return m_storage->cells.connectivity; }
  /// the `number_of_cells() + 1` positions in `connectivity()` where the cells start, the last
  /// one being `connectivity().size()` (whichever form was given to the constructor)
  const std::vector<Index>& offsets() const { return m_storage->cells.offsets; }
  /// the VTK cell types
  const std::vector<unsigned char>& cell_types() const { return m_storage->cells.cell_types; }
  /// the cells sharing a face with cell `cell` (conforming faces with exactly the same points),
  /// in the order of the cell's faces; computed on each call (from the hierarchy, as the walk
  /// does, but without its cache).
  /// \pre `cell < number_of_cells()`
  std::vector<std::size_t> face_neighbours(std::size_t cell) const
  {
    CGAL_precondition(cell < number_of_cells());
    return m_storage->cells.face_neighbours(cell);
  }

  /// @}

private:
  typedef internal::Cell_point_location::Hit Hit;

  static std::array<double, 3> coordinates(const Point_3& p)
  {
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

  // Whether a cell contains p, with the hit (Cell_point_location::find()).
  bool find(const Point_3& p, Hit& hit) const { return m_storage->cells.find(coordinates(p).data(), hit); }

  // The mesh and its point location, and the velocities at the points.
  struct Storage {
    internal::Cell_point_location cells;
    std::vector<float> vectors;
  };

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
      const int n = internal::number_of_cell_points(cell_types[c]);
      if (n == 0) {
        msg << "cell_types[" << c << "] is " << int(cell_types[c])
            << "; expected 10 (tetrahedron), 12 (hexahedron), 13 (wedge) or 14 (pyramid)";
        fail(msg.str());
      }
      if (std::int64_t(offsets[c + 1]) - std::int64_t(offsets[c]) != n) {
        msg << "cell " << c << " (a " << internal::cell_type_name(cell_types[c]) << ") has offsets[" << c
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
    s.cells.connectivity = std::move(connectivity);
    s.cells.offsets = std::move(offsets);
    s.cells.cell_types = std::move(cell_types);
  }

  static void store_points(Storage& s, std::vector<float> points)
  {
    s.cells.float_points = std::move(points);
  }
  static void store_points(Storage& s, std::vector<double> points)
  {
    if (points.empty())
      return; // no point (so no cell either: refused before)
    s.cells.double_points = std::move(points);
  }

  Vector_3 interpolate(const Hit& hit) const
  {
    double r[3] = {0., 0., 0.};
    const Storage& s = *m_storage;
    const Index* c = s.cells.connectivity.data() + s.cells.offsets[hit.cell];
    for (int i = 0; i < hit.n; ++i) {
      const float* v = s.vectors.data() + 3 * static_cast<std::size_t>(c[i]);
      for (int d = 0; d < 3; ++d)
        r[d] += hit.N[i] * static_cast<double>(v[d]);
    }
    return Vector_3(FT(r[0]), FT(r[1]), FT(r[2]));
  }

  std::shared_ptr<const Storage> m_storage;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_UNSTRUCTURED_FLOW_FIELD_3_H
