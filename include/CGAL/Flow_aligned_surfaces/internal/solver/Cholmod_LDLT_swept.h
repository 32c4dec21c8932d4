// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default sparse Cholesky of the package, A = L D L^T for a symmetric positive definite A
// (n x n, its lower triangle read): CHOLMOD's simplicial LDL^T factorization (one thread, no
// BLAS: see Sparse_cholesky.h), called through cholmod.h, whose back-substitutions, which the
// deformation pays every iteration (three coordinate columns) while it pays the factorization
// once, are swept here by supernodes on large factors.
//
// On these surfaces (2D meshes) the solve reads the whole factor twice, forward and backward.
// CHOLMOD's simplicial solve reads a row index with every value.  Here the columns that share
// their pattern below the diagonal (the fundamental supernodes of the elimination tree:
// separators of the ordering, chains), found in the simplicial factor after each
// factorization, are swept as one lower trapezoid, where CHOLMOD stores them (column by column,
// D then the unit L below it; Supernode_sweeper.h), with one list of row indices per supernode
// (the only copy: about 15 % of the factor's entries, as ints), so that each sweep reads the
// values in order for the three right-hand sides at once.  A large factor also keeps a
// single-precision copy of its values for `solve_correction()`: one step of iterative
// refinement in double from a first approximation the caller already has (the deformation's
// current surface), whose correction is swept in single precision, the copy's values and the
// arithmetic (four floats per row: one SIMD register), to an error proportional to the
// correction, not to the solution (about 1e-7 times the condition number).  With
// `use_parallelism()` the independent subtrees of the elimination tree are swept on the threads
// of the caller's TBB arena (Elimination_subtrees.h); the result is the same bit for bit.
//
// When to sweep and when to keep the copy is a rule on the size of the factor against the
// last-level cache, stated (8 MB) rather than queried, so that the solutions, whose rounding
// the choice changes, do not depend on the machine:
//  - a factor whose double values fit in the cache is read from it by every solve of the
//    iterations: CHOLMOD's own solve, which does less work per entry, is the faster, and a
//    single-precision copy costs more to make than a short alignment saves;
//  - from the size of the cache on (1e6 entries, about 5e4 faces), the values stream from memory
//    in every solve, and the copy, half the bytes, halves the corrections' time;
//  - from three times the cache on (3e6 entries, about 1.5e5 faces), the sweeps of the double
//    factor also beat CHOLMOD's solve: they read 8 bytes an entry against its 12 (a value and a
//    row index), a gain that their larger work per entry hides until most of the factor comes
//    from memory (measured break-even between 1.5e6 and 3e6 entries).
// benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver", has the measurements.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_CHOLMOD_LDLT_SWEPT_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_CHOLMOD_LDLT_SWEPT_H

#include <CGAL/Flow_aligned_surfaces/internal/solver/Elimination_subtrees.h>
#include <CGAL/Flow_aligned_surfaces/internal/solver/Supernode_sweeper.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// An Eigen sparse solver (compute(), analyzePattern(), factorize(), info(), solve()), so that
/// `CGAL::Eigen_solver_traits<Cholmod_LDLT_swept>` is a SparseLinearAlgebraWithFactorTraits_d.
class Cholmod_LDLT_swept : public Eigen::SparseSolverBase<Cholmod_LDLT_swept> {
public:
  using MatrixType = Eigen::SparseMatrix<double>;
  using Matrix_type = MatrixType;
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  Cholmod_LDLT_swept()
  {
    cholmod_start(&m_common);
    m_common.supernodal = CHOLMOD_SIMPLICIAL;
    m_common.final_asis = 1;
  }

  Cholmod_LDLT_swept(const Cholmod_LDLT_swept&) = delete;
  Cholmod_LDLT_swept& operator=(const Cholmod_LDLT_swept&) = delete;

  ~Cholmod_LDLT_swept()
  {
    free_factor();
    cholmod_finish(&m_common);
  }

  /// Analysis and numerical factorization.
  Cholmod_LDLT_swept& compute(const Matrix_type& matrix)
  {
    analyzePattern(matrix);
    factorize(matrix);
    return *this;
  }

