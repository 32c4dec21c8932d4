// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The factorization of L + W in its two phases, through the Eigen solver that a
// SparseLinearAlgebraWithFactorTraits_d model (CGAL::Eigen_solver_traits<S>) wraps:
// the symbolic analysis (fill-reducing ordering, elimination tree, column counts), which
// depends on the sparsity pattern only, and the numeric factorization.  Timed apart, so that a
// caller can tell which one it waits for.  `S::compute(A)` is `analyzePattern(A)` followed by
// `factorize(A)` in every Eigen sparse Cholesky solver (CHOLMOD's and Eigen's own), so this is
// the same factorization.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TIMED_FACTORIZATION_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TIMED_FACTORIZATION_H

#include <CGAL/Flow_aligned_surfaces/internal/solver/Sparse_cholesky.h>

#include <Eigen/Sparse>

#include <chrono>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

struct Factorization_times {
  double analyze_ms = 0, factorize_ms = 0;
};

/// Factors `matrix` with `solver` (analysis, then numeric factorization) and returns the time of
/// each phase; throws std::runtime_error naming `what` when the factorization fails.
template <class SparseLinearSolver>
Factorization_times timed_factor_or_throw(SparseLinearSolver& solver,
                                          const Eigen::SparseMatrix<double>& matrix, const std::string& what)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  solver.solver().analyzePattern(matrix);
  const auto analyzed = Clock::now();
  factor_pattern_or_throw(solver, matrix, what);
  const auto end = Clock::now();
  return {std::chrono::duration<double, std::milli>(analyzed - start).count(),
          std::chrono::duration<double, std::milli>(end - analyzed).count()};
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TIMED_FACTORIZATION_H
