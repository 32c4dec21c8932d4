// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete Poisson operators of Section 3 of the paper, on a triangle mesh
// with m vertices and n faces:
//
//   G  (3n x m)  per-face gradient of a piecewise linear function: (G u)_j = sum_i grad(phi_i^j) u_i
//   A  (3n x 3n) diagonal, the area of face j repeated three times
//   L  (m x m)   = G^T A G, the cotangent Laplacian (symmetric positive semi-definite)
//   D  (m x 3n)  = G^T A, the divergence of a per-face vector field
//
// Each face also keeps what an iteration needs without touching the sparse
// matrices: its vertex indices and its local stiffness K_j = A_j grad^T grad (3 x 3, kept as its
// three entries off the diagonal), so that the face's share of D Y' is K_j X_j T_j^T.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_POISSON_OPERATORS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_POISSON_OPERATORS_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// The constant gradients of the three barycentric basis functions of a triangle.
struct Triangle_gradients {
  Eigen::Matrix3d gradients; // column i = grad(phi_i), i = a, b, c
  Eigen::Vector3d unit_normal;
  double area = 0;
};

/// grad(phi_a) = n x (x_c - x_b) / (2A), and cyclically: the solution of the paper's 3x3 system.
/// Returns nothing for a degenerate triangle (zero area), whose gradients do not exist.
inline std::optional<Triangle_gradients>
triangle_gradients(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d cross = (b - a).cross(c - a);
  const double twice_area = cross.norm();
  const double scale = (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  // Relative threshold: a triangle whose area is tiny compared to its longest edge squared has
  // gradients that amplify rounding errors without bound.
  if (!(twice_area > 1e-12 * scale))
    return std::nullopt;
  Triangle_gradients t;
  t.unit_normal = cross / twice_area;
  t.area = 0.5 * twice_area;
  t.gradients.col(0) = t.unit_normal.cross(c - b) / twice_area;
  t.gradients.col(1) = t.unit_normal.cross(a - c) / twice_area;
  t.gradients.col(2) = t.unit_normal.cross(b - a) / twice_area;
  return t;
}

/// Per-face data of the reference mesh M_0.
struct Reference_face {
  std::array<Eigen::Index, 3> vertices;
  // The local stiffness K_j = A_j grad^T grad by its entries off the diagonal: entry i for the
  // edge opposite corner i, K(k, l) with {i, k, l} = {0, 1, 2}.  The basis functions sum to one,
  // so the gradients sum to zero and so do K's rows: K(i, i) = -(K(i, k) + K(i, l)).  Three
  // numbers instead of nine, and L = sum_j K_j has L 1 = 0 exactly.
  std::array<double, 3> edge_stiffness{};
  double area = 0;

  /// The entry (i, k) of K_j.
  double stiffness(int i, int k) const
  {
    return i == k ? -(edge_stiffness[std::size_t((i + 1) % 3)] + edge_stiffness[std::size_t((i + 2) % 3)])
                  : edge_stiffness[std::size_t(3 - i - k)];
  }

  /// The corner of the face at vertex `v` (one of its vertices).
  int corner(Eigen::Index v) const { return vertices[0] == v ? 0 : vertices[1] == v ? 1 : 2; }

  /// K_j m, for m with one row per corner: row i is sum over k != i of K(i, k) (m_k - m_i).
  Eigen::Matrix3d times_stiffness(const Eigen::Matrix3d& m) const
  {
    const Eigen::RowVector3d d01 = m.row(1) - m.row(0), d02 = m.row(2) - m.row(0), d12 = m.row(2) - m.row(1);
    Eigen::Matrix3d result;
    result.row(0) = edge_stiffness[2] * d01 + edge_stiffness[1] * d02;
    result.row(1) = edge_stiffness[0] * d12 - edge_stiffness[2] * d01;
    result.row(2) = -edge_stiffness[1] * d02 - edge_stiffness[0] * d12;
    return result;
  }
};

/// The operators of Section 3 assembled on one mesh.
struct Poisson_operators {
  using Sparse_matrix = Eigen::SparseMatrix<double>;

  std::vector<Reference_face> faces;
  Eigen::VectorXd face_areas; // n
  Sparse_matrix G;            // 3n x m (empty unless asked for)
  Sparse_matrix L;            // m x m
  Sparse_matrix D;            // m x 3n (empty unless asked for)

  Eigen::Index number_of_vertices() const { return L.rows(); }
  Eigen::Index number_of_faces() const { return face_areas.size(); }
  /// A (3n x 3n) as a diagonal matrix.
  Eigen::DiagonalMatrix<double, Eigen::Dynamic> area_matrix() const
  {
    return Eigen::VectorXd(face_areas.replicate(1, 3).transpose().reshaped()).asDiagonal();
  }
};

/// The data of the face `fv` of the mesh with vertex positions `positions` (m x 3), and its basis
/// gradients in `*gradients` when asked; nothing for a degenerate face.
inline std::optional<Reference_face>
make_reference_face(const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                    const std::array<Eigen::Index, 3>& fv, Eigen::Matrix3d* gradients = nullptr)
{
  const auto t = triangle_gradients(positions.row(fv[0]).transpose(), positions.row(fv[1]).transpose(),
                                    positions.row(fv[2]).transpose());
  if (!t)
    return std::nullopt;
  Reference_face face;
  face.vertices = fv;
  face.area = t->area;
  for (int i = 0; i < 3; ++i)
    face.edge_stiffness[std::size_t(i)] =
        t->area * t->gradients.col((i + 1) % 3).dot(t->gradients.col((i + 2) % 3));
  if (gradients)
    *gradients = t->gradients;
  return face;
}

/// Index of the first degenerate face in `positions`/`face_vertices`, if any.
struct Degenerate_face {
  std::size_t face;
};

/// The faces from `first_face` on around each vertex of a mesh with m vertices, in increasing
/// face order, as a CSR array: those of vertex v are `around[first[v]]` to `around[first[v + 1] - 1]`.
struct Faces_around_vertices {
  using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;
  std::vector<StorageIndex> first;
  std::vector<StorageIndex> around;

  Faces_around_vertices(Eigen::Index m, const std::vector<Reference_face>& faces, std::size_t first_face = 0)
      : first(std::size_t(m) + 1, 0)
  {
    for (std::size_t j = first_face; j < faces.size(); ++j)
      for (Eigen::Index v : faces[j].vertices)
        ++first[std::size_t(v) + 1];
    for (std::size_t v = 0; v < std::size_t(m); ++v)
      first[v + 1] += first[v];
    around.resize(static_cast<std::size_t>(first[std::size_t(m)]));
    std::vector<StorageIndex> next(first.begin(), first.end() - 1);
    for (std::size_t j = first_face; j < faces.size(); ++j)
      for (Eigen::Index v : faces[j].vertices)
        around[std::size_t(next[std::size_t(v)]++)] = StorageIndex(j);
  }

  bool none_around(std::size_t v) const { return first[v + 1] == first[v]; }
};

/// L = sum_j K_j (each face's local stiffness scattered to its vertices), assembled directly in
/// compressed column form: the rows of column v are v and the vertices of the faces around v,
/// and each entry sums the faces' contributions in increasing face order, as
/// `setFromTriplets()` does, so the matrix is the same to the last bit.  Unlike
/// `setFromTriplets()` it needs no triplet list and no transposed copy (9 triplets of 16 bytes
/// and 9 more entries per face): it touches about a third of the memory, and on a machine whose
/// page faults are slow the first touch of fresh memory is most of the assembly time.
inline Eigen::SparseMatrix<double> assemble_stiffness_matrix(Eigen::Index m,
                                                             const std::vector<Reference_face>& faces)
{
  using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;
  const Faces_around_vertices faces_around(m, faces);
  const std::vector<StorageIndex>& first = faces_around.first;
  const std::vector<StorageIndex>& around = faces_around.around;
  // The rows of column v: v and the other vertices of its faces, each once (`seen[u] == v` marks
  // u as taken), sorted; `at[u]` then is the position of row u in the column.
  std::vector<StorageIndex> seen(static_cast<std::size_t>(m), StorageIndex(-1));
  std::vector<StorageIndex> at(static_cast<std::size_t>(m));
  std::vector<StorageIndex> rows;
  auto column_rows = [&](std::size_t v) {
    rows.clear();
    for (StorageIndex k = first[v]; k < first[v + 1]; ++k)
      for (Eigen::Index u : faces[std::size_t(around[std::size_t(k)])].vertices)
        if (seen[std::size_t(u)] != StorageIndex(v)) {
          seen[std::size_t(u)] = StorageIndex(v);
          rows.push_back(StorageIndex(u));
        }
  };

  Eigen::SparseMatrix<double> l(m, m);
  StorageIndex* outer = l.outerIndexPtr();
  outer[0] = 0;
  for (std::size_t v = 0; v < std::size_t(m); ++v) {
    column_rows(v);
    outer[v + 1] = outer[v] + StorageIndex(rows.size());
  }
  std::fill(seen.begin(), seen.end(), StorageIndex(-1));
  l.resizeNonZeros(outer[m]);
  StorageIndex* inner = l.innerIndexPtr();
  double* values = l.valuePtr();
  for (std::size_t v = 0; v < std::size_t(m); ++v) {
    column_rows(v);
    std::sort(rows.begin(), rows.end());
    const StorageIndex begin = outer[v];
    for (std::size_t k = 0; k < rows.size(); ++k) {
      inner[begin + StorageIndex(k)] = rows[k];
      values[begin + StorageIndex(k)] = 0;
      at[std::size_t(rows[k])] = begin + StorageIndex(k);
    }
    for (StorageIndex k = first[v]; k < first[v + 1]; ++k) {
      const Reference_face& face = faces[std::size_t(around[std::size_t(k)])];
      const int corner = face.corner(Eigen::Index(v));
      for (int i = 0; i < 3; ++i)
        values[at[std::size_t(face.vertices[i])]] += face.stiffness(i, corner);
    }
  }
  return l;
}

/// Which operators `make_poisson_operators()` assembles besides L and the per-face data: the
/// deformation needs neither G nor D, the parametrizations D only (G and D cost about half of the
/// assembly with G's triplets and the product G^T A).
enum class Operators_asked { stiffness, divergence, gradient_and_divergence };

/// D = G^T A (m x 3n), filled column by column as `make_poisson_operators()` meets the faces:
/// column 3j + d holds the rows of face j's vertices in increasing order, each the d-th component
/// of that vertex's basis gradient times the face's area.  Those are the product's entries to the
/// last bit (one product each), without G's triplets, its transposed copy and the product.
class Divergence_matrix {
public:
  using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;

  Divergence_matrix(Eigen::Index m, Eigen::Index n) : m_d(m, 3 * n)
  {
    m_d.resizeNonZeros(9 * n);
    StorageIndex* outer = m_d.outerIndexPtr();
    for (Eigen::Index k = 0; k <= 3 * n; ++k)
      outer[k] = StorageIndex(3 * k);
  }

  /// The columns of face j with vertices `fv`, basis gradients `gradients` (column i: vertex
  /// fv[i]) and area `area`.
  void add_face(Eigen::Index j, const std::array<Eigen::Index, 3>& fv, const Eigen::Matrix3d& gradients,
                double area)
  {
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&fv](int a, int b) { return fv[std::size_t(a)] < fv[std::size_t(b)]; });
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k) {
        const Eigen::Index entry = 9 * j + 3 * d + k;
        const int i = order[std::size_t(k)];
        m_d.innerIndexPtr()[entry] = StorageIndex(fv[std::size_t(i)]);
        m_d.valuePtr()[entry] = gradients(d, i) * area;
      }
  }

  Eigen::SparseMatrix<double> take() { return std::move(m_d); }