  /// The symbolic analysis (fill-reducing ordering, by the strategy of `cholmod()`'s settings:
  /// CHOLMOD's default, which picks AMD on these meshes, and pattern of the factor).
  void analyzePattern(const Matrix_type& matrix)
  {
    free_factor();
    cholmod_sparse lower = lower_triangle_view(matrix);
    m_factor = cholmod_analyze(&lower, &m_common);
    m_isInitialized = true;
    m_info = m_factor ? Eigen::Success : Eigen::InvalidInput;
  }

  /// The numerical factorization of a matrix with the pattern seen by `analyzePattern()`.
  void factorize(const Matrix_type& matrix)
  {
    m_subtrees = Elimination_subtrees();
    m_super.clear();
    m_single.clear();
    m_sweeps = false;
    if (!m_factor) {
      m_info = Eigen::InvalidInput;
      return;
    }
    cholmod_sparse lower = lower_triangle_view(matrix);
    cholmod_factorize(&lower, m_factor, &m_common);
    // On failure CHOLMOD sets `minor` to the column where it stopped; on success to n.
    m_info = m_factor->minor == m_factor->n ? Eigen::Success : Eigen::NumericalIssue;
    if (m_info != Eigen::Success)
      return;
    if (!has_positive_pivots(*m_factor)) {
      m_info = Eigen::NumericalIssue;
      return;
    }
    const double entries = m_common.lnz;
    m_sweeps = entries >= m_smallest_swept_factor;
    const bool single_copy = entries >= m_smallest_single_precision_factor;
    if (!m_sweeps && !single_copy)
      return;
    find_supernodes(*m_factor);
    if (single_copy)
      copy_values(*m_factor);
    m_subtrees =
        Elimination_subtrees(int(number_of_supernodes()), m_super.data(), m_pi.data(), m_rows.data());
    m_subtrees.use_parallelism(m_parallel);
  }

  /// Success, or why the last analysis or factorization failed.
  Eigen::ComputationInfo info() const { return m_info; }

  /// The order of the matrix factored.
  Eigen::Index rows() const { return m_factor ? Eigen::Index(m_factor->n) : 0; }
  Eigen::Index cols() const { return rows(); }

  /// Whether the sweeps run the independent subtrees on the threads of the caller's TBB arena
  /// (the result is the same bit for bit).
  void use_parallelism(bool parallel)
  {
    m_parallel = parallel;
    m_subtrees.use_parallelism(parallel);
  }

  /// The last-level cache the default thresholds below assume (see the top of this file).
  static constexpr double assumed_last_level_cache_bytes = 8e6;

  /// From this many nonzeros of the factor on (by default: three times what fills the assumed
  /// cache with doubles), solve() sweeps the supernodes; below, CHOLMOD's own simplicial solve
  /// is used.  Sweeping CHOLMOD's factor in place copies only the row lists (5 MB instead of
  /// 63 MB at 3.2e5 faces), but the sweeps are no faster than CHOLMOD's solve below about 1e5
  /// faces: 22 to 36 % slower at 5e3 and 2e4 faces (the factor in the caches, CHOLMOD's kernel
  /// does less per entry), as fast within the noise at 8e4 (1.5e6 nonzeros), up to 15 % faster at
  /// 3.2e5 (7e6 nonzeros) (benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver").  The
  /// choice does not depend on `use_parallelism()`, so that the solutions do not either.
  static constexpr double default_smallest_swept_factor = 3 * assumed_last_level_cache_bytes / sizeof(double);

  /// Sets the number of nonzeros of the factor from which the next factorizations are solved by
  /// the supernodal sweeps.
  void sweep_from(double entries) { m_smallest_swept_factor = entries; }

  /// Whether solve() uses the supernodal sweeps (else CHOLMOD's simplicial solve).
  bool uses_supernodal_sweeps() const { return m_sweeps; }

  /// From this many nonzeros of the factor on (by default: as many doubles as fill the assumed
  /// cache), a factorization also keeps the values in single precision for `solve_correction()`
  /// (4 more bytes per nonzero, made by each factorization: 25 to 35 ms of the first
  /// construction at 8e4 faces, most of it page faults).  Its sweeps read half the bytes of the
  /// double factor's and compute in single precision: the iterations' SOLVE takes half the time
  /// of CHOLMOD's solve at 8e4 faces (1.5e6 nonzeros) and 40 % less than the double sweeps at
  /// 3.2e5 (benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver").
  static constexpr double default_smallest_single_precision_factor =
      assumed_last_level_cache_bytes / sizeof(double);

