#include "vtkStreamSurfaceFromCurve.h"

#include "fas_flow_state.h"
#include "fas_paraview_support.h"
#include "fas_paraview_surface_input.h"

#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace fas_paraview;

vtkStandardNewMacro(vtkStreamSurfaceFromCurve);

namespace {

// One value per seed curve, as a field-data array.
void add_per_curve(vtkDataObject* data, const char* name, const std::vector<double>& values)
{
  auto array = make_array(name, 1, vtkIdType(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(vtkIdType(i), values[i]);
  data->GetFieldData()->AddArray(array);
}

void add_per_curve(vtkDataObject* data, const char* name, const std::vector<std::string>& values)
{
  auto array = vtkSmartPointer<vtkStringArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(vtkIdType(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(vtkIdType(i), values[i]);
  data->GetFieldData()->AddArray(array);
}

bool surface_is_empty(const FAS::Stream_surface_report& r)
{
  return r.number_of_faces == 0;
}

// The integration time that carries a particle at the seed curves' mean speed over the data's
// largest extent (`bounds`): the length of a stream surface when the user gave none.  0 when no
// seed point has a flow.
template <class Field>
double time_across_the_data(const Field& field, const std::vector<Polyline>& curves, const double bounds[6])
{
  double speed = 0;
  std::size_t sampled = 0;
  std::vector<Point> points;
  for (const Polyline& curve : curves)
    points.insert(points.end(), curve.begin(), curve.end());
  for (const std::optional<Vector>& v : velocities_at(field, points, 0)) // one batch
    if (v)
    {
      speed += std::sqrt(v->squared_length());
      ++sampled;
    }
  const double extent = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  return sampled > 0 && speed > 0 ? extent / (speed / double(sampled)) : 0.;
}


// The limits of the surfaces: the properties, or the defaults that depend on the data.
struct Surface_limits {
  double max_time = 0, max_length = 0, time_line_step = 0;
};

// The surfaces of the seed curves in one mesh, with their seed parameter u and time-line
// parameter t per vertex, and what the integration of each curve reported.
struct Surfaces {
  Mesh tm;
  Mesh::Property_map<Mesh::Vertex_index, double> u, t;
  std::vector<std::size_t> curve_of_vertex;
  std::vector<FAS::Stream_surface_report> reports;
  bool cancelled = false;
  double start_time = 0; // of path surfaces

  Surfaces()
    : u(tm.add_property_map<Mesh::Vertex_index, double>("v:u", 0.).first)
    , t(tm.add_property_map<Mesh::Vertex_index, double>("v:t", 0.).first)
  {
  }
  Surfaces(const Surfaces&) = delete;
  Surfaces& operator=(const Surfaces&) = delete;
};

// The surfaces of `curves` in `field` with the properties of `f` (stream surfaces of a
// FlowField_3; path surfaces of an UnsteadyFlowField_3, from the start time that `with_start`
// adds to the named parameters).  Progress per time line of each seed curve; Abort
// (AbortExecute) stops after the time line in progress, keeping the surfaces integrated so far.
template <class Field, class WithStart>
void integrate_curves(vtkStreamSurfaceFromCurve* f, const Field& field, const std::vector<Polyline>& curves,
                      const Surface_limits& limits, const WithStart& with_start, Surfaces& out)
{
  const bool limited = f->GetArcLengthTimeLines() ? limits.max_length > 0 : limits.max_time > 0;
  const std::size_t max_time_lines = f->GetMaxNumberOfTimeLines() > 0
    ? std::size_t(f->GetMaxNumberOfTimeLines())
    : (limited ? std::numeric_limits<std::size_t>::max() : std::size_t(100));
  const int d = f->GetIntegrationDirection();
  const FAS::Integration_direction direction = d == vtkStreamSurfaceFromCurve::BACKWARD
    ? FAS::Integration_direction::BACKWARD
    : (d == vtkStreamSurfaceFromCurve::BOTH ? FAS::Integration_direction::BOTH : FAS::Integration_direction::FORWARD);
  std::size_t current_curve = 0;
  const auto progress = [&](double fraction) {
    f->UpdateProgress((double(current_curve) + fraction) / double(curves.size()));
    return !f->GetAbortExecute();
  };
  const auto base = with_start(FAS::parameters::integration_direction(direction,
    FAS::parameters::arc_length_time_lines(f->GetArcLengthTimeLines(),
      FAS::parameters::max_number_of_time_lines(max_time_lines,
        FAS::parameters::max_number_of_vertices(std::size_t(f->GetMaxNumberOfVertices()),
          FAS::parameters::tear_angle(f->GetTearAngle(),
            FAS::parameters::relative_tolerance(f->GetRelativeTolerance(),
              FAS::parameters::absolute_tolerance(f->GetAbsoluteTolerance(),
                FAS::parameters::max_number_of_steps(std::size_t(f->GetMaxNumberOfSteps()),
                  FAS::parameters::seed_parameter_map(
                    out.u, FAS::parameters::integration_time_map(out.t,
                      CGAL::parameters::callback(std::function<bool(double)>(progress)))))))))))));
  for (std::size_t c = 0; c < curves.size() && !out.cancelled; ++c)
  {
    current_curve = c;
    // The library tells a given parameter from an absent one at compile time (an absent front
    // spacing, time-line step or limit takes a default that depends on the seed or on the other
    // parameters), so the optional ones are passed only when set.
    const auto integrate = [&](const auto& np) {
      out.reports.push_back(FAS::integrate_stream_surface(field, curves[c], out.tm, np));
    };
    const auto with_max_length = [&](const auto& np) {
      if (limits.max_length > 0)
        integrate(FAS::parameters::max_length(limits.max_length, np));
      else
        integrate(np);
    };
    const auto with_max_time = [&](const auto& np) {
      if (limits.max_time > 0)
        with_max_length(FAS::parameters::max_time(limits.max_time, np));
      else
        with_max_length(np);
    };
    const auto with_step = [&](const auto& np) {
      if (limits.time_line_step > 0)
        with_max_time(FAS::parameters::time_line_step(limits.time_line_step, np));
      else
        with_max_time(np);
    };
    try
    {
      if (f->GetFrontSpacing() > 0)
        with_step(FAS::parameters::front_spacing(f->GetFrontSpacing(), base));
      else
        with_step(base);
    }
    catch (const std::invalid_argument& e)
    {
      throw std::invalid_argument("seed curve " + std::to_string(c) + " of " + std::to_string(curves.size()) +
                                  ": " + e.what());
    }
    out.curve_of_vertex.resize(out.tm.number_of_vertices(), c);
    out.cancelled = out.reports.back().stopped;
  }
}

// The surfaces as polygonal data: point data u, t, IntegrationTime, seed_curve and SeedIds; per
// seed curve the report's values as field data.  A seed curve without a surface is said in a
// warning of `f`; none with a surface (while some were integrated) is an error.
vtkSmartPointer<vtkPolyData> surfaces_output(vtkStreamSurfaceFromCurve* f, const Surfaces& s,
                                             const Distributed_input& pieces)
{
  std::string empty;
  for (std::size_t c = 0; c < s.reports.size(); ++c)
    if (surface_is_empty(s.reports[c]))
      empty += (empty.empty() ? "" : "; ") + std::string("curve ") + std::to_string(c) + ": " +
        FAS::to_string(s.reports[c].termination) + " (" + s.reports[c].message + ")";
  if (s.tm.number_of_faces() == 0 && !s.reports.empty())
    throw std::invalid_argument("no seed curve gives a surface (" + empty +
      "); the seed curves must lie in the data set (bounds " + bounds_text(pieces.bounds.data()) +
      ") where the flow is not zero");
  if (!empty.empty())
    vtkWarningWithObjectMacro(f, << "Stream Surface From Curve: some seed curves give no surface: " << empty);

  vtkSmartPointer<vtkPolyData> result = to_polydata(s.tm);
  const vtkIdType n = vtkIdType(s.tm.number_of_vertices());
  auto u = make_array("u", 1, n);
  auto t = make_array("t", 1, n);
  auto integration_time = make_array("IntegrationTime", 1, n);
  auto seed_curve = make_array("seed_curve", 1, n);
  auto seed_ids = vtkSmartPointer<vtkIdTypeArray>::New();
  seed_ids->SetName("SeedIds");
  seed_ids->SetNumberOfTuples(n);
  for (Mesh::Vertex_index v : s.tm.vertices())
  {
    const vtkIdType i = vtkIdType(v.idx());
    u->SetValue(i, s.u[v]);
    t->SetValue(i, s.t[v]);
    integration_time->SetValue(i, s.t[v]);
    seed_curve->SetValue(i, double(s.curve_of_vertex[std::size_t(v.idx())]));
    seed_ids->SetValue(i, vtkIdType(s.curve_of_vertex[std::size_t(v.idx())]));
  }
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(u), static_cast<vtkDataArray*>(t),
                           static_cast<vtkDataArray*>(integration_time), static_cast<vtkDataArray*>(seed_curve),
                           static_cast<vtkDataArray*>(seed_ids) })
    result->GetPointData()->AddArray(a);
  result->GetPointData()->SetActiveScalars("u");
  if (s.reports.empty())
    return result;

  const auto per_curve = [&](const char* name, auto value) {
    std::vector<decltype(value(s.reports.front()))> values;
    for (const FAS::Stream_surface_report& r : s.reports)
      values.push_back(value(r));
    add_per_curve(result, name, values);
  };
  using R = FAS::Stream_surface_report;
  per_curve("termination", [](const R& r) { return std::string(FAS::to_string(r.termination)); });
  per_curve("termination_message", [](const R& r) { return r.message; });
  if (f->GetIntegrationDirection() == vtkStreamSurfaceFromCurve::BOTH)
  {
    per_curve("backward_termination",
      [](const R& r) { return std::string(r.backward ? FAS::to_string(r.backward->termination) : ""); });
    per_curve("backward_termination_message", [](const R& r) { return r.backward ? r.backward->message : std::string(); });
    per_curve("backward_number_of_time_lines",
      [](const R& r) { return double(r.backward ? r.backward->number_of_time_lines : 0); });
  }
  per_curve("number_of_time_lines", [](const R& r) { return double(r.number_of_time_lines); });
  per_curve("final_parameter", [](const R& r) { return r.final_parameter; });
  per_curve("seed_length", [](const R& r) { return r.seed_length; });
  per_curve("front_spacing", [](const R& r) { return r.front_spacing; });
  per_curve("time_line_step", [](const R& r) { return r.time_line_step; });
  per_curve("number_of_tears", [](const R& r) { return double(r.number_of_tears); });
  per_curve("number_of_lost_particles", [](const R& r) { return double(r.number_of_lost_particles); });
  return result;
}

} // namespace

struct vtkStreamSurfaceFromCurve::Internals {
  explicit Internals(FlowState& flow)
    : field(flow.field)
    , steps(flow.steps)
  {
  }
  const Distributed_velocity_field& field; // the flow of input 0 (vtkFlowAlignedFilter's)
  const Temporal_flow_input& steps;        // its time steps

  std::vector<std::size_t> needed_steps(vtkStreamSurfaceFromCurve* f, vtkInformationVector* outputVector) const;
  void integrate_stream_surfaces(vtkStreamSurfaceFromCurve* f, const std::vector<Polyline>& curves,
                                 const Distributed_input& pieces, Surfaces& surfaces) const;
  void integrate_path_surfaces(vtkStreamSurfaceFromCurve* f, const std::vector<Polyline>& curves,
                               vtkInformationVector* outputVector, Surfaces& surfaces) const;
};

vtkStreamSurfaceFromCurve::vtkStreamSurfaceFromCurve()
  : IntegrationDirection(FORWARD)
  , FrontSpacing(0)
  , TimeLineStep(0)
  , ArcLengthTimeLines(false)
  , MaxTime(0)
  , MaxLength(0)
  , MaxNumberOfTimeLines(0)
  , MaxNumberOfVertices(1000000)
  , TearAngle(vtkMath::Pi() / 4)
  , RelativeTolerance(1e-10)
  , AbsoluteTolerance(1e-12)
  , MaxNumberOfSteps(100000)
  , SurfaceType(STREAM_SURFACE)
  , StartTime(0)
  , Internal(new Internals(*this->Flow))
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::VECTORS);
}

