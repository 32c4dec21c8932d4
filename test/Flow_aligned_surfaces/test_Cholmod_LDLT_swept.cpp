// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default solver's own back-substitutions (internal/solver/Cholmod_LDLT_swept.h) against
// CHOLMOD's simplicial solve of the same matrix (the peer) and against the residual, and the
// schedule of internal/solver/Elimination_subtrees.h against the rules of a triangular sweep,
// checked on a tree built here by hand.

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD

#include <CGAL/Flow_aligned_surfaces/internal/solver/Cholmod_LDLT_swept.h>
#include <CGAL/Flow_aligned_surfaces/internal/solver/Elimination_subtrees.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace {

namespace FASI = CGAL::Flow_aligned_surfaces::internal;
using Sparse_matrix = Eigen::SparseMatrix<double>;

// The cotangent-free Laplacian of an m x m grid cut into triangles (each node linked to its
// four neighbours and along one diagonal), plus `shift` on the diagonal of the middle node: the
// structure of L + W of a planar patch, symmetric positive definite.
Sparse_matrix triangulated_grid_laplacian(int m, double shift = 6e-3)
{
  std::vector<Eigen::Triplet<double>> triplets;
  const int offsets[6][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}};
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int node = i * m + j;
      double degree = 0;
      for (const auto& o : offsets) {
        const int a = i + o[0], b = j + o[1];
        if (a < 0 || b < 0 || a >= m || b >= m)
          continue;
        triplets.emplace_back(node, a * m + b, -1.);
        degree += 1;
      }
      triplets.emplace_back(node, node, degree + (i == m / 2 && j == m / 2 ? shift : 0.));
    }
  Sparse_matrix matrix(m * m, m * m);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return (a - b).norm() / b.norm();
}

TEST(CholmodLDLTSwept, SweepsSolveLikeCholmodForAnyNumberOfColumns)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(60);
  FASI::Cholmod_LDLT_swept solver;
  solver.sweep_from(0); // the sweeps even on this small factor
  solver.compute(matrix);
  ASSERT_EQ(solver.info(), Eigen::Success);
  ASSERT_TRUE(solver.uses_supernodal_sweeps());
  EXPECT_GT(solver.number_of_supernodes(), 10u);
  EXPECT_LT(solver.number_of_supernodes(), std::size_t(matrix.rows()));
  Eigen::CholmodSimplicialLDLT<Sparse_matrix> peer;
  peer.compute(matrix);
  ASSERT_EQ(peer.info(), Eigen::Success);
  for (int columns : {1, 2, 3, 4, 7}) {
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), columns);
    const Eigen::MatrixXd x = solver.solve(b);
    ASSERT_EQ(x.cols(), columns);
    EXPECT_LT((matrix * x - b).norm() / b.norm(), 1e-9) << columns << " columns";
    EXPECT_LT(relative_difference(x, peer.solve(b)), 1e-10) << columns << " columns";
  }
}

// Whether some column of CHOLMOD's factor has room after its entries.
bool has_unpacked_columns(const cholmod_factor& factor)
{
  const int* p = static_cast<const int*>(factor.p);
  const int* count = static_cast<const int*>(factor.nz);
  for (std::size_t j = 0; j < factor.n; ++j)
    if (p[j + 1] - p[j] > count[j])
      return true;
  return false;
}

// A symmetric tridiagonal matrix, positive definite: its factor's columns have two entries,
// the last one, so that nearly every supernode is one column wide.
Sparse_matrix tridiagonal(int n)
{
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < n; ++i) {
    triplets.emplace_back(i, i, 2.5);
    if (i + 1 < n) {
      triplets.emplace_back(i, i + 1, -1.);
      triplets.emplace_back(i + 1, i, -1.);
    }
  }
  Sparse_matrix matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

TEST(CholmodLDLTSwept, SweepsInPlaceMatchCholmodsSolveAtEverySize)
{
  for (int m : {2, 5, 12, 30, 70, 150}) {
    const Sparse_matrix matrix = triangulated_grid_laplacian(m);
    FASI::Cholmod_LDLT_swept solver;
    solver.sweep_from(0);
    solver.compute(matrix);
    ASSERT_EQ(solver.info(), Eigen::Success);
    ASSERT_TRUE(solver.uses_supernodal_sweeps());
    EXPECT_FALSE(has_unpacked_columns(*solver.factor())) << m; // CHOLMOD allocates each column tight
    Eigen::CholmodSimplicialLDLT<Sparse_matrix> peer;
    peer.compute(matrix);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
    EXPECT_LT(relative_difference(solver.solve(b), peer.solve(b)), 1e-12) << m << " x " << m;
  }
}

