// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's Table 1 (Section 7, "Performance"): for planar patches of about 8e2, 5e3, 2e4,
// 8e4 and 3.2e5 faces, single-threaded,
//
//   FACTOR   ms, the one factorization of L + W (symbolic analysis + numeric), from
//            Alignment_report::factor_ms
//   GTRANSF  ms per iteration: sampling, local transformations, right-hand side
//            (Iteration_report::gradient_transformation_ms)
//   SOLVE    ms per iteration: the back-substitutions (Iteration_report::solve_ms)
//   IT/s     1000 / (GTRANSF + SOLVE), the paper's definition; the wall-clock rate of whole
//            step() calls (which also write the positions back and measure the step) beside it
//   NCONV    iterations until the package's stopping rule holds, from a fixed start (below)
//
// and, in the same run, the sparse Cholesky solvers compared on the same matrix: CHOLMOD
// supernodal LL^T with CHOLMOD's default ordering strategy, with AMD only and with METIS only,
// and converted to a simplicial factor for the solves; CHOLMOD simplicial LDL^T; Eigen's
// SimplicialLDLT (AMD).  The table's columns use the package's default solver, whichever it is.
// The largest size (>= 2e5 faces) uses --large-repetitions (default 3) to stay within minutes.
//
// The flow: the point source of strength 4 pi (|v| = 1/r^2) at c = (0, 0, -1.6), sampled on a
// 128^3 grid over [-1, 1]^3 and evaluated by trilinear interpolation (Regular_grid_flow_field_3),
// so that every face costs one grid query as on real data.  Its orthogonal surfaces are the
// spheres about c and its stream surfaces the cones with apex c: both kinds are curved.
//
// The fixed starts: a 1 x 1 planar patch (make_planar_patch) centered at p0 = (0, 0, 0.2),
// where the flow is +z, at distance 1.8 from c, tilted by 0.3 rad from alignment at p0:
//   ORTHOGONAL  normal = e_z rotated by 0.3 rad about e_x (aligned state: a sphere, R = 1.8)
//   TANGENTIAL  normal = e_x rotated by 0.3 rad about e_y (the plane holds e_y and makes
//               0.3 rad with the flow at p0; aligned state: a cone with apex c)
// NCONV counts step() calls until one reports `converged`, the package's rule: every requested
// rotation below epsilon = 1e-6 (and no fold), or the largest vertex step below 1e-4 of the
// bounding-box diagonal (default parameters: eta = 0.1, theta_max = pi/2, area correction on).
//
//   bench_deformation [output.json] [--sizes 800,5000,...] [--repetitions N]
//                     [--large-repetitions N] [--quick]
//
// Medians over the repetitions (and, within a run, over its iterations) are reported, since the
// machine may be shared.  Writes ./table1.json by default.  The program re-executes itself with
// OMP_NUM_THREADS=OMP_THREAD_LIMIT=OPENBLAS_NUM_THREADS=MKL_NUM_THREADS=1 when they are not
// already set, so that CHOLMOD (which links OpenMP) and a threaded BLAS stay on one thread; it
// records the BLAS it loaded, which the system chooses (Debian: update-alternatives libblas.so.3).

#include "bench_clock.h"
#include "bench_solvers.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

using fas_benchmark::thread_cpu_ms;

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef FAS::Regular_grid_flow_field_3<K> Grid;
typedef Eigen::SparseMatrix<double> Sparse_matrix;
typedef std::chrono::steady_clock Clock;

double ms_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}