vtkStreamSurfaceFromCurve::~vtkStreamSurfaceFromCurve()
{
  delete this->Internal;
}

int vtkStreamSurfaceFromCurve::FillInputPortInformation(int port, vtkInformation* info)
{
  return fill_surface_filter_input_port(port, info);
}

const char* vtkStreamSurfaceFromCurve::GetLabel()
{
  return "Stream Surface From Curve";
}

void vtkStreamSurfaceFromCurve::SelectSteps(vtkInformationVector* outputVector)
{
  this->Flow->needed = this->Internal->needed_steps(this, outputVector);
}

std::vector<std::size_t> vtkStreamSurfaceFromCurve::Internals::needed_steps(
  vtkStreamSurfaceFromCurve* f, vtkInformationVector* outputVector) const
{
  // None for a steady input; a stream surface: the flow at the view's time; a path surface:
  // from Start Time to it.
  if (!steps.temporal())
    return {};
  const double t = steps.requested_time(outputVector->GetInformationObject(0));
  const double start = std::clamp(f->StartTime, steps.times().front(), steps.times().back());
  if (f->SurfaceType == PATH_SURFACE && t > start)
    return steps.steps_between(start, t);
  return steps.steps_around(t);
}

bool vtkStreamSurfaceFromCurve::Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const Internals& in = *this->Internal;
  const Distributed_input& pieces = this->Flow->pieces;
  const vtkSmartPointer<vtkPolyData>& seeds = this->Flow->gathered;
  this->CheckProperties();
  pieces.require_samples();
  const std::vector<Polyline> curves = polylines_from_polydata(seeds);
  if (curves.empty())
    throw std::invalid_argument(
      "the seed input (port 1) has no line or polyline of two points or more; give it seed "
      "curves (Parametrize And Seed's, a Line source, a contour)");
  Surfaces surfaces;
  if (this->SurfaceType == PATH_SURFACE)
    in.integrate_path_surfaces(this, curves, outputVector, surfaces);
  else
    in.integrate_stream_surfaces(this, curves, pieces, surfaces);
  if (surfaces.cancelled)
  {
    abort_handled(this);
    vtkWarningMacro(<< "Stream Surface From Curve: cancelled during seed curve " << surfaces.reports.size() - 1 << " of "
                    << curves.size() << "; the output holds what was integrated until then");
  }
  vtkSmartPointer<vtkPolyData> result = surfaces_output(this, surfaces, pieces);
  add_distribution_values(result, pieces, in.field);
  if (this->SurfaceType == PATH_SURFACE)
    add_field_value(result, "start_time", surfaces.start_time);
  vtkPolyData::GetData(outputVector, 0)->ShallowCopy(result);
  return true;
}