TEST(CholmodLDLTSwept, ColumnsMovedWithRoomToGrowAreSweptWhereTheyAre)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(90);
  FASI::Cholmod_LDLT_swept solver;
  solver.sweep_from(0);
  solver.compute(matrix);
  ASSERT_EQ(solver.info(), Eigen::Success);
  ASSERT_FALSE(has_unpacked_columns(*solver.factor()));
  const std::size_t n = solver.factor()->n;
  // CHOLMOD moves a column it gives more room to the end of its storage: the factor is then
  // neither packed nor in column order, as after an update of the factor.
  cholmod_factor& factor = const_cast<cholmod_factor&>(*solver.factor());
  const int* count = static_cast<const int*>(factor.nz);
  for (std::size_t j : {std::size_t(0), n / 3, n / 2, n / 2 + 1, n - 2})
    ASSERT_TRUE(cholmod_reallocate_column(j, std::size_t(count[j]) + 7, &factor, &solver.cholmod()));
  ASSERT_TRUE(has_unpacked_columns(factor));
  ASSERT_FALSE(factor.is_monotonic);
  Eigen::CholmodSimplicialLDLT<Sparse_matrix> peer;
  peer.compute(matrix);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
  EXPECT_LT(relative_difference(solver.solve(b), peer.solve(b)), 1e-12);
}

TEST(CholmodLDLTSwept, SupernodesOfOneColumnAreSwept)
{
  Sparse_matrix diagonal(300, 300);
  diagonal.setIdentity();
  diagonal *= 1.5;
  for (const Sparse_matrix& matrix : {tridiagonal(500), diagonal}) {
    FASI::Cholmod_LDLT_swept solver;
    solver.sweep_from(0);
    solver.compute(matrix);
    ASSERT_EQ(solver.info(), Eigen::Success);
    ASSERT_TRUE(solver.uses_supernodal_sweeps());
    EXPECT_GE(solver.number_of_supernodes(), std::size_t(matrix.rows() - 1));
    Eigen::CholmodSimplicialLDLT<Sparse_matrix> peer;
    peer.compute(matrix);
    for (int columns : {1, 3}) {
      const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), columns);
      EXPECT_LT(relative_difference(solver.solve(b), peer.solve(b)), 1e-12) << matrix.rows() << " rows";
    }
  }
}

TEST(CholmodLDLTSwept, SmallFactorsUseCholmodsSolveAndLargeOnesTheSweeps)
{
  FASI::Cholmod_LDLT_swept small, large;
  small.compute(triangulated_grid_laplacian(20));
  EXPECT_FALSE(small.uses_supernodal_sweeps());
  large.sweep_from(1e4);
  large.compute(triangulated_grid_laplacian(40));
  EXPECT_TRUE(large.uses_supernodal_sweeps());
  // Both answer the same as the peer.
  for (const auto* solver : {&small, &large}) {
    const Sparse_matrix matrix = triangulated_grid_laplacian(solver == &small ? 20 : 40);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
    EXPECT_LT((matrix * solver->solve(b) - b).norm() / b.norm(), 1e-9);
  }
}

TEST(CholmodLDLTSwept, RowMajorRightHandSidesAreSolvedToo)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(50);
  FASI::Cholmod_LDLT_swept solver;
  solver.sweep_from(0);
  solver.compute(matrix);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> b =
      Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Random(matrix.rows(), 3);
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x(matrix.rows(), 3);
  x = solver.solve(b);
  EXPECT_LT((matrix * x - b).norm() / b.norm(), 1e-9);
}