private:
  Eigen::SparseMatrix<double> m_d;
};

/// Assembles the operators from vertex positions (m x 3) and the vertex indices of each face:
/// L and the per-face data, and the operators `asked` for (the others are left empty).  Returns
/// the index of a degenerate face instead when there is one.
inline std::variant<Poisson_operators, Degenerate_face>
make_poisson_operators(const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                       const std::vector<std::array<Eigen::Index, 3>>& face_vertices,
                       Operators_asked asked = Operators_asked::gradient_and_divergence)
{
  using Triplet = Eigen::Triplet<double>;
  const Eigen::Index m = positions.rows();
  const Eigen::Index n = static_cast<Eigen::Index>(face_vertices.size());
  const bool with_gradient = asked == Operators_asked::gradient_and_divergence;
  const bool with_divergence = asked != Operators_asked::stiffness;

  Poisson_operators ops;
  ops.faces.resize(face_vertices.size());
  ops.face_areas.resize(n);
  std::vector<Triplet> g_entries;
  if (with_gradient)
    g_entries.reserve(9 * face_vertices.size());
  std::optional<Divergence_matrix> divergence;
  if (with_divergence)
    divergence.emplace(m, n);

  Eigen::Matrix3d gradients;
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& fv = face_vertices[std::size_t(j)];
    const std::optional<Reference_face> face = make_reference_face(positions, fv, &gradients);
    if (!face)
      return Degenerate_face{std::size_t(j)};
    ops.faces[std::size_t(j)] = *face;
    ops.face_areas[j] = face->area;
    if (with_gradient)
      for (int i = 0; i < 3; ++i)
        for (int d = 0; d < 3; ++d)
          g_entries.emplace_back(3 * j + d, fv[i], gradients(d, i));
    if (divergence)
      divergence->add_face(j, fv, gradients, face->area);
  }

  ops.L = assemble_stiffness_matrix(m, ops.faces);
  if (with_gradient) {
    ops.G.resize(3 * n, m);
    ops.G.setFromTriplets(g_entries.begin(), g_entries.end());
  }
  if (divergence)
    ops.D = divergence->take();
  return ops;
}