double median(std::vector<double> v)
{
  if (v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---------------------------------------------------------------------------------------------
// Solvers instrumented to split the factorization into its symbolic and numeric parts and to
// report the fill.  Flow_aligned_deformation calls `solver().compute(matrix)` on the static type,
// so the `compute` below (which hides the base's) is the one used; it does what the base's does.

struct Factor_stats {
  double analyze_ms = 0, numeric_ms = 0;
  double cpu_ms = 0; // thread CPU time of analyze + numeric
  double nnz_L = 0;  // nonzeros of the factor
  double flops = -1; // CHOLMOD's flop count of the numeric factorization; -1 if unknown
  std::string ordering;
  bool supernodal = false;
  double bytes_per_solve = -1; // bytes of the factor read by one solve (both sweeps); -1 if unknown
};
Factor_stats last_factor_stats;

// Runs the symbolic and the numeric phase of `solver` on `matrix` (then `after_numeric()`, timed
// with the numeric phase) and records their times in last_factor_stats.
template <class Solver, class AfterNumeric>
void timed_factorization(Solver& solver, const Sparse_matrix& matrix, const AfterNumeric& after_numeric)
{
  const double cpu_start = thread_cpu_ms();
  const auto start = Clock::now();
  solver.analyzePattern(matrix);
  last_factor_stats.analyze_ms = ms_since(start);
  const auto numeric = Clock::now();
  solver.factorize(matrix);
  after_numeric();
  last_factor_stats.numeric_ms = ms_since(numeric);
  last_factor_stats.cpu_ms = thread_cpu_ms() - cpu_start;
}

// The last solve, timed inside the solver: wall clock and thread CPU time.
struct Solve_stats {
  double wall_ms = 0, cpu_ms = 0;
};
Solve_stats last_solve_stats;

// Hides the solver's solve() and, where it has one (the package's default solver),
// solve_correction(), to time them; Flow_aligned_deformation calls them on the static type.  The
// result has the right-hand side's shape, so no copy is added.
template <class EigenSolver>
class Timed_solve : public EigenSolver {
public:
  template <class Base, class Residual, class Dest, class S = EigenSolver>
  auto solve_correction(const Base& base, const Residual& residual, Dest& dest) const
      -> decltype(std::declval<const S&>().solve_correction(base, residual, dest), void())
  {
    const double cpu_start = thread_cpu_ms();
    const auto start = Clock::now();
    S::solve_correction(base, residual, dest);
    last_solve_stats.wall_ms = ms_since(start);
    last_solve_stats.cpu_ms = thread_cpu_ms() - cpu_start;
  }

  template <class Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    const double cpu_start = thread_cpu_ms();
    const auto start = Clock::now();
    Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> x = EigenSolver::solve(b);
    last_solve_stats.wall_ms = ms_since(start);
    last_solve_stats.cpu_ms = thread_cpu_ms() - cpu_start;
    return x;
  }
};

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
const char* cholmod_ordering_name(int ordering)
{
  switch (ordering) {
  case CHOLMOD_NATURAL:
    return "natural";
  case CHOLMOD_GIVEN:
    return "given";
  case CHOLMOD_AMD:
    return "AMD";
  case CHOLMOD_METIS:
    return "METIS";
  case CHOLMOD_NESDIS:
    return "NESDIS";
  case CHOLMOD_COLAMD:
    return "COLAMD";
  case CHOLMOD_POSTORDERED:
    return "postordered";
  default:
    return "unknown";
  }
}

// Ordering < 0: CHOLMOD's default strategy (nmethods = 0: AMD, and METIS/NESDIS as well when
// AMD's fill is high); otherwise that ordering only.  What the factorization chose is read from
// CHOLMOD's common structure (Eigen's public cholmod()), never from Eigen's members: the ordering
// of the method selected, and supernodal when CHOLMOD's rule chose it (flops per nonzero of the
// factor at least its supernodal_switch, unless the solver forces one kind).
template <class CholmodSolver, int Ordering>
class Instrumented_cholmod : public Timed_solve<CholmodSolver> {
public:
  Instrumented_cholmod()
  {
    if (Ordering >= 0) {
      this->cholmod().nmethods = 1;
      this->cholmod().method[0].ordering = Ordering;
    }
  }

  // Flow_aligned_deformation calls analyzePattern() then factorize(): both are timed here, in
  // factorize(), by compute().
  void analyzePattern(const Sparse_matrix&) {}
  void factorize(const Sparse_matrix& matrix) { compute(matrix); }

  Instrumented_cholmod& compute(const Sparse_matrix& matrix)
  {
    timed_factorization(static_cast<Timed_solve<CholmodSolver>&>(*this), matrix, [] {});
    const cholmod_common& common = this->cholmod();
    const bool supernodal = common.supernodal == CHOLMOD_SUPERNODAL ||
                            (common.supernodal != CHOLMOD_SIMPLICIAL && common.lnz > 0 &&
                             common.fl / common.lnz >= common.supernodal_switch);
    last_factor_stats.nnz_L = common.lnz;
    last_factor_stats.flops = common.fl;
    last_factor_stats.ordering =
        common.selected >= 0 ? cholmod_ordering_name(common.method[common.selected].ordering) : "none";
    last_factor_stats.supernodal = supernodal;
    // The simplicial solve reads a value and a row index per nonzero, and the column pointers.
    last_factor_stats.bytes_per_solve =
        supernodal ? -1 : 2 * (common.lnz * (sizeof(double) + sizeof(int)) + 2. * matrix.rows() * sizeof(int));
    return *this;
  }
};
#endif

template <class EigenSimplicialSolver>
class Instrumented_eigen : public Timed_solve<EigenSimplicialSolver> {
public:
  // Flow_aligned_deformation calls analyzePattern() then factorize(): both are timed here, in
  // factorize(), by compute().
  void analyzePattern(const Sparse_matrix&) {}
  void factorize(const Sparse_matrix& matrix) { compute(matrix); }

  Instrumented_eigen& compute(const Sparse_matrix& matrix)
  {
    timed_factorization(static_cast<Timed_solve<EigenSimplicialSolver>&>(*this), matrix, [] {});
    // Strictly lower part plus the diagonal, as CHOLMOD counts it (matrixL(): Eigen's public view
    // of the factor, unit diagonal not stored).
    const auto& L = this->matrixL().nestedExpression();
    last_factor_stats.nnz_L = double(L.nonZeros()) + double(L.rows());
    last_factor_stats.flops = -1;
    last_factor_stats.ordering = "AMD (Eigen)";
    last_factor_stats.supernodal = false;
    last_factor_stats.bytes_per_solve = -1;
    return *this;
  }
};

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
// The package's default solver (internal::Cholmod_LDLT_swept: CHOLMOD's simplicial LDL^T swept in
// place by supernodes for the solves, the iterations' corrections swept with a single-precision
// copy on large factors), its solves in double or swept with the single-precision copy
// (SinglePrecisionSolves), with the ordering chosen by size (Ordering < 0) or forced, its solves
// swept in sequence or over the threads of TBB's default arena (Parallel), with the
// single-precision copy for the corrections where the package keeps it or never
// (DoubleCorrections).
template <bool SinglePrecisionSolves, int Ordering, bool Parallel = false, bool DoubleCorrections = false>
class Instrumented_supernodal
    : public Timed_solve<fas_benchmark::Benchmarked_LDLT_swept<Ordering, SinglePrecisionSolves>> {
  using Base = fas_benchmark::Benchmarked_LDLT_swept<Ordering, SinglePrecisionSolves>;

public:
  Instrumented_supernodal()
  {
    this->use_parallelism(Parallel);
    if (DoubleCorrections)
      this->single_precision_from(std::numeric_limits<double>::infinity());
  }

  // Flow_aligned_deformation calls analyzePattern() then factorize(): both are timed here, in
  // factorize(), by compute().
  void analyzePattern(const Sparse_matrix&) {}
  void factorize(const Sparse_matrix& matrix) { compute(matrix); }

  Instrumented_supernodal& compute(const Sparse_matrix& matrix)
  {
    timed_factorization(static_cast<Timed_solve<Base>&>(*this), matrix, [] {});
    last_factor_stats.nnz_L = this->number_of_entries();
    last_factor_stats.flops = this->cholmod().fl;
    last_factor_stats.ordering = cholmod_ordering_name(this->ordering());
    last_factor_stats.supernodal = this->uses_supernodal_sweeps();
    // The iterations solve corrections (two sweeps each).
    last_factor_stats.bytes_per_solve = 2 * fas_benchmark::bytes_per_correction_sweep(*this);
    return *this;
  }
};

#endif

// A warm-started preconditioned conjugate gradient (Eigen's, with an incomplete Cholesky
// preconditioner): each solve starts from the previous solution, which between iterations of the
// deformation changes little.  FACTOR is the preconditioner's factorization.  Relative residual
// tolerance 1e-10 (the direct solves reach about 1e-12).
class Warm_conjugate_gradient
    : public Eigen::ConjugateGradient<Sparse_matrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> {
  using Base = Eigen::ConjugateGradient<Sparse_matrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>>;

public:
  // Flow_aligned_deformation calls analyzePattern() then factorize(): both are timed here, in
  // factorize(), by compute().
  void analyzePattern(const Sparse_matrix&) {}
  void factorize(const Sparse_matrix& matrix) { compute(matrix); }

  Warm_conjugate_gradient& compute(const Sparse_matrix& matrix)
  {
    this->setTolerance(1e-10);
    this->setMaxIterations(5000);
    m_previous.resize(0, 0);
    // Eigen's iterative solvers keep a reference to the matrix; the caller's is a temporary.
    m_matrix = matrix;
    timed_factorization(static_cast<Base&>(*this), m_matrix, [] {});
    last_factor_stats.nnz_L = -1;
    last_factor_stats.flops = -1;
    last_factor_stats.ordering = "AMD (Eigen, incomplete)";
    last_factor_stats.supernodal = false;
    last_factor_stats.bytes_per_solve = -1;
    return *this;
  }

  template <class Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    const double cpu_start = thread_cpu_ms();
    const auto start = Clock::now();
    if (m_previous.rows() != b.rows() || m_previous.cols() != b.cols())
      m_previous = Eigen::MatrixXd::Zero(b.rows(), b.cols());
    Eigen::MatrixXd x = Base::solveWithGuess(b, m_previous);
    m_previous = x;
    last_solve_stats.wall_ms = ms_since(start);
    last_solve_stats.cpu_ms = thread_cpu_ms() - cpu_start;
    return x;
  }

private:
  Sparse_matrix m_matrix;
  mutable Eigen::MatrixXd m_previous;
};

