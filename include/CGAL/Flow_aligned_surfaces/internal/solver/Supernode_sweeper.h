// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The dense kernels of the supernodal back-substitutions of Cholmod_LDLT_swept.h: L D L^T z = z
// for one supernode at a time, on a simplicial LDL^T factor as CHOLMOD stores it (column by
// column, the diagonal D_jj first, then the entries of the unit L below it), with the
// right-hand side interleaved (W values per row, side by side).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_SUPERNODE_SWEEPER_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_SUPERNODE_SWEEPER_H

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

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

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_SUPERNODE_SWEEPER_H