/// Extends L = sum_j K_j of the first `old_faces` of `faces` to all of them, on m vertices, in
/// place: its old columns are moved toward the end of its arrays from the last one down, the new
/// faces' entries merged in, and each entry is the old sum plus the new faces' contributions in
/// increasing face order.
class Stiffness_matrix_extension {
public:
  using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;

  Stiffness_matrix_extension(Eigen::SparseMatrix<double>& l, Eigen::Index m,
                             const std::vector<Reference_face>& faces, std::size_t old_faces)
      : m_l(l), m_old_m(l.cols()), m_m(m), m_faces(faces), m_new_faces(m, faces, old_faces),
        m_old_outer(l.outerIndexPtr(), l.outerIndexPtr() + m_old_m + 1),
        m_seen(std::size_t(m), StorageIndex(-1))
  {
  }

  void extend()
  {
    count_column_entries();
    std::fill(m_seen.begin(), m_seen.end(), StorageIndex(-1));
    const Eigen::Index nonzeros = m_outer[std::size_t(m_m)];
    if (nonzeros > Eigen::Index(m_l.data().allocatedSize()))
      m_l.data().reserve(nonzeros - m_l.nonZeros() + nonzeros / 2);
    m_l.conservativeResize(m_m, m_m);
    m_l.resizeNonZeros(nonzeros);
    // From the last column down: a column's new place starts at or after its old one and ends
    // before the old place of the next column, which was already moved.
    for (std::size_t v = std::size_t(m_m); v-- > 0;) {
      if (m_new_faces.none_around(v))
        move_old_column(v);
      else {
        merge_added_rows(v);
        add_new_face_stiffness(v);
      }
    }
    std::copy(m_outer.begin(), m_outer.end(), m_l.outerIndexPtr());
  }

private:
  StorageIndex old_begin(std::size_t v) const { return v < std::size_t(m_old_m) ? m_old_outer[v] : 0; }
  StorageIndex old_end(std::size_t v) const { return v < std::size_t(m_old_m) ? m_old_outer[v + 1] : 0; }