void vtkStreamSurfaceFromCurve::Internals::integrate_stream_surfaces(vtkStreamSurfaceFromCurve* f,
  const std::vector<Polyline>& curves, const Distributed_input& pieces, Surfaces& surfaces) const
{
  // No length given: the surface reaches as far as the data's largest extent (a time at the
  // seeds' mean speed, or that arc length), in 200 time lines unless a step is given.
  Surface_limits limits{ f->MaxTime, f->MaxLength, f->TimeLineStep };
  if (limits.max_time <= 0 && limits.max_length <= 0)
  {
    const double* b = pieces.bounds.data();
    if (f->ArcLengthTimeLines)
      limits.max_length = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
    else
    {
      limits.max_time = time_across_the_data(field, curves, b);
    }
    if (limits.time_line_step <= 0)
      limits.time_line_step = (f->ArcLengthTimeLines ? limits.max_length : limits.max_time) / 200;
  }
  const auto no_start_time = [](const auto& np) { return np; };
  if (field.distributed())
    integrate_curves(f, field, curves, limits, no_start_time, surfaces);
  else
    integrate_curves(f, Pointwise_view{ field }, curves, limits, no_start_time, surfaces);
}

void vtkStreamSurfaceFromCurve::Internals::integrate_path_surfaces(vtkStreamSurfaceFromCurve* f,
  const std::vector<Polyline>& curves, vtkInformationVector* outputVector, Surfaces& surfaces) const
{
  // Released at Start Time, integrated forward in time up to the view's time (at most Max Time).
  if (!steps.temporal())
    throw std::invalid_argument("Surface Type is Path Surface, but the Input has no time steps (a steady flow: "
                                "choose Stream Surface)");
  require_property(f->IntegrationDirection == FORWARD, "Integration Direction", f->IntegrationDirection,
                   "Forward for a path surface (released at Start Time, integrated to the view's time)");
  require_property(!f->ArcLengthTimeLines, "Arc Length Time Lines", 1., "off for a path surface");
  const double start = std::clamp(f->StartTime, steps.times().front(), steps.times().back());
  const double t = steps.requested_time(outputVector->GetInformationObject(0));
  surfaces.start_time = start;
  Surface_limits limits{ t - start, 0., f->TimeLineStep };
  if (f->MaxTime > 0)
    limits.max_time = std::min(limits.max_time, f->MaxTime);
  if (limits.max_time <= 0)
    return; // the view is at Start Time or before it: nothing integrated yet
  if (limits.time_line_step <= 0)
    limits.time_line_step = limits.max_time / 200;
  const auto from_start = [start](const auto& np) { return FAS::parameters::start_time(start, np); };
  if (field.distributed())
    integrate_curves(f, Unsteady_view{ field }, curves, limits, from_start, surfaces);
  else
    integrate_curves(f, Pointwise_unsteady_view{ field }, curves, limits, from_start, surfaces);
}