// The single-precision copy solves a whole system (a correction from 0) to single precision.
TEST(CholmodLDLTSwept, SinglePrecisionCopyIsAccurateToSinglePrecision)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(80);
  FASI::Cholmod_LDLT_swept exact, single;
  exact.sweep_from(0);
  single.sweep_from(0);
  single.single_precision_from(0);
  exact.compute(matrix);
  single.compute(matrix);
  ASSERT_EQ(single.info(), Eigen::Success);
  ASSERT_TRUE(single.solves_corrections_in_single_precision());
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
  Eigen::MatrixXd x;
  single.solve_correction(Eigen::MatrixXd::Zero(matrix.rows(), 3), b, x);
  const double error = relative_difference(x, exact.solve(b));
  EXPECT_LT(error, 1e-5);
  // Really single precision: a double factor would agree to about 1e-14.
  EXPECT_GT(error, 1e-10);
}

// One step of iterative refinement from a first approximation x0: the single-precision copy's
// error is proportional to the correction x - x0, not to x.  It is largest, about cond(A) 1e-7 of
// the correction, along the near-null space of A (here the constant vector, whose only stiffness
// is the shift at the middle node: the structure of L + W); the component of the correction
// along it is known exactly (sum of A c = shift c_middle = sum of the residual), and with it set,
// what remains is about 1e-7 times the condition number of A on the other directions.
TEST(CholmodLDLTSwept, CorrectionsAreAccurateRelativeToTheCorrection)
{
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  const int m = 80;
  const double shift = 6e-3;
  const Sparse_matrix matrix = triangulated_grid_laplacian(m, shift);
  const Eigen::Index middle = (m / 2) * m + m / 2;
  FASI::Cholmod_LDLT_swept solver, without_copy;
  solver.single_precision_from(0);
  without_copy.single_precision_from(1e300);
  solver.compute(matrix);
  without_copy.compute(matrix);
  ASSERT_EQ(solver.info(), Eigen::Success);
  EXPECT_TRUE(solver.solves_corrections_in_single_precision());
  EXPECT_FALSE(solver.uses_supernodal_sweeps()); // solve() is still CHOLMOD's, in double
  EXPECT_FALSE(without_copy.solves_corrections_in_single_precision());

  const Rows b = Rows::Random(matrix.rows(), 3);
  const Rows exact = without_copy.solve(b);
  double error_by_correction[2] = {0, 0};
  int k = 0;
  for (double step : {1e-1, 1e-4}) {
    // A first approximation off by `step` of the solution's entries.
    const Rows start = exact + step * exact.norm() / std::sqrt(double(exact.size())) * Rows::Random(matrix.rows(), 3);
    const Rows residual = b - matrix * start;
    Rows corrected, reference;
    solver.solve_correction(start, residual, corrected);
    without_copy.solve_correction(start, residual, reference);
    const double correction = (exact - start).norm();
    // The double path: the solution to double precision (for this condition number).
    EXPECT_LT((reference - exact).norm() / exact.norm(), 1e-8) << step;
    // The single-precision path: really single precision (a double sweep would agree to about
    // 1e-14 of the correction), its error a multiple of the correction.
    error_by_correction[k++] = (corrected - exact).norm() / correction;
    EXPECT_GT(error_by_correction[k - 1], 1e-11) << step;
    // The correction's constant component set exactly: 1e-3 of the correction is left.
    const Eigen::RowVector3d constant =
        residual.colwise().sum() / shift - (corrected.row(middle) - start.row(middle));
    corrected.rowwise() += constant;
    EXPECT_LT((corrected - exact).norm(), 1e-3 * correction) << step;
    EXPECT_GT((corrected - exact).norm(), 1e-11 * correction) << step;
  }
  // Proportional to the correction: the same ratio for corrections 1,000 times apart.
  EXPECT_LT(error_by_correction[1], 10 * error_by_correction[0]);
  EXPECT_GT(error_by_correction[1], 0.1 * error_by_correction[0]);
}

// Where the single-precision copy is kept: large factors of a double solver by default.
TEST(CholmodLDLTSwept, SinglePrecisionCopyOnlyOnLargeFactors)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(40);
  FASI::Cholmod_LDLT_swept by_default, forced;
  by_default.compute(matrix);
  EXPECT_LT(by_default.number_of_entries(), FASI::Cholmod_LDLT_swept::default_smallest_single_precision_factor);
  EXPECT_FALSE(by_default.solves_corrections_in_single_precision());
  forced.single_precision_from(by_default.number_of_entries());
  forced.compute(matrix);
  EXPECT_TRUE(forced.solves_corrections_in_single_precision());
}

