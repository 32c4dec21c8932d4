// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default sparse Cholesky of the package: CHOLMOD's simplicial LDL^T factorization
// (one thread, no BLAS: see Sparse_cholesky.h), whose back-substitutions, which the deformation
// pays every iteration (three coordinate columns) while it pays the factorization once, are
// swept here by supernodes on large factors.
//
// On these surfaces (2D meshes) the solve reads the whole factor twice, forward and backward.
// CHOLMOD's simplicial solve reads a row index with every value.  Here the columns that share
// their pattern below the diagonal (the fundamental supernodes of the elimination tree:
// separators of the ordering, chains) are swept as one lower trapezoid, where CHOLMOD stores
// them (column by column, D then the unit L below it), with one list of row indices per
// supernode (the only copy: about 15 % of the factor's entries, as ints), so that each sweep
// reads the values in order for the three right-hand sides at once, in double or, with
// `FactorScalar = float`, in a single-precision copy of the values (half the bytes; the
// solution's relative error grows from about 1e-15 to about 1e-7).  A double factor also keeps
// that copy on large factors for `solve_correction()`: one step of iterative refinement in double
// from a first approximation the caller already has (the deformation's current surface), whose
// correction is swept in single precision, the copy's values and the arithmetic (four floats per
// row: one SIMD register), to an error proportional to the correction, not to the solution (about
// 1e-7 times the condition number).  With `use_parallelism()`
// the independent subtrees of the elimination tree are swept on the threads of the caller's
// TBB arena (Elimination_subtrees.h); the result is the same bit for bit.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SUPERNODAL_LLT_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SUPERNODAL_LLT_H

#include <CGAL/Flow_aligned_surfaces/internal/Elimination_subtrees.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

