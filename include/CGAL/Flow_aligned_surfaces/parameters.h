// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own named parameters.  CGAL 5.5 has no hook to add members to
// its parameter pack, so each package parameter is a free function taking an
// optional pack to chain onto:
//
//   FAS::parameters::max_rotation_angle(0.05, CGAL::parameters::number_of_iterations(50))
//
// The result is an ordinary CGAL::Named_function_parameters, so CGAL's own
// parameters can also be chained after it (`.number_of_iterations(50)`).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_PARAMETERS_H
#define CGAL_FLOW_ALIGNED_SURFACES_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \cond SKIP_IN_MANUAL
namespace internal_np {
#define CGAL_FAS_DECLARE_TAG(name)                                                                           \
  struct name##_t {};
CGAL_FAS_DECLARE_TAG(max_rotation_angle)
CGAL_FAS_DECLARE_TAG(convergence_angle)
CGAL_FAS_DECLARE_TAG(convergence_step)
CGAL_FAS_DECLARE_TAG(max_dihedral_angle)
CGAL_FAS_DECLARE_TAG(area_correction)
CGAL_FAS_DECLARE_TAG(constraint_weight)
CGAL_FAS_DECLARE_TAG(use_parallelism)
CGAL_FAS_DECLARE_TAG(patch_axis)
CGAL_FAS_DECLARE_TAG(array_name)
CGAL_FAS_DECLARE_TAG(mask_array_name)
CGAL_FAS_DECLARE_TAG(error_message)
CGAL_FAS_DECLARE_TAG(growth_direction)
CGAL_FAS_DECLARE_TAG(across_flow)
CGAL_FAS_DECLARE_TAG(flow_field)
CGAL_FAS_DECLARE_TAG(normalized)
CGAL_FAS_DECLARE_TAG(angle)
CGAL_FAS_DECLARE_TAG(gradient_direction)
CGAL_FAS_DECLARE_TAG(intrinsic_delaunay)
CGAL_FAS_DECLARE_TAG(constraint_vertex)
CGAL_FAS_DECLARE_TAG(resampling_step)
CGAL_FAS_DECLARE_TAG(min_relative_speed)
// integrate_streamline(), integrate_pathline()
CGAL_FAS_DECLARE_TAG(relative_tolerance)
CGAL_FAS_DECLARE_TAG(absolute_tolerance)
CGAL_FAS_DECLARE_TAG(max_length)
CGAL_FAS_DECLARE_TAG(max_time)
CGAL_FAS_DECLARE_TAG(max_number_of_steps)
CGAL_FAS_DECLARE_TAG(integration_direction)
CGAL_FAS_DECLARE_TAG(output_time_step)
CGAL_FAS_DECLARE_TAG(output_length_step)
// integrate_stream_surface()
CGAL_FAS_DECLARE_TAG(front_spacing)
CGAL_FAS_DECLARE_TAG(time_line_step)
CGAL_FAS_DECLARE_TAG(max_number_of_time_lines)
CGAL_FAS_DECLARE_TAG(arc_length_time_lines)
CGAL_FAS_DECLARE_TAG(start_time)
CGAL_FAS_DECLARE_TAG(tear_angle)
CGAL_FAS_DECLARE_TAG(max_number_of_vertices)
CGAL_FAS_DECLARE_TAG(seed_parameter_map)
CGAL_FAS_DECLARE_TAG(integration_time_map)
CGAL_FAS_DECLARE_TAG(time_output_iterator)
#undef CGAL_FAS_DECLARE_TAG
} // namespace internal_np
/// \endcond

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;
/// The empty parameter pack, the default of every `np` argument.
using Default_named_parameters = CGAL::parameters::Default_named_parameters;

