// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Variants of the package's sparse Cholesky that only the benchmarks measure, beside the
// default one (FAS::internal::Cholmod_LDLT_swept), and the bytes a solve reads from a factor:
//  - Cholmod_auto_LDLT: the former default, CHOLMOD's own choice of factorization;
//  - Benchmarked_LDLT_swept: the default solver with a forced fill-reducing ordering and, on
//    request, its solves swept with the single-precision copy of the factor;
//  - bytes_per_sweep(), bytes_per_correction_sweep(): what one sweep of a solve reads.
// benchmark/Flow_aligned_surfaces/RESULTS.md, "The solver", has their measurements.

#ifndef FAS_BENCHMARK_BENCH_SOLVERS_H
#define FAS_BENCHMARK_BENCH_SOLVERS_H

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD

#include <CGAL/Flow_aligned_surfaces/internal/solver/Cholmod_LDLT_swept.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Core>

#include <cstddef>

namespace fas_benchmark {

/// CHOLMOD's LDL^T: factored the way CHOLMOD's own switch chooses (simplicial when
/// flops / nnz(L) < 40, i.e. below about 5e3 faces; supernodal LL^T above, blocked BLAS-3), then
/// left by `cholmod_factorize` as a simplicial LDL^T factor
/// (`final_super = 0`, `final_ll = 0`) without the zeros of relaxed supernodal amalgamation
/// (`final_resymbol = 1`).  Not the package's default: its supernodal factorization starts OpenMP
/// threads and the BLAS's (internal/solver/Sparse_cholesky.h).
template <class MatrixType>
class Cholmod_auto_LDLT : public Eigen::CholmodBase<MatrixType, Eigen::Lower, Cholmod_auto_LDLT<MatrixType>> {
  using Base = Eigen::CholmodBase<MatrixType, Eigen::Lower, Cholmod_auto_LDLT<MatrixType>>;

public:
  Cholmod_auto_LDLT() : Base()
  {
    cholmod_common& common = this->cholmod();
    common.supernodal = CHOLMOD_AUTO;
    common.final_asis = 0;
    common.final_super = 0;
    common.final_ll = 0;
    common.final_pack = 1;
    common.final_monotonic = 1;
    common.final_resymbol = 1;
  }
};

/// The package's default solver with the CHOLMOD ordering `Ordering` (CHOLMOD_AMD, CHOLMOD_METIS,
/// CHOLMOD_NESDIS, ...) only, or CHOLMOD's default strategy when it is negative (AMD on these
/// meshes).  METIS's nested dissection gives up to 9 % fewer nonzeros on the patches of the
/// benchmark but no faster solve, and its analysis costs up to 18 times AMD's.  With
/// `SinglePrecisionSolves`, the factors the default solver sweeps keep the single-precision
/// copy, and solve() sweeps it as the corrections do (half the bytes; the solution's relative
/// error grows from about 1e-15 to about 1e-7).
template <int Ordering = -1, bool SinglePrecisionSolves = false>
class Benchmarked_LDLT_swept : public CGAL::Flow_aligned_surfaces::internal::Cholmod_LDLT_swept {
  using Base = CGAL::Flow_aligned_surfaces::internal::Cholmod_LDLT_swept;

public:
  Benchmarked_LDLT_swept()
  {
    if (SinglePrecisionSolves)
      single_precision_from(default_smallest_swept_factor);
  }

  // Flow_aligned_deformation calls these on the static type: they hide the base's.
  Benchmarked_LDLT_swept& compute(const Matrix_type& matrix)
  {
    analyzePattern(matrix);
    factorize(matrix);
    return *this;
  }

  void analyzePattern(const Matrix_type& matrix)
  {
    cholmod_common& common = cholmod();
    if (Ordering >= 0) {
      common.nmethods = 1;
      common.method[0].ordering = Ordering;
    }
    Base::analyzePattern(matrix);
    if (Ordering >= 0 && factor() == nullptr) {
      // An ordering this CHOLMOD was built without (METIS): its default strategy.
      common.nmethods = 0;
      Base::analyzePattern(matrix);
    }
  }

  template <class Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> x(b.rows(), b.cols());
    if (SinglePrecisionSolves && solves_corrections_in_single_precision())
      solve_correction(
          Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime>::Zero(b.rows(), b.cols()), b, x);
    else
      x = Base::solve(b);
    return x;
  }

  /// The fill-reducing ordering of the last analysis (CHOLMOD_AMD, CHOLMOD_METIS, ...; -1 if none).
  int ordering() const { return factor() ? factor()->ordering : -1; }
};

/// The bytes one supernodal sweep of `solver`'s factor reads: the values, in `value_size` bytes
/// each, the row indices of the first column of each supernode and the start of every column.
inline double
bytes_per_supernodal_sweep(const CGAL::Flow_aligned_surfaces::internal::Cholmod_LDLT_swept& solver,
                           std::size_t value_size)
{
  const double columns = double(solver.factor()->n);
  return solver.number_of_entries() * double(value_size) +
         double(solver.number_of_supernode_row_indices()) * sizeof(int) +
         (columns + 2. * double(solver.number_of_supernodes() + 1)) * sizeof(int);
}

/// The bytes one sweep of `solver.solve()` reads from the factor: the supernodal sweep's, or,
/// when CHOLMOD's simplicial solve is used, its values and a row index per value.
inline double bytes_per_sweep(const CGAL::Flow_aligned_surfaces::internal::Cholmod_LDLT_swept& solver)
{
  if (!solver.factor())
    return 0;
  if (!solver.uses_supernodal_sweeps())
    return solver.number_of_entries() * (sizeof(double) + sizeof(int)) +
           2. * double(solver.factor()->n) * sizeof(int);
  return bytes_per_supernodal_sweep(solver, sizeof(double));
}

/// The bytes one sweep of `solver.solve_correction()` reads from the factor.
inline double
bytes_per_correction_sweep(const CGAL::Flow_aligned_surfaces::internal::Cholmod_LDLT_swept& solver)
{
  if (!solver.solves_corrections_in_single_precision())
    return bytes_per_sweep(solver);
  return bytes_per_supernodal_sweep(solver, sizeof(float));
}

} // namespace fas_benchmark

#endif // CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD

#endif // FAS_BENCHMARK_BENCH_SOLVERS_H