// ---------------------------------------------------------------------------------------------
// The field and the fixed starts.

constexpr std::size_t kGridNodes = 128;
const Point_3 kSource(0, 0, -1.6);
const Point_3 kPatchCenter(0, 0, 0.2);
constexpr double kTilt = 0.3;      // radians from alignment at the patch center
constexpr double kPatchSize = 1.0; // width = height
constexpr std::size_t kMaxIterations = 200;

Grid make_grid()
{
  const FAS::Point_source_flow<K> source(kSource, 4 * CGAL_PI);
  const double h = 2. / double(kGridNodes - 1);
  return FAS::sample_on_grid(source, Point_3(-1, -1, -1), Vector_3(h, h, h),
                             {kGridNodes, kGridNodes, kGridNodes});
}

Vector_3 start_normal(FAS::Alignment alignment)
{
  const double c = std::cos(kTilt), s = std::sin(kTilt);
  return alignment == FAS::Alignment::ORTHOGONAL ? Vector_3(0, -s, c)  // e_z about e_x
                                                 : Vector_3(c, 0, -s); // e_x about e_y
}

void make_start(Mesh& tm, FAS::Alignment alignment, std::size_t target_faces)
{
  tm.clear();
  FAS::make_planar_patch(tm, kPatchCenter, start_normal(alignment), kPatchSize, kPatchSize, target_faces);
}

const char* name(FAS::Alignment alignment)
{
  return alignment == FAS::Alignment::ORTHOGONAL ? "orthogonal" : "tangential";
}

// ---------------------------------------------------------------------------------------------
// Measurements.

// One alignment run to convergence from the fixed start, with the package's default solver.
struct Convergence_run {
  double construct_ms = 0; // the whole constructor: checks, operators, factorization
  double factor_ms = 0;
  std::vector<FAS::Iteration_report> iterations;
  std::vector<double> step_wall_ms; // whole step() calls
  std::vector<double> step_cpu_ms;  // their thread CPU time
  std::size_t nconv = 0;
  bool converged = false;
  std::string rule; // which stopping rule held: "angle" or "step"
  double initial_flux = 0, final_flux = 0;
};

