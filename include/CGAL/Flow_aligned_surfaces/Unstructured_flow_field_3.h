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
/// A point is located in two steps: first a walk from the cell that answered the previous
/// query of the same thread on the same field (the hint), each step crossing the face through
/// which the cell's inverted map says the point lies outside, then the hint's face neighbours,
/// then the cells whose bounding boxes cover the point's bucket in a uniform grid of buckets
/// over the mesh.  A cell
/// contains `p` when the Newton inversion of its isoparametric map converges and the parametric
/// coordinates lie in the reference cell up to `1e-10` (so that points on shared faces and on
/// the mesh boundary are inside; points outside the bounding box of the points never are).
/// On a face shared by two conforming cells (the same points) both give the same value, up to
/// rounding; a quadrilateral face against two triangles is not conforming.  Degenerate cells
/// (zero volume) contain no point.
///
/// The hint is kept in a `thread_local` cache, one entry per thread, keyed by the field's
/// shared storage: `operator()` is `const` and safe to call from several threads at once, a
/// copy shares the hint of its original, and a thread alternating between two fields only
/// loses the hint.  A stale hint costs one rejected candidate, never a wrong answer.
///
/// Copies share the arrays and the acceleration structures (through `std::shared_ptr`), so
/// copying a field is cheap.  A query performs no allocation.
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
  /// The type of point indices in `connectivity` and of positions in `offsets` (VTK's `vtkIdType`).
  typedef std::int64_t Index;

  /// The supported VTK cell types.
  enum Cell_type : unsigned char {
    TETRA = 10,      ///< VTK_TETRA, 4 points
    HEXAHEDRON = 12, ///< VTK_HEXAHEDRON, 8 points
    WEDGE = 13,      ///< VTK_WEDGE, 6 points
    PYRAMID = 14     ///< VTK_PYRAMID, 5 points
  };
  /// @}

  /// \name Creation
  /// @{

  /// creates the field from the arrays of a VTK unstructured grid.
  ///
  /// \tparam Real `float` or `double`
  ///
  /// \param points the coordinates, `x, y, z` per point
  /// \param connectivity the point indices of all cells, cell after cell
  /// \param offsets where each cell starts in `connectivity`: either `number_of_cells + 1`
  ///        entries starting with `0` and ending with `connectivity.size()` (VTK's
  ///        `vtkCellArray` and legacy `OFFSETS`), or `number_of_cells` entries giving where
  ///        each cell ends (the `offsets` array of `.vtu` files)
  /// \param cell_types one VTK cell type per cell, each one of `Cell_type`
  ///
  /// `connectivity`, `offsets`, `cell_types` and `vectors` are kept as given (moved into
  /// the shared storage): pass them with `std::move()` to avoid copies.  `points` is converted
  /// to `double`.
  /// \param vectors the velocities, `x, y, z` per point; pass it with `std::move()` to avoid
  ///        a copy
  ///
  /// \throws std::invalid_argument naming the faulty argument and index, with the expected and
  ///         actual values, if there is no cell, a size is wrong, an offset decreases, a cell
  ///         has the wrong number of points for its type, a point index is out of range, a cell
  ///         type is not supported, or a coordinate or velocity is not finite.
  template <typename Real>
  Unstructured_flow_field_3(const std::vector<Real>& points, std::vector<Index> connectivity,
                            std::vector<Index> offsets, std::vector<unsigned char> cell_types,
                            std::vector<float> vectors)
  {
    static_assert(std::is_floating_point<Real>::value, "points must hold float or double coordinates");
    auto s = std::make_shared<Storage>();
    validate_and_store(*s, points, std::move(connectivity), std::move(offsets), std::move(cell_types),
                       std::move(vectors));
    build_bounding_boxes(*s);
    build_buckets(*s);
    build_neighbours(*s);
    storage_ = std::move(s);
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
    if (!try_cell(cell, x, hit))
      return std::nullopt;
    return interpolate(hit);
  }

  /// @}

  /// \name Access
  /// @{

  /// the number of points
  std::size_t number_of_points() const { return storage_->points.size() / 3; }
  /// the number of cells
  std::size_t number_of_cells() const { return storage_->cell_types.size(); }
  /// the bounding box of the points
  Bbox_3 bbox() const
  {
    const double* b = storage_->bbox;
    return Bbox_3(b[0], b[1], b[2], b[3], b[4], b[5]);
  }
  /// the point coordinates, `x, y, z` per point, converted to `double`
  const std::vector<double>& points() const { return storage_->points; }
  /// the velocities, `x, y, z` per point
  const std::vector<float>& vectors() const { return storage_->vectors; }
  /// the point indices of all cells, cell after cell
  const std::vector<Index>& connectivity() const { return storage_->connectivity; }
  /// the `number_of_cells() + 1` positions in `connectivity()` where the cells start, the last
  /// one being `connectivity().size()` (whichever form was given to the constructor)
  const std::vector<Index>& offsets() const { return storage_->offsets; }
  /// the VTK cell types
  const std::vector<unsigned char>& cell_types() const { return storage_->cell_types; }
  /// the cells sharing a face with cell `cell` (conforming faces with exactly the same points)
  /// \pre `cell < number_of_cells()`
  std::vector<std::size_t> face_neighbours(std::size_t cell) const
  {
    CGAL_precondition(cell < number_of_cells());
    std::vector<std::size_t> r;
    const std::uint32_t* n = storage_->neighbour.data() + storage_->face_stride * cell;
    for (std::size_t f = 0; f < storage_->face_stride; ++f)
      if (n[f] != no_cell)
        r.push_back(n[f]);
    return r;
  }

  /// @}