void vtkStreamSurfaceFromCurve::CheckProperties()
{
  const char* zero_or_more = ">= 0 (0: the default)";
  require_property(this->FrontSpacing >= 0, "Front Spacing", this->FrontSpacing, zero_or_more);
  require_property(this->TimeLineStep >= 0, "Time Line Step", this->TimeLineStep, zero_or_more);
  require_property(this->MaxTime >= 0, "Max Time", this->MaxTime, zero_or_more);
  require_property(this->MaxLength >= 0, "Max Length", this->MaxLength, zero_or_more);
  require_property(this->MaxNumberOfTimeLines >= 0, "Max Number Of Time Lines", this->MaxNumberOfTimeLines,
                   zero_or_more);
  require_property(this->MaxNumberOfVertices >= 1, "Max Number Of Vertices", this->MaxNumberOfVertices, ">= 1");
  require_property(this->TearAngle > 0, "Tear Angle", this->TearAngle, "> 0 radians (pi or more: no tear)");
  require_property(this->RelativeTolerance > 0, "Relative Tolerance", this->RelativeTolerance, "> 0");
  require_property(this->AbsoluteTolerance > 0, "Absolute Tolerance", this->AbsoluteTolerance, "> 0");
  require_property(this->MaxNumberOfSteps >= 1, "Max Number Of Steps", this->MaxNumberOfSteps, ">= 1");
}

void vtkStreamSurfaceFromCurve::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationDirection: " << this->IntegrationDirection << "\n";
  os << indent << "FrontSpacing: " << this->FrontSpacing << "\n";
  os << indent << "TimeLineStep: " << this->TimeLineStep << "\n";
  os << indent << "ArcLengthTimeLines: " << this->ArcLengthTimeLines << "\n";
  os << indent << "MaxTime: " << this->MaxTime << "\n";
  os << indent << "MaxLength: " << this->MaxLength << "\n";
  os << indent << "MaxNumberOfTimeLines: " << this->MaxNumberOfTimeLines << "\n";
  os << indent << "MaxNumberOfVertices: " << this->MaxNumberOfVertices << "\n";
  os << indent << "TearAngle: " << this->TearAngle << "\n";
  os << indent << "RelativeTolerance: " << this->RelativeTolerance << "\n";
  os << indent << "AbsoluteTolerance: " << this->AbsoluteTolerance << "\n";
  os << indent << "MaxNumberOfSteps: " << this->MaxNumberOfSteps << "\n";
  os << indent << "SurfaceType: " << this->SurfaceType << "\n";
  os << indent << "StartTime: " << this->StartTime << "\n";
}