// --parallel: the per-face work on all cores (FAS::parameters::use_parallelism); not Table 1,
// which is single-threaded like the paper's.
bool g_use_parallelism = false;

Convergence_run run_to_convergence(const Grid& grid, FAS::Alignment alignment, std::size_t target_faces,
                                   std::size_t& faces, std::size_t& vertices, bool parallel)
{
  Mesh tm;
  make_start(tm, alignment, target_faces);
  faces = num_faces(tm);
  vertices = num_vertices(tm);
  const auto construct_start = Clock::now();
  FAS::Flow_aligned_deformation<Mesh, Grid> deformation(tm, grid, alignment,
                                                        FAS::parameters::use_parallelism(parallel));
  Convergence_run run;
  run.construct_ms = ms_since(construct_start);
  run.factor_ms = deformation.run(0).factor_ms; // no iteration: only the constructor's factorization
  for (std::size_t k = 0; k < kMaxIterations; ++k) {
    const double cpu_start = thread_cpu_ms();
    const auto start = Clock::now();
    const FAS::Iteration_report report = deformation.step();
    run.step_wall_ms.push_back(ms_since(start));
    run.step_cpu_ms.push_back(thread_cpu_ms() - cpu_start);
    run.iterations.push_back(report);
    if (k == 0)
      run.initial_flux = report.normalized_flux.value.value();
    if (report.converged) {
      run.converged = true;
      run.rule = (report.max_rotation_angle < 1e-6 && report.number_of_folds == 0) ? "angle" : "step";
      break;
    }
  }
  run.nconv = run.iterations.size();
  run.final_flux = deformation.current_normalized_flux().value.value();
  return run;
}

// FACTOR and SOLVE of one solver on the orthogonal start: construct (factor), then a few steps.
constexpr std::size_t kSolverSteps = 3;

struct Solver_sample {
  double factor_ms = 0, solve_ms = 0, gtransf_ms = 0;
  double solve_cpu_ms = 0; // thread CPU time of the solves, timed inside the solver
  Factor_stats stats;
};

template <class Solver>
Solver_sample measure_solver(const Grid& grid, std::size_t target_faces)
{
  Mesh tm;
  make_start(tm, FAS::Alignment::ORTHOGONAL, target_faces);
  FAS::Flow_aligned_deformation<Mesh, Grid, CGAL::Default, CGAL::Default, Solver> deformation(
      tm, grid, FAS::Alignment::ORTHOGONAL);
  Solver_sample sample;
  sample.stats = last_factor_stats;
  sample.factor_ms = deformation.run(0).factor_ms;
  std::vector<double> solve, gtransf, solve_cpu;
  for (std::size_t k = 0; k < kSolverSteps; ++k) {
    const FAS::Iteration_report r = deformation.step();
    solve.push_back(r.solve_ms);
    gtransf.push_back(r.gradient_transformation_ms);
    solve_cpu.push_back(last_solve_stats.cpu_ms);
  }
  sample.solve_ms = median(solve);
  sample.solve_cpu_ms = median(solve_cpu);
  sample.gtransf_ms = median(gtransf);
  return sample;
}

struct Solver_config {
  std::string name, description;
  std::function<Solver_sample(const Grid&, std::size_t)> measure;
};

std::vector<Solver_config> solver_configs()
{
  std::vector<Solver_config> configs;
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
  typedef Eigen::CholmodSupernodalLLT<Sparse_matrix> Supernodal;
  typedef Eigen::CholmodSimplicialLDLT<Sparse_matrix> Cholmod_simplicial;
  configs.push_back({"supernodal_llt",
                     "the package's Cholmod_LDLT_swept: CHOLMOD simplicial LDL^T (default ordering strategy) "
                     "swept in place by supernodes for the solves, double, solves in sequence",
                     measure_solver<CGAL::Eigen_solver_traits<Instrumented_supernodal<false, -1>>>});
  configs.push_back({"supernodal_llt_double_corrections",
                     "supernodal_llt without the single-precision copy: the corrections swept in double "
                     "precision",
                     measure_solver<CGAL::Eigen_solver_traits<Instrumented_supernodal<false, -1, false, true>>>});
  configs.push_back({"supernodal_llt_metis", "the same with METIS's nested dissection at every size",
                     measure_solver<CGAL::Eigen_solver_traits<Instrumented_supernodal<false, CHOLMOD_METIS>>>});
  configs.push_back({"supernodal_llt_float", "the same factor's single-precision copy swept for the solves too, in single-precision arithmetic (half the bytes)",
                     measure_solver<CGAL::Eigen_solver_traits<Instrumented_supernodal<true, -1>>>});
#ifdef CGAL_LINKED_WITH_TBB
  configs.push_back({"supernodal_llt_parallel",
                     "supernodal_llt with the solves swept over independent subtrees on TBB's threads (2 here)",
                     measure_solver<CGAL::Eigen_solver_traits<Instrumented_supernodal<false, -1, true>>>});
#endif
  configs.push_back(
      {"cholmod_simplicial_ldlt", "CHOLMOD simplicial LDL^T and its own solve (the default's factor), default ordering strategy",
       measure_solver<CGAL::Eigen_solver_traits<Instrumented_cholmod<Cholmod_simplicial, -1>>>});
  configs.push_back({"cholmod_supernodal", "CHOLMOD supernodal LL^T and its own solve, default ordering strategy",
                     measure_solver<CGAL::Eigen_solver_traits<Instrumented_cholmod<Supernodal, -1>>>});
#endif
  configs.push_back(
      {"eigen_simplicial_ldlt", "Eigen SimplicialLDLT (Eigen's AMD)",
       measure_solver<CGAL::Eigen_solver_traits<Instrumented_eigen<Eigen::SimplicialLDLT<Sparse_matrix>>>>});
  configs.push_back({"warm_conjugate_gradient",
                     "Eigen's conjugate gradient, incomplete Cholesky preconditioner, started from the previous "
                     "solution, relative tolerance 1e-10",
                     measure_solver<CGAL::Eigen_solver_traits<Warm_conjugate_gradient>>});
  return configs;
}

