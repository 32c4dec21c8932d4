// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse Cholesky factorization behind every Poisson solve: factor once,
// back-substitute many right-hand sides.  The solver is a model of CGAL's
// SparseLinearAlgebraWithFactorTraits_d wrapping an Eigen solver
// (CGAL::Eigen_solver_traits<S>); its Eigen solver is used directly so that the
// three coordinate columns are solved in one call.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SPARSE_CHOLESKY_H

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
/// CHOLMOD's simplicial LDL^T with its fill-reducing ordering.  Measured against the supernodal
/// LL^T (benchmark/Flow_aligned_surfaces/RESULTS.md): its back-substitutions, paid every
/// iteration, are 1.6 to 2.8 times faster at every size, and its factorization, paid once, is
/// faster up to 2e4 faces and repaid within 7 (8e4 faces) to 30 (3.2e5) iterations above.
using Default_sparse_linear_solver =
    CGAL::Eigen_solver_traits<Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>>>;
#else
using Default_sparse_linear_solver =
    CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>;
#endif

/// Factors `matrix` with `solver`; throws std::runtime_error naming `what` when it fails.
template <class SparseLinearSolver>
void factor_or_throw(SparseLinearSolver& solver, const Eigen::SparseMatrix<double>& matrix,
                     const std::string& what)
{
  solver.solver().compute(matrix);
  if (solver.solver().info() != Eigen::Success)
    throw std::runtime_error("Flow_aligned_surfaces: the factorization of " + what +
                             " failed (the matrix is not positive definite)");
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_SPARSE_CHOLESKY_H