// Defines one package parameter: a free function returning a pack that chains onto `np`.
#define CGAL_FAS_NAMED_PARAMETER(name, type)                                                                 \
  template <typename NamedParameters = Default_named_parameters>                                             \
  CGAL::Named_function_parameters<type, internal_np::name##_t, NamedParameters> name(                        \
      const type& value, const NamedParameters& np = NamedParameters())                                      \
  {                                                                                                          \
    return CGAL::Named_function_parameters<type, internal_np::name##_t, NamedParameters>(value, np);         \
  }

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// η, the largest rotation (radians) applied to a face in one iteration.  Default: `0.1`.
CGAL_FAS_NAMED_PARAMETER(max_rotation_angle, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// ε, the deformation has converged when every face's alignment rotation is below it
/// (radians).  Default: `1e-6`.
CGAL_FAS_NAMED_PARAMETER(convergence_angle, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The practical stopping rule beside ε: the deformation has also converged when the
/// largest vertex displacement of an iteration is below this fraction of the diagonal of the
/// surface's bounding box.  Default: `1e-4`.  `0` disables the rule.
CGAL_FAS_NAMED_PARAMETER(convergence_step, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// θmax, the largest dihedral angle (radians, between face normals) before the fold
/// correction acts.  Default: `π/2`.
CGAL_FAS_NAMED_PARAMETER(max_dihedral_angle, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Whether the gradients are rescaled by `sqrt(A_0/A_k)` to keep face areas.  Default: `true`.
CGAL_FAS_NAMED_PARAMETER(area_correction, bool)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The soft-constraint weight relative to the mean diagonal of `L`.  Default: `1e-3`.
CGAL_FAS_NAMED_PARAMETER(constraint_weight, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Whether the per-face work of an iteration (field samples, local transformations) runs in
/// parallel with TBB, in the task arena of the caller (a `tbb::task_arena` bounds the threads);
/// the field must then be safe to call concurrently.  Without it (the default, `false`) the
/// algorithms run on the calling thread and start no thread, the factorization included.
CGAL_FAS_NAMED_PARAMETER(use_parallelism, bool)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The name of the velocity array that a flow field reader reads, or that a writer writes.
/// Default (reading): the first vector array of the file's point data; (writing): `"velocity"`.
CGAL_FAS_NAMED_PARAMETER(array_name, std::string)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The name of the node mask array (nonzero = fluid) that a flow field reader reads, or that a
/// writer writes.  Default: `"inside"` (read only if present); the empty string reads no mask.
CGAL_FAS_NAMED_PARAMETER(mask_array_name, std::string)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Where a reader or writer of files (`IO::read_flow_field()`, `IO::read_VTK_flow_field()`,
/// `IO::write_VTK_flow_field()`, ...) puts the reason of a failure: when it returns `false`,
/// `*error` holds a message naming the function, the file and what is wrong (the line and byte
/// for a reader).  `*error` is left as it is on success.  Default: `nullptr`, no message.
template <typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<std::string*, internal_np::error_message_t, NamedParameters>
error_message(std::string* error, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<std::string*, internal_np::error_message_t, NamedParameters>(error,
                                                                                                      np);
}
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Growing (`grow_boundary()`, `Flow_aligned_deformation::grow()`): grow only the boundary edges
/// whose outward direction is within 60 degrees of the direction across the flow `n × v/|v|`, on
/// either side; each moves along its own outward direction.  Default: `false`.
CGAL_FAS_NAMED_PARAMETER(across_flow, bool)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Whether a parametrization's guidance field is normalized per face (`true`: near-equidistant
/// iso-contours; `false`: its gradient follows the field's magnitude, the time-like coordinate
/// of LIC).  Default: `true` in `parametrize_tangential()`, `false` in `parametrize_orthogonal()`.
CGAL_FAS_NAMED_PARAMETER(normalized, bool)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// α, the angle (radians) by which `parametrize_orthogonal()` turns its reference direction
/// about the normal at the constrained vertex.  Default: `0`.
CGAL_FAS_NAMED_PARAMETER(angle, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Whether `compute_geodesic_distance()` runs the heat method on the intrinsic Delaunay
/// triangulation of the mesh (edges flipped within the surface until every edge is Delaunay; the
/// same surface, better shaped triangles), as CGAL's `Heat_method_3::Intrinsic_Delaunay` mode does,
/// instead of on the mesh's own triangles.  Default: `true`.
CGAL_FAS_NAMED_PARAMETER(intrinsic_delaunay, bool)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The arc length between consecutive points of a polyline resampled by `project_polyline()`.
/// Default: the mean edge length of the mesh.
CGAL_FAS_NAMED_PARAMETER(resampling_step, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// `alignment_angle_statistics()`, `compute_face_alignment_angles()`: faces where the speed of
/// the flow is below this fraction of the largest speed sampled on the surface are left out
/// (their area is reported).  Default: `0`, every face, as the paper measured.
CGAL_FAS_NAMED_PARAMETER(min_relative_speed, double)

// Stream lines and path lines (integrate_streamline(), integrate_pathline()).
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The relative tolerance of the local error of each integration step.  Default: `1e-8`.
CGAL_FAS_NAMED_PARAMETER(relative_tolerance, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The absolute tolerance (a length) of the local error of each integration step.
/// Default: `1e-10`.
CGAL_FAS_NAMED_PARAMETER(absolute_tolerance, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The largest arc length of a stream line in each direction.  Default: no limit.
CGAL_FAS_NAMED_PARAMETER(max_length, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The largest integration time \f$ |t - t_0| \f$ of a stream line or path line in each
/// direction.  Default: no limit.
CGAL_FAS_NAMED_PARAMETER(max_time, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The largest number of accepted integration steps of a stream line in each direction.
/// Default: `100000`.
CGAL_FAS_NAMED_PARAMETER(max_number_of_steps, std::size_t)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Stream line output sampled every Δt of integration time (on the dense output) instead of at
/// the integrator's steps.  Default: the steps.
CGAL_FAS_NAMED_PARAMETER(output_time_step, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Stream line output sampled every Δs of arc length (on the dense output) instead of at the
/// integrator's steps.  Default: the steps.
CGAL_FAS_NAMED_PARAMETER(output_length_step, double)

// Stream surfaces (integrate_stream_surface()).
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// h, the requested distance between neighbouring particles of a stream surface's front: a
/// particle is inserted where neighbours are farther than 2h apart, one is removed where they
/// are closer than h/2.  Default: the mean segment length of the seed polyline.
CGAL_FAS_NAMED_PARAMETER(front_spacing, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Δ, the integration time (or arc length, with `arc_length_time_lines(true)`) between
/// consecutive time lines of a stream surface; its last time line is at `max_time()`
/// (`max_length()`).  Default: h divided by the median speed on the
/// seed (time lines about h apart), or h with `arc_length_time_lines(true)`; with the default, a
/// time line whose strip would be thinner than h/2 (a sheared front) is left out of the mesh.
CGAL_FAS_NAMED_PARAMETER(time_line_step, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The largest number of time lines of a stream surface after its seed curve (per direction).
/// Default: no limit when `max_time()` (`max_length()` with arc-length time lines) is given, else `100`.
CGAL_FAS_NAMED_PARAMETER(max_number_of_time_lines, std::size_t)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Whether the particles of a stream surface advance in lock-step of arc length (the field is
/// normalized) instead of integration time.  Steady fields only.  Default: `false`.
CGAL_FAS_NAMED_PARAMETER(arc_length_time_lines, bool)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The time \f$ t_0 \f$ at which the seed of a path surface is released in an unsteady field.
/// Default: `0`.
CGAL_FAS_NAMED_PARAMETER(start_time, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The angle (radians) between the flow directions at neighbouring front particles above which
/// the front is refined, and torn where it cannot be refined.  Default: `π/4`.
CGAL_FAS_NAMED_PARAMETER(tear_angle, double)
/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The largest number of vertices a stream surface may have (a bound on memory and time).
/// Default: `1000000`.
CGAL_FAS_NAMED_PARAMETER(max_number_of_vertices, std::size_t)

#undef CGAL_FAS_NAMED_PARAMETER

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The in-plane direction of a patch's first side (its `width`), projected into the patch's
/// plane.  Type: the kernel's `Vector_3`.  Default: a unit vector orthogonal to the normal.
template <typename Vector_3, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<Vector_3, internal_np::patch_axis_t, NamedParameters>
patch_axis(const Vector_3& axis, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<Vector_3, internal_np::patch_axis_t, NamedParameters>(axis, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// Growing (`grow_boundary()`, `Flow_aligned_deformation::grow()`): grow only the boundary edges
/// whose outward direction (in the plane of the edge's face, orthogonal to the edge) is within
/// 60 degrees of this direction projected on that plane; each moves along its own outward
/// direction.  Type: the kernel's `Vector_3`, not zero.  Default: the whole boundary is grown.
template <typename Vector_3, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<Vector_3, internal_np::growth_direction_t, NamedParameters>
growth_direction(const Vector_3& direction, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<Vector_3, internal_np::growth_direction_t, NamedParameters>(
      direction, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The flow field (a model of `FlowField_3`) of a function that needs one besides its mesh,
/// such as `grow_boundary()` with `across_flow(true)`.  A field given as a variable is held by
/// reference, not copied (the pack must then not outlive it); a temporary is kept by value.
/// Default: none.
template <typename FlowField, typename NamedParameters = Default_named_parameters>
auto flow_field(FlowField&& field, const NamedParameters& np = NamedParameters())
{
  using Field = std::remove_cv_t<std::remove_reference_t<FlowField>>;
  using Stored = std::conditional_t<std::is_lvalue_reference<FlowField>::value,
                                    std::reference_wrapper<const Field>, Field>;
  return CGAL::Named_function_parameters<Stored, internal_np::flow_field_t, NamedParameters>(
      Stored(std::forward<FlowField>(field)), np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The vertex at which a parametrization is constrained to 0 (in its connected component; the
/// other components keep the default).  Type: the mesh's `vertex_descriptor`.  Default: the
/// vertex nearest to the area-weighted barycenter of each connected component.
template <typename VertexDescriptor, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<VertexDescriptor, internal_np::constraint_vertex_t, NamedParameters>
constraint_vertex(const VertexDescriptor& v, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<VertexDescriptor, internal_np::constraint_vertex_t, NamedParameters>(
      v, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// `parametrize_orthogonal()`: the direction that \f$ \nabla r \f$ takes at the constrained vertex
/// with `angle(0)` (projected into the tangent plane there; `angle` turns it about the normal).
/// Type: the kernel's `Vector_3`, not zero and not normal to the surface at that vertex.
/// Default: the direction given by the package's own frame (see `parametrize_orthogonal()`).
template <typename Vector_3, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<Vector_3, internal_np::gradient_direction_t, NamedParameters>
gradient_direction(const Vector_3& direction, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<Vector_3, internal_np::gradient_direction_t, NamedParameters>(
      direction, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// The direction of a stream line or path line from its seed.  Type:
/// `CGAL::Flow_aligned_surfaces::Integration_direction` (`FORWARD`, `BACKWARD` or `BOTH`).
/// Default: `FORWARD`.
template <typename Direction, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<Direction, internal_np::integration_direction_t, NamedParameters>
integration_direction(const Direction& direction, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<Direction, internal_np::integration_direction_t, NamedParameters>(
      direction, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// `integrate_stream_surface()` writes the seed parameter \f$ u \f$ (arc length along the seed
/// polyline from its first point) of every vertex it adds through this map.  Type: a model of
/// `WritablePropertyMap` with the mesh's `vertex_descriptor` as key and `double` as value.
/// Default: not written.
template <typename VertexDoubleMap, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<VertexDoubleMap, internal_np::seed_parameter_map_t, NamedParameters>
seed_parameter_map(const VertexDoubleMap& map, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<VertexDoubleMap, internal_np::seed_parameter_map_t, NamedParameters>(
      map, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// `integrate_stream_surface()` writes the time-line parameter \f$ \tau \f$ (integration time
/// since the seed, or arc length with `arc_length_time_lines(true)`) of every vertex it adds
/// through this map.  Type: as `seed_parameter_map()`.  Default: not written.
template <typename VertexDoubleMap, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<VertexDoubleMap, internal_np::integration_time_map_t, NamedParameters>
integration_time_map(const VertexDoubleMap& map, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<VertexDoubleMap, internal_np::integration_time_map_t,
                                         NamedParameters>(map, np);
}

/// \ingroup PkgFlowAlignedSurfacesNamedParameters
/// `integrate_streamline()` and `integrate_pathline()` write the time of every point they write
/// through this output iterator (accepting `double`), in the same order: the signed integration
/// time of a stream line's point, the time \f$ t_0 \pm \tau \f$ of a path line's.  Default: not
/// written.
template <typename OutputIterator, typename NamedParameters = Default_named_parameters>
CGAL::Named_function_parameters<OutputIterator, internal_np::time_output_iterator_t, NamedParameters>
time_output_iterator(const OutputIterator& out, const NamedParameters& np = NamedParameters())
{
  return CGAL::Named_function_parameters<OutputIterator, internal_np::time_output_iterator_t,
                                         NamedParameters>(out, np);
}

} // namespace parameters
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_PARAMETERS_H