TEST(CholmodLDLTSwept, NotPositiveDefiniteIsReported)
{
  Sparse_matrix matrix = triangulated_grid_laplacian(10);
  matrix.coeffRef(55, 55) = -4;
  // Solved by CHOLMOD (a small factor) and by the sweeps.
  FASI::Cholmod_LDLT_swept solver, swept;
  solver.compute(matrix);
  EXPECT_NE(solver.info(), Eigen::Success);
  swept.sweep_from(0);
  swept.compute(matrix);
  EXPECT_NE(swept.info(), Eigen::Success);
}

TEST(CholmodLDLTSwept, OrderingCanBeChosen)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(100);
  FASI::Cholmod_LDLT_swept by_default, dissected;
  by_default.compute(matrix);
  EXPECT_EQ(by_default.factor()->ordering, CHOLMOD_AMD);
  // Through CHOLMOD's own settings: the next analysis tries METIS only.
  dissected.cholmod().nmethods = 1;
  dissected.cholmod().method[0].ordering = CHOLMOD_METIS;
  dissected.sweep_from(0);
  dissected.compute(matrix);
  ASSERT_EQ(dissected.info(), Eigen::Success);
  EXPECT_EQ(dissected.factor()->ordering, CHOLMOD_METIS);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
  EXPECT_LT(relative_difference(dissected.solve(b), by_default.solve(b)), 1e-9);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(CholmodLDLTSwept, ParallelSweepsGiveTheSerialSolutionBitForBit)
{
  const Sparse_matrix matrix = triangulated_grid_laplacian(120);
  FASI::Cholmod_LDLT_swept serial, parallel;
  serial.sweep_from(0);
  serial.single_precision_from(0);
  serial.compute(matrix);
  parallel.sweep_from(0);
  parallel.single_precision_from(0);
  parallel.use_parallelism(true);
  parallel.compute(matrix);
  ASSERT_TRUE(parallel.subtrees().is_split());
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
  const Eigen::MatrixXd x = serial.solve(b), y = parallel.solve(b);
  EXPECT_EQ((x - y).cwiseAbs().maxCoeff(), 0.);
  EXPECT_LT((matrix * y - b).norm() / b.norm(), 1e-9);
  // The single-precision sweeps of the corrections too.
  const Eigen::MatrixXd start = Eigen::MatrixXd::Zero(matrix.rows(), 3);
  Eigen::MatrixXd serial_correction, parallel_correction;
  serial.solve_correction(start, b, serial_correction);
  parallel.solve_correction(start, b, parallel_correction);
  ASSERT_TRUE(parallel.solves_corrections_in_single_precision());
  EXPECT_EQ((serial_correction - parallel_correction).cwiseAbs().maxCoeff(), 0.);
  EXPECT_GT((serial_correction - x).cwiseAbs().maxCoeff(), 0.);
}
#endif

// A supernodal structure built by hand: a complete binary tree of depth `depth`, numbered in
// postorder, one column per supernode (super[s] = s), each supernode's rows its own column then
// all its ancestors' columns in increasing order.
struct Hand_made_tree {
  std::vector<int> super, pi, rows, parent;

  explicit Hand_made_tree(int depth)
  {
    build(depth);
    const int n = int(parent.size());
    for (int s = 0; s <= n; ++s)
      super.push_back(s);
    pi.assign(1, 0);
    for (int s = 0; s < n; ++s) {
      rows.push_back(s);
      for (int a = parent[std::size_t(s)]; a >= 0; a = parent[std::size_t(a)])
        rows.push_back(a);
      pi.push_back(int(rows.size()));
    }
  }

  // Numbers the subtree of the given depth in postorder; returns its root.
  int build(int depth)
  {
    std::vector<int> children;
    for (int c = 0; depth > 0 && c < 2; ++c)
      children.push_back(build(depth - 1));
    const int root = int(parent.size());
    parent.push_back(-1);
    for (int c : children)
      parent[std::size_t(c)] = root;
    return root;
  }
};

