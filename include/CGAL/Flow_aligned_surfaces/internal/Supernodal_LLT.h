// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default sparse Cholesky of the package: CHOLMOD's simplicial LDL^T factorization
// (one thread, no BLAS: see Sparse_cholesky.h), repacked into supernodes for the
// back-substitutions, which the deformation pays every iteration (three coordinate columns)
// while it pays the factorization once.
//
// On these surfaces (2D meshes) the solve reads the whole factor twice, forward and backward.
// CHOLMOD's simplicial solve reads a row index with every value and walks the factor one column
// at a time.  Here the columns that share their pattern below the diagonal (the fundamental
// supernodes of the elimination tree: separators of the ordering, chains) are stored as one
// dense block with one list of row indices, so that each sweep reads each block's values in
// order for the three right-hand sides at once (supernodal LL^T, L scaled by sqrt(D)), in
// double or, with `FactorScalar = float`, in a single-precision copy (half the bytes; the
// solution's relative error grows from about 1e-15 to about 1e-7).  With `use_parallelism()`
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
  /// AMD on these meshes).  METIS's nested dissection gives 2 to 10 % fewer nonzeros on the
  /// patches of the benchmark but no faster solve, and its analysis costs 15 times AMD's
  /// (benchmark/Flow_aligned_surfaces/RESULTS.md, issue 18).
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
    if (this->m_info != Eigen::Success)
      return;
    // A factor below the threshold is solved by CHOLMOD: no copy (fresh memory costs a page
    // fault per 4 KiB, 10 us each on the benchmark's virtual machine).
    if (this->cholmod().lnz < m_smallest_swept_factor) {
      if (!has_positive_pivots(*this->m_cholmodFactor))
        this->m_info = Eigen::NumericalIssue;
      return;
    }
    if (!pack(*this->m_cholmodFactor)) {
      this->m_info = Eigen::NumericalIssue;
      return;
    }
    m_subtrees = Elimination_subtrees(int(m_super.size()) - 1, m_super.data(), m_pi.data(), m_rows.data());
    m_subtrees.use_parallelism(m_parallel);
  }

  /// Whether the sweeps run the independent subtrees on the threads of the caller's TBB arena
  /// (the result is the same bit for bit).
  void use_parallelism(bool parallel)
  {
    m_parallel = parallel;
    m_subtrees.use_parallelism(parallel);
  }

  /// From this many nonzeros of the factor on (by default), the factor is repacked and solve()
  /// sweeps the supernodes; below, CHOLMOD's own simplicial solve is used.  On the benchmark's
  /// patches the sweeps are 5 % faster than CHOLMOD's solve at 1.5e6 nonzeros (8e4 faces) and
  /// 15 % at 7e6 (3.2e5 faces), and the copy costs the factorization the page faults of its
  /// fresh memory (about 30 ms at 8e4 faces): so from about 1.5e5 faces on
  /// (benchmark/Flow_aligned_surfaces/RESULTS.md, issue 18).  The choice does not depend on
  /// `use_parallelism()`, so that the solutions do not either.
  static constexpr double default_smallest_swept_factor = 3e6;

  /// Sets the number of nonzeros of the factor from which the next factorizations are repacked
  /// and solved by the supernodal sweeps.
  void sweep_from(double entries) { m_smallest_swept_factor = entries; }

  /// Whether solve() uses the supernodal sweeps (else CHOLMOD's simplicial solve).
  bool uses_supernodal_sweeps() const { return !m_super.empty(); }

  /// The fill-reducing ordering of the last analysis (CHOLMOD_AMD, CHOLMOD_METIS, ...; -1 if none).
  int ordering() const { return this->m_cholmodFactor ? this->m_cholmodFactor->ordering : -1; }

  /// How the sweeps are split over the elimination tree.
  const Elimination_subtrees& subtrees() const { return m_subtrees; }

  /// The number of supernodes.
  std::size_t number_of_supernodes() const { return m_super.empty() ? 0 : m_super.size() - 1; }

  /// The nonzeros of the factor, which each sweep reads once.
  double number_of_entries() const
  {
    return uses_supernodal_sweeps() ? m_entries : this->m_cholmodFactor ? double(this->m_cholmod.lnz) : 0.;
  }

  /// The bytes one sweep of solve() reads from the factor: the values and the row indices of the
  /// supernodes, or, when CHOLMOD's simplicial solve is used, its values and a row index per value.
  double bytes_per_sweep() const
  {
    if (!this->m_cholmodFactor)
      return 0;
    if (!uses_supernodal_sweeps())
      return number_of_entries() * (sizeof(double) + sizeof(int)) + 2. * double(this->m_cholmodFactor->n) * sizeof(int);
    return number_of_entries() * sizeof(FactorScalar) + double(m_rows.size()) * sizeof(int) +
           double(m_super.size() + m_pi.size() + m_px.size()) * sizeof(int);
  }

  /// \internal Eigen's solve() expression ends here.
  template <class Rhs, class Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest) const
  {
    if (!uses_supernodal_sweeps()) {
      Base::_solve_impl(b, dest);
      return;
    }
    dest.derived().resize(b.rows(), b.cols());
    for (Eigen::Index first = 0; first < b.cols(); first += 3) {
      const int columns = int((std::min)(Eigen::Index(3), b.cols() - first));
      switch (columns) {
      case 1:
        solve_block<1>(b, dest, first);
        break;
      case 2:
        solve_block<2>(b, dest, first);
        break;
      default:
        solve_block<3>(b, dest, first);
      }
    }
  }