// The name, among the configurations above, of the package's default solver.
const char* default_solver_name()
{
  typedef FAS::internal::Default_sparse_linear_solver::Solver Default;
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
  if (std::is_same<Default, Eigen::CholmodSupernodalLLT<Sparse_matrix>>::value)
    return "cholmod_supernodal";
  if (std::is_same<Default, Eigen::CholmodSimplicialLDLT<Sparse_matrix>>::value)
    return "cholmod_simplicial_ldlt";
  if (std::is_same<Default, fas_benchmark::Cholmod_auto_LDLT<Sparse_matrix>>::value)
    return "cholmod_auto_ldlt";
  if (std::is_same<Default, FAS::internal::Cholmod_LDLT_swept>::value)
    return "supernodal_llt";
#endif
  if (std::is_same<Default, Eigen::SimplicialLDLT<Sparse_matrix>>::value)
    return "eigen_simplicial_ldlt";
  return "other";
}

// ---------------------------------------------------------------------------------------------
// JSON output (hand-written: no dependency).

class Json {
public:
  Json& open(const std::string& key, char bracket)
  {
    separator();
    if (!key.empty())
      m_out << quote(key) << ": ";
    m_out << bracket;
    m_first = true;
    ++m_depth;
    return *this;
  }
  Json& close(char bracket)
  {
    --m_depth;
    m_out << '\n' << std::string(2 * m_depth, ' ') << bracket;
    m_first = false;
    return *this;
  }
  Json& value(const std::string& key, double v)
  {
    separator();
    m_out << quote(key) << ": ";
    if (std::isfinite(v)) {
      std::ostringstream s;
      s.precision(6);
      s << v;
      m_out << s.str();
    }
    else
      m_out << "null";
    return *this;
  }
  Json& value(const std::string& key, std::size_t v)
  {
    separator();
    m_out << quote(key) << ": " << v;
    return *this;
  }
  Json& value(const std::string& key, bool v)
  {
    separator();
    m_out << quote(key) << ": " << (v ? "true" : "false");
    return *this;
  }
  Json& value(const std::string& key, const std::string& v)
  {
    separator();
    m_out << quote(key) << ": " << quote(v);
    return *this;
  }
  Json& value(const std::string& key, const char* v) { return value(key, std::string(v)); }
  Json& array(const std::string& key, const std::vector<double>& v)
  {
    separator();
    m_out << quote(key) << ": [";
    for (std::size_t i = 0; i < v.size(); ++i) {
      std::ostringstream s;
      s.precision(6);
      if (std::isfinite(v[i]))
        s << v[i];
      else
        s << "null";
      m_out << (i ? ", " : "") << s.str();
    }
    m_out << ']';
    return *this;
  }
  std::string str() const { return m_out.str() + "\n"; }

private:
  void separator()
  {
    if (m_depth > 0)
      m_out << (m_first ? "" : ",") << '\n' << std::string(2 * m_depth, ' ');
    m_first = false;
  }
  static std::string quote(const std::string& s)
  {
    std::string q = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\')
        q += '\\';
      if (c == '\n')
        q += "\\n";
      else if (static_cast<unsigned char>(c) >= 0x20)
        q += c;
    }
    return q + "\"";
  }
  std::ostringstream m_out;
  bool m_first = true;
  int m_depth = 0;
};

std::string read_first_line_matching(const char* path, const std::string& prefix)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, prefix.size(), prefix) == 0) {
      const std::size_t colon = line.find(':');
      std::string v = colon == std::string::npos ? line : line.substr(colon + 1);
      v.erase(0, v.find_first_not_of(" \t"));
      return v;
    }
  return "";
}