template <class FactorScalar = double>
class Supernodal_LLT
    : public Eigen::CholmodBase<Eigen::SparseMatrix<double>, Eigen::Lower, Supernodal_LLT<FactorScalar>> {
  using Base = Eigen::CholmodBase<Eigen::SparseMatrix<double>, Eigen::Lower, Supernodal_LLT<FactorScalar>>;

public:
  using Matrix_type = Eigen::SparseMatrix<double>;

  Supernodal_LLT() : Base()
  {
    cholmod_common& common = this->cholmod();
    common.supernodal = CHOLMOD_SIMPLICIAL;
    common.final_asis = 1;
  }

  /// Analysis and numerical factorization.
  Supernodal_LLT& compute(const Matrix_type& matrix)
  {
    analyzePattern(matrix);
    factorize(matrix);
    return *this;
  }

  /// Makes the next analyses use the CHOLMOD ordering `ordering` (CHOLMOD_AMD, CHOLMOD_METIS,
  /// CHOLMOD_NESDIS, ...) only, or CHOLMOD's default strategy when it is negative (the default:
  /// AMD on these meshes).  METIS's nested dissection gives up to 9 % fewer nonzeros on the
  /// patches of the benchmark but no faster solve, and its analysis costs up to 18 times AMD's
  /// (benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver").
  void use_ordering(int ordering) { m_ordering = ordering; }

  /// The symbolic analysis (fill-reducing ordering and pattern of the factor).
  void analyzePattern(const Matrix_type& matrix)
  {
    cholmod_common& common = this->cholmod();
    common.nmethods = m_ordering >= 0 ? 1 : 0;
    common.method[0].ordering = m_ordering >= 0 ? m_ordering : CHOLMOD_AMD;
    Base::analyzePattern(matrix);
    if (m_ordering >= 0 && this->m_cholmodFactor == nullptr) {
      // An ordering this CHOLMOD was built without (METIS): its default strategy.
      common.nmethods = 0;
      Base::analyzePattern(matrix);
    }
  }

  /// The numerical factorization of a matrix with the pattern seen by `analyzePattern()`.
  void factorize(const Matrix_type& matrix)
  {
    Base::factorize(matrix);
    m_subtrees = Elimination_subtrees();
    m_super.clear();
    m_single.clear();
    m_sweeps = false;
    if (this->m_info != Eigen::Success)
      return;
    const cholmod_factor& factor = *this->m_cholmodFactor;
    if (!has_positive_pivots(factor)) {
      this->m_info = Eigen::NumericalIssue;
      return;
    }
    const double entries = this->cholmod().lnz;
    m_sweeps = entries >= m_smallest_swept_factor;
    const bool single_copy = std::is_same<FactorScalar, float>::value ? m_sweeps
                                                                      : entries >= m_smallest_single_precision_factor;
    if (!m_sweeps && !single_copy)
      return;
    find_supernodes(factor);
    if (single_copy)
      copy_values(factor);
    m_subtrees = Elimination_subtrees(int(number_of_supernodes()), m_super.data(), m_pi.data(), m_rows.data());
    m_subtrees.use_parallelism(m_parallel);
  }

  /// Whether the sweeps run the independent subtrees on the threads of the caller's TBB arena
  /// (the result is the same bit for bit).
  void use_parallelism(bool parallel)
  {
    m_parallel = parallel;
    m_subtrees.use_parallelism(parallel);
  }

  /// From this many nonzeros of the factor on (by default), solve() sweeps the supernodes;
  /// below, CHOLMOD's own simplicial solve is used.  Sweeping CHOLMOD's factor in place copies
  /// only the row lists (5 MB instead of 63 MB at 3.2e5 faces), but the sweeps are no faster
  /// than CHOLMOD's solve below about 1e5 faces: 22 to 36 % slower at 5e3 and 2e4 faces (the
  /// factor in the caches, CHOLMOD's kernel does less per entry), as fast within the noise at 8e4
  /// (1.5e6 nonzeros), up to 15 % faster at 3.2e5 (7e6 nonzeros); so from about 1.5e5 faces on
  /// (benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver").  The choice does not
  /// depend on `use_parallelism()`, so that the solutions do not either.
  static constexpr double default_smallest_swept_factor = 3e6;

  /// Sets the number of nonzeros of the factor from which the next factorizations are solved by
  /// the supernodal sweeps.
  void sweep_from(double entries) { m_smallest_swept_factor = entries; }

  /// Whether solve() uses the supernodal sweeps (else CHOLMOD's simplicial solve).
  bool uses_supernodal_sweeps() const { return m_sweeps; }

  /// From this many nonzeros of the factor on (by default), a double factor also keeps its values
  /// in single precision for `solve_correction()` (4 more bytes per nonzero, made by each
  /// factorization: 25 to 35 ms of the first construction at 8e4 faces, most of it page faults).
  /// Its sweeps read half the bytes of the double factor's and compute in single precision: the
  /// iterations' SOLVE takes half the time of CHOLMOD's solve at 8e4 faces (1.5e6 nonzeros) and
  /// 40 % less than the double sweeps at 3.2e5 (benchmark/Flow_aligned_surfaces/RESULTS.md,
  /// "The solver");
  /// below 1e6 nonzeros (about 5e4 faces) the copy would cost more than a short alignment saves.
  static constexpr double default_smallest_single_precision_factor = 1e6;

  /// Sets the number of nonzeros of the factor from which the next factorizations keep the
  /// single-precision copy (ignored by a single-precision factor, which is swept in single
  /// precision whenever it is swept).
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

  /// The fill-reducing ordering of the last analysis (CHOLMOD_AMD, CHOLMOD_METIS, ...; -1 if none).
  int ordering() const { return this->m_cholmodFactor ? this->m_cholmodFactor->ordering : -1; }

  /// How the sweeps are split over the elimination tree.
  const Elimination_subtrees& subtrees() const { return m_subtrees; }

  /// The number of supernodes.
  std::size_t number_of_supernodes() const { return m_super.empty() ? 0 : m_super.size() - 1; }

  /// The nonzeros of the factor, which each sweep reads once.
  double number_of_entries() const { return this->m_cholmodFactor ? double(this->m_cholmod.lnz) : 0.; }

  /// The bytes one sweep of solve() reads from the factor: its values, the row indices of the
  /// first column of each supernode and the start of every column, or, when CHOLMOD's simplicial
  /// solve is used, its values and a row index per value.
  double bytes_per_sweep() const
  {
    if (!this->m_cholmodFactor)
      return 0;
    const double columns = double(this->m_cholmodFactor->n);
    if (!uses_supernodal_sweeps())
      return number_of_entries() * (sizeof(double) + sizeof(int)) + 2. * columns * sizeof(int);
    return bytes_per_supernodal_sweep(sizeof(FactorScalar));
  }

  /// The bytes one sweep of `solve_correction()` reads from the factor.
  double bytes_per_correction_sweep() const
  {
    if (!solves_corrections_in_single_precision())
      return bytes_per_sweep();
    return bytes_per_supernodal_sweep(sizeof(float));
  }

  /// \internal Eigen's solve() expression ends here.
  template <class Rhs, class Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest) const
  {
    if (!uses_supernodal_sweeps()) {
      Base::_solve_impl(b, dest);
      return;
    }
    solve_blocks<FactorScalar, double>(b, dest,
                                       [](Eigen::Index, Eigen::Index, double value) { return value; });
  }

