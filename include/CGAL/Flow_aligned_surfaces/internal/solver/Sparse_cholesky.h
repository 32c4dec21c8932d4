// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse Cholesky factorization behind every Poisson solve: factor once,
// back-substitute many right-hand sides.  The solver is a model of CGAL's
// SparseLinearAlgebraWithFactorTraits_d wrapping an Eigen solver
// (CGAL::Eigen_solver_traits<S>); its Eigen solver is used directly so that the
// three coordinate columns are solved in one call.
//
// Threads: the default solver starts none (its back-substitutions use the caller's TBB arena
// only when asked, use_parallelism_in()).  CHOLMOD's simplicial LDL^T calls no BLAS and runs no
// OpenMP loop; CHOLMOD 3's supernodal factorization does both (loops with
// num_threads(CHOLMOD_OMP_NUM_THREADS) = 4, which omp_set_num_threads() cannot lower, and
// dgemm/dsyrk of the system's BLAS, OpenBLAS with its own thread pool on Debian); the threads
// of both spin after their work and, on a loaded machine, steal the cores of the caller.  CHOLMOD
// 3 has no Common->nthreads_max (CHOLMOD 4 has), and the other knobs (omp_set_*,
// openblas_set_num_threads) change the whole process, so the supernodal factorization is not the
// default: a user who wants it passes it as the SparseLinearSolver and controls its threads with
// the environment (OMP_THREAD_LIMIT, OPENBLAS_NUM_THREADS).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_SPARSE_CHOLESKY_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_SPARSE_CHOLESKY_H

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
#include <CGAL/Flow_aligned_surfaces/internal/solver/Cholmod_LDLT_swept.h>
#endif

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
/// CHOLMOD's simplicial LDL^T (fill-reducing ordering by CHOLMOD's default strategy): one thread,
/// no BLAS; on large factors, its back-substitutions sweep the factor by supernodes where CHOLMOD
/// stores it, the three coordinate columns at once, in parallel over independent subtrees when
/// asked (Cholmod_LDLT_swept.h).
using Default_sparse_linear_solver = CGAL::Eigen_solver_traits<Cholmod_LDLT_swept>;
#else
using Default_sparse_linear_solver =
    CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>;
#endif

/// Lets `solver` use the threads of the caller's TBB arena in its solves when `parallel`, if it
/// can (the package's default solver can; the results are the same bit for bit).
template <class EigenSolver>
void use_parallelism_in(EigenSolver&, bool)
{
}
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
inline void use_parallelism_in(Cholmod_LDLT_swept& solver, bool parallel)
{
  solver.use_parallelism(parallel);
}
#endif

/// `dest = base + A^{-1} residual`, `residual = b - A base` computed by the caller in double: one
/// step of iterative refinement from `base`, a first approximation of the solution of `A x = b`,
/// with `solver`, an Eigen solver of A.  The package's default solver sweeps the correction with
/// a single-precision copy of a large factor (Cholmod_LDLT_swept::solve_correction()); any other
/// solves it as it solves everything.
template <class EigenSolver, class Base, class Residual, class Dest>
auto solve_correction(const EigenSolver& solver, const Base& base, const Residual& residual, Dest& dest, int)
    -> decltype(solver.solve_correction(base, residual, dest), void())
{
  solver.solve_correction(base, residual, dest);
}
template <class EigenSolver, class Base, class Residual, class Dest>
void solve_correction(const EigenSolver& solver, const Base& base, const Residual& residual, Dest& dest, long)
{
  dest = solver.solve(residual);
  dest += base;
}
template <class EigenSolver, class Base, class Residual, class Dest>
void solve_correction(const EigenSolver& solver, const Base& base, const Residual& residual, Dest& dest)
{
  solve_correction(solver, base, residual, dest, 0);
}

/// Throws std::runtime_error naming `what` when the last factorization of `solver` failed.
template <class SparseLinearSolver>
void throw_if_factorization_failed(SparseLinearSolver& solver, const std::string& what)
{
  if (solver.solver().info() != Eigen::Success)
    throw std::runtime_error("Flow_aligned_surfaces: the factorization of " + what +
                             " failed (the matrix is not positive definite)");
}

/// Factors `matrix` with `solver`; throws std::runtime_error naming `what` when it fails.
template <class SparseLinearSolver>
void factor_or_throw(SparseLinearSolver& solver, const Eigen::SparseMatrix<double>& matrix,
                     const std::string& what)
{
  solver.solver().compute(matrix);
  throw_if_factorization_failed(solver, what);
}

/// The numerical factorization of `matrix` by a solver whose `analyzePattern()` has seen a
/// matrix of the same pattern; throws as `factor_or_throw()`.
template <class SparseLinearSolver>
void factor_pattern_or_throw(SparseLinearSolver& solver, const Eigen::SparseMatrix<double>& matrix,
                             const std::string& what)
{
  solver.solver().factorize(matrix);
  throw_if_factorization_failed(solver, what);
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SOLVER_SPARSE_CHOLESKY_H