std::string read_file_line(const char* path)
{
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// The shared libraries of the linear algebra actually loaded (the BLAS behind CHOLMOD's
// supernodal factorization is chosen by the system's alternatives, not at build time).
std::string loaded_libraries()
{
  std::ifstream maps("/proc/self/maps");
  std::string line, list;
  std::vector<std::string> seen;
  while (std::getline(maps, line)) {
    const std::size_t slash = line.find('/');
    if (slash == std::string::npos)
      continue;
    const std::string path = line.substr(slash);
    const std::string file = path.substr(path.rfind('/') + 1);
    const bool wanted = file.find("blas") != std::string::npos || file.find("lapack") != std::string::npos ||
                        file.find("cholmod") != std::string::npos || file.find("metis") != std::string::npos;
    if (wanted && std::find(seen.begin(), seen.end(), path) == seen.end()) {
      seen.push_back(path);
      list += (list.empty() ? "" : " ") + path;
    }
  }
  return list;
}

std::string utc_now()
{
  const std::time_t t = std::time(nullptr);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buffer;
}

double cpu_seconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The read bandwidth of `threads` threads streaming a 256 MiB array (each its own part, four
// partial sums so that the additions do not wait for each other), GB/s, median of 5 passes: the
// physical bound of a solve that streams its factor.
double read_bandwidth_gb_s(unsigned threads)
{
  const std::size_t n = (std::size_t(256) << 20) / sizeof(double);
  std::vector<double> data(n, 1.0);
  std::vector<double> rates;
  std::vector<double> sums(threads);
  for (int pass = 0; pass < 5; ++pass) {
    const auto start = Clock::now();
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
      workers.emplace_back([&, t] {
        const std::size_t begin = n / threads * t, end = t + 1 == threads ? n : n / threads * (t + 1);
        double a = 0, b = 0, c = 0, d = 0;
        std::size_t i = begin;
        for (; i + 3 < end; i += 4) {
          a += data[i];
          b += data[i + 1];
          c += data[i + 2];
          d += data[i + 3];
        }
        sums[t] = a + b + c + d;
      });
    for (std::thread& w : workers)
      w.join();
    rates.push_back(double(n * sizeof(double)) / (ms_since(start) * 1e6));
  }
  if (std::accumulate(sums.begin(), sums.end(), 0.) != double(n - n % 4))
    std::cerr << "bench_deformation: bandwidth check sum differs\n";
  return median(rates);
}

std::vector<std::size_t> parse_sizes(const std::string& list)
{
  std::vector<std::size_t> sizes;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    sizes.push_back(static_cast<std::size_t>(std::stod(item)));
  return sizes;
}

} // namespace

int main(int argc, char** argv)
{
  // CHOLMOD links OpenMP and may load a threaded BLAS (OpenBLAS); both read their thread count
  // from the environment when they are loaded, so set it and start again (once) to be sure that
  // the whole measurement is single-threaded.  OMP_THREAD_LIMIT is needed too: CHOLMOD 3's
  // supernodal factorization asks for num_threads(CHOLMOD_OMP_NUM_THREADS = 4) explicitly in
  // some loops, which OMP_NUM_THREADS does not override.
  bool restart = false;
  for (const char* variable :
       {"OMP_NUM_THREADS", "OMP_THREAD_LIMIT", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"}) {
    const char* value = std::getenv(variable);
    if (value == nullptr || std::string(value) != "1") {
      setenv(variable, "1", 1);
      restart = true;
    }
  }
  if (restart) {
    execv("/proc/self/exe", argv);
    std::cerr << "bench_deformation: could not re-execute with one thread; continuing\n";
  }

  std::string output = "table1.json";
  std::vector<std::size_t> sizes = {800, 5000, 20000, 80000, 320000};
  std::size_t repetitions = 5, large_repetitions = 3;
  const std::size_t large_size = 200000; // sizes from here on use large_repetitions
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sizes" && i + 1 < argc)
      sizes = parse_sizes(argv[++i]);
    else if (a == "--repetitions" && i + 1 < argc)
      repetitions = std::stoul(argv[++i]);
    else if (a == "--large-repetitions" && i + 1 < argc)
      large_repetitions = std::stoul(argv[++i]);
    else if (a == "--parallel")
      g_use_parallelism = true;
    else if (a == "--quick") {
      sizes = {800, 5000};
      repetitions = large_repetitions = 1;
    }
    else if (a == "--help" || a == "-h") {
      std::cout << "usage: " << argv[0]
                << " [output.json] [--sizes 800,5000,...] [--repetitions N] [--large-repetitions N] "
                   "[--quick] [--parallel]\n";
      return 0;
    }
    else if (!a.empty() && a[0] != '-')
      output = a;
    else {
      std::cerr << "bench_deformation: unknown argument " << a << "\n";
      return 2;
    }
  }
  if (repetitions == 0 || large_repetitions == 0) {
    std::cerr << "bench_deformation: repetitions must be at least 1\n";
    return 2;
  }

  const auto program_start = Clock::now();
  const double cpu_start = cpu_seconds();
  const std::string load_before = read_file_line("/proc/loadavg");

  const auto grid_start = Clock::now();
  const Grid grid = make_grid();
  const double grid_ms = ms_since(grid_start);
  std::cerr << "grid " << kGridNodes << "^3 sampled in " << grid_ms << " ms\n";

  const std::vector<Solver_config> configs = solver_configs();
  const double bandwidth_1 = read_bandwidth_gb_s(1);
  const unsigned cores = (std::max)(1u, std::thread::hardware_concurrency());
  const double bandwidth_all = read_bandwidth_gb_s(cores);
  std::cerr << "read bandwidth: " << bandwidth_1 << " GB/s on one thread, " << bandwidth_all << " GB/s on " << cores
            << "\n";

  Json json;
  json.open("", '{');
  json.value("benchmark", "bench_deformation");
  json.value("date", utc_now());
  json.open("paper", '{')
      .array("faces", {8e2, 5e3, 2e4, 8e4, 3.2e5})
      .array("factor_ms", {0.5, 2.3, 13.2, 932, 8000})
      .array("gtransf_ms", {0.26, 1.5, 6.4, 24.2, 91.1})
      .array("solve_ms", {0.16, 0.25, 0.83, 4.5, 23.0})
      .array("its_per_s", {2300, 570, 130, 35, 9})
      .array("nconv", {5, 9, 16, 19, 22})
      .value("machine", "Intel Core i7-2600 3.4GHz, single-threaded, CHOLMOD")
      .close('}');
  json.open("machine", '{')
      .value("cpu_model", read_first_line_matching("/proc/cpuinfo", "model name"))
      .value("hardware_threads", std::size_t(std::thread::hardware_concurrency()))
      .value("loadavg_before", load_before)
      .value("compiler", __VERSION__)
      .value("cgal", CGAL_VERSION_STR)
      .value("eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                          std::to_string(EIGEN_MINOR_VERSION))
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
      .value("cholmod", std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) +
                            "." + std::to_string(CHOLMOD_SUBSUB_VERSION))
#else
      .value("cholmod", "not used")
#endif
#ifdef NDEBUG
      .value("ndebug", true)
#else
      .value("ndebug", false)
#endif
#ifdef FAS_BENCHMARK_INCLUDE_OVERLAY
      .value("include_overlay", FAS_BENCHMARK_INCLUDE_OVERLAY)
#else
      .value("include_overlay", "")
#endif
      .value("omp_num_threads", std::getenv("OMP_NUM_THREADS") ? std::getenv("OMP_NUM_THREADS") : "unset")
      .value("omp_thread_limit", std::getenv("OMP_THREAD_LIMIT") ? std::getenv("OMP_THREAD_LIMIT") : "unset")
      .value("openblas_num_threads",
             std::getenv("OPENBLAS_NUM_THREADS") ? std::getenv("OPENBLAS_NUM_THREADS") : "unset")
      .value("libraries", loaded_libraries())
      .value("read_bandwidth_gb_s_1_thread", bandwidth_1)
      .value("read_bandwidth_gb_s_all_threads", bandwidth_all)
      .close('}');
  {
    std::ostringstream field;
    field << "point source, |v| = 1/r^2, at (0, 0, -1.6); sampled on a " << kGridNodes
          << "^3 grid over [-1, 1]^3 (" << grid_ms
          << " ms), trilinear interpolation (Regular_grid_flow_field_3)";
    json.open("setup", '{')
        .value("field", field.str())
        .value("use_parallelism", g_use_parallelism)
        .value("patch", "make_planar_patch, 1 x 1, centered at (0, 0, 0.2) (distance 1.8 from the source)")
        .value("start_orthogonal",
               "normal = e_z rotated by 0.3 rad about e_x (aligned state: sphere R = 1.8)")
        .value("start_tangential",
               "normal = e_x rotated by 0.3 rad about e_y (aligned state: cone with apex at the source)")
        .value("convergence",
               "package rule: every requested rotation < epsilon = 1e-6 (and no fold), or the largest "
               "vertex step < 1e-4 of the bounding-box diagonal; default eta = 0.1, theta_max = pi/2")
        .value("max_iterations", kMaxIterations)
        .value("default_solver", default_solver_name())
        .value("solver_steps", kSolverSteps)
        .value("statistics", "median over repetitions of the per-run median over iterations")
        .close('}');
  }

  json.open("sizes", '[');
  for (const std::size_t target : sizes) {
    const std::size_t reps = target >= large_size ? large_repetitions : repetitions;
    std::cerr << "size " << target << " (" << reps << " repetitions)\n";
    std::size_t faces = 0, vertices = 0;

    // Convergence runs with the package's default solver, orthogonal and tangential.
    const FAS::Alignment alignments[2] = {FAS::Alignment::ORTHOGONAL, FAS::Alignment::TANGENTIAL};
    std::vector<double> construct_all, factor_all, gtransf_runs, solve_runs, wall_runs, cpu_runs;
    std::vector<double> gtransf_by[2], solve_by[2];
    std::vector<double> parallel_gtransf, parallel_solve, parallel_final_flux;
    Convergence_run first[2];
    // The solver comparison, interleaved with the convergence runs so that both see the same noise.
    std::vector<std::vector<Solver_sample>> solver_samples(configs.size());
    for (std::size_t r = 0; r < reps; ++r) {
      for (int a = 0; a < 2; ++a) {
        const Convergence_run run = run_to_convergence(grid, alignments[a], target, faces, vertices, g_use_parallelism);
        std::vector<double> g, s, w, u;
        for (std::size_t k = 0; k < run.iterations.size(); ++k) {
          g.push_back(run.iterations[k].gradient_transformation_ms);
          s.push_back(run.iterations[k].solve_ms);
          w.push_back(run.step_wall_ms[k]);
          u.push_back(run.step_cpu_ms[k]);
        }
        factor_all.push_back(run.factor_ms);
        construct_all.push_back(run.construct_ms);
        gtransf_runs.push_back(median(g));
        solve_runs.push_back(median(s));
        wall_runs.push_back(median(w));
        cpu_runs.push_back(median(u));
        gtransf_by[a].push_back(median(g));
        solve_by[a].push_back(median(s));
        if (r == 0)
          first[a] = run;
        else if (run.nconv != first[a].nconv)
          std::cerr << "  note: NCONV changed between repetitions (" << first[a].nconv << " vs " << run.nconv
                    << ")\n";
        std::cerr << "  " << name(alignments[a]) << ": NCONV " << run.nconv << " (" << run.rule << "), flux "
                  << run.initial_flux << " -> " << run.final_flux << ", construct " << run.construct_ms
                  << " ms, factor " << run.factor_ms << " ms, gtransf " << median(g) << " ms, solve "
                  << median(s) << " ms\n";
      }
#ifdef CGAL_LINKED_WITH_TBB
      // The same orthogonal run with use_parallelism (TBB's default arena: every core), beside
      // the single-threaded one in the same repetition.
      if (!g_use_parallelism) {
        const Convergence_run run = run_to_convergence(grid, alignments[0], target, faces, vertices, true);
        std::vector<double> g, s;
        for (const auto& it : run.iterations) {
          g.push_back(it.gradient_transformation_ms);
          s.push_back(it.solve_ms);
        }
        parallel_gtransf.push_back(median(g));
        parallel_solve.push_back(median(s));
        parallel_final_flux.push_back(run.final_flux);
        std::cerr << "  orthogonal, use_parallelism: gtransf " << median(g) << " ms, solve " << median(s)
                  << " ms, final flux " << run.final_flux << "\n";
      }
#endif
      for (std::size_t c = 0; c < configs.size(); ++c) {
        solver_samples[c].push_back(configs[c].measure(grid, target));
        const Solver_sample& s = solver_samples[c].back();
        std::cerr << "  " << configs[c].name << ": factor " << s.factor_ms << " ms (analyze "
                  << s.stats.analyze_ms << ", numeric " << s.stats.numeric_ms << ", " << s.stats.ordering
                  << "), solve " << s.solve_ms << " ms\n";
      }
    }

    const double gtransf = median(gtransf_runs), solve = median(solve_runs);
    json.open("", '{');
    json.value("target_faces", target)
        .value("faces", faces)
        .value("vertices", vertices)
        .value("repetitions", reps)
        .value("default_solver", default_solver_name())
        .value("factor_ms", median(factor_all))
        .array("factor_ms_all", factor_all)
        .value("construct_ms", median(construct_all))
        .value("gtransf_ms", gtransf)
        .value("solve_ms", solve)
        .value("its_per_s", 1000. / (gtransf + solve))
        .value("step_wall_ms", median(wall_runs))
        .value("its_per_s_wall", 1000. / median(wall_runs))
        .value("step_cpu_ms", median(cpu_runs))
        .array("gtransf_ms_runs", gtransf_runs)
        .array("solve_ms_runs", solve_runs);
    if (!parallel_gtransf.empty())
      json.open("parallel", '{')
          .value("threads", std::size_t(std::thread::hardware_concurrency()))
          .value("gtransf_ms", median(parallel_gtransf))
          .value("solve_ms", median(parallel_solve))
          .value("its_per_s", 1000. / (median(parallel_gtransf) + median(parallel_solve)))
          .array("final_flux", parallel_final_flux)
          .close('}');
    json.open("by_alignment", '{');
    for (int a = 0; a < 2; ++a) {
      const Convergence_run& run = first[a];
      std::vector<double> flux, rotation, step;
      for (const auto& it : run.iterations) {
        flux.push_back(it.normalized_flux.value.value());
        rotation.push_back(it.max_rotation_angle);
        step.push_back(it.max_vertex_step);
      }
      json.open(name(alignments[a]), '{')
          .value("nconv", run.nconv)
          .value("converged", run.converged)
          .value("rule", run.rule)
          .value("initial_flux", run.initial_flux)
          .value("final_flux", run.final_flux)
          .value("last_max_rotation_angle",
                 run.iterations.empty() ? 0. : run.iterations.back().max_rotation_angle)
          .value("gtransf_ms", median(gtransf_by[a]))
          .value("solve_ms", median(solve_by[a]))
          .array("flux_before_iteration", flux)
          .array("max_rotation_angle", rotation)
          .array("max_vertex_step", step)
          .close('}');
    }
    json.close('}');
    json.open("solvers", '[');
    for (std::size_t c = 0; c < configs.size(); ++c) {
      std::vector<double> f, s, an, nu, cpu, scpu;
      for (const Solver_sample& x : solver_samples[c]) {
        f.push_back(x.factor_ms);
        s.push_back(x.solve_ms);
        an.push_back(x.stats.analyze_ms);
        nu.push_back(x.stats.numeric_ms);
        cpu.push_back(x.stats.cpu_ms);
        scpu.push_back(x.solve_cpu_ms);
      }
      const Factor_stats& stats = solver_samples[c].front().stats;
      json.open("", '{')
          .value("name", configs[c].name)
          .value("description", configs[c].description)
          .value("factor_ms", median(f))
          .value("analyze_ms", median(an))
          .value("numeric_ms", median(nu))
          .value("factor_cpu_ms", median(cpu))
          .value("solve_ms", median(s))
          .value("solve_cpu_ms", median(scpu))
          .value("ordering", stats.ordering)
          .value("supernodal", stats.supernodal)
          .value("nnz_L", stats.nnz_L)
          .value("flops", stats.flops)
          .value("bytes_per_solve", stats.bytes_per_solve)
          .array("factor_ms_all", f)
          .array("solve_ms_all", s)
          .close('}');
    }
    json.close(']');
    json.close('}');
  }
  json.close(']');

  const double wall_s = ms_since(program_start) / 1000;
  const double bandwidth_after = read_bandwidth_gb_s(1);
  json.open("run", '{')
      .value("read_bandwidth_gb_s_1_thread_after", bandwidth_after)
      .value("wall_s", wall_s)
      .value("cpu_s", cpu_seconds() - cpu_start)
      .value("loadavg_after", read_file_line("/proc/loadavg"))
      .close('}');
  json.close('}');

  std::ofstream out(output);
  out << json.str();
  if (!out) {
    std::cerr << "bench_deformation: could not write " << output << "\n";
    return 1;
  }
  std::cerr << "wrote " << output << " (" << wall_s << " s)\n";
  return 0;
}