private:
  // The bytes one supernodal sweep reads: the values, in `value_size` bytes each, the row indices
  // of the first column of each supernode and the start of every column.
  double bytes_per_supernodal_sweep(std::size_t value_size) const
  {
    const double columns = double(this->m_cholmodFactor->n);
    return number_of_entries() * double(value_size) + double(m_rows.size()) * sizeof(int) +
           (columns + 2. * double(m_super.size())) * sizeof(int);
  }

  // All columns of b, three at a time, solved by the sweeps with the factor's values in precision
  // `Value` and arithmetic in `Scalar`; dest(i, c) = result(i, c, the solution's entry).
  template <class Value, class Scalar, class Rhs, class Dest, class Result>
  void solve_blocks(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest, const Result& result) const
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
      return static_cast<const double*>(this->m_cholmodFactor->x);
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
    const cholmod_factor* factor = this->m_cholmodFactor;
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
    const cholmod_factor& factor = *this->m_cholmodFactor;
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

  // The dense work of one supernode of k columns, a lower trapezoid stored as CHOLMOD stores it:
  // column c0 + j holds D_jj then the entries of the unit L below it, at the rows of positions
  // j, j + 1, ... of the supernode's row list (that of its first column), so that column(s, j)[i]
  // is the entry at position i >= j.  Forward: z1 := L11^{-1} z1, z2 -= L21 z1, then z1 := D^{-1} z1;
  // backward: z1 := L11^{-T} (z1 - L21^T z2).  Each row of the right-hand side is W values of
  // `Scalar` side by side, handled as one Eigen array (one or two SIMD registers), times one entry
  // of the factor at a time.  Wide supernodes gather the rows they touch into `buffer` and are
  // swept in panels of `panel_width` columns: the panel's small triangle, then all the rows below
  // it at once, so that each gathered row is read and written once per panel.
  template <int W, class Value, class Scalar>
  struct Supernode_sweeper {
    static constexpr int panel_width = 4;
    // Supernodes of at most this many columns (most of them: chains of the tree are short) are
    // swept in place, without the gather buffer.
    static constexpr int narrow_width = 4;

    using Row = Eigen::Array<Scalar, W, 1>;
    using Row_map = Eigen::Map<Row>;

    // Calls f with std::integral_constant<int, width>, width in [1, panel_width].
    template <class F>
    static void with_width(int width, const F& f)
    {
      switch (width) {
      case 1:
        f(std::integral_constant<int, 1>());
        break;
      case 2:
        f(std::integral_constant<int, 2>());
        break;
      case 3:
        f(std::integral_constant<int, 3>());
        break;
      default:
        f(std::integral_constant<int, 4>());
      }
    }

    /// The buffer a supernode of `nrows` rows needs.
    static std::size_t buffer_size(std::size_t nrows) { return nrows * W; }

    const int *super, *pi, *rows, *start, *count;
    const Value* x;
    int super_count;

    int columns_of(int s) const { return super[s + 1] - super[s]; }
    int rows_of(int s) const { return pi[s + 1] - pi[s]; }
    const int* row_list(int s) const { return rows + pi[s]; }
    // Column j of supernode s, indexed by the position in the row list (valid from j on).
    const Value* column(int s, int j) const { return x + (std::ptrdiff_t(start[super[s] + j]) - j); }
    // Row i of the interleaved rows z.
    static Row_map row_at(Scalar* z, int i) { return Row_map(z + std::size_t(i) * W); }

    // The K columns of supernode s from column j on, and the entry of column b at position i.
    template <int K>
    struct Columns {
      const Value* l[K];
      Columns(const Supernode_sweeper& sweeper, int s, int j)
      {
        for (int b = 0; b < K; ++b)
          l[b] = sweeper.column(s, j + b);
      }
      Scalar operator()(int b, int i) const { return Scalar(l[b][i]); }
      // The sum over b of L(i, b) p[b].
      Row combination(int i, const Row (&p)[K]) const
      {
        Row update = (*this)(0, i) * p[0];
        for (int b = 1; b < K; ++b)
          update += (*this)(b, i) * p[b];
        return update;
      }
    };

    // forward() of a supernode of K columns, in place.
    template <int K>
    void forward_narrow(int s, Scalar* z, Scalar* target, int split) const
    {
      const int c0 = super[s];
      const int nrows = rows_of(s);
      const int* row = row_list(s);
      const Columns<K> l(*this, s, 0);
      Row v[K];
      for (int j = 0; j < K; ++j)
        v[j] = row_at(z, c0 + j);
      for (int j = 0; j < K; ++j)
        for (int i = j + 1; i < K; ++i)
          v[i] -= l(j, i) * v[j];
      for (int j = 0; j < K; ++j)
        row_at(z, c0 + j) = v[j] / l(j, j);
      const int end_z = split < 0 ? nrows : (std::max)(split, K);
      for (int i = K; i < nrows; ++i)
        row_at(i < end_z ? z : target, row[i]) -= l.combination(i, v);
    }

    // backward() of a supernode of K columns, in place.
    template <int K>
    void backward_narrow(int s, Scalar* z) const
    {
      const int c0 = super[s];
      const int nrows = rows_of(s);
      const int* row = row_list(s);
      const Columns<K> l(*this, s, 0);
      Row sum[K];
      for (int j = 0; j < K; ++j)
        sum[j].setZero();
      for (int i = K; i < nrows; ++i) {
        const Row in = row_at(z, row[i]);
        for (int j = 0; j < K; ++j)
          sum[j] += l(j, i) * in;
      }
      for (int j = K - 1; j >= 0; --j) {
        Row value = row_at(z, c0 + j) - sum[j];
        for (int i = j + 1; i < K; ++i)
          value -= l(j, i) * row_at(z, c0 + i);
        row_at(z, c0 + j) = value;
      }
    }

    // The updates of the rows at positions [k, split) go to z, those at [split, nrows) to
    // `target` (a private copy of the top rows, or z itself when split < 0).
    void forward(int s, Scalar* z, Scalar* target, int split, Scalar* buffer) const
    {
      const int c0 = super[s], k = columns_of(s);
      const int nrows = rows_of(s);
      const int* row = row_list(s);
      if (k <= narrow_width) {
        with_width(k, [&](auto width) { forward_narrow<decltype(width)::value>(s, z, target, split); });
        return;
      }
      // The rows of the right-hand side a supernode updates are scattered over it (its ancestors
      // in the elimination tree): ask for those of the next supernode while this one is computed.
      if (s + 1 < super_count)
        prefetch_rows(z, s + 1);
      std::copy_n(z + std::size_t(c0) * W, std::size_t(k) * W, buffer);
      std::fill(buffer + std::size_t(k) * W, buffer + std::size_t(nrows) * W, Scalar(0));
      for (int j0 = 0; j0 < k; j0 += panel_width)
        with_width((std::min)(panel_width, k - j0),
                   [&](auto b) { forward_panel<decltype(b)::value>(s, nrows, j0, buffer); });
      for (int i = 0; i < k; ++i)
        row_at(z, c0 + i) = row_at(buffer, i) / Scalar(column(s, i)[i]);
      const int end_z = split < 0 ? nrows : (std::max)(split, k);
      for (int i = k; i < nrows; ++i)
        row_at(i < end_z ? z : target, row[i]) += row_at(buffer, i);
    }

    void backward(int s, Scalar* z, Scalar* buffer) const
    {
      const int c0 = super[s], k = columns_of(s);
      const int nrows = rows_of(s);
      const int* row = row_list(s);
      // The sweep runs down through memory, where the hardware prefetchers of common processors
      // do not follow: ask for the values and the rows of the supernode visited next (most often
      // s - 1) while this one is computed.
      if (s > 0) {
        prefetch_values(s - 1);
        prefetch_rows(z, s - 1);
      }
      if (k <= narrow_width) {
        with_width(k, [&](auto width) { backward_narrow<decltype(width)::value>(s, z); });
        return;
      }
      std::copy_n(z + std::size_t(c0) * W, std::size_t(k) * W, buffer);
      for (int i = k; i < nrows; ++i)
        row_at(buffer, i) = row_at(z, row[i]);
      // The panels of forward(), last first.
      for (int j0 = (k - 1) / panel_width * panel_width; j0 >= 0; j0 -= panel_width)
        with_width((std::min)(panel_width, k - j0),
                   [&](auto b) { backward_panel<decltype(b)::value>(s, nrows, j0, buffer); });
      std::copy_n(buffer, std::size_t(k) * W, z + std::size_t(c0) * W);
    }

    // The rows of supernode s below its own columns.
    void prefetch_rows(const Scalar* z, int s) const
    {
#if defined(__GNUC__) || defined(__clang__)
      const int* row = row_list(s);
      for (int i = columns_of(s); i < rows_of(s); ++i)
        __builtin_prefetch(z + std::size_t(row[i]) * W);
#else
      (void)z;
      (void)s;
#endif
    }

    // The values of supernode s.
    void prefetch_values(int s) const
    {
#if defined(__GNUC__) || defined(__clang__)
      for (int j = super[s]; j < super[s + 1]; ++j)
        for (const char* p = reinterpret_cast<const char*>(x + start[j]);
             p < reinterpret_cast<const char*>(x + start[j] + count[j]); p += 64)
          __builtin_prefetch(p);
#else
      (void)s;
#endif
    }

    // The panel of columns [j, j + B) of the gathered rows v: its triangle, then
    // v[i] -= sum over b of L(i, j + b) v[j + b] for every row i below it.
    template <int B>
    void forward_panel(int s, int nrows, int j, Scalar* v) const
    {
      const Columns<B> l(*this, s, j);
      for (int b = 0; b < B; ++b)
        for (int i = b + 1; i < B; ++i)
          row_at(v, j + i) -= l(b, j + i) * row_at(v, j + b);
      Row p[B];
      for (int b = 0; b < B; ++b)
        p[b] = row_at(v, j + b);
      for (int i = j + B; i < nrows; ++i)
        row_at(v, i) -= l.combination(i, p);
    }

    // backward of the panel of columns [j, j + B): v[j + b] -= sum over the rows i below the
    // panel of L(i, j + b) v[i], then the panel's triangle, last column first.
    template <int B>
    void backward_panel(int s, int nrows, int j, Scalar* v) const
    {
      const Columns<B> l(*this, s, j);
      Row sum[B];
      for (int b = 0; b < B; ++b)
        sum[b].setZero();
      for (int i = j + B; i < nrows; ++i) {
        const Row in = row_at(v, i);
        for (int b = 0; b < B; ++b)
          sum[b] += l(b, i) * in;
      }
      for (int b = B - 1; b >= 0; --b) {
        Row value = row_at(v, j + b) - sum[b];
        for (int i = b + 1; i < B; ++i)
          value -= l(b, j + i) * row_at(v, j + i);
        row_at(v, j + b) = value;
      }
    }
  };

  // The supernodes of CHOLMOD's factor: their first columns (and n at the end), the offsets of
  // their row lists in m_rows, the row lists (copies of their first columns' row indices).  The
  // values stay where CHOLMOD put them, swept there in double, or copied in single precision.
  std::vector<int> m_super, m_pi, m_rows;
  std::vector<float> m_single;
  bool m_sweeps = false;
  double m_smallest_swept_factor = default_smallest_swept_factor;
  double m_smallest_single_precision_factor = default_smallest_single_precision_factor;
  int m_ordering = -1;
  Elimination_subtrees m_subtrees;
  bool m_parallel = false;
  std::size_t m_largest_supernode_rows = 0;
  mutable std::tuple<Workspace<double>, Workspace<float>> m_workspaces;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SUPERNODAL_LLT_H