  /// Sets the number of nonzeros of the factor from which the next factorizations keep the
  /// single-precision copy.
  void single_precision_from(double entries) { m_smallest_single_precision_factor = entries; }

  /// Whether `solve_correction()` sweeps a single-precision copy of the factor.
  bool solves_corrections_in_single_precision() const { return !m_single.empty(); }

  /// One step of iterative refinement from `base`, a first approximation of the solution:
  /// `dest = base + A^{-1} residual`, where `residual` is `b - A base`, computed in double by the
  /// caller.  The correction is solved by the single-precision copy of the factor, in
  /// single-precision arithmetic, when there is one, else by `solve()`.  Its error, about 1e-7
  /// times the condition number of A, is relative to the correction, not to the solution; it is
  /// largest along the near-null space of A, which a caller that knows it sets exactly (the
  /// deformation sets the translation).  Sweeping in float rather than in double arithmetic
  /// halves the time of the sweeps (four floats per row in one SIMD register against two of two
  /// doubles) and leaves 1 to 10 times the error of the double arithmetic, at most 4e-4 of the
  /// correction on a 400 x 400 grid once the translation is set
  /// (benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver").
  /// `residual`, `base` and `dest` have the same size; `dest` may be neither of the others.
  template <class Base, class Residual, class Dest>
  void solve_correction(const Eigen::MatrixBase<Base>& base, const Eigen::MatrixBase<Residual>& residual,
                        Eigen::MatrixBase<Dest>& dest) const
  {
    if (!solves_corrections_in_single_precision()) {
      dest.derived() = this->solve(residual);
      dest.derived() += base;
      return;
    }
    solve_blocks<float, float>(residual, dest, [&](Eigen::Index row, Eigen::Index column, double correction) {
      return base(row, column) + correction;
    });
  }

  /// CHOLMOD's settings and statistics, which cholmod.h documents (for instance the ordering
  /// strategy of the next analyses, `nmethods` and `method[]`, or `lnz` after one).
  cholmod_common& cholmod() { return m_common; }

  /// The factor as CHOLMOD stores it (cholmod.h: a simplicial LDL^T `cholmod_factor`, its
  /// permutation in `Perm`), or null before an analysis; for tests and measurements.
  const cholmod_factor* factor() const { return m_factor; }

  /// How the sweeps are split over the elimination tree.
  const Elimination_subtrees& subtrees() const { return m_subtrees; }

  /// The number of supernodes (0 when the factor is neither swept nor copied).
  std::size_t number_of_supernodes() const { return m_super.empty() ? 0 : m_super.size() - 1; }

  /// The number of row indices the supernodes keep (their first columns' row lists).
  std::size_t number_of_supernode_row_indices() const { return m_rows.size(); }

  /// The nonzeros of the factor, which each sweep reads once.
  double number_of_entries() const { return m_factor ? double(m_common.lnz) : 0.; }

  /// \internal Eigen's solve() expression ends here.
  template <class Rhs, class Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest) const
  {
    if (!uses_supernodal_sweeps()) {
      cholmod_solve_into(b, dest);
      return;
    }
    solve_blocks<double, double>(b, dest, [](Eigen::Index, Eigen::Index, double value) { return value; });
  }

