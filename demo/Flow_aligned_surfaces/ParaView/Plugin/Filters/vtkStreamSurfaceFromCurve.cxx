#include "vtkStreamSurfaceFromCurve.h"

#include "fas_distributed_field.h"
#include "fas_paraview_support.h"
#include "fas_paraview_surface_input.h"

#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
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
  for (const Polyline& curve : curves)
    for (const Point& p : curve)
      if (const std::optional<Vector> v = field(p))
      {
        speed += std::sqrt(v->squared_length());
        ++sampled;
      }
  const double extent = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  return sampled > 0 && speed > 0 ? extent / (speed / double(sampled)) : 0.;
}

} // namespace

struct vtkStreamSurfaceFromCurve::Internals {
  Distributed_velocity_field field; // the flow of input 0 (on several ranks: every rank's piece)
  Temporal_flow_input steps;        // the time steps of input 0
  Kept_outputs kept; // the outputs of the last successful run
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
  , Internal(new Internals)
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

int vtkStreamSurfaceFromCurve::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  this->Internal->steps.read_time_steps(inputVector[0]->GetInformationObject(0));
  return 1;
}

int vtkStreamSurfaceFromCurve::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  request_steps_around_requested_time(this->Internal->steps, inputVector, outputVector);
  return 1;
}

