/*!
\ingroup PkgFlowAlignedSurfacesConcepts
\cgalConcept

The concept `UnsteadyFlowField_3` describes a time-dependent 3D vector field
\f$ v(x, t) \f$: a copyable callable that maps a point and a time to the velocity there and
then, or to nothing when the point is outside the domain at that time.

It obeys the rules of `FlowField_3` (the types `Point_3` and `Vector_3`, the meaning of
`std::nullopt`, of NaN, infinite and zero vectors, cheap copies, a `const` call operator),
with the time as a second argument.  A lambda is a model.

A steady field is an unsteady one that ignores the time; conversely, an unsteady field
frozen at a time \f$ t_0 \f$, `[&](const Point_3& p) { return field(p, t0); }`, is a model
of `FlowField_3`; `Time_slice_flow_field_3` is one whose time can be changed, which is how the
deformation of this package looks at one instant of an unsteady flow and follows it through
time.

\cgalHasModelsBegin
\cgalHasModels{Any callable `std::optional<Vector_3>(const Point_3&, double)`, such as a lambda}
\cgalHasModels{`CGAL::Flow_aligned_surfaces::Unsteady_flow_field_3<FlowField>`}
\cgalHasModelsEnd

\sa `FlowField_3`
*/
class UnsteadyFlowField_3 {
public:
  /// \name Creation
  /// @{

  /// Copy constructor; the copy answers every query as the original does.
  UnsteadyFlowField_3(const UnsteadyFlowField_3& other);

  /// @}

  /// \name Operations
  /// @{

  /// Returns the velocity at `p` at time `t`, or `std::nullopt` when `p` is outside the
  /// domain at that time.
  std::optional<Vector_3> operator()(const Point_3& p, double t) const;

  /// Optional.  Returns the velocities at `points[i]` at time `times[i]`, in order, as
  /// `FlowField_3::sample()` does for a steady field (the path surfaces of
  /// `integrate_stream_surface()` ask for their stages in batches).
  std::vector<std::optional<Vector_3>> sample(const std::vector<Point_3>& points,
                                              const std::vector<double>& times) const;

  /// @}
};
