/*!
\ingroup PkgFlowAlignedSurfacesConcepts
\cgalConcept

The concept `FlowField_3` describes a steady 3D vector field, the velocity \f$ v(x) \f$ of a
flow, as the algorithms of this package sample it: a copyable callable that maps a point to
the velocity there, or to nothing when the point is outside the flow's domain.

`Point_3` and `Vector_3` are the point and vector types of the kernel that the algorithm
works with, the one of its `geom_traits` named parameter, which by default is the kernel of
the mesh's vertex point type.  A model need not define any type: a lambda is a model.

\code{.cpp}
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
// a vortex about the z-axis, defined outside the cylinder of radius 0.1 only
auto vortex = [](const K::Point_3& p) -> std::optional<K::Vector_3> {
  const double r2 = p.x() * p.x() + p.y() * p.y();
  if (r2 < 0.01)
    return std::nullopt;
  return K::Vector_3(-p.y() / r2, p.x() / r2, 0.2);
};
\endcode

<b>How the algorithms treat the answers.</b>  `std::nullopt` means that the point is outside
the domain (an obstacle, outside the grid of a simulation).  A vector with a NaN or infinite
coordinate is treated like `std::nullopt`, and counted separately in the reports; a zero
vector (a critical point) has no direction.  In all three cases the face sampled there is
left as it is by the alignment (its transformation is the identity) and is left out of the
measures.  Only the direction of the vector matters to the alignment; its length weighs
nothing, as the measures normalize it.

<b>Copies.</b>  The algorithms never copy the field: the free functions take it by `const`
reference, a `Flow_aligned_deformation` holds a reference to it (the field must outlive the
deformation, as the mesh must), and `parameters::flow_field()` holds a reference to a field given
as a variable (a temporary is kept by value).  So a model may hold its samples by value, a
`std::vector` of a large grid for instance, at no cost; the copy constructor is needed only by
a user's own code and by the field classes that combine fields
(`CGAL::Flow_aligned_surfaces::Sampled_flow_field_3`,
`CGAL::Flow_aligned_surfaces::Unsteady_flow_field_3`, which take their fields by value or by
move).  Its copy must answer like the original; the package's grid fields share their arrays
between copies with a `std::shared_ptr`, so their copies are cheap too.  The call operator is
`const`; it should not modify state shared between calls, so that a field can be sampled from
several threads at once (`parameters::use_parallelism(true)`).

<b>Batches (optional).</b>  A field whose samples are cheaper many at a time than one by one
(a field whose pieces live on the processes of a cluster, where every query is an exchange of
messages) may add `sample()`, which answers a batch of points in one call.  The algorithms then
ask for the points they know beforehand in one batch (the face centroids of a measure or of a
parametrization), and integrate stream surfaces a time line at a time: every particle's
Runge-Kutta stage in one batch, re-integrated particles level by level.  The results are the same,
bit for bit, as with the call operator alone (the same samples, the same arithmetic); the report
of `integrate_stream_surface()` counts the batches (`Stream_surface_report::number_of_sample_batches`).
On one process a field should not offer it: a stream surface then runs in rounds, one per
stage, and rounds cost more than they save without exchanges (20 times the time of the same
surface point by point, in the package's tests).

\cgalHasModelsBegin
\cgalHasModels{Any callable `std::optional<Vector_3>(const Point_3&)`, such as a lambda}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Uniform_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Linear_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Helical_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::ABC_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Hill_spherical_vortex<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Point_source_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Cylinder_potential_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Sphere_potential_flow<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Burgers_vortex<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Crawfis_tornado<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Regular_grid_flow_field_3<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Rectilinear_grid_flow_field_3<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Unstructured_flow_field_3<GeomTraits>`}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::VTK_flow_field_3<GeomTraits>` (needs VTK)}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Sampled_flow_field_3<GeomTraits>`}
\cgalHasModelsEnd

The analytic flows are declared in `<CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>`.

\sa `UnsteadyFlowField_3`
*/
class FlowField_3 {
public:
  /// \name Creation
  /// @{

  /// Copy constructor; the copy answers every query as the original does.
  FlowField_3(const FlowField_3& other);

  /// @}

  /// \name Operations
  /// @{

  /// Returns the velocity at `p`, or `std::nullopt` when `p` is outside the domain.
  std::optional<Vector_3> operator()(const Point_3& p) const;

  /// Optional.  Returns the velocities at `points`, in order: what the call operator returns for
  /// each, as many as there are points.  An algorithm that finds a batch of another size throws
  /// `std::logic_error`.
  std::vector<std::optional<Vector_3>> sample(const std::vector<Point_3>& points) const;

  /// @}
};