int vtkStreamSurfaceFromCurve::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  // Every rank: the flow at the requested time (a temporal input: once its steps have come).
  const std::optional<Distributed_input> update =
    update_at_requested_time(in.steps, in.field, request, inputVector, outputVector, selected_velocity(this));
  if (!update)
    return 1; // the pipeline runs this filter again with the next time step
  const Distributed_input& pieces = *update;
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // Every rank: the seed curves' pieces go to rank 0, and every rank samples its piece of the
  // flow for rank 0 (one process: the input's own field).  The particles' positions depend on
  // the samples before them: on several ranks every sample is an exchange of its own.
  const vtkSmartPointer<vtkPolyData> seeds = gather_on_root(vtkPolyData::GetData(inputVector[1], 0));
  if (!in.field.is_root())
  {
    serve_rank_0(in.field, outputVector);
    return 1;
  }
  try
  {
    Finish_probes finish_probes(in.field);
    this->CheckProperties();
    pieces.require_samples();
    const Distributed_velocity_field& field = in.field;
    const std::vector<Polyline> curves = polylines_from_polydata(seeds);
    if (curves.empty())
      throw std::invalid_argument(
        "the seed input (port 1) has no line or polyline of two points or more; give it seed "
        "curves (Parametrize And Seed's, a Line source, a contour)");

    // No length given: the surface reaches as far as the data's largest extent (a time at the
    // seeds' mean speed, or that arc length), in 200 time lines unless a step is given.
    double max_time = this->MaxTime, max_length = this->MaxLength, time_line_step = this->TimeLineStep;
    if (max_time <= 0 && max_length <= 0)
    {
      const double* b = pieces.bounds.data();
      if (this->ArcLengthTimeLines)
        max_length = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
      else
      {
        field.probe_points_of([&] { time_across_the_data(field, curves, b); });
        max_time = time_across_the_data(field, curves, b);
      }
      if (time_line_step <= 0)
        time_line_step = (this->ArcLengthTimeLines ? max_length : max_time) / 200;
    }
    const bool limited = this->ArcLengthTimeLines ? max_length > 0 : max_time > 0;
    const std::size_t max_time_lines = this->MaxNumberOfTimeLines > 0
      ? std::size_t(this->MaxNumberOfTimeLines)
      : (limited ? std::numeric_limits<std::size_t>::max() : std::size_t(100));
    const FAS::Integration_direction direction = this->IntegrationDirection == BACKWARD
      ? FAS::Integration_direction::BACKWARD
      : (this->IntegrationDirection == BOTH ? FAS::Integration_direction::BOTH
                                            : FAS::Integration_direction::FORWARD);

    // Progress per time line of each seed curve; Abort (AbortExecute) stops after the time line
    // in progress, keeping the surfaces integrated so far.
    std::size_t current_curve = 0;
    const auto progress = [&](double fraction) {
      this->UpdateProgress((double(current_curve) + fraction) / double(curves.size()));
      return !this->GetAbortExecute();
    };
    Mesh tm;
    auto u_map = tm.add_property_map<Mesh::Vertex_index, double>("v:u", 0.).first;
    auto t_map = tm.add_property_map<Mesh::Vertex_index, double>("v:t", 0.).first;
    std::vector<std::size_t> curve_of_vertex;
    std::vector<FAS::Stream_surface_report> reports;
    const auto base = FAS::parameters::integration_direction(direction,
      FAS::parameters::arc_length_time_lines(this->ArcLengthTimeLines,
        FAS::parameters::max_number_of_time_lines(max_time_lines,
          FAS::parameters::max_number_of_vertices(std::size_t(this->MaxNumberOfVertices),
            FAS::parameters::tear_angle(this->TearAngle,
              FAS::parameters::relative_tolerance(this->RelativeTolerance,
                FAS::parameters::absolute_tolerance(this->AbsoluteTolerance,
                  FAS::parameters::max_number_of_steps(std::size_t(this->MaxNumberOfSteps),
                    FAS::parameters::seed_parameter_map(
                      u_map, FAS::parameters::integration_time_map(t_map,
                        CGAL::parameters::callback(std::function<bool(double)>(progress))))))))))));

    bool cancelled = false;
    for (std::size_t c = 0; c < curves.size() && !cancelled; ++c)
    {
      current_curve = c;
      // The library tells a given parameter from an absent one at compile time (an absent
      // front spacing, time-line step or limit takes a default that depends on the seed or on
      // the other parameters), so the optional ones are passed only when set.
      const auto integrate = [&](const auto& np) {
        reports.push_back(FAS::integrate_stream_surface(field, curves[c], tm, np));
      };
      const auto with_max_length = [&](const auto& np) {
        if (max_length > 0)
          integrate(FAS::parameters::max_length(max_length, np));
        else
          integrate(np);
      };
      const auto with_max_time = [&](const auto& np) {
        if (max_time > 0)
          with_max_length(FAS::parameters::max_time(max_time, np));
        else
          with_max_length(np);
      };
      const auto with_step = [&](const auto& np) {
        if (time_line_step > 0)
          with_max_time(FAS::parameters::time_line_step(time_line_step, np));
        else
          with_max_time(np);
      };
      try
      {
        if (this->FrontSpacing > 0)
          with_step(FAS::parameters::front_spacing(this->FrontSpacing, base));
        else
          with_step(base);
      }
      catch (const std::invalid_argument& e)
      {
        throw std::invalid_argument("seed curve " + std::to_string(c) + " of " +
          std::to_string(curves.size()) + ": " + e.what());
      }
      curve_of_vertex.resize(tm.number_of_vertices(), c);
      cancelled = reports.back().stopped;
    }
    if (cancelled)
    {
      abort_handled(this);
      vtkWarningMacro(<< "Stream Surface From Curve: cancelled during seed curve " << reports.size() - 1 << " of "
                      << curves.size() << "; the output holds what was integrated until then");
    }

    std::string empty;
    for (std::size_t c = 0; c < reports.size(); ++c)
      if (surface_is_empty(reports[c]))
        empty += (empty.empty() ? "" : "; ") + std::string("curve ") + std::to_string(c) + ": " +
          FAS::to_string(reports[c].termination) + " (" + reports[c].message + ")";
    if (tm.number_of_faces() == 0)
      throw std::invalid_argument("no seed curve gives a surface (" + empty +
        "); the seed curves must lie in the data set (bounds " + bounds_text(pieces.bounds.data()) +
        ") where the flow is not zero");
    if (!empty.empty())
      vtkWarningMacro(<< "Stream Surface From Curve: some seed curves give no surface: " << empty);

    vtkSmartPointer<vtkPolyData> result = to_polydata(tm);
    const vtkIdType n = vtkIdType(tm.number_of_vertices());
    auto u = make_array("u", 1, n);
    auto t = make_array("t", 1, n);
    auto integration_time = make_array("IntegrationTime", 1, n);
    auto seed_curve = make_array("seed_curve", 1, n);
    for (Mesh::Vertex_index v : tm.vertices())
    {
      const vtkIdType i = vtkIdType(v.idx());
      u->SetValue(i, u_map[v]);
      t->SetValue(i, t_map[v]);
      integration_time->SetValue(i, t_map[v]);
      seed_curve->SetValue(i, double(curve_of_vertex[std::size_t(v.idx())]));
    }
    for (vtkDoubleArray* a : { u.Get(), t.Get(), integration_time.Get(), seed_curve.Get() })
      result->GetPointData()->AddArray(a);
    result->GetPointData()->SetActiveScalars("u");
    add_distribution_values(result, pieces, in.field);

    const auto per_curve = [&](const char* name, auto value) {
      std::vector<decltype(value(reports.front()))> values;
      for (const FAS::Stream_surface_report& r : reports)
        values.push_back(value(r));
      add_per_curve(result, name, values);
    };
    using R = FAS::Stream_surface_report;
    per_curve("termination", [](const R& r) { return std::string(FAS::to_string(r.termination)); });
    per_curve("termination_message", [](const R& r) { return r.message; });
    if (direction == FAS::Integration_direction::BOTH)
    {
      per_curve("backward_termination", [](const R& r) {
        return std::string(r.backward ? FAS::to_string(r.backward->termination) : "");
      });
      per_curve("backward_termination_message",
        [](const R& r) { return r.backward ? r.backward->message : std::string(); });
    }
    per_curve("number_of_time_lines", [](const R& r) { return double(r.number_of_time_lines); });
    per_curve("final_parameter", [](const R& r) { return r.final_parameter; });
    per_curve("seed_length", [](const R& r) { return r.seed_length; });
    per_curve("front_spacing", [](const R& r) { return r.front_spacing; });
    per_curve("time_line_step", [](const R& r) { return r.time_line_step; });
    per_curve("number_of_tears", [](const R& r) { return double(r.number_of_tears); });
    per_curve("number_of_lost_particles", [](const R& r) { return double(r.number_of_lost_particles); });

    output->ShallowCopy(result);
    in.kept.keep(outputVector);
    return 1;
  }
  catch (const std::exception& e)
  {
    const bool kept = in.kept.restore(outputVector);
    vtkErrorMacro(<< "Stream Surface From Curve: " << e.what() << (kept ? "; the previous output is kept" : ""));
    return 1;
  }
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
}