private:
  // The neighbour across a boundary face; cell indices are below it (checked on creation).
  static constexpr std::uint32_t no_cell = (std::numeric_limits<std::uint32_t>::max)();
  // Parametric tolerance of the inside test: dimensionless, far above the rounding of a Newton
  // solution (~1e-15 for well-shaped cells) so that a point on a shared face is inside both
  // cells, and far below any distance that matters for sampling a flow.
  static constexpr double inside_tolerance = 1e-10;
  // The longest walk from the hint before the bucket grid is asked; coherent queries move by a
  // fraction of a cell, so they need one or two steps.
  static constexpr int max_walk_steps = 8;

  struct Storage {
    std::vector<double> points;
    std::vector<float> vectors;
    std::vector<Index> connectivity, offsets;
    std::vector<unsigned char> cell_types;
    // Per cell: xmin, ymin, zmin, xmax, ymax, zmax, rounded outwards to float.
    std::vector<float> cell_bbox;
    double bbox[6];
    // Bucket grid: cell lists per bucket in CSR form.
    double bucket_lo[3], bucket_inv_h[3];
    std::size_t bucket_n[3];
    std::vector<std::uint32_t> bucket_begin, bucket_cells;
    // Per cell face, the cell across it (or no_cell): face f of cell c (in the numbering of
    // faces_of()) at neighbour[face_stride * c + f]; face_stride is the largest number of faces
    // of the mesh's cell types (unused slots are no_cell).
    std::size_t face_stride = 0;
    std::vector<std::uint32_t> neighbour;
  };

  struct Hit {
    std::size_t cell = 0;
    int n = 0;
    double N[8];
    // The parametric coordinates of the last inversion: where the point is when it was found,
    // else where Newton ended outside the reference cell if finite (xi_valid; the walk's
    // direction).
    bool xi_valid = false;
    double xi[3];
  };

  struct Hint {
    const Storage* owner = nullptr;
    std::size_t cell = 0;
    double xi[3]; // where the last query was found in `cell`: Newton's start for the next one
  };

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

  // Faces in VTK's local numbering; triangles end with -1.
  static int faces_of(unsigned char t, const std::array<int, 4>*& f)
  {
    static const std::array<int, 4> tet[4] = {{0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}, {0, 2, 1, -1}};
    static const std::array<int, 4> hex[6] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                              {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
    static const std::array<int, 4> wedge[5] = {
        {0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
    static const std::array<int, 4> pyramid[5] = {
        {0, 3, 2, 1}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};
    switch (t) {
    case TETRA:
      f = tet;
      return 4;
    case HEXAHEDRON:
      f = hex;
      return 6;
    case WEDGE:
      f = wedge;
      return 5;
    default:
      f = pyramid;
      return 5;
    }
  }

  [[noreturn]] static void fail(const std::string& what)
  {
    throw std::invalid_argument("Unstructured_flow_field_3: " + what);
  }

  template <typename Real>
  static void validate_and_store(Storage& s, const std::vector<Real>& points, std::vector<Index> connectivity,
                                 std::vector<Index> offsets, std::vector<unsigned char> cell_types,
                                 std::vector<float> vectors)
  {
    std::ostringstream msg;
    if (points.size() % 3 != 0) {
      msg << "points.size() is " << points.size() << "; expected a multiple of 3 (x, y, z per point)";
      fail(msg.str());
    }
    const std::size_t np = points.size() / 3;
    if (vectors.size() != points.size()) {
      msg << "vectors.size() is " << vectors.size() << " but there are " << np << " points; expected "
          << points.size() << " (x, y, z per point)";
      fail(msg.str());
    }
    const std::size_t nc = cell_types.size();
    if (nc == 0)
      fail("cell_types is empty; expected at least one cell");
    if (nc > (std::numeric_limits<std::uint32_t>::max)() - 1) {
      msg << "cell_types.size() is " << nc << "; at most " << (std::numeric_limits<std::uint32_t>::max)() - 1
          << " cells are supported";
      fail(msg.str());
    }
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
      if (offsets[c + 1] - offsets[c] != n) {
        msg << "cell " << c << " (a " << type_name(cell_types[c]) << ") has offsets[" << c
            << "] = " << offsets[c] << " and offsets[" << c + 1 << "] = " << offsets[c + 1] << ", so "
            << offsets[c + 1] - offsets[c] << " points; expected " << n;
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
    s.points.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      s.points[i] = static_cast<double>(points[i]);
      if (!std::isfinite(s.points[i])) {
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
    s.vectors = std::move(vectors);
    s.connectivity = std::move(connectivity);
    s.offsets = std::move(offsets);
    s.cell_types = std::move(cell_types);
  }

  static void build_bounding_boxes(Storage& s)
  {
    const std::size_t nc = s.cell_types.size();
    const double inf = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      s.bbox[a] = inf;
      s.bbox[a + 3] = -inf;
    }
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      s.bbox[i % 3] = (std::min)(s.bbox[i % 3], s.points[i]);
      s.bbox[i % 3 + 3] = (std::max)(s.bbox[i % 3 + 3], s.points[i]);
    }
    s.cell_bbox.resize(6 * nc);
    const float finf = std::numeric_limits<float>::infinity();
    for (std::size_t c = 0; c < nc; ++c) {
      double b[6] = {inf, inf, inf, -inf, -inf, -inf};
      for (Index k = s.offsets[c]; k < s.offsets[c + 1]; ++k) {
        const double* x = s.points.data() + 3 * static_cast<std::size_t>(s.connectivity[k]);
        for (int a = 0; a < 3; ++a) {
          b[a] = (std::min)(b[a], x[a]);
          b[a + 3] = (std::max)(b[a + 3], x[a]);
        }
      }
      // Enlarged by the inside tolerance (relative to the cell size) and rounded outwards, so
      // that the box never rejects a point the exact test accepts.
      for (int a = 0; a < 3; ++a) {
        const double pad = 1e-8 * (b[a + 3] - b[a]) + 1e-300;
        s.cell_bbox[6 * c + a] = std::nextafter(static_cast<float>(b[a] - pad), -finf);
        s.cell_bbox[6 * c + a + 3] = std::nextafter(static_cast<float>(b[a + 3] + pad), finf);
      }
    }
  }

  static void build_buckets(Storage& s)
  {
    const std::size_t nc = s.cell_types.size();
    // About one bucket per cell, shaped like the mesh's bounding box.
    double ext[3];
    double volume = 1.;
    int flat = 0;
    for (int a = 0; a < 3; ++a) {
      ext[a] = s.bbox[a + 3] - s.bbox[a];
      if (ext[a] > 0.)
        volume *= ext[a];
      else
        ++flat;
    }
    // The bucket edge: that of about one bucket per cell, but at least the mean edge of the
    // cells' boxes, so that a cell's box (6 times a tetrahedron's volume for the tetrahedra of
    // a cube) does not cover dozens of buckets (1 M tetrahedra: -21 % memory, random queries
    // ~5 % slower).
    const double dimension = double(3 - (std::min)(flat, 2));
    double box_edge = 1.;
    for (int a = 0; a < 3; ++a) {
      if (!(ext[a] > 0.))
        continue;
      double mean = 0.;
      for (std::size_t c = 0; c < nc; ++c)
        mean += double(s.cell_bbox[6 * c + a + 3]) - double(s.cell_bbox[6 * c + a]);
      box_edge *= mean / static_cast<double>(nc);
    }
    box_edge = std::pow(box_edge, 1. / dimension);
    const double per_bucket =
        (std::max)(std::pow(volume / static_cast<double>(nc), 1. / dimension), box_edge);
    for (int a = 0; a < 3; ++a) {
      std::size_t n = 1;
      if (ext[a] > 0. && per_bucket > 0.)
        n = static_cast<std::size_t>((std::max)(1., (std::min)(ext[a] / per_bucket, 1024.)));
      s.bucket_n[a] = n;
      s.bucket_lo[a] = s.bbox[a];
      s.bucket_inv_h[a] = ext[a] > 0. ? static_cast<double>(n) / ext[a] : 0.;
    }
    const std::size_t nb = s.bucket_n[0] * s.bucket_n[1] * s.bucket_n[2];
    // 32-bit counts and positions: the counting pass checks that the total fits.
    std::vector<std::size_t> count(nb + 1, 0);
    // Two passes over the cells: count, then fill.
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> fill;
      if (pass == 1) {
        for (std::size_t b = 0; b < nb; ++b)
          count[b + 1] += count[b];
        if (count[nb] > (std::numeric_limits<std::uint32_t>::max)()) {
          std::ostringstream msg;
          msg << "the cells' bounding boxes cover " << count[nb] << " buckets in all; at most "
              << (std::numeric_limits<std::uint32_t>::max)() << " are supported (too many cells)";
          fail(msg.str());
        }
        s.bucket_begin.assign(count.begin(), count.end());
        count = std::vector<std::size_t>();
        s.bucket_cells.resize(s.bucket_begin[nb]);
        fill.assign(s.bucket_begin.begin(), s.bucket_begin.end() - 1);
      }
      for (std::size_t c = 0; c < nc; ++c) {
        std::size_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
          lo[a] = bucket_coordinate(s, a, s.cell_bbox[6 * c + a]);
          hi[a] = bucket_coordinate(s, a, s.cell_bbox[6 * c + a + 3]);
        }
        for (std::size_t k = lo[2]; k <= hi[2]; ++k)
          for (std::size_t j = lo[1]; j <= hi[1]; ++j)
            for (std::size_t i = lo[0]; i <= hi[0]; ++i) {
              const std::size_t b = i + s.bucket_n[0] * (j + s.bucket_n[1] * k);
              if (pass == 0)
                ++count[b + 1];
              else
                s.bucket_cells[fill[b]++] = static_cast<std::uint32_t>(c);
            }
      }
    }
  }

  static std::size_t bucket_coordinate(const Storage& s, int a, double x)
  {
    const double t = (x - s.bucket_lo[a]) * s.bucket_inv_h[a];
    if (!(t > 0.))
      return 0;
    return (std::min)(static_cast<std::size_t>(t), s.bucket_n[a] - 1);
  }

  static void build_neighbours(Storage& s)
  {
    const std::size_t nc = s.cell_types.size();
    const std::array<int, 4>* f = nullptr;
    std::size_t number_of_faces = 0;
    s.face_stride = 0;
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t nf = static_cast<std::size_t>(faces_of(s.cell_types[c], f));
      number_of_faces += nf;
      s.face_stride = (std::max)(s.face_stride, nf);
    }
    // A face is identified by its sorted point indices (a triangle padded with -1); sorting all
    // faces brings the two sides of every shared face together.
    struct Face {
      std::array<Index, 4> key;
      std::uint32_t cell;
      std::uint8_t local; // the face's number in its cell
      bool operator<(const Face& o) const { return key < o.key; }
    };
    std::vector<Face> faces;
    faces.reserve(number_of_faces);
    for (std::size_t c = 0; c < nc; ++c) {
      const int nf = faces_of(s.cell_types[c], f);
      const Index* v = s.connectivity.data() + s.offsets[c];
      for (int i = 0; i < nf; ++i) {
        Face face;
        for (int k = 0; k < 4; ++k)
          face.key[k] = f[i][k] < 0 ? Index(-1) : v[f[i][k]];
        std::sort(face.key.begin(), face.key.end());
        face.cell = static_cast<std::uint32_t>(c);
        face.local = static_cast<std::uint8_t>(i);
        faces.push_back(face);
      }
    }
    std::sort(faces.begin(), faces.end());
    s.neighbour.assign(s.face_stride * nc, no_cell);
    for (std::size_t i = 0; i + 1 < faces.size(); ++i) {
      if (faces[i].key == faces[i + 1].key) {
        s.neighbour[s.face_stride * faces[i].cell + faces[i].local] = faces[i + 1].cell;
        s.neighbour[s.face_stride * faces[i + 1].cell + faces[i + 1].local] = faces[i].cell;
      }
    }
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

  // Inverts the cell's map x(xi) = p by Newton's method from `start` (in the reference cell)
  // or else from the cell's parametric center.  Returns whether it converged and xi is in the
  // reference cell, with the shape function values and xi in hit; otherwise hit.xi is the last
  // xi when it is finite.
  static bool invert(const Storage& s, std::size_t cell, const double* p, Hit& hit,
                     const double* start = nullptr)
  {
    hit.xi_valid = false;
    const unsigned char type = s.cell_types[cell];
    const Index* v = s.connectivity.data() + s.offsets[cell];
    double X[8][3];
    const int n = points_of(type);
    double size = 0.;
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        X[i][a] = s.points[3 * static_cast<std::size_t>(v[i]) + a];
        size = (std::max)(size, std::abs(X[i][a] - X[0][a]));
      }
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
    double N[8], dN[8][3];
    // Linear cells converge in one step; the trilinear map in a few for reasonable cells.  The
    // cap bounds the cost of points that are far outside a cell (in its bounding box only).
    const int max_iterations = type == TETRA ? 2 : 12;
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
      if (step < 1e-13) {
        converged = true;
        break;
      }
      if (it >= 3) {
        // Far from the reference cell after a few steps: p is not in this cell.
        bool far = false;
        for (int a = 0; a < 3; ++a)
          far = far || xi[a] < -0.5 || xi[a] > 1.5;
        if (far)
          return keep_xi(xi, hit);
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
        return keep_xi(xi, hit);
    }
    if (type == PYRAMID && xi[2] >= 1. - 1e-8) {
      // At the apex r and s are undetermined and irrelevant.
      xi[0] = (std::min)((std::max)(xi[0], 0.), 1.);
      xi[1] = (std::min)((std::max)(xi[1], 0.), 1.);
    }
    if (!in_reference_cell(type, xi))
      return keep_xi(xi, hit);
    hit.cell = cell;
    hit.n = shape(type, xi, hit.N, dN);
    for (int a = 0; a < 3; ++a)
      hit.xi[a] = xi[a];
    return true;
  }

  // Keeps xi in hit for the walk when it is finite; returns false (no hit).
  static bool keep_xi(const double* xi, Hit& hit)
  {
    hit.xi_valid = std::isfinite(xi[0]) && std::isfinite(xi[1]) && std::isfinite(xi[2]);
    for (int a = 0; a < 3; ++a)
      hit.xi[a] = xi[a];
    return false;
  }

  // The face (in the numbering of faces_of()) through which the parametric point xi lies
  // farthest outside the reference cell, or -1 if xi is inside it.
  static int exit_face(unsigned char type, const double* xi)
  {
    const double r = xi[0], s = xi[1], t = xi[2];
    double m[6];
    int nf;
    switch (type) {
    case TETRA: // faces without point 2, 0, 1, 3
      m[0] = s, m[1] = 1. - r - s - t, m[2] = r, m[3] = t, nf = 4;
      break;
    case HEXAHEDRON:
      m[0] = r, m[1] = 1. - r, m[2] = s, m[3] = 1. - s, m[4] = t, m[5] = 1. - t, nf = 6;
      break;
    case WEDGE:
      m[0] = t, m[1] = 1. - t, m[2] = s, m[3] = 1. - r - s, m[4] = r, nf = 5;
      break;
    default: // PYRAMID
      m[0] = t, m[1] = s, m[2] = 1. - r, m[3] = 1. - s, m[4] = r, nf = 5;
    }
    int best = -1;
    double worst = 0.;
    for (int f = 0; f < nf; ++f)
      if (m[f] < worst) {
        worst = m[f];
        best = f;
      }
    return best;
  }

  // Whether x is in the cell's bounding box enlarged by its own extent on every side: the
  // walk starts only from such cells (farther points go to the bucket grid directly).
  static bool near_cell_bbox(const Storage& s, std::size_t c, const double* x)
  {
    const float* b = s.cell_bbox.data() + 6 * c;
    for (int a = 0; a < 3; ++a) {
      const double e = double(b[a + 3]) - double(b[a]);
      if (!(x[a] >= b[a] - e && x[a] <= b[a + 3] + e))
        return false;
    }
    return true;
  }

  static bool in_cell_bbox(const Storage& s, std::size_t c, const double* x)
  {
    const float* b = s.cell_bbox.data() + 6 * c;
    return x[0] >= b[0] && x[0] <= b[3] && x[1] >= b[1] && x[1] <= b[4] && x[2] >= b[2] && x[2] <= b[5];
  }

  Vector_3 interpolate(const Hit& hit) const
  {
    double r[3] = {0., 0., 0.};
    const Storage& s = *storage_;
    const Index* c = s.connectivity.data() + s.offsets[hit.cell];
    for (int i = 0; i < hit.n; ++i) {
      const float* v = s.vectors.data() + 3 * static_cast<std::size_t>(c[i]);
      for (int d = 0; d < 3; ++d)
        r[d] += hit.N[i] * static_cast<double>(v[d]);
    }
    return Vector_3(FT(r[0]), FT(r[1]), FT(r[2]));
  }

  bool try_cell(std::size_t c, const double* x, Hit& hit) const
  {
    return in_cell_bbox(*storage_, c, x) && invert(*storage_, c, x, hit);
  }

  static void remember(Hint& hint, const Hit& hit)
  {
    hint.cell = hit.cell;
    for (int a = 0; a < 3; ++a)
      hint.xi[a] = hit.xi[a];
  }

  bool find(const double* x, Hit& hit) const
  {
    const Storage& s = *storage_;
    // Written so that NaN coordinates fail too.
    if (!(x[0] >= s.bbox[0] && x[0] <= s.bbox[3] && x[1] >= s.bbox[1] && x[1] <= s.bbox[4] &&
          x[2] >= s.bbox[2] && x[2] <= s.bbox[5]))
      return false;
    static thread_local Hint hint;
    const std::size_t nc = s.cell_types.size();
    if (hint.owner == &s && hint.cell < nc && near_cell_bbox(s, hint.cell, x)) {
      // The walk: invert in the current cell (without the box test, whose rejection would not
      // tell a direction) and cross the face the point lies beyond, a few steps at most.
      const std::size_t h = hint.cell;
      std::size_t c = h, previous = no_cell;
      for (int step = 0; step < max_walk_steps; ++step) {
        if (invert(s, c, x, hit, c == h ? hint.xi : nullptr)) {
          remember(hint, hit);
          return true;
        }
        if (!hit.xi_valid)
          break;
        const int f = exit_face(s.cell_types[c], hit.xi);
        const std::uint32_t next = f < 0 ? no_cell : s.neighbour[s.face_stride * c + std::size_t(f)];
        if (next == no_cell || next == previous)
          break;
        previous = c;
        c = next;
      }
      // Then the hint's other face neighbours (the walk's first step may have chosen a wrong
      // face in a strongly distorted cell).
      const std::uint32_t* n = s.neighbour.data() + s.face_stride * h;
      for (std::size_t f = 0; f < s.face_stride; ++f) {
        const std::uint32_t c2 = n[f];
        if (c2 != no_cell && c2 != c && try_cell(c2, x, hit)) {
          remember(hint, hit);
          return true;
        }
      }
    }
    std::size_t b = 0;
    for (int a = 2; a >= 0; --a)
      b = b * s.bucket_n[a] + bucket_coordinate(s, a, x[a]);
    for (std::size_t k = s.bucket_begin[b]; k < s.bucket_begin[b + 1]; ++k) {
      const std::size_t c = s.bucket_cells[k];
      if (try_cell(c, x, hit)) {
        hint.owner = &s;
        remember(hint, hit);
        return true;
      }
    }
    return false;
  }

  std::shared_ptr<const Storage> storage_;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_UNSTRUCTURED_FLOW_FIELD_3_H
