// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one-call form of the flow-aligning deformation: build a
// Flow_aligned_deformation on the mesh and iterate it to convergence.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_ALIGN_TO_FLOW_H
#define CGAL_FLOW_ALIGNED_SURFACES_ALIGN_TO_FLOW_H

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>

#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Flow_aligned_surfaces {

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Deforms `tm` until it is tangential (a stream surface) or orthogonal to `field`, and
reports how it went.

Equivalent to constructing a `Flow_aligned_deformation` with the same arguments and calling
its `run()`; the factorization is made once.

\tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph` whose faces are triangles
\tparam FlowField a model of `FlowField_3`
\tparam NamedParameters a sequence of named parameters

\param tm the surface, deformed in place through its vertex point map
\param field the flow field
\param alignment `Alignment::TANGENTIAL` or `Alignment::ORTHOGONAL`
\param np an optional sequence of named parameters: every parameter of the constructor of
       `Flow_aligned_deformation` (`vertex_point_map`, `geom_traits`, `vertex_index_map`,
       `face_index_map`, `number_of_iterations`, `visitor`, `callback`, `max_rotation_angle`,
       `convergence_angle`, `convergence_step`, `max_dihedral_angle`, `area_correction`,
       `constraint_weight`), and:

\cgalNamedParamsBegin
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{an instance of the sparse linear solver; only its type is used}
    \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d` wrapping an Eigen sparse
      Cholesky solver, such as `CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>`}
    \cgalParamDefault{CHOLMOD's simplicial \f$ LDL^T \f$ when found, else Eigen's `SimplicialLDLT`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of iterations, whether the last one converged, the normalized flux
of the final surface, and whether the `callback` stopped the iterations (see \ref fas_progress).
\throws std::invalid_argument if `tm` is empty, not a valid manifold triangle mesh, has a
degenerate face, or a parameter is out of range.
\sa `Flow_aligned_deformation`, `normalized_flux()`
*/
template <class TriangleMesh, class FlowField, class NamedParameters = parameters::Default_named_parameters>
Alignment_report align_to_flow(TriangleMesh& tm, const FlowField& field, Alignment alignment,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using Vertex_point_map = typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type;
  using Geom_traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Solver_parameter =
      typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t,
                                                         NamedParameters, CGAL::Default>::type;
  Flow_aligned_deformation<TriangleMesh, FlowField, Vertex_point_map, Geom_traits, Solver_parameter>
      deformation(tm, field, alignment, np);
  return deformation.run();
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_ALIGN_TO_FLOW_H