private:
  void free_factor()
  {
    if (m_factor)
      cholmod_free_factor(&m_factor, &m_common);
  }

  // The lower triangle of `matrix` as CHOLMOD reads a symmetric matrix (stype < 0: the entries
  // above the diagonal are ignored), without a copy.
  static cholmod_sparse lower_triangle_view(const Matrix_type& matrix)
  {
    cholmod_sparse view{};
    view.nrow = std::size_t(matrix.rows());
    view.ncol = std::size_t(matrix.cols());
    view.nzmax = std::size_t(matrix.nonZeros());
    view.p = const_cast<int*>(matrix.outerIndexPtr());
    view.i = const_cast<int*>(matrix.innerIndexPtr());
    view.x = const_cast<double*>(matrix.valuePtr());
    view.nz = matrix.isCompressed() ? nullptr : const_cast<int*>(matrix.innerNonZeroPtr());
    view.packed = matrix.isCompressed();
    view.sorted = 1;
    view.stype = -1;
    view.itype = CHOLMOD_INT;
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    return view;
  }

  // CHOLMOD's simplicial solve of all the columns of b.
  template <class Rhs, class Dest>
  void cholmod_solve_into(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest) const
  {
    // CHOLMOD reads column-major columns with a stride.
    const Eigen::Ref<const Eigen::MatrixXd> columns(b.derived());
    cholmod_dense rhs{};
    rhs.nrow = std::size_t(columns.rows());
    rhs.ncol = std::size_t(columns.cols());
    rhs.d = std::size_t(columns.outerStride());
    rhs.nzmax = rhs.d * rhs.ncol;
    rhs.x = const_cast<double*>(columns.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, m_factor, &rhs, &m_common);
    if (!x) {
      m_info = Eigen::NumericalIssue;
      return;
    }
    dest.derived() = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), b.rows(), b.cols());
    cholmod_free_dense(&x, &m_common);
  }

  // All columns of b, three at a time, solved by the sweeps with the factor's values in precision
  // `Value` and arithmetic in `Scalar`; dest(i, c) = result(i, c, the solution's entry).
  template <class Value, class Scalar, class Rhs, class Dest, class Result>
  void solve_blocks(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest,
                    const Result& result) const
  {
    dest.derived().resize(b.rows(), b.cols());
    for (Eigen::Index first = 0; first < b.cols(); first += 3) {
      switch (int((std::min)(Eigen::Index(3), b.cols() - first))) {
      case 1:
        solve_block<1, Value, Scalar>(b, dest, first, result);
        break;
      case 2:
        solve_block<2, Value, Scalar>(b, dest, first, result);
        break;
      default:
        solve_block<3, Value, Scalar>(b, dest, first, result);
      }
    }
  }

  // Whether every pivot of D is positive and finite (CHOLMOD's LDL^T accepts indefinite matrices).
  static bool has_positive_pivots(const cholmod_factor& factor)
  {
    const int* p = static_cast<const int*>(factor.p);
    const double* value = static_cast<const double*>(factor.x);
    for (std::size_t j = 0; j < factor.n; ++j) {
      const double d = value[p[j]]; // the diagonal comes first
      if (!(d > 0) || !std::isfinite(d))
        return false;
    }
    return true;
  }

  // The fundamental supernodes of the simplicial factor: column j + 1 continues one when it is
  // j's parent (the first row below j's diagonal) and has j's pattern minus j (one entry fewer:
  // the pattern of a column less its diagonal is contained in its parent's).
  void find_supernodes(const cholmod_factor& factor)
  {
    const int n = int(factor.n);
    const int* p = static_cast<const int*>(factor.p);
    const int* index = static_cast<const int*>(factor.i);
    const int* count = static_cast<const int*>(factor.nz);
    m_pi.assign(1, 0);
    m_largest_supernode_rows = 0;
    for (int c0 = 0; c0 < n;) {
      int k = 1;
      while (c0 + k < n && count[c0 + k - 1] == count[c0 + k] + 1 && count[c0 + k - 1] > 1 &&
             index[p[c0 + k - 1] + 1] == c0 + k)
        ++k;
      m_super.push_back(c0);
      m_pi.push_back(m_pi.back() + count[c0]);
      m_largest_supernode_rows = (std::max)(m_largest_supernode_rows, std::size_t(count[c0]));
      c0 += k;
    }
    m_super.push_back(n);
    m_rows.resize(std::size_t(m_pi.back()));
    for (std::size_t s = 0; s + 1 < m_super.size(); ++s)
      std::copy_n(index + p[m_super[s]], m_pi[s + 1] - m_pi[s], m_rows.begin() + m_pi[s]);
  }

  // The single-precision copy of the values, at the places CHOLMOD's factor has them.
  void copy_values(const cholmod_factor& factor)
  {
    const int* p = static_cast<const int*>(factor.p);
    const int* count = static_cast<const int*>(factor.nz);
    const double* value = static_cast<const double*>(factor.x);
    m_single.resize(factor.nzmax);
    for (std::size_t j = 0; j < factor.n; ++j)
      std::transform(value + p[j], value + p[j] + count[j], m_single.begin() + p[j],
                     [](double v) { return float(v); });
  }

  // The values the sweeps read in precision `Value`: CHOLMOD's, or their single-precision copy.
  template <class Value>
  const Value* values() const
  {
    if constexpr (std::is_same<Value, double>::value)
      return static_cast<const double*>(m_factor->x);
    else
      return m_single.data();
  }

  // The number of values the sweeps keep per row of the right-hand side for R columns: three
  // columns are padded to four, so that a row is one SIMD packet of four floats (or two of two
  // doubles) for Eigen's fixed-size arrays.  (Left to themselves, compilers vectorized the
  // sweeps' loops over the rows, transposing the interleaved rows at every step.)
  static constexpr int row_width(int R) { return R == 3 ? 4 : R; }

  // The rows of the right-hand side being swept and the gather buffers, in `Scalar`: kept from
  // one solve to the next (no allocation per solve), one set per arithmetic (m_workspaces).
  template <class Scalar>
  struct Workspace {
    std::vector<Scalar> rows;
    std::vector<std::vector<Scalar>> buffers; // one per group of subtrees, one more for the top
  };

  // Columns [first, first + R) of b, solved by the factor's values in precision `Value` with
  // arithmetic in `Scalar`; dest(i, c) = result(i, c, the solution's entry).
  template <int R, class Value, class Scalar, class Rhs, class Dest, class Result>
  void solve_block(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest, Eigen::Index first,
                   const Result& result) const
  {
    constexpr int W = row_width(R);
    const cholmod_factor* factor = m_factor;
    const int n = int(factor->n);
    const int* perm = static_cast<const int*>(factor->Perm);
    // Interleaved: the values of a row side by side, as the sweeps use them.
    std::vector<Scalar>& rows = std::get<Workspace<Scalar>>(m_workspaces).rows;
    rows.resize(std::size_t(n) * W);
    Scalar* z = rows.data();
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < R; ++c)
        z[std::size_t(i) * W + c] = Scalar(b(perm[i], first + c));
      for (int c = R; c < W; ++c)
        z[std::size_t(i) * W + c] = Scalar(0);
    }
    sweeps<W, Value>(z);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < R; ++c)
        dest(perm[i], first + c) = result(perm[i], first + c, double(z[std::size_t(i) * W + c]));
  }

  // L D L^T z = z in place (z interleaved, W values per row, permuted), with the factor's values
  // in precision `Value`.
  template <int W, class Value, class Scalar>
  void sweeps(Scalar* z) const
  {
    const cholmod_factor& factor = *m_factor;
    using Sweeper = Supernode_sweeper<W, Value, Scalar>;
    const Sweeper sweeper{m_super.data(),
                          m_pi.data(),
                          m_rows.data(),
                          static_cast<const int*>(factor.p),
                          static_cast<const int*>(factor.nz),
                          values<Value>(),
                          int(number_of_supernodes())};
    // One gather buffer per group of subtrees (and one more for the top).
    std::vector<std::vector<Scalar>>& buffers = std::get<Workspace<Scalar>>(m_workspaces).buffers;
    buffers.resize(std::size_t(Elimination_subtrees::number_of_groups + 1));
    for (std::vector<Scalar>& buffer : buffers)
      buffer.resize(Sweeper::buffer_size(m_largest_supernode_rows));
    m_subtrees.forward(z, W, [&](int s, Scalar* target, int split, int group) {
      sweeper.forward(s, z, target, split, buffers[std::size_t(group)].data());
    });
    m_subtrees.backward(
        [&](int s, int group) { sweeper.backward(s, z, buffers[std::size_t(group)].data()); });
  }

  // CHOLMOD's state: mutable, since CHOLMOD's solve records its statistics there.
  mutable cholmod_common m_common;
  cholmod_factor* m_factor = nullptr;
  mutable Eigen::ComputationInfo m_info = Eigen::Success;
  // The supernodes of CHOLMOD's factor: their first columns (and n at the end), the offsets of
  // their row lists in m_rows, the row lists (copies of their first columns' row indices).  The
  // values stay where CHOLMOD put them, swept there in double, or copied in single precision.
  std::vector<int> m_super, m_pi, m_rows;
  std::vector<float> m_single;
  bool m_sweeps = false;
  double m_smallest_swept_factor = default_smallest_swept_factor;
  double m_smallest_single_precision_factor = default_smallest_single_precision_factor;
  Elimination_subtrees m_subtrees;
  bool m_parallel = false;
  std::size_t m_largest_supernode_rows = 0;
  mutable std::tuple<Workspace<double>, Workspace<float>> m_workspaces;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_CHOLMOD_LDLT_SWEPT_H