TEST(EliminationSubtrees, ScheduleKeepsTheOrderOfTheSweepsOnAHandMadeTree)
{
  const Hand_made_tree tree(7); // 255 supernodes
  const int n = int(tree.parent.size());
  ASSERT_EQ(n, 255);
  FASI::Elimination_subtrees schedule(n, tree.super.data(), tree.pi.data(), tree.rows.data());
  ASSERT_TRUE(schedule.is_split());
  EXPECT_LT(schedule.top_fraction(), 0.2);

  // Forward: every supernode once, after all its descendants.
  std::vector<int> forward_position(std::size_t(n), -1), group_of(std::size_t(n), -1), split_of(std::size_t(n), 0);
  int position = 0;
  std::vector<double> right_hand_side(std::size_t(n), 0.); // one value per column
  double* z = right_hand_side.data();
  schedule.forward(z, 1, [&](int s, double* target, int split, int group) {
    EXPECT_EQ(forward_position[std::size_t(s)], -1) << "supernode " << s << " visited twice";
    forward_position[std::size_t(s)] = position++;
    group_of[std::size_t(s)] = group;
    split_of[std::size_t(s)] = split;
    EXPECT_EQ(target == z, group == 0) << "a grouped supernode writes its top rows to a private target";
    if (target == z) {
      EXPECT_LT(split, 0);
    }
  });
  for (int s = 0; s < n; ++s) {
    ASSERT_GE(forward_position[std::size_t(s)], 0) << "supernode " << s << " not visited";
    const int p = tree.parent[std::size_t(s)];
    if (p >= 0) {
      EXPECT_LT(forward_position[std::size_t(s)], forward_position[std::size_t(p)]);
    }
  }
  // The rows before a grouped supernode's split are in its own group, those after in the top;
  // a top supernode has no split.
  for (int s = 0; s < n; ++s) {
    const int group = group_of[std::size_t(s)], split = split_of[std::size_t(s)];
    if (group == 0) {
      EXPECT_LT(split, 0);
      continue;
    }
    const int begin = tree.pi[std::size_t(s)], end = tree.pi[std::size_t(s) + 1];
    for (int r = begin + 1; r < end; ++r) {
      const int row = tree.rows[std::size_t(r)];
      EXPECT_EQ(group_of[std::size_t(row)], r - begin < split ? group : 0) << "supernode " << s << " row " << row;
    }
  }
  // The top and every group of subtrees are used.
  std::vector<int> groups_used;
  for (int g : group_of)
    if (std::find(groups_used.begin(), groups_used.end(), g) == groups_used.end())
      groups_used.push_back(g);
  EXPECT_EQ(int(groups_used.size()), FASI::Elimination_subtrees::number_of_groups + 1);

  // Backward: every supernode once, after its parent.
  std::vector<int> backward_position(std::size_t(n), -1);
  position = 0;
  schedule.backward([&](int s, int) {
    EXPECT_EQ(backward_position[std::size_t(s)], -1);
    backward_position[std::size_t(s)] = position++;
  });
  for (int s = 0; s < n; ++s) {
    ASSERT_GE(backward_position[std::size_t(s)], 0);
    const int p = tree.parent[std::size_t(s)];
    if (p >= 0) {
      EXPECT_GT(backward_position[std::size_t(s)], backward_position[std::size_t(p)]);
    }
  }
}

TEST(EliminationSubtrees, ATreeThatIsNotPostorderedIsSweptInSequence)
{
  // A chain of 40 supernodes each of which is the child of the one before: the parents come
  // first, which no postorder allows.  The same chain the other way round is split-able input
  // (and a chain is swept in sequence anyway, so only the refusal is checked here).
  const int n = 40;
  std::vector<int> super, pi = {0}, rows;
  for (int s = 0; s <= n; ++s)
    super.push_back(s);
  for (int s = 0; s < n; ++s) {
    rows.push_back(s);
    for (int a = s - 1; a >= 0; --a)
      rows.push_back(a);
    std::sort(rows.end() - (s + 1), rows.end());
    pi.push_back(int(rows.size()));
  }
  FASI::Elimination_subtrees schedule(n, super.data(), pi.data(), rows.data());
  EXPECT_FALSE(schedule.is_split());
  int visits = 0;
  std::vector<double> z(std::size_t(n), 0.);
  schedule.forward(z.data(), 1, [&](int, double*, int split, int) {
    EXPECT_LT(split, 0);
    ++visits;
  });
  EXPECT_EQ(visits, n);
}

} // namespace

#else // CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD

#include "skip_without_tool.h"

#include <gtest/gtest.h>

TEST(CholmodLDLTSwept, NeedsCholmod)
{
  FAS_SKIP_WITHOUT_CHOLMOD();
}

#endif // CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
