// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The interactive flux-optimizing Poisson deformation of Section 4 of the paper.
// Each iteration k rotates every face's coordinate gradients toward the flow
// (Y'_j = Y_j T_j^T with Y = G X_k, G on the reference mesh M_0) and reconstructs
//
//   X_{k+1} = (L + W)^{-1} (D Y' + W X_c)
//
// with L, D on M_0 factored once.  T_j = sqrt(A_j^0 / A_j^k) R_fold R(n_j x v_j, angle_j),
// angle_j = gamma(n_j, v_j) (orthogonal) or gamma(n_j, v_j) - pi/2 (tangential),
// clamped to eta.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_FLOW_ALIGNED_DEFORMATION_H
#define CGAL_FLOW_ALIGNED_SURFACES_FLOW_ALIGNED_DEFORMATION_H

#include <CGAL/Flow_aligned_surfaces/Alignment.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/solver/Sparse_cholesky.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/parametrization.h>
#include <CGAL/Flow_aligned_surfaces/internal/progress_callback.h>
#include <CGAL/Flow_aligned_surfaces/internal/rotations.h>
#include <CGAL/Flow_aligned_surfaces/internal/timed_factorization.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/Default.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesRef
/// Where the time of the last preparation of a `Flow_aligned_deformation` went: its constructor,
/// or the rebuild of the operators after `grow()` (then the check and mesh-array phases are
/// `grow()`'s own, reported in its `Growth_report`, and are 0 here).  Wall-clock milliseconds.
struct Construction_report {
  double check_ms = 0;       ///< the mesh checked (triangles, manifold, finite positions)
  double mesh_arrays_ms = 0; ///< the mesh flattened into arrays (faces, interior edges, components)
  double operators_ms = 0;   ///< the Poisson operators assembled on \f$ M_0 \f$
  double constraints_ms = 0; ///< the constrained faces chosen and \f$ L + W \f$ formed
  double analyze_ms = 0;     ///< the symbolic analysis (fill-reducing ordering, elimination tree)
  double factorize_ms = 0;   ///< the numeric factorization
};

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief The interactive flow-aligning deformation of a triangulated surface (Section 4 of
the paper): each iteration rotates every face a little toward the flow and reconstructs the
surface by a Poisson solve whose matrix was factored once.

The mesh `tm` given at construction is the surface the user sees: every iteration, rigid
move and growth writes the new vertex positions through the vertex point map, and every
iteration reads them back first, so the user may also move vertices between iterations.
The positions at construction are the reference mesh \f$ M_0 \f$ on which the operators are
discretized; iterations never accumulate errors because they always reconstruct from it.

\tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph` whose faces are triangles
\tparam FlowField a model of `FlowField_3` whose point type is the point type of the vertex point map
\tparam VertexPointMap a model of `ReadWritePropertyMap` with the vertices as key type and a
        point of `GeomTraits` as value type; default: the internal vertex point map of `tm`
\tparam GeomTraits a model of `Kernel`; default: the kernel of the point type
\tparam SparseLinearSolver a model of `SparseLinearAlgebraWithFactorTraits_d` wrapping an Eigen
        sparse Cholesky solver, such as `CGAL::Eigen_solver_traits<S>`; its `solver()` is used to
        factor once and solve the three coordinates at once.  Default: when CHOLMOD was found
        (the macro `CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD`), CHOLMOD's simplicial \f$ LDL^T \f$
        factorization, whose factor the package sweeps in place by supernodes for its own
        back-substitutions on large surfaces (over independent subtrees in parallel with
        `use_parallelism`), and of which it keeps a single-precision copy there for the
        iterations, which solve for the change of the positions (see \ref fas_poisson_reconstruction),
        else `CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>`;
        both run on the calling thread only unless parallelism is asked for (see \ref fas_threads).

The field is held by reference, not copied, as the mesh is: both must outlive this object.

\sa `align_to_flow()`, `normalized_flux()`
*/
template <class TriangleMesh, class FlowField, class VertexPointMap = CGAL::Default,
          class GeomTraits = CGAL::Default, class SparseLinearSolver = CGAL::Default>
class Flow_aligned_deformation {
public:
  /// \name Types
  /// @{

  /// The vertex point map.
  using Vertex_point_map = typename CGAL::Default::Get<
      VertexPointMap, typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::type;
  /// The point type of the vertex point map.
  using Point_3 = typename boost::property_traits<Vertex_point_map>::value_type;
  /// The geometric traits.
  using Geom_traits =
      typename CGAL::Default::Get<GeomTraits, typename CGAL::Kernel_traits<Point_3>::Kernel>::type;
  /// The number type.
  using FT = typename Geom_traits::FT;
  /// The vector type.
  using Vector_3 = typename Geom_traits::Vector_3;
  /// The sparse linear solver.
  using Sparse_linear_solver =
      typename CGAL::Default::Get<SparseLinearSolver, internal::Default_sparse_linear_solver>::type;
  /// The type of the callable that receives every iteration's report.
  using Visitor = std::function<void(const Iteration_report&)>;
  /// The vertex descriptor of `TriangleMesh`.
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  /// @}

private:
  using Positions = internal::Positions;
  using Row_positions = internal::Row_positions;

public:
  /// \name Construction
  /// @{
  /*!
  Prepares the deformation of `tm`: assembles the Poisson operators on the current positions
  (\f$ M_0 \f$) and factors \f$ L + W \f$ once.

  \param tm the surface; it must stay alive and keep its connectivity while this object is used
            (except through `grow()`)
  \param field the flow field; held by reference, never copied, so it must stay alive (and
               unchanged, unless the user wants the next iterations to see the change) as long
               as this object is used.  A temporary is refused at compile time.
  \param alignment tangential (stream surface) or orthogonal (seeding surface)
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tm`}
      \cgalParamType{`Vertex_point_map`}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{`Geom_traits`}
      \cgalParamDefault{a default-constructed `Geom_traits`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `std::size_t` as value type}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
      \cgalParamType{a class model of `ReadablePropertyMap` with `std::size_t` as value type}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the largest number of iterations of `run()`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`100`}
    \cgalParamNEnd
    \cgalParamNBegin{visitor}
      \cgalParamDescription{a callable invoked with the `Iteration_report` of every iteration}
      \cgalParamType{a type convertible to `Visitor`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{callback}
      \cgalParamDescription{CGAL's progress callback (`CGAL::parameters::callback()`), called by
        `run()` after each iteration with the fraction of its iterations done: \f$ k/N \f$ after
        iteration \f$ k \f$ of at most \f$ N \f$, and `1` after the last one (converged or the
        \f$ N \f$-th); if it returns `false`, `run()` returns after that iteration with the
        report's `stopped` set (see \ref fas_progress).  `step()` does not call it.}
      \cgalParamType{a callable convertible to `std::function<bool(double)>`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{max_rotation_angle}
      \cgalParamDescription{η: the largest rotation (radians) applied to a face in one iteration
        (see `Flow_aligned_surfaces::parameters::max_rotation_angle()`)}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.1`}
    \cgalParamNEnd
    \cgalParamNBegin{convergence_angle}
      \cgalParamDescription{ε: converged when every requested rotation is below it (radians)}
      \cgalParamType{`double`}
      \cgalParamDefault{`1e-6`}
    \cgalParamNEnd
    \cgalParamNBegin{convergence_step}
      \cgalParamDescription{also converged when the largest vertex displacement of an iteration
        is below this fraction of the bounding-box diagonal; `0` disables this rule}
      \cgalParamType{`double`}
      \cgalParamDefault{`1e-4`}
    \cgalParamNEnd
    \cgalParamNBegin{max_dihedral_angle}
      \cgalParamDescription{θmax: the largest angle between the normals of two adjacent faces
        before the fold correction acts (radians)}
      \cgalParamType{`double`}
      \cgalParamDefault{`CGAL_PI / 2`}
    \cgalParamNEnd
    \cgalParamNBegin{area_correction}
      \cgalParamDescription{whether gradients are rescaled by \f$ \sqrt{A_j^0/A_j^k} \f$}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{constraint_weight}
      \cgalParamDescription{the soft-constraint weight relative to the mean diagonal of `L`}
      \cgalParamType{`double`}
      \cgalParamDefault{`1e-3`}
    \cgalParamNEnd
    \cgalParamNBegin{use_parallelism}
      \cgalParamDescription{whether the field is sampled and the faces are transformed in
        parallel (with TBB, when the macro `CGAL_LINKED_WITH_TBB` is defined, as the CMake target
        `CGAL::Flow_aligned_surfaces` does when TBB is found, and for 4096 faces or more), and,
        with the default solver, the back-substitutions swept over independent subtrees of the
        elimination tree in parallel, in the
        TBB task arena that `step()` is called from: a caller limits the threads with its own
        `tbb::task_arena`.  The field's `operator()` must then be safe to call concurrently.  The
        surfaces are the same either way.  Without it (the default) this object runs on the
        calling thread only and starts no thread, the factorization included (see
        \ref fas_threads).}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws std::invalid_argument if `tm` is empty, not a valid manifold triangle mesh, has a
          degenerate face, or a parameter is out of range; the message names what is wrong.
  \throws std::runtime_error if the factorization fails.
  */
  template <class NamedParameters = parameters::Default_named_parameters>
  Flow_aligned_deformation(TriangleMesh& tm, const FlowField& field, Alignment alignment,
                           const NamedParameters& np = CGAL::parameters::default_values())
      : m_tm(tm), m_field(field), m_alignment(alignment)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    namespace fnp = Flow_aligned_surfaces::internal_np;

    m_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, tm));
    m_gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    m_max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 100u);
    m_visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), Visitor());
    m_callback = internal::progress_callback(np);
    set_max_rotation_angle(choose_parameter(get_parameter(np, fnp::max_rotation_angle_t()), 0.1));
    set_convergence_angle(choose_parameter(get_parameter(np, fnp::convergence_angle_t()), 1e-6));
    set_convergence_step(choose_parameter(get_parameter(np, fnp::convergence_step_t()), 1e-4));
    set_max_dihedral_angle(choose_parameter(get_parameter(np, fnp::max_dihedral_angle_t()), CGAL_PI / 2));
    set_area_correction(choose_parameter(get_parameter(np, fnp::area_correction_t()), true));
    m_relative_constraint_weight = choose_parameter(get_parameter(np, fnp::constraint_weight_t()), 1e-3);
    m_parallel = choose_parameter(get_parameter(np, fnp::use_parallelism_t()), false);
    internal::use_parallelism_in(m_solver.solver(), m_parallel);
    check_parameter("constraint_weight", m_relative_constraint_weight, m_relative_constraint_weight > 0);

    using Clock = std::chrono::steady_clock;
    const auto checking = Clock::now();
    internal::check_triangle_mesh(tm, "Flow_aligned_deformation: tm");
    const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    const auto fim = CGAL::get_initialized_face_index_map(tm, np);
    m_vertices = internal::vertices_in_index_order(tm, vim);
    m_reference = internal::read_positions(m_vertices, m_vpm);
    internal::check_finite_positions(m_reference, "Flow_aligned_deformation: tm");
    const auto flattening = Clock::now();
    m_arrays = internal::make_mesh_arrays(tm, vim, fim);
    const auto flattened = Clock::now();
    rebuild_operators(m_reference);
    m_construction.check_ms = milliseconds_between(checking, flattening);
    m_construction.mesh_arrays_ms = milliseconds_between(flattening, flattened);
  }

  /// The field is held by reference: a temporary would be destroyed before the first
  /// iteration.  Keep the field in a variable that outlives the deformation.
  template <class NamedParameters = parameters::Default_named_parameters>
  Flow_aligned_deformation(TriangleMesh& tm, const FlowField&& field, Alignment alignment,
                           const NamedParameters& np = CGAL::parameters::default_values()) = delete;
  /// @}

  /// \name Iterations
  /// @{

  /*!
  Performs one iteration on the current positions of `tm` and writes the new ones.
  Calls the visitor with the report, and returns it.
  */
  Iteration_report step()
  {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    Iteration_report report;
    report.iteration = ++m_number_of_iterations;

    // Into buffers kept between iterations: the positions, the right-hand side and the solution
    // are each a few megabytes at 1e5 faces, and fresh memory costs a page fault per 4 KiB.
    // Row by row, so that the three coordinates of a vertex are read and written together.
    internal::read_positions(m_vertices, m_vpm, m_positions);
    const Row_positions& x = m_positions;
    // The user may have moved vertices since the last iteration.
    internal::check_finite_positions(x, "Flow_aligned_deformation::step(): tm");
    const std::size_t n = m_ops.faces.size();
    m_normals.resize(n);
    m_has_normal.assign(n, 0);

    // The new positions solve (L + W) X' = D Y' + W X_c (X_c the constrained vertices' current
    // positions), found as X' = X + C from the current positions X: the residual
    // D Y' + W X_c - (L + W) X = D Y' - L X = sum_j K_j X_j (T_j - I)^T (K_j the M_0 stiffness of
    // face j, T_j its local transformation) is assembled in double, each face's term added as
    // soon as T_j is known (one pass over the faces, nothing stored per face but its normal for
    // the fold test), and (L + W) C = residual is solved.  This is one step of iterative
    // refinement from X: the default solver solves C in single precision with a copy of a large
    // factor (half the bytes to read), whose error is proportional to C, the step, not to X'
    // (and is largest in C's translation, which translate_as_the_exact_correction() sets;
    // RESULTS.md, "The solver").
    m_residual.setZero(x.rows(), 3);
    Face_pass face_pass;
#ifdef CGAL_LINKED_WITH_TBB
    // Faces are independent; below a few thousand the threads cost more than they save.  The
    // algorithm runs in the caller's task arena (tbb::this_task_arena), so a caller's
    // tbb::task_arena bounds the threads.
    if (m_parallel && n >= 4096)
      face_pass = parallel_face_pass(x);
    else
#endif
    {
      transform_faces(x, 0, n, face_pass, [this](std::size_t j, const Eigen::Matrix3d& term) {
        const auto& vertices = m_ops.faces[j].vertices;
        for (int i = 0; i < 3; ++i)
          m_residual.row(vertices[i]) += term.row(i);
      });
    }
    report.number_of_outside_samples = face_pass.outside;
    report.number_of_invalid_samples = face_pass.invalid;
    report.number_of_zero_samples = face_pass.zero;
    report.normalized_flux = face_pass.flux.result();
    report.max_rotation_angle = face_pass.largest_requested.radians();
    report.number_of_folds = correct_folds(x);
    const auto transformed = Clock::now();

    internal::solve_correction(m_solver.solver(), x, m_residual, m_next);
    translate_as_the_exact_correction(x, m_next);
    const Row_positions& next = m_next;
    const auto solved = Clock::now();
    if (m_solver.solver().info() != Eigen::Success || !next.allFinite())
      throw std::runtime_error("Flow_aligned_deformation::step(): the Poisson solve failed");

    const double diagonal = bounding_box_diagonal(x);
    report.max_vertex_step = diagonal > 0 ? (next - x).rowwise().norm().maxCoeff() / diagonal : 0;
    internal::write_positions(next, m_vertices, m_vpm, m_gt);

    report.gradient_transformation_ms =
        std::chrono::duration<double, std::milli>(transformed - start).count();
    report.solve_ms = std::chrono::duration<double, std::milli>(solved - transformed).count();
    // The paper's rule (every rotation below epsilon; a fold correction is a rotation too), or
    // the practical one: on curved targets the requested rotations stall at a floor of about
    // 0.1 h kappa that the Poisson solve cannot remove, while the surface no longer moves.
    report.converged = (report.max_rotation_angle < m_epsilon && report.number_of_folds == 0) ||
                       report.max_vertex_step < m_convergence_step;
    m_last_report = report;
    if (m_visitor)
      m_visitor(report);
    return report;
  }

  /*!
  Writes to `out` the points at which the next `step()` samples the field, if the positions
  of `tm` are not changed in between: the centroid of every face of the current surface that
  has a normal (a face collapsed to zero area is not sampled), one point per face in the order
  of the faces, bit for bit the points that `step()` passes to the field's `operator()`.

  This lets a caller whose field is expensive to query point by point (a data set distributed
  over MPI ranks, a remote server) compute all the samples of an iteration in one batch and
  hand them to `step()` through a field that looks them up.  The iteration reads nothing else
  of the field.

  \tparam OutputIterator an output iterator accepting `Point_3`
  \returns the output iterator after the last point written
  \throws std::invalid_argument if a position of `tm` is not finite (as `step()` would)
  */
  template <class OutputIterator>
  OutputIterator next_sample_points(OutputIterator out) const
  {
    const Positions x = internal::read_positions(m_vertices, m_vpm);
    internal::check_finite_positions(x, "Flow_aligned_deformation::next_sample_points(): tm");
    auto construct_point = m_gt.construct_point_3_object();
    for (const internal::Reference_face& face : m_ops.faces) {
      const Current_face current = current_face(x, face);
      if (current.sampled)
        *out++ = construct_point(current.centroid.x(), current.centroid.y(), current.centroid.z());
    }
    return out;
  }

  /*!
  Iterates until an iteration converges or `number_of_iterations` (given at construction)
  iterations were made, or the `callback` given at construction returns `false`.  The report's
  flux is that of the final surface.
  */
  Alignment_report run()
  {
    return run(m_max_iterations);
  }

  /// Same as `run()` with at most `max_iterations` iterations.
  Alignment_report run(std::size_t max_iterations)
  {
    Alignment_report result;
    for (std::size_t k = 1; k <= max_iterations; ++k) {
      const Iteration_report r = step();
      ++result.number_of_iterations;
      result.max_rotation_angle = r.max_rotation_angle;
      result.converged = r.converged;
      const bool last = r.converged || k == max_iterations;
      if (!internal::report_progress(m_callback, last ? 1. : double(k) / double(max_iterations))) {
        // A stop that came after the last iteration ended nothing.
        result.stopped = !last;
        break;
      }
      if (last)
        break;
    }
    result.normalized_flux = current_normalized_flux();
    result.factor_ms = m_factor_ms;
    return result;
  }
  /// @}

  /// \name Rigid Moves
  /// Moves between iterations: they change the current surface only, so nothing is refactored.
  /// @{

  /// Translates the surface by `v`.  \throws std::invalid_argument if `v` is not finite.
  void translate(const Vector_3& v)
  {
    if (!to_eigen(v).allFinite())
      throw std::invalid_argument("Flow_aligned_deformation::translate(): the vector is not finite");
    Positions x = internal::read_positions(m_vertices, m_vpm);
    x.rowwise() += to_eigen(v).transpose();
    internal::write_positions(x, m_vertices, m_vpm, m_gt);
  }

  /// Rotates the surface by `angle` (radians, right-handed) about the line through `center`
  /// along `axis`.  \throws std::invalid_argument if `axis` is zero or anything is not finite.
  void rotate(const Point_3& center, const Vector_3& axis, FT angle)
  {
    const Eigen::Vector3d a = to_eigen(axis);
    const Eigen::RowVector3d c(CGAL::to_double(center.x()), CGAL::to_double(center.y()),
                               CGAL::to_double(center.z()));
    if (!(a.norm() > 0) || !a.allFinite() || !std::isfinite(CGAL::to_double(angle)) || !c.allFinite())
      throw std::invalid_argument("Flow_aligned_deformation::rotate(): the axis must be a finite non-zero "
                                  "vector, and the angle and the center finite");
    const Eigen::Matrix3d r = internal::rotation_matrix(a.normalized(), CGAL::to_double(angle));
    Positions x = internal::read_positions(m_vertices, m_vpm);
    x = ((x.rowwise() - c) * r.transpose()).rowwise() + c;
    internal::write_positions(x, m_vertices, m_vpm, m_gt);
  }

  /// Rotates the surface by `angle` about the axis `axis` through the centroid of its vertices.
  void rotate(const Vector_3& axis, FT angle)
  {
    const Eigen::RowVector3d c = internal::read_positions(m_vertices, m_vpm).colwise().mean();
    rotate(m_gt.construct_point_3_object()(c[0], c[1], c[2]), axis, angle);
  }
  /// @}

  /// \name Growing
  /// @{

  /*!
  Grows the surface at its boundary by `distance` (Section 4 of the paper), as
  `grow_boundary()` does to the current surface \f$ M_k \f$, and applies the same update to the
  reference mesh \f$ M_0 \f$: there each offset is expressed in \f$ M_0 \f$'s own boundary frame
  (boundary tangent, outward direction, normal) at the same vertex, and each new vertex takes
  the barycentric coordinates it has in the untessellated strip of \f$ M_k \f$ in the same
  strip of \f$ M_0 \f$.  Then the operators are rebuilt on \f$ M_0 \f$ and \f$ L + W \f$ is
  refactored once (`number_of_factorizations()` grows by one); iterations continue from the
  grown surface.

  With `across_flow`, the flow is the deformation's own field.

  \param distance the offset, positive and finite
  \param np an optional sequence of named parameters among `growth_direction`, `across_flow`
         and `callback`, with the meanings of `grow_boundary()`: the callback is called with
         `0.5` once the strip is built and with `1` once the surface is grown and \f$ L + W \f$
         refactored; if the first call returns `false`, nothing is modified (neither `tm` nor
         this object) and the report's `stopped` is set

  \returns what was grown, with the times of the offset, the tessellation, the placement in
           \f$ M_0 \f$ and the refactorization; its grown edges are given by indices into
           `vertices()`.
  \throws std::invalid_argument, before anything is modified, in the cases of `grow_boundary()`
          (the checks of the strip are made on \f$ M_k \f$, and its folding also on \f$ M_0 \f$),
          and if `across_flow` is asked of an orthogonal deformation (whose surface is across the
          flow everywhere, so no boundary direction is across it).
  \throws std::runtime_error if the refactorization fails (the mesh is then grown, but this
          object must not be used any more).
  \sa `grow_boundary()`
  */
  template <class NamedParameters = parameters::Default_named_parameters>
  Growth_report grow(double distance, const NamedParameters& np = CGAL::parameters::default_values())
  {
    const char* caller = "Flow_aligned_deformation::grow()";
    const internal::Growth_options options = internal::read_growth_options(np, caller);
    if (options.across_flow && m_alignment != Alignment::TANGENTIAL)
      internal::throw_growth_error(caller,
                                   "across_flow needs a tangential deformation (this one is orthogonal)");
    const Positions x = internal::read_positions(m_vertices, m_vpm);
    internal::check_finite_positions(x, std::string(caller) + ": tm");

    auto vim = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m_tm);
    for (std::size_t i = 0; i < m_vertices.size(); ++i)
      put(vim, m_vertices[i], i);
    auto construct_point = m_gt.construct_point_3_object();
    const internal::Boundary_strip strip = internal::make_boundary_strip(
        m_tm, vim, x, &m_reference, distance, options,
        [&](const Eigen::Vector3d& p) {
          return internal::sample_flow(m_field, construct_point(p.x(), p.y(), p.z()));
        },
        caller);
    const internal::Progress_callback callback = internal::progress_callback(np);
    if (!internal::report_progress(callback, internal::strip_built_fraction))
      return internal::stopped_growth(strip.report);

    const auto append_start = std::chrono::steady_clock::now();
    const std::vector<vertex_descriptor> added = internal::append_strip(m_tm, m_vpm, m_gt, m_vertices, strip);
    const Eigen::Index m = m_reference.rows();
    m_reference.conservativeResize(m + Eigen::Index(added.size()), 3);
    for (std::size_t i = 0; i < added.size(); ++i) {
      m_reference.row(m + Eigen::Index(i)) = strip.reference_points[i].transpose();
      put(vim, added[i], m_vertices.size());
      m_vertices.push_back(added[i]);
    }
    auto fim = get(CGAL::dynamic_face_property_t<std::size_t>(), m_tm);
    std::size_t face_index = 0;
    for (auto f : faces(m_tm))
      put(fim, f, face_index++);
    m_arrays = internal::make_mesh_arrays(m_tm, vim, fim);
    const auto factor_start = std::chrono::steady_clock::now();
    rebuild_operators(m_reference, true);
    const auto end = std::chrono::steady_clock::now();

    Growth_report report = strip.report;
    report.reference_map_ms += std::chrono::duration<double, std::milli>(factor_start - append_start).count();
    report.factor_ms = std::chrono::duration<double, std::milli>(end - factor_start).count();
    internal::report_progress(callback, 1.);
    return report;
  }
  /// @}

  /// \name Parametrizing with the Factored Operators (Section 5)
  /// The parametrizations of `parametrize.h` on the current surface \f$ M_k \f$, solved with
  /// this object's factorization of \f$ L + W \f$ on \f$ M_0 \f$ instead of a new one: the
  /// per-face guidance \f$ a_j \f$ is computed on \f$ M_k \f$, pulled back to the same face of
  /// \f$ M_0 \f$ (the vector whose dot products with the face's edges in \f$ M_0 \f$ are those of
  /// \f$ a_j \f$ with the edges in \f$ M_k \f$, so that a function with gradient \f$ a_j \f$ on
  /// \f$ M_k \f$ has that gradient on \f$ M_0 \f$), and eq. (7) is solved on \f$ M_0 \f$ with one
  /// back-substitution pair for both columns, as the paper's reuse of the prefactored
  /// \f$ \mathbf{L} \f$ implies.  The energy is then measured with \f$ M_0 \f$'s metric, equal
  /// to \f$ M_k \f$'s where the deformation is isometric (the area correction keeps it near
  /// isometric).  On \f$ M_k = M_0 \f$ the results equal the free functions' up to the soft
  /// constraint, which here sits on the three vertices of the deformation's constrained face
  /// (weight \f$ 10^{-3} \f$ of the mean diagonal of \f$ L \f$): a relative difference of the order of
  /// \f$ 10^{-3} h / \mathrm{diameter} \f$.  Results are shifted to 0 at the vertex of
  /// `parametrize.h`'s rule (or at `constraint_vertex`).
  /// @{

  /*!
  `parametrize_tangential()` of the current surface in this object's field, with the factored
  \f$ L + W \f$: one pass over the faces and one back-substitution pair.
  \param r_map, s_map receive \f$ r \f$ and \f$ s \f$ at the vertices
  \param np an optional sequence of named parameters among `normalized` and `constraint_vertex`,
         with the meanings and defaults of `parametrize_tangential()`
  \throws std::invalid_argument if `constraint_vertex` is not a vertex of the mesh, if a face of
          the current surface is degenerate, or if no face gets a usable direction; the maps are
          then untouched.
  \sa `parametrize_tangential()`
  */
  template <class RMap, class SMap, class NamedParameters = parameters::Default_named_parameters>
  void parametrize_tangential(RMap r_map, SMap s_map,
                              const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    const std::string caller = "Flow_aligned_deformation::parametrize_tangential";
    const bool normalize =
        parameters::choose_parameter(parameters::get_parameter(np, internal_np::normalized_t()), true);
    const internal::Surface_faces current = current_surface_faces(caller);
    const auto constrained = parametrization_constraints(current, np, caller);
    const internal::Positions a = internal::tangential_guidance(
        current, internal::sample_face_velocities(current, m_field, m_gt), normalize);
    const Eigen::MatrixXd rs =
        solve_on_reference(current, internal::cross_field(current, a, caller), constrained);
    internal::write_vertex_values(m_vertices, rs, 0, r_map);
    internal::write_vertex_values(m_vertices, rs, 1, s_map);
  }

  /*!
  `parametrize_orthogonal()` of the current surface in this object's field, with the factored
  \f$ L + W \f$: one pass over the faces and one back-substitution pair.
  \param r_map, s_map receive \f$ r \f$ and \f$ s \f$ at the vertices
  \param np an optional sequence of named parameters among `angle`, `gradient_direction`,
         `normalized` and `constraint_vertex`, with the meanings and defaults of
         `parametrize_orthogonal()`
  \throws std::invalid_argument if `angle` is not finite, if `gradient_direction` is not finite,
          zero or normal to the surface at a constrained vertex, and in the cases of the member
          `parametrize_tangential()`; the maps are then untouched.
  \sa `parametrize_orthogonal()`
  */
  template <class RMap, class SMap, class NamedParameters = parameters::Default_named_parameters>
  void parametrize_orthogonal(RMap r_map, SMap s_map,
                              const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    const std::string caller = "Flow_aligned_deformation::parametrize_orthogonal";
    const double alpha = internal::orthogonal_parametrization_angle(np, caller);
    const bool normalize =
        parameters::choose_parameter(parameters::get_parameter(np, internal_np::normalized_t()), false);
    const internal::Surface_faces current = current_surface_faces(caller);
    const auto constrained = parametrization_constraints(current, np, caller);
    const internal::Positions a = internal::orthogonal_guidance(
        m_arrays, current, internal::sample_face_velocities(current, m_field, m_gt), constrained, alpha,
        normalize, internal::orthogonal_gradient_direction(np, caller), caller);
    const Eigen::MatrixXd rs =
        solve_on_reference(current, internal::cross_field(current, a, caller), constrained);
    internal::write_vertex_values(m_vertices, rs, 0, r_map);
    internal::write_vertex_values(m_vertices, rs, 1, s_map);
  }

  /*!
  `compute_geodesic_distance()` on the current surface (the circular seeds of Section 5): the
  heat step \f$ (\mathbf{M} + t\mathbf{L}) h = h_0 \f$ with \f$ \mathbf{L} \f$, \f$ \mathbf{M} \f$
  and \f$ t = 5 A_M / |T| \f$ of \f$ M_0 \f$ (one new factorization), the normalized
  \f$ -\nabla h \f$ on the faces of \f$ M_k \f$, and the final Poisson solve with the factored
  \f$ L + W \f$: two solves and one factorization in all.  The operators are those of
  \f$ M_0 \f$'s own triangles, as the free function's with `intrinsic_delaunay(false)`: on a
  mesh whose triangles are far from Delaunay the free function's default is more accurate.
  \param source the vertex where the distance is 0
  \param distance_map receives the distance at every vertex (\f$ +\infty \f$ on other components)
  \throws std::invalid_argument if `source` is not a vertex of the mesh or a face of the current
          surface is degenerate; `distance_map` is then untouched.
  \throws std::runtime_error if the heat system cannot be factored.
  \sa `compute_geodesic_distance()`
  */
  template <class DistanceMap>
  void compute_geodesic_distance(vertex_descriptor source, DistanceMap distance_map) const
  {
    const std::string caller = "Flow_aligned_deformation::compute_geodesic_distance";
    const Eigen::Index source_index =
        internal::vertex_index_or_throw(m_vertices, source, caller + ": source");
    const internal::Surface_faces current = current_surface_faces(caller);
    const std::size_t component = current.vertex_component[std::size_t(source_index)];
    const Eigen::Index m = m_ops.number_of_vertices();

    const Eigen::VectorXd h =
        internal::heat_step<Sparse_linear_solver>(m_ops, m_arrays, source_index, component);

    Eigen::MatrixXd d =
        solve_on_reference(current, internal::normalized_negative_gradient(m_arrays, current, h),
                           internal::constrained_vertices(m_arrays, current, source_index));
    for (Eigen::Index i = 0; i < m; ++i)
      if (current.vertex_component[std::size_t(i)] != component)
        d(i, 0) = std::numeric_limits<double>::infinity();
    internal::write_vertex_values(m_vertices, d, 0, distance_map);
  }
  /// @}

  /// \name Access
  /// @{

  /// The vertices of the surface in the order of the rows of the operators (the order of the
  /// vertex index map at construction, then the vertices added by `grow()`).
  const std::vector<vertex_descriptor>& vertices() const
  {
    return m_vertices;
  }
  /// The position in the reference mesh \f$ M_0 \f$ of `vertices()[i]`.
  Point_3 reference_point(std::size_t i) const
  {
    const auto r = m_reference.row(Eigen::Index(i));
    return m_gt.construct_point_3_object()(r[0], r[1], r[2]);
  }

  /// The surface.
  const TriangleMesh& mesh() const
  {
    return m_tm;
  }
  /// The alignment target.
  Alignment alignment() const
  {
    return m_alignment;
  }
  /// Changes the alignment target; the factorization is kept.
  void set_alignment(Alignment alignment)
  {
    m_alignment = alignment;
  }

  /// The flow field.
  const FlowField& field() const
  {
    return m_field;
  }
  /// Iterations performed since construction.
  std::size_t number_of_iterations() const
  {
    return m_number_of_iterations;
  }
  /// Factorizations of \f$ L + W \f$ performed since construction (one, unless the connectivity changed).
  std::size_t number_of_factorizations() const
  {
    return m_number_of_factorizations;
  }
  /// Where the time of the constructor, or of the last `grow()`'s rebuild of the operators, went.
  const Construction_report& construction_report() const
  {
    return m_construction;
  }
  /// The report of the last iteration.
  const Iteration_report& last_report() const
  {
    return m_last_report;
  }
  /// The normalized flux of the current surface and its sampled area fraction (one more sampling
  /// of the field); no value when no face of the surface has a usable sample.
  Normalized_flux current_normalized_flux() const
  {
    return internal::normalized_flux(internal::read_positions(m_vertices, m_vpm), m_arrays.face_vertices,
                                     m_field, m_gt);
  }
  /// @}

  /// \name Parameters of the Iterations
  /// The parameters of the constructor that do not enter \f$ L + W \f$: changing them between
  /// iterations keeps the factorization, and the next iterations use the new values (`run()`
  /// takes its number of iterations as an argument).
  /// \throws std::invalid_argument from a setter, naming the parameter, when the value is out of
  ///         the range the constructor accepts; the parameter is then left as it was.
  /// @{

  /// η, the largest rotation of a face in one iteration (radians, in \f$ ]0, \pi] \f$).
  double max_rotation_angle() const
  {
    return m_eta;
  }
  /// sets η.
  void set_max_rotation_angle(double eta)
  {
    check_parameter("max_rotation_angle", eta, eta > 0 && eta <= CGAL_PI);
    m_eta = eta;
    // Requested angles never exceed pi/2, so a larger eta never clamps.
    m_cos_eta = std::cos((std::min)(m_eta, CGAL_PI / 2));
    m_sin_eta = std::sin((std::min)(m_eta, CGAL_PI / 2));
  }
  /// θmax, the dihedral angle above which the fold correction acts (radians, in \f$ ]0, \pi] \f$).
  double max_dihedral_angle() const
  {
    return m_theta_max;
  }
  /// sets θmax.
  void set_max_dihedral_angle(double theta_max)
  {
    check_parameter("max_dihedral_angle", theta_max, theta_max > 0 && theta_max <= CGAL_PI);
    m_theta_max = theta_max;
    m_cos_theta_max_margin = std::cos(m_theta_max) + 1e-9;
  }
  /// ε, the convergence angle (radians, at least 0).
  double convergence_angle() const
  {
    return m_epsilon;
  }
  /// sets ε.
  void set_convergence_angle(double epsilon)
  {
    check_parameter("convergence_angle", epsilon, epsilon >= 0);
    m_epsilon = epsilon;
  }
  /// The convergence step: the fraction of the bounding-box diagonal below which the largest
  /// vertex displacement of an iteration means convergence (at least 0; 0: the rule is off).
  double convergence_step() const
  {
    return m_convergence_step;
  }
  /// sets the convergence step.
  void set_convergence_step(double step)
  {
    check_parameter("convergence_step", step, step >= 0);
    m_convergence_step = step;
  }
  /// Whether gradients are rescaled by \f$ \sqrt{A_j^0/A_j^k} \f$.
  bool area_correction() const
  {
    return m_area_correction;
  }
  /// sets whether gradients are rescaled by \f$ \sqrt{A_j^0/A_j^k} \f$.
  void set_area_correction(bool correct)
  {
    m_area_correction = correct;
  }
  /// @}

private:
  static void check_parameter(const char* name, double value, bool valid)
  {
    if (!valid || !std::isfinite(value))
      throw std::invalid_argument(std::string("Flow_aligned_deformation: parameter ") + name + " = " +
                                  std::to_string(value) + " is out of range");
  }

  static double milliseconds_between(std::chrono::steady_clock::time_point start,
                                     std::chrono::steady_clock::time_point end)
  {
    return std::chrono::duration<double, std::milli>(end - start).count();
  }

  static Eigen::Vector3d to_eigen(const Vector_3& v)
  {
    return Eigen::Vector3d(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
  }

  template <class Matrix>
  static double bounding_box_diagonal(const Matrix& x)
  {
    return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  }

  // An angle in [0, pi/2] known by its cosine and sine; compared through a key that is
  // monotone in the angle and keeps full precision for tiny angles, so the hot loop needs no
  // trigonometric function.
  struct Rotation_angle {
    double cos = 1, sin = 0;
    double key() const { return cos >= sin ? sin : 2 - cos; }
    double radians() const { return std::atan2(sin, cos); }
  };

  // What the pass over the faces accumulates besides the per-face transforms.
  struct Face_pass {
    internal::Normalized_flux_sum flux;
    Rotation_angle largest_requested;
    std::size_t outside = 0, invalid = 0, zero = 0;
    void join(const Face_pass& other)
    {
      flux.join(other.flux);
      if (other.largest_requested.key() > largest_requested.key())
        largest_requested = other.largest_requested;
      outside += other.outside;
      invalid += other.invalid;
      zero += other.zero;
    }
  };

  // A face of the current positions: its unit normal and centroid, and whether step() samples
  // the field there (a face collapsed to zero area, or with non-finite positions, has no normal
  // and is not sampled).  The one place the sampled points are computed: step() and
  // next_sample_points() both use it, so that they agree bit for bit.
  struct Current_face {
    Eigen::Vector3d normal, centroid;
    double twice_area = 0, inverse_twice_area = 0;
    bool sampled = false;
  };
  template <class Matrix>
  static Current_face current_face(const Matrix& x, const internal::Reference_face& face)
  {
    Current_face current;
    const Eigen::Vector3d a = x.row(face.vertices[0]).transpose(), b = x.row(face.vertices[1]).transpose(),
                          c = x.row(face.vertices[2]).transpose();
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    current.twice_area = cross.norm();
    if (!(current.twice_area > 0) || !std::isfinite(current.twice_area))
      return current;
    // Products by reciprocals: three divisions fewer per face than dividing here and in
    // measure_alignment() (2 % of GTRANSF at 3.2e5 faces; RESULTS.md,
    // "Alignment iterations (Table 1)").
    current.inverse_twice_area = 1 / current.twice_area;
    current.normal = cross * current.inverse_twice_area;
    current.centroid = (a + b + c) * (1. / 3);
    current.sampled = true;
    return current;
  }

  // What the rotation of a face toward alignment needs besides the face's normal: the field's
  // sample at the centroid, c = n . v, n x v and its norm s (the cosine and sine of the angle
  // between normal and direction, when the sample is valid), and the area correction's factor.
  struct Face_alignment {
    internal::Flow_sample sample;
    Eigen::Vector3d cross = Eigen::Vector3d::Zero();
    double sin = 0, cos = 1, area_scale = 1;
  };

  // The faces [begin, end) of the current positions `x`, a block at a time, each stage over the
  // whole block before the next: the frames, the field's queries, the samples' directions, the
  // angles and area factors, and last the transformations T_j, whose terms K_j X_j T_j^T go to
  // `add_term(j, term)` in face order.  Per face this is the same computation as one face at a
  // time (`transform_face()`: the same results, bit for bit).  By stages, the square roots and
  // divisions of neighbouring faces, whose latencies are most of GTRANSF face by face, overlap
  // in the processor (0.61 to 0.69 times the time face by face; RESULTS.md,
  // "Alignment iterations (Table 1)").
  template <class Matrix, class AddTerm>
  void transform_faces(const Matrix& x, std::size_t begin, std::size_t end, Face_pass& pass, AddTerm add_term)
  {
    constexpr std::size_t block = 32;
    std::array<Current_face, block> current;
    std::array<Face_alignment, block> alignment;
    for (std::size_t first = begin; first < end; first += block) {
      const std::size_t size = (std::min)(block, end - first);
      for (std::size_t k = 0; k < size; ++k)
        current[k] = current_face(x, m_ops.faces[first + k]);
      for (std::size_t k = 0; k < size; ++k)
        alignment[k].sample = current[k].sampled
                                  ? internal::unclassified_sample(m_field(point(current[k].centroid)))
                                  : internal::Flow_sample();
      for (std::size_t k = 0; k < size; ++k)
        internal::classify_sample(alignment[k].sample);
      for (std::size_t k = 0; k < size; ++k)
        measure_alignment(first + k, current[k], alignment[k]);
      for (std::size_t k = 0; k < size; ++k)
        add_term(first + k, face_term(x, first + k, transform_face(first + k, current[k], alignment[k], pass)));
    }
  }

  // The local transformation T_j of face j alone (as `transform_faces()` computes it).
  template <class Matrix>
  Eigen::Matrix3d transform_face(const Matrix& x, std::size_t j, Face_pass& pass)
  {
    const Current_face current = current_face(x, m_ops.faces[j]);
    Face_alignment alignment;
    if (current.sampled)
      alignment.sample = internal::sample_flow(m_field, point(current.centroid));
    measure_alignment(j, current, alignment);
    return transform_face(j, current, alignment, pass);
  }

  auto point(const Eigen::Vector3d& p) const { return m_gt.construct_point_3_object()(p.x(), p.y(), p.z()); }

  // Fills in `alignment` the angle and the area factor of face j, whose sample it holds.
  void measure_alignment(std::size_t j, const Current_face& current, Face_alignment& alignment) const
  {
    if (!current.sampled)
      return;
    if (m_area_correction)
      alignment.area_scale = std::sqrt(2 * m_ops.faces[j].area * current.inverse_twice_area);
    if (alignment.sample.kind == internal::Sample_kind::VALID) {
      alignment.cross = current.normal.cross(alignment.sample.direction);
      alignment.sin = alignment.cross.norm();
      alignment.cos = current.normal.dot(alignment.sample.direction);
    }
  }

  // The local transformation T_j of face j, given its frame `current` and its `alignment`:
  // rotates toward alignment and corrects the area; records the face's normal for the fold test
  // and its sample in `pass`.
  Eigen::Matrix3d transform_face(std::size_t j, const Current_face& current, const Face_alignment& alignment,
                                 Face_pass& pass)
  {
    // A face collapsed by the user has no normal; it keeps its gradients (T = I).
    if (!current.sampled)
      return Eigen::Matrix3d::Identity();
    const Eigen::Vector3d& normal = current.normal;
    m_normals[j] = normal;
    m_has_normal[j] = true;

    const internal::Flow_sample& sample = alignment.sample;
    pass.flux.add(0.5 * current.twice_area, internal::face_flux(normal, sample));
    Eigen::Matrix3d t = Eigen::Matrix3d::Identity();
    switch (sample.kind) {
    case internal::Sample_kind::OUTSIDE:
      ++pass.outside;
      break;
    case internal::Sample_kind::INVALID:
      ++pass.invalid;
      break;
    case internal::Sample_kind::ZERO:
      ++pass.zero;
      break;
    case internal::Sample_kind::VALID: {
      Rotation_angle requested;
      t = alignment_rotation(normal, alignment, requested);
      if (requested.key() > pass.largest_requested.key())
        pass.largest_requested = requested;
      break;
    }
    }
    if (m_area_correction)
      t *= alignment.area_scale;
    return t;
  }

  // The correction C = next - x of step() translated so that each connected component's
  // constrained vertices keep their mean, as the exact C does: the residual sums to zero over a
  // component (so do the rows of every K_j), and the sum of (L + W) C over it is W's part alone.
  // This is C's component along the constant vectors, the near-null space of L + W (its only
  // stiffness the weak W), where a single-precision factor's error is largest by far (about 1e-7
  // of the positions there, 1e-9 with the translation set, on 8e3 faces: test
  // SinglePrecisionCorrectionsReachTheDoublePrecisionSurface).
  void translate_as_the_exact_correction(const Row_positions& x, Row_positions& next)
  {
    const std::size_t components = m_arrays.number_of_components;
    m_component_shift.assign(components, Eigen::RowVector3d::Zero());
    for (std::size_t k = 0; k < m_constrained_vertices.size(); ++k) {
      const Eigen::Index v = m_constrained_vertices[k];
      m_component_shift[k / 3] += (next.row(v) - x.row(v)) / 3;
    }
    if (components == 1) {
      next.rowwise() -= m_component_shift[0];
      return;
    }
    for (Eigen::Index v = 0; v < next.rows(); ++v)
      next.row(v) -= m_component_shift[m_vertex_component[std::size_t(v)]];
  }

  // Face j's term K_j X_j (T - I)^T of the residual, one row per corner.
  Eigen::Matrix3d face_term(const Row_positions& x, std::size_t j, const Eigen::Matrix3d& t) const
  {
    const internal::Reference_face& face = m_ops.faces[j];
    Eigen::Matrix3d local;
    for (int i = 0; i < 3; ++i)
      local.row(i) = x.row(face.vertices[i]);
    return face.times_stiffness(local * (t - Eigen::Matrix3d::Identity()).transpose());
  }

#ifdef CGAL_LINKED_WITH_TBB
  // The pass over the faces on the threads of the caller's arena: the terms of the faces are
  // computed in parallel, then each vertex adds those of its faces in face order, as the serial
  // pass does, so that the right-hand side is the same bit for bit.
  Face_pass parallel_face_pass(const Row_positions& x)
  {
    const std::size_t n = m_ops.faces.size();
    m_terms.resize(n);
    const Face_pass pass = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 1024), Face_pass(),
        [&](const tbb::blocked_range<std::size_t>& range, Face_pass partial) {
          transform_faces(x, range.begin(), range.end(), partial,
                          [this](std::size_t j, const Eigen::Matrix3d& term) { m_terms[j] = term; });
          return partial;
        },
        [](Face_pass left, const Face_pass& right) {
          left.join(right);
          return left;
        });
    if (m_corner_offsets.size() != std::size_t(x.rows()) + 1)
      make_vertex_corners(std::size_t(x.rows()));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, std::size_t(x.rows()), 2048),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t v = range.begin(); v != range.end(); ++v)
                          for (std::size_t c = m_corner_offsets[v]; c != m_corner_offsets[v + 1]; ++c)
                            m_residual.row(Eigen::Index(v)) += m_terms[m_corners[c] / 3].row(int(m_corners[c] % 3));
                      });
    return pass;
  }

  // For every vertex, its corners (3 j + i: corner i of face j) in increasing face order.
  void make_vertex_corners(std::size_t number_of_vertices)
  {
    m_corner_offsets.assign(number_of_vertices + 1, 0);
    for (const internal::Reference_face& face : m_ops.faces)
      for (Eigen::Index v : face.vertices)
        ++m_corner_offsets[std::size_t(v) + 1];
    for (std::size_t v = 0; v < number_of_vertices; ++v)
      m_corner_offsets[v + 1] += m_corner_offsets[v];
    m_corners.resize(3 * m_ops.faces.size());
    std::vector<std::size_t> next(m_corner_offsets.begin(), m_corner_offsets.end() - 1);
    for (std::size_t j = 0; j < m_ops.faces.size(); ++j)
      for (int i = 0; i < 3; ++i)
        m_corners[next[std::size_t(m_ops.faces[j].vertices[i])]++] = 3 * j + std::size_t(i);
  }
#endif

  // Fold correction: opens every crease sharper than theta_max by delta/2 on each side, that is
  // T_p becomes R T_p, and replaces the faces' terms in the right-hand side accordingly.
  // Returns the number of folded edges.
  std::size_t correct_folds(const Row_positions& x)
  {
    std::vector<std::pair<std::size_t, Eigen::Matrix3d>> folded; // face, product of its fold rotations
    m_fold_slot.resize(m_ops.faces.size(), -1);                  // face -> its place in `folded`
    auto rotation_of = [&](std::size_t face) -> Eigen::Matrix3d& {
      if (m_fold_slot[face] < 0) {
        m_fold_slot[face] = std::ptrdiff_t(folded.size());
        folded.emplace_back(face, Eigen::Matrix3d::Identity());
      }
      return folded[std::size_t(m_fold_slot[face])].second;
    };
    std::size_t folds = 0;
    for (const auto& edge : m_arrays.interior_edges) {
      const std::size_t p = edge.faces[0], q = edge.faces[1];
      if (!m_has_normal[p] || !m_has_normal[q])
        continue;
      // Cheap rejection of the unfolded edges, nearly all of them; the margin sends every edge
      // near theta_max to the exact test.
      if (m_normals[p].dot(m_normals[q]) >= m_cos_theta_max_margin)
        continue;
      const double theta = internal::angle_between(m_normals[p], m_normals[q]);
      const double delta = theta - m_theta_max;
      if (!(delta > 0))
        continue;
      Eigen::Vector3d axis = m_normals[p].cross(m_normals[q]);
      // Exactly opposite normals: any axis orthogonal to both opens the fold; the shared edge is one.
      if (axis.norm() < 1e-12)
        axis = (x.row(edge.vertices[1]) - x.row(edge.vertices[0])).transpose();
      axis.normalize();
      Eigen::Matrix3d& rp = rotation_of(p);
      rp = internal::rotation_matrix(axis, delta / 2) * rp;
      Eigen::Matrix3d& rq = rotation_of(q);
      rq = internal::rotation_matrix(-axis, delta / 2) * rq;
      ++folds;
    }
    // The transformation of a folded face again (the same computation, the same result), and
    // its term replaced.
    for (const auto& [j, rotation] : folded) {
      m_fold_slot[j] = -1;
      Face_pass ignored;
      const Eigen::Matrix3d t = transform_face(x, j, ignored);
      const Eigen::Matrix3d change = face_term(x, j, rotation * t) - face_term(x, j, t);
      for (int i = 0; i < 3; ++i)
        m_residual.row(m_ops.faces[j].vertices[i]) += change.row(i);
    }
    return folds;
  }

  // The rotation that turns the unit normal toward alignment, clamped to eta; `requested`
  // receives the unclamped angle's magnitude.  With c = cos(gamma), s = sin(gamma) the angle
  // is gamma (orthogonal; gamma - pi when -v is nearer, so that a patch whose normal faces
  // against the flow is not turned over) or gamma - pi/2 (tangential).
  Eigen::Matrix3d alignment_rotation(const Eigen::Vector3d& normal, const Face_alignment& alignment,
                                     Rotation_angle& requested) const
  {
    Eigen::Vector3d axis = alignment.cross;
    const double s = alignment.sin, c = alignment.cos;
    double angle_cos = 0, angle_sin = 0;
    // n parallel to v: n x v defines no axis.  Orthogonally there is nothing to do;
    // tangentially any axis in the face's plane turns n away from v.
    if (s < 1e-12) {
      if (m_alignment == Alignment::ORTHOGONAL) {
        requested = Rotation_angle{1, s};
        return Eigen::Matrix3d::Identity();
      }
      axis = internal::any_orthogonal(normal);
      angle_cos = s;
      angle_sin = -std::abs(c);
    }
    else {
      axis *= 1 / s;
      if (m_alignment == Alignment::ORTHOGONAL) {
        angle_cos = std::abs(c);
        angle_sin = c >= 0 ? s : -s;
      }
      else {
        angle_cos = s;
        angle_sin = -c;
      }
    }
    requested = Rotation_angle{angle_cos, std::abs(angle_sin)};
    if (angle_cos < m_cos_eta) {
      angle_cos = m_cos_eta;
      angle_sin = angle_sin >= 0 ? m_sin_eta : -m_sin_eta;
    }
    return internal::rotation_matrix(axis, angle_cos, angle_sin);
  }

  // The frames of the faces of the current surface M_k; throws naming `caller` on a degenerate face.
  internal::Surface_faces current_surface_faces(const std::string& caller) const
  {
    internal::Positions x = internal::read_positions(m_vertices, m_vpm);
    internal::check_finite_positions(x, caller + ": tm");
    Eigen::Index degenerate = -1;
    internal::Surface_faces faces = internal::make_surface_faces(m_arrays, std::move(x), degenerate);
    if (degenerate >= 0)
      throw std::invalid_argument(caller + ": tm: face " + std::to_string(degenerate) +
                                  " of the current surface is degenerate (zero area)");
    return faces;
  }

  template <class NamedParameters>
  std::vector<Eigen::Index> parametrization_constraints(const internal::Surface_faces& current,
                                                        const NamedParameters& np,
                                                        const std::string& caller) const
  {
    return internal::constrained_vertices(m_arrays, current,
                                          internal::chosen_constraint_vertex(m_vertices, np, caller));
  }

  // The least-squares scalar fields on M_0 whose gradients best match the per-face vectors
  // `field_on_current` (3n x k) given on M_k: (L + W)^{-1} D_0 (pulled-back field), shifted to 0
  // at `constrained`.
  Eigen::MatrixXd solve_on_reference(const internal::Surface_faces& current,
                                     const Eigen::MatrixXd& field_on_current,
                                     const std::vector<Eigen::Index>& constrained) const
  {
    Eigen::MatrixXd x = m_solver.solver().solve(
        internal::reference_divergence(m_ops, m_reference, current.positions, field_on_current));
    internal::shift_to_constraints(x, constrained, current.vertex_component);
    return x;
  }

  // The vertices of the face nearest to the area-weighted barycenter of each connected
  // component, three per component.  Symmetric patches have several faces at the same distance;
  // a tolerance makes the choice (the lowest index among them) independent of rounding, so equal
  // inputs in other mesh types or precisions anchor the same face.  Centroids are recomputed in
  // the second pass rather than stored (fresh memory is slow to touch).
  static std::vector<Eigen::Index> central_face_vertices(const std::vector<internal::Reference_face>& faces,
                                                         const Positions& reference,
                                                         const std::vector<std::size_t>& face_component,
                                                         std::size_t components)
  {
    const auto centroid = [&](const internal::Reference_face& f) -> Eigen::Vector3d {
      return (reference.row(f.vertices[0]) + reference.row(f.vertices[1]) + reference.row(f.vertices[2]))
                 .transpose() /
             3;
    };
    std::vector<Eigen::Vector3d> barycenter(components, Eigen::Vector3d::Zero());
    std::vector<double> component_area(components, 0);
    for (std::size_t j = 0; j < faces.size(); ++j) {
      barycenter[face_component[j]] += faces[j].area * centroid(faces[j]);
      component_area[face_component[j]] += faces[j].area;
    }
    std::vector<std::size_t> nearest(components, 0);
    std::vector<double> nearest_distance(components, std::numeric_limits<double>::infinity());
    const double tolerance =
        1e-10 * (reference.colwise().maxCoeff() - reference.colwise().minCoeff()).squaredNorm();
    for (std::size_t j = 0; j < faces.size(); ++j) {
      const std::size_t c = face_component[j];
      const double d = (centroid(faces[j]) - barycenter[c] / component_area[c]).squaredNorm();
      if (d < nearest_distance[c] - tolerance) {
        nearest_distance[c] = d;
        nearest[c] = j;
      }
    }
    std::vector<Eigen::Index> constrained;
    for (std::size_t c = 0; c < components; ++c)
      for (Eigen::Index v : faces[nearest[c]].vertices)
        constrained.push_back(v);
    return constrained;
  }

  // Whether the faces of m_ops are the first faces of m_arrays, in the same order with the same
  // vertices: then the operators of a grown mesh extend the old ones.
  bool operators_are_a_prefix() const
  {
    const std::size_t n = m_ops.faces.size();
    if (n == 0 || n > m_arrays.face_vertices.size() || m_ops.number_of_vertices() > m_reference.rows())
      return false;
    for (std::size_t j = 0; j < n; ++j)
      if (m_ops.faces[j].vertices != m_arrays.face_vertices[j])
        return false;
    return true;
  }

  // Assembles the operators on the reference positions, chooses the constrained faces and
  // factors L + W.  Called at construction and whenever the connectivity changes; after
  // `grow()` (`grown`), whose new faces and vertices come after the old ones in the mesh's
  // order, the old operators are extended instead of assembled anew.
  void rebuild_operators(const Positions& reference, bool grown = false)
  {
    using Clock = std::chrono::steady_clock;
    m_construction = Construction_report();
    const auto assembling = Clock::now();
    std::optional<internal::Degenerate_face> degenerate;
    if (grown && operators_are_a_prefix())
      degenerate = internal::extend_poisson_operators(m_ops, reference, m_arrays.face_vertices);
    else {
      // The iterations use L and the per-face stiffness only (D Y' is assembled face by face).
      auto built = internal::make_poisson_operators(reference, m_arrays.face_vertices,
                                                    internal::Operators_asked::stiffness);
      if (auto* face = std::get_if<internal::Degenerate_face>(&built))
        degenerate = *face;
      else
        m_ops = std::move(std::get<internal::Poisson_operators>(built));
    }
    if (degenerate)
      throw std::invalid_argument("Flow_aligned_deformation: tm: face " + std::to_string(degenerate->face) +
                                  " is degenerate (zero area)");
    m_corner_offsets.clear(); // the corners of each vertex, for the parallel pass, are made again
    const auto choosing = Clock::now();

    m_constrained_vertices =
        central_face_vertices(m_ops.faces, reference, m_arrays.face_component, m_arrays.number_of_components);
    m_vertex_component.clear();
    if (m_arrays.number_of_components > 1)
      m_vertex_component = internal::vertex_components(m_arrays, std::size_t(reference.rows()));

    // Small weight: it only has to remove the translational null space.  A large one pins
    // the constrained face's orientation and leaves a kink there.  L + W is factored in place
    // of L (no copy of L: fresh memory is slow to touch), and L's diagonal entries are
    // restored bit for bit afterwards.
    const double constraint_weight = m_relative_constraint_weight * m_ops.L.diagonal().mean();
    std::vector<double> unconstrained;
    for (Eigen::Index v : m_constrained_vertices) {
      unconstrained.push_back(m_ops.L.coeff(v, v));
      m_ops.L.coeffRef(v, v) += constraint_weight;
    }
    const Eigen::SparseMatrix<double>& system = m_ops.L;
    const auto factoring = Clock::now();
    const auto restore = [&] {
      for (std::size_t k = m_constrained_vertices.size(); k-- > 0;)
        m_ops.L.coeffRef(m_constrained_vertices[k], m_constrained_vertices[k]) = unconstrained[k];
    };
    internal::Factorization_times times;
    try {
      times = internal::timed_factor_or_throw(m_solver, system, "L + W");
    } catch (...) {
      restore();
      throw;
    }
    restore();
    m_construction.operators_ms = milliseconds_between(assembling, choosing);
    m_construction.constraints_ms = milliseconds_between(choosing, factoring);
    m_construction.analyze_ms = times.analyze_ms;
    m_construction.factorize_ms = times.factorize_ms;
    m_factor_ms += times.analyze_ms + times.factorize_ms;
    ++m_number_of_factorizations;
  }

  TriangleMesh& m_tm;
  const FlowField& m_field; // not a copy: a field may hold gigabytes of samples by value
  Alignment m_alignment;
  Vertex_point_map m_vpm;
  Geom_traits m_gt;
  std::size_t m_max_iterations = 100;
  Visitor m_visitor;
  internal::Progress_callback m_callback;
  double m_cos_eta = 1, m_sin_eta = 0, m_cos_theta_max_margin = -2;
  double m_eta = 0.1, m_epsilon = 1e-6, m_convergence_step = 1e-4, m_theta_max = CGAL_PI / 2;
  bool m_area_correction = true;
  bool m_parallel = false;
  double m_relative_constraint_weight = 1e-3;

  std::vector<vertex_descriptor> m_vertices; // in vertex-index order
  Positions m_reference;                     // M_0, row i for m_vertices[i]
  internal::Mesh_arrays m_arrays;
  internal::Poisson_operators m_ops;
  std::vector<Eigen::Index> m_constrained_vertices;
  std::vector<std::size_t> m_vertex_component; // of each vertex, when there are several components
  mutable Sparse_linear_solver m_solver; // mutable: CGAL's solver traits have no const solver()
  std::size_t m_number_of_factorizations = 0;
  double m_factor_ms = 0;
  Construction_report m_construction;
  std::size_t m_number_of_iterations = 0;
  Iteration_report m_last_report;

  // Per-iteration buffers, kept to avoid reallocations.
  std::vector<Eigen::Vector3d> m_normals;
  std::vector<unsigned char> m_has_normal; // not vector<bool>: read in the hot loop
  Row_positions m_positions, m_residual, m_next;
  // With use_parallelism: the faces' terms of the right-hand side, and the corners of each vertex
  // (offsets into m_corners by vertex; corner 3 j + i is corner i of face j).
  std::vector<Eigen::Matrix3d> m_terms;
  std::vector<std::size_t> m_corner_offsets, m_corners;
  std::vector<std::ptrdiff_t> m_fold_slot; // -1 between iterations
  std::vector<Eigen::RowVector3d> m_component_shift;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_FLOW_ALIGNED_DEFORMATION_H