  bool old_column_has(std::size_t v, StorageIndex row) const
  {
    if (v >= std::size_t(m_old_m))
      return false;
    const StorageIndex* begin = m_l.innerIndexPtr() + m_old_outer[v];
    const StorageIndex* end = m_l.innerIndexPtr() + m_old_outer[v + 1];
    return std::binary_search(begin, end, row);
  }

  // The rows the new faces add to column v (not in the old column), unsorted, into `m_rows`.
  void find_added_rows(std::size_t v)
  {
    m_rows.clear();
    for (StorageIndex k = m_new_faces.first[v]; k < m_new_faces.first[v + 1]; ++k)
      for (Eigen::Index u : m_faces[std::size_t(m_new_faces.around[std::size_t(k)])].vertices)
        if (m_seen[std::size_t(u)] != StorageIndex(v)) {
          m_seen[std::size_t(u)] = StorageIndex(v);
          if (!old_column_has(v, StorageIndex(u)))
            m_rows.push_back(StorageIndex(u));
        }
  }

  // The extended matrix's column starts, into `m_outer`.
  void count_column_entries()
  {
    m_outer.assign(std::size_t(m_m) + 1, 0);
    for (std::size_t v = 0; v < std::size_t(m_m); ++v) {
      const StorageIndex old_count = old_end(v) - old_begin(v);
      if (!m_new_faces.none_around(v))
        find_added_rows(v);
      else
        m_rows.clear();
      m_outer[v + 1] = m_outer[v] + old_count + StorageIndex(m_rows.size());
    }
  }