private:
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

  // Copies the simplicial LDL^T factor into supernodes of L sqrt(D); false if a pivot of D is
  // not positive (the matrix is not positive definite).
  bool pack(const cholmod_factor& factor)
  {
    const int n = int(factor.n);
    const int* p = static_cast<const int*>(factor.p);
    const int* index = static_cast<const int*>(factor.i);
    const int* count = static_cast<const int*>(factor.nz);
    const double* value = static_cast<const double*>(factor.x);
    // The supernodes: column j + 1 continues one when it is j's parent and has j's pattern minus j.
    m_super.clear();
    m_pi.assign(1, 0);
    m_px.assign(1, 0);
    for (int c0 = 0; c0 < n;) {
      int k = 1;
      while (c0 + k < n && count[c0 + k - 1] == count[c0 + k] + 1 && count[c0 + k - 1] > 1 &&
             index[p[c0 + k - 1] + 1] == c0 + k)
        ++k;
      m_super.push_back(c0);
      m_pi.push_back(m_pi.back() + count[c0]);
      m_px.push_back(m_px.back() + count[c0] * k);
      c0 += k;
    }
    m_super.push_back(n);
    // Their row lists and dense blocks.
    const std::size_t nsuper = m_super.size() - 1;
    m_rows.resize(std::size_t(m_pi.back()));
    m_values.assign(std::size_t(m_px.back()), FactorScalar(0));
    m_largest_supernode_rows = 0;
    m_entries = 0;
    for (std::size_t s = 0; s < nsuper; ++s) {
      const int c0 = m_super[s], k = m_super[s + 1] - c0, nrows = m_pi[s + 1] - m_pi[s];
      std::copy(index + p[c0], index + p[c0] + nrows, m_rows.begin() + m_pi[s]);
      for (int b = 0; b < k; ++b) {
        const int column = c0 + b;
        const double d = value[p[column]]; // the diagonal comes first
        if (!(d > 0) || !std::isfinite(d))
          return false;
        const double root = std::sqrt(d);
        FactorScalar* target = m_values.data() + m_px[s] + std::size_t(b) * nrows + b;
        target[0] = FactorScalar(root);
        for (int t = 1; t < count[column]; ++t)
          target[t] = FactorScalar(value[p[column] + t] * root);
      }
      m_largest_supernode_rows = (std::max)(m_largest_supernode_rows, std::size_t(nrows));
      m_entries += double(k) * nrows - double(k) * (k - 1) / 2;
    }
    return true;
  }

  // Columns [first, first + R) of b, solved into the same columns of dest.
  template <int R, class Rhs, class Dest>
  void solve_block(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest, Eigen::Index first) const
  {
    const cholmod_factor* factor = this->m_cholmodFactor;
    const int n = int(factor->n);
    const int* perm = static_cast<const int*>(factor->Perm);
    // Interleaved: the R values of a row side by side, as the sweeps use them.
    m_work.resize(std::size_t(n) * R);
    double* z = m_work.data();
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < R; ++c)
        z[std::size_t(i) * R + c] = b(perm[i], first + c);
    sweeps<R>(z);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < R; ++c)
        dest(perm[i], first + c) = z[std::size_t(i) * R + c];
  }

  // L L^T z = z in place (z interleaved, permuted).
  template <int R>
  void sweeps(double* z) const
  {
    const Supernode_sweeper<R> sweeper{m_super.data(), m_pi.data(), m_px.data(), m_rows.data(), m_values.data(),
                                       int(number_of_supernodes())};
    // One gather buffer per group of subtrees (and one more for the top).
    m_buffers.resize(std::size_t(Elimination_subtrees::number_of_groups + 1));
    for (std::vector<double>& buffer : m_buffers)
      buffer.resize(Supernode_sweeper<R>::buffer_size(m_largest_supernode_rows));
    m_subtrees.forward(z, R, [&](int s, double* target, int split, int group) {
      sweeper.forward(s, z, target, split, m_buffers[std::size_t(group)].data());
    });
    m_subtrees.backward([&](int s, int group) { sweeper.backward(s, z, m_buffers[std::size_t(group)].data()); });
  }

  // The dense work of one supernode: its block is nrows x k, column-major, the first k rows the
  // supernode's own columns (lower triangle used), the other rows scattered below.  The rows of
  // the right-hand side it touches are gathered into `buffer`, one contiguous array of nrows
  // values per right-hand side, and the block is swept in panels of `panel_width` columns: the
  // panel's small triangle, then all the rows below it at once, so that each gathered row is
  // read and written once per panel, on pairs of consecutive rows (two lanes a compiler
  // vectorizes).
  template <int R>
  struct Supernode_sweeper {
    static constexpr int panel_width = 4;
    // Supernodes of at most this many columns (most of them: chains of the tree are short) are
    // swept in place, row by row of the right-hand side, without the gather buffer.
    static constexpr int narrow_width = 4;

    // Calls f with std::integral_constant<int, width>, width in [1, narrow_width].
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

    // forward() of a supernode of K columns, in place.
    template <int K>
    void forward_narrow(int s, double* z, double* target, int split) const
    {
      const int c0 = super[s];
      const int nrows = pi[s + 1] - pi[s];
      const int* row = rows + pi[s];
      const FactorScalar* block = x + px[s];
      double v[K][R];
      for (int j = 0; j < K; ++j)
        for (int c = 0; c < R; ++c)
          v[j][c] = z[std::size_t(c0 + j) * R + c];
      for (int j = 0; j < K; ++j) {
        const FactorScalar* column = block + std::size_t(j) * nrows;
        for (int c = 0; c < R; ++c)
          v[j][c] /= double(column[j]);
        for (int i = j + 1; i < K; ++i)
          for (int c = 0; c < R; ++c)
            v[i][c] -= double(column[i]) * v[j][c];
      }
      for (int j = 0; j < K; ++j)
        for (int c = 0; c < R; ++c)
          z[std::size_t(c0 + j) * R + c] = v[j][c];
      const int end_z = split < 0 ? nrows : (std::max)(split, K);
      for (int i = K; i < nrows; ++i) {
        double* out = (i < end_z ? z : target) + std::size_t(row[i]) * R;
        double update[R] = {};
        for (int j = 0; j < K; ++j) {
          const double l = double(block[std::size_t(j) * nrows + i]);
          for (int c = 0; c < R; ++c)
            update[c] += l * v[j][c];
        }
        for (int c = 0; c < R; ++c)
          out[c] -= update[c];
      }
    }

    // backward() of a supernode of K columns, in place.
    template <int K>
    void backward_narrow(int s, double* z) const
    {
      const int c0 = super[s];
      const int nrows = pi[s + 1] - pi[s];
      const int* row = rows + pi[s];
      const FactorScalar* block = x + px[s];
      if (s > 0) {
        prefetch(x + px[s - 1], x + px[s]);
        prefetch_rows(z, s - 1);
      }
      double sum[K][R] = {};
      for (int i = K; i < nrows; ++i) {
        const double* in = z + std::size_t(row[i]) * R;
        for (int j = 0; j < K; ++j) {
          const double l = double(block[std::size_t(j) * nrows + i]);
          for (int c = 0; c < R; ++c)
            sum[j][c] += l * in[c];
        }
      }
      double v[K][R];
      for (int j = K - 1; j >= 0; --j) {
        const FactorScalar* column = block + std::size_t(j) * nrows;
        for (int c = 0; c < R; ++c) {
          double value = z[std::size_t(c0 + j) * R + c] - sum[j][c];
          for (int i = j + 1; i < K; ++i)
            value -= double(column[i]) * v[i][c];
          v[j][c] = value / double(column[j]);
        }
      }
      for (int j = 0; j < K; ++j)
        for (int c = 0; c < R; ++c)
          z[std::size_t(c0 + j) * R + c] = v[j][c];
    }
    /// The buffer a supernode of `nrows` rows needs.
    static std::size_t buffer_size(std::size_t nrows) { return nrows * R; }

    const int *super, *pi, *px, *rows;
    const FactorScalar* x;
    int super_count;

    // z := L11^{-1} z on the supernode's columns; then the updates -L21 z1 are added to the rows
    // below: those at positions [k, split) to z, those at [split, nrows) to `target` (a private
    // copy of the top rows, or z itself when split < 0).
    void forward(int s, double* z, double* target, int split, double* buffer) const
    {
      const int c0 = super[s], k = super[s + 1] - c0;
      const int nrows = pi[s + 1] - pi[s];
      const int* row = rows + pi[s];
      const FactorScalar* block = x + px[s];
      if (k <= narrow_width) {
        with_width(k, [&](auto width) { forward_narrow<decltype(width)::value>(s, z, target, split); });
        return;
      }
      // The rows of the right-hand side a supernode updates are scattered over it (its ancestors
      // in the elimination tree): ask for those of the next supernode while this one is computed.
      if (s + 1 < super_count)
        prefetch_rows(z, s + 1);
      double* v[R];
      for (int c = 0; c < R; ++c) {
        v[c] = buffer + std::size_t(c) * nrows;
        for (int i = 0; i < k; ++i)
          v[c][i] = z[std::size_t(c0 + i) * R + c];
        std::fill(v[c] + k, v[c] + nrows, 0.);
      }
      for (int j0 = 0; j0 < k; j0 += panel_width) {
        const int width = (std::min)(panel_width, k - j0);
        for (int j = j0; j < j0 + width; ++j) {
          const FactorScalar* column = block + std::size_t(j) * nrows;
          for (int c = 0; c < R; ++c) {
            v[c][j] /= double(column[j]);
            for (int i = j + 1; i < j0 + width; ++i)
              v[c][i] -= double(column[i]) * v[c][j];
          }
        }
        with_width(width, [&](auto b) { subtract_panel<decltype(b)::value>(block, nrows, j0, v); });
      }
      for (int i = 0; i < k; ++i)
        for (int c = 0; c < R; ++c)
          z[std::size_t(c0 + i) * R + c] = v[c][i];
      const int end_z = split < 0 ? nrows : (std::max)(split, k);
      for (int i = k; i < end_z; ++i)
        for (int c = 0; c < R; ++c)
          z[std::size_t(row[i]) * R + c] += v[c][i];
      for (int i = end_z; i < nrows; ++i)
        for (int c = 0; c < R; ++c)
          target[std::size_t(row[i]) * R + c] += v[c][i];
    }

    // z := L11^{-T} (z1 - L21^T z2) on the supernode's columns, z2 the final rows below.
    void backward(int s, double* z, double* buffer) const
    {
      const int c0 = super[s], k = super[s + 1] - c0;
      const int nrows = pi[s + 1] - pi[s];
      const int* row = rows + pi[s];
      const FactorScalar* block = x + px[s];
      if (k <= narrow_width) {
        with_width(k, [&](auto width) { backward_narrow<decltype(width)::value>(s, z); });
        return;
      }
      // The sweep runs down through memory, where the hardware prefetchers of common processors
      // do not follow: ask for the block and the rows of the supernode visited next (most often
      // s - 1) while this one is computed.
      if (s > 0) {
        prefetch(x + px[s - 1], x + px[s]);
        prefetch_rows(z, s - 1);
      }
      double* v[R];
      for (int c = 0; c < R; ++c) {
        v[c] = buffer + std::size_t(c) * nrows;
        for (int i = 0; i < k; ++i)
          v[c][i] = z[std::size_t(c0 + i) * R + c];
        for (int i = k; i < nrows; ++i)
          v[c][i] = z[std::size_t(row[i]) * R + c];
      }
      // The panels of forward(), last first: all the rows below the panel, then its triangle.
      for (int j0 = (k - 1) / panel_width * panel_width; j0 >= 0; j0 -= panel_width) {
        const int width = (std::min)(panel_width, k - j0);
        with_width(width, [&](auto b) { dot_panel<decltype(b)::value>(block, nrows, j0, v); });
        for (int j = j0 + width - 1; j >= j0; --j) {
          const FactorScalar* column = block + std::size_t(j) * nrows;
          for (int c = 0; c < R; ++c) {
            double sum = 0;
            for (int i = j + 1; i < j0 + width; ++i)
              sum += double(column[i]) * v[c][i];
            v[c][j] = (v[c][j] - sum) / double(column[j]);
          }
        }
      }
      for (int i = 0; i < k; ++i)
        for (int c = 0; c < R; ++c)
          z[std::size_t(c0 + i) * R + c] = v[c][i];
    }

    // The rows of supernode s below its own columns.
    void prefetch_rows(const double* z, int s) const
    {
#if defined(__GNUC__) || defined(__clang__)
      const int k = super[s + 1] - super[s];
      for (const int* row = rows + pi[s] + k; row < rows + pi[s + 1]; ++row)
        __builtin_prefetch(z + std::size_t(*row) * R);
#else
      (void)z;
      (void)s;
#endif
    }

    static void prefetch(const FactorScalar* begin, const FactorScalar* end)
    {
#if defined(__GNUC__) || defined(__clang__)
      for (const char* p = reinterpret_cast<const char*>(begin); p < reinterpret_cast<const char*>(end); p += 64)
        __builtin_prefetch(p);
#else
      (void)begin;
      (void)end;
#endif
    }

    // v[c][i] -= sum over the panel's columns b of L(i, j + b) v[c][j + b], for the rows i below
    // the panel: no sum runs across rows, so the loop over i vectorizes as it stands.
    template <int B>
    static void subtract_panel(const FactorScalar* block, int nrows, int j, double* const* v)
    {
      const FactorScalar* __restrict column[B];
      double p[B][R];
      for (int b = 0; b < B; ++b) {
        column[b] = block + std::size_t(j + b) * nrows;
        for (int c = 0; c < R; ++c)
          p[b][c] = v[c][j + b];
      }
      for (int c = 0; c < R; ++c) {
        double* __restrict vc = v[c];
        for (int i = j + B; i < nrows; ++i) {
          double update = 0;
          for (int b = 0; b < B; ++b)
            update += double(column[b][i]) * p[b][c];
          vc[i] -= update;
        }
      }
    }

    // v[c][j + b] -= sum over the rows i below the panel of L(i, j + b) v[c][i], for the panel's
    // columns b: even and odd rows summed apart, two lanes written out so that a compiler that
    // may not reorder a floating-point sum still pairs them.
    template <int B>
    static void dot_panel(const FactorScalar* block, int nrows, int j, double* const* v)
    {
      const FactorScalar* __restrict column[B];
      for (int b = 0; b < B; ++b)
        column[b] = block + std::size_t(j + b) * nrows;
      double sum[B][R][2] = {};
      int i = j + B;
      for (; i + 1 < nrows; i += 2)
        for (int c = 0; c < R; ++c) {
          const double* __restrict vc = v[c];
          for (int b = 0; b < B; ++b) {
            sum[b][c][0] += double(column[b][i]) * vc[i];
            sum[b][c][1] += double(column[b][i + 1]) * vc[i + 1];
          }
        }
      if (i < nrows)
        for (int c = 0; c < R; ++c)
          for (int b = 0; b < B; ++b)
            sum[b][c][0] += double(column[b][i]) * v[c][i];
      for (int b = 0; b < B; ++b)
        for (int c = 0; c < R; ++c)
          v[c][j + b] -= sum[b][c][0] + sum[b][c][1];
    }
  };

  // The factor L sqrt(D) by supernodes: first column, offsets of the row lists and of the dense
  // blocks (nrows x k, column-major), the row lists, the blocks.
  std::vector<int> m_super, m_pi, m_px, m_rows;
  std::vector<FactorScalar> m_values;
  double m_entries = 0;
  double m_smallest_swept_factor = default_smallest_swept_factor;
  int m_ordering = -1;
  Elimination_subtrees m_subtrees;
  bool m_parallel = false;
  std::size_t m_largest_supernode_rows = 0;
  mutable std::vector<double> m_work;
  mutable std::vector<std::vector<double>> m_buffers;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SUPERNODAL_LLT_H