  void move_old_column(std::size_t v)
  {
    StorageIndex* inner = m_l.innerIndexPtr();
    double* values = m_l.valuePtr();
    std::copy_backward(inner + old_begin(v), inner + old_end(v), inner + m_outer[v + 1]);
    std::copy_backward(values + old_begin(v), values + old_end(v), values + m_outer[v + 1]);
  }

  // Column v at its new place: its old entries and the new faces' rows with zero values, merged
  // from the back.
  void merge_added_rows(std::size_t v)
  {
    StorageIndex* inner = m_l.innerIndexPtr();
    double* values = m_l.valuePtr();
    find_added_rows(v);
    std::sort(m_rows.begin(), m_rows.end());
    const StorageIndex begin = old_begin(v);
    StorageIndex read = old_end(v); // one past the next old entry
    StorageIndex write = m_outer[v + 1];
    std::size_t r = m_rows.size();
    while (write > m_outer[v]) {
      --write;
      if (r > 0 && (read == begin || m_rows[r - 1] > inner[read - 1])) {
        inner[write] = m_rows[--r];
        values[write] = 0;
      }
      else {
        --read;
        inner[write] = inner[read];
        values[write] = values[read];
      }
    }
  }

  void add_new_face_stiffness(std::size_t v)
  {
    const StorageIndex* inner = m_l.innerIndexPtr();
    double* values = m_l.valuePtr();
    const StorageIndex* column = inner + m_outer[v];
    const StorageIndex* column_end = inner + m_outer[v + 1];
    for (StorageIndex k = m_new_faces.first[v]; k < m_new_faces.first[v + 1]; ++k) {
      const Reference_face& face = m_faces[std::size_t(m_new_faces.around[std::size_t(k)])];
      const int corner = face.corner(Eigen::Index(v));
      for (int i = 0; i < 3; ++i) {
        const StorageIndex row = StorageIndex(face.vertices[i]);
        values[std::lower_bound(column, column_end, row) - inner] += face.stiffness(i, corner);
      }
    }
  }

  Eigen::SparseMatrix<double>& m_l;
  const Eigen::Index m_old_m, m_m;
  const std::vector<Reference_face>& m_faces;
  const Faces_around_vertices m_new_faces;
  const std::vector<StorageIndex> m_old_outer;
  std::vector<StorageIndex> m_seen;  // m_seen[u] == v: row u of column v is taken
  std::vector<StorageIndex> m_rows;  // of the column at hand
  std::vector<StorageIndex> m_outer; // of the extended matrix
};

/// The faces of `face_vertices` after the `ops.faces.size()` ones of `ops`, appended to `ops.faces`
/// and `ops.face_areas`; the first degenerate one instead, if any, and then `ops` is untouched.
inline std::optional<Degenerate_face>
append_reference_faces(Poisson_operators& ops, const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                       const std::vector<std::array<Eigen::Index, 3>>& face_vertices)
{
  const std::size_t old_faces = ops.faces.size();
  std::vector<Reference_face> added;
  added.reserve(face_vertices.size() - old_faces);
  for (std::size_t j = old_faces; j < face_vertices.size(); ++j) {
    const std::optional<Reference_face> face = make_reference_face(positions, face_vertices[j]);
    if (!face)
      return Degenerate_face{j};
    added.push_back(*face);
  }
  if (ops.faces.capacity() < face_vertices.size())
    ops.faces.reserve(face_vertices.size() + face_vertices.size() / 2);
  ops.faces.insert(ops.faces.end(), added.begin(), added.end());
  ops.face_areas.conservativeResize(Eigen::Index(ops.faces.size()));
  for (std::size_t j = old_faces; j < ops.faces.size(); ++j)
    ops.face_areas[Eigen::Index(j)] = ops.faces[j].area;
  return std::nullopt;
}

/// Extends `ops`, assembled by `make_poisson_operators()` without G and D on the first
/// `ops.faces.size()` faces of `face_vertices`, to all of them: the faces after those (a mesh
/// grown at its boundary) on `positions`, whose rows for the vertices of the old faces must be
/// the ones `ops` was made from.  The old faces' data are kept, the new faces' computed, and L
/// is extended in place (`Stiffness_matrix_extension`): each entry is the old sum plus the new
/// faces' contributions in increasing face order, so the result is what
/// `make_poisson_operators()` makes of the whole mesh, to the last bit, with a fraction of the
/// work and little fresh memory (the arrays grow by half again when full, so repeated growing
/// mostly reuses them).
/// Returns the first degenerate new face, if any, and then leaves `ops` untouched.
/// \pre `face_vertices[j] == ops.faces[j].vertices` for the old faces; `ops.G` is empty.
inline std::optional<Degenerate_face>
extend_poisson_operators(Poisson_operators& ops, const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                         const std::vector<std::array<Eigen::Index, 3>>& face_vertices)
{
  const std::size_t old_faces = ops.faces.size();
  if (const std::optional<Degenerate_face> degenerate = append_reference_faces(ops, positions, face_vertices))
    return degenerate;
  Stiffness_matrix_extension(ops.L, positions.rows(), ops.faces, old_faces).extend();
  return std::nullopt;
}

/// The divergence D_0 on the reference mesh M_0 of a per-face field given on a deformed mesh
/// M_k with the same connectivity: column l of `field_on_current` (3n x k) stacks one vector
/// a_j per face of M_k.  Each a_j is pulled back to face j of M_0 as a cotangent vector: the
/// vector b_j in the plane of the M_0 face with b_j . e^0 = a_j . e^k for its edges (e^0 and e^k
/// the same edge in M_0 and M_k), so that grad_0 (r o phi) = b_j when grad_k r = a_j (phi the
/// piecewise linear map M_0 -> M_k).  With E = [x_b - x_a, x_c - x_a] (3 x 2),
/// b_j = E_0 (E_0^T E_0)^{-1} E_k^T a_j, and since grad_0^T E_0 = S = [-1 -1; 1 0; 0 1] the face's
/// share of D_0 b is A_j^0 S (E_0^T E_0)^{-1} E_k^T a_j: no gradients needed.  Equals D a when
/// M_k = M_0.
inline Eigen::MatrixXd
reference_divergence(const Poisson_operators& reference_ops,
                     const Eigen::Matrix<double, Eigen::Dynamic, 3>& reference_positions,
                     const Eigen::Matrix<double, Eigen::Dynamic, 3>& current_positions,
                     const Eigen::MatrixXd& field_on_current)
{
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(reference_positions.rows(), field_on_current.cols());
  for (std::size_t j = 0; j < reference_ops.faces.size(); ++j) {
    const Reference_face& face = reference_ops.faces[j];
    const auto& v = face.vertices;
    Eigen::Matrix<double, 3, 2> e0, ek;
    e0.col(0) = (reference_positions.row(v[1]) - reference_positions.row(v[0])).transpose();
    e0.col(1) = (reference_positions.row(v[2]) - reference_positions.row(v[0])).transpose();
    ek.col(0) = (current_positions.row(v[1]) - current_positions.row(v[0])).transpose();
    ek.col(1) = (current_positions.row(v[2]) - current_positions.row(v[0])).transpose();
    const Eigen::Matrix2d metric_inverse = (e0.transpose() * e0).inverse();
    for (Eigen::Index l = 0; l < field_on_current.cols(); ++l) {
      const Eigen::Vector2d w = face.area * metric_inverse *
                                (ek.transpose() * field_on_current.block<3, 1>(3 * Eigen::Index(j), l));
      result(v[0], l) -= w[0] + w[1];
      result(v[1], l) += w[0];
      result(v[2], l) += w[1];
    }
  }
  return result;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_POISSON_OPERATORS_H
