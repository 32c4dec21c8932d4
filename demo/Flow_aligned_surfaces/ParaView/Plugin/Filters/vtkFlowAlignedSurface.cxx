#include "vtkFlowAlignedSurface.h"

#include "fas_default_patch.h"
#include "fas_flow_state.h"
#include "fas_paraview_support.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <map>
#include <chrono>
#include <iterator>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

using namespace fas_paraview;

vtkStandardNewMacro(vtkFlowAlignedSurface);

namespace {

using Deformation = FAS::Flow_aligned_deformation<Mesh, Distributed_velocity_field>;

// What the factorization depends on: the patch's connectivity and reference shape up to a
// rigid move, and the deformation's parameters.
struct Patch_key {
  int shape;
  double size;
  int faces;
  bool operator==(const Patch_key& o) const { return shape == o.shape && size == o.size && faces == o.faces; }
};

// The patch the properties ask for: Center, Normal, Size (or the default patch, Size 0).
struct Patch_pose {
  std::array<double, 3> center{}, normal{};
  double size = 0;
};

void make_patch(Mesh& tm, int shape, const Patch_pose& pose, int faces)
{
  tm.clear();
  const Point c(pose.center[0], pose.center[1], pose.center[2]);
  const Vector n(pose.normal[0], pose.normal[1], pose.normal[2]);
  if (shape == vtkFlowAlignedSurface::DISK)
    FAS::make_disk_patch(tm, c, n, pose.size / 2, std::size_t(faces));
  else
    FAS::make_planar_patch(tm, c, n, pose.size, pose.size, std::size_t(faces));
}

// `info` = the ranges (value, value + span) of the components of `value`: their minima are the
// defaults ParaView's panel takes (DoubleRangeDomain, default_mode min).
void set_range_info(vtkDoubleArray* info, const std::array<double, 3>& value, double span)
{
  info->SetNumberOfTuples(6);
  for (int i = 0; i < 3; ++i)
  {
    info->SetValue(2 * i, value[std::size_t(i)]);
    info->SetValue(2 * i + 1, value[std::size_t(i)] + span);
  }
}

// Every property in its range, or std::invalid_argument naming it.
void check_properties(vtkFlowAlignedSurface* f)
{
  require_property(f->GetSize() >= 0, "Size", f->GetSize(),
                   "> 0 (the side of the square or the diameter of the disk; 0: placed from the data)");
  require_property(f->GetNumberOfFaces() >= 2 && f->GetNumberOfFaces() <= 10000000, "Number Of Faces",
                   f->GetNumberOfFaces(), "from 2 to 10,000,000");
  require_alignment_properties(f->GetMaxRotationAngle(), f->GetMaxDihedralAngle(), f->GetConvergenceAngle(),
                               f->GetNumberOfIterations());
  const double* n = f->GetNormal();
  require_property(std::isfinite(n[0] + n[1] + n[2]) && n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0, "Normal",
                   std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), "a non-zero vector (its length is shown)");
  const double* c = f->GetCenter();
  require_property(std::isfinite(c[0] + c[1] + c[2]), "Center", c[0] + c[1] + c[2], "finite coordinates");
}

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string point_text(const double x[3])
{
  std::ostringstream os;
  os << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  return os.str();
}

// Says how long the iterations left take when that is long (from the first one's duration).
void expect_duration(double first_ms, std::size_t left)
{
  const double seconds = first_ms * double(left) / 1000;
  if (seconds < 30)
    return;
  std::ostringstream os;
  os << "Flow-Aligned Surface: an iteration takes " << first_ms / 1000 << " s: the " << left
     << " iterations left take about " << std::lround(seconds) << " s (or fewer, if it converges first)\n";
  vtkOutputWindowDisplayText(os.str().c_str());
}

} // namespace

struct vtkFlowAlignedSurface::Internals {
  explicit Internals(FlowState& flow)
    : field(flow.field)
    , kept(flow.kept)
    , steps(flow.steps)
  {
  }

  // The input's velocity (vtkFlowAlignedFilter's: on several ranks, its samples probed from
  // every rank's piece); the deformation holds a reference to it: never replaced.
  Distributed_velocity_field& field;

  Mesh tm;                    // the surface the deformation writes
  std::unique_ptr<Deformation> deformation;
  std::optional<Patch_key> key;
  int factorizations_before = 0; // by the deformations replaced so far

  std::array<double, 6> pose{};  // centre and normal the iterations started from

  // The default patch offered to the panel, and what it was computed for.
  vtkNew<vtkDoubleArray> center_info, normal_info, size_info;
  vtkMTimeType default_input_time = 0;
  Velocity_selection default_selection;
  int default_alignment = -1;
  // The patch placed for Size 0, and the alignment it was placed for.
  std::optional<Default_patch> placed;
  int placed_alignment = -1;
  int alignment = -1;
  bool restart = true;
  std::vector<std::vector<Point>> positions; // after 0, 1, ... iterations
  std::vector<FAS::Iteration_report> reports;   // reports[k] made positions[k + 1]
  bool converged = false;

  Kept_outputs& kept; // the outputs of the last successful run (vtkFlowAlignedFilter's)
  double exchange_ms = 0, step_ms = 0; // of the iterations of the last update

  // A temporal input: the surface after following the flow from the patch through the steps
  // 0, 1, ..., i (aligned at each step's time from the surface of the step before), by step
  // index; dropped when the input or a property changes.
  struct Followed {
    std::vector<Point> positions;
    std::size_t iterations = 0;
    bool converged = false;
    double max_rotation_angle = 0;
  };
  Temporal_flow_input& steps;          // the time steps of the input (vtkFlowAlignedFilter's)
  std::map<std::size_t, Followed> followed;
  std::vector<Point> initial;          // the patch at its pose, where following starts
  std::size_t followed_in_update = 0;  // steps followed by the last update

  // The steps of an update on rank 0 (RequestData), in order.
  std::array<double, 7> requested_pose(vtkFlowAlignedSurface* f, const Distributed_input& pieces, bool data_changed);
  void prepare_patch(vtkFlowAlignedSurface* f, const std::array<double, 7>& requested_pose);
  void start_iterations(const Distributed_input& pieces);
  std::size_t iterate(vtkFlowAlignedSurface* f, std::size_t requested);
  void show_iteration(vtkFlowAlignedSurface* f, std::size_t k, std::size_t computed,
                      const Distributed_input& pieces, vtkInformationVector* outputVector);
  // What the output says of the surface it shows.
  struct Shown {
    std::size_t iteration = 0;
    bool converged = false;
    double max_rotation_angle = 0;
  };
  void show(vtkFlowAlignedSurface* f, const std::vector<Point>& x, const Shown& shown, std::size_t computed,
            const Distributed_input& pieces, vtkInformationVector* outputVector);
  bool in_converged_state(std::size_t k) const { return converged && k + 1 >= positions.size(); }
  // A temporal input, instead of start_iterations(), iterate() and show_iteration().
  std::vector<std::size_t> needed_steps(vtkInformation* output_information) const;
  void follow_the_flow(vtkFlowAlignedSurface* f, double t, const Distributed_input& pieces,
                       vtkInformationVector* outputVector);
  Followed align_at(vtkFlowAlignedSurface* f, double t);
  // The first step up to step k that was not followed yet (k + 1: none).
  std::size_t first_step_to_follow(std::size_t k) const
  {
    const auto after = followed.upper_bound(k);
    return after == followed.begin() ? 0 : std::prev(after)->first + 1;
  }
  FAS::Iteration_report one_iteration();

  int factorizations() const
  {
    return factorizations_before + (deformation ? int(deformation->number_of_factorizations()) : 0);
  }

  std::vector<Point> current_positions() const
  {
    std::vector<Point> x;
    x.reserve(tm.number_of_vertices());
    for (Mesh::Vertex_index v : tm.vertices())
      x.push_back(tm.point(v));
    return x;
  }

  void set_positions(const std::vector<Point>& x)
  {
    std::size_t i = 0;
    for (Mesh::Vertex_index v : tm.vertices())
      tm.point(v) = x[i++];
  }
};

vtkFlowAlignedSurface::vtkFlowAlignedSurface()
  : Center{ 0, 0, 0 }
  , Normal{ 1, 0, 0 }
  , PatchShape(PLANAR)
  , Size(0)
  , NumberOfFaces(5000)
  , Alignment(TANGENTIAL)
  , MaxRotationAngle(0.1)
  , MaxDihedralAngle(vtkMath::Pi() / 2)
  , ConvergenceAngle(1e-6)
  , NumberOfIterations(100)
  , Internal(new Internals(*this->Flow))
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::VECTORS);
}

vtkFlowAlignedSurface::~vtkFlowAlignedSurface()
{
  delete this->Internal;
}

int vtkFlowAlignedSurface::GetNumberOfFactorizations()
{
  return this->Internal->factorizations();
}

int vtkFlowAlignedSurface::FillInputPortInformation(int, vtkInformation* info)
{
  accept_flow_inputs(info);
  return 1;
}

vtkDoubleArray* vtkFlowAlignedSurface::GetCenterInfo()
{
  return this->Internal->center_info;
}

vtkDoubleArray* vtkFlowAlignedSurface::GetNormalInfo()
{
  return this->Internal->normal_info;
}

vtkDoubleArray* vtkFlowAlignedSurface::GetSizeInfo()
{
  return this->Internal->size_info;
}

const char* vtkFlowAlignedSurface::GetLabel()
{
  return "Flow-Aligned Surface";
}

int vtkFlowAlignedSurface::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  this->Superclass::RequestInformation(request, inputVector, outputVector);
  if (in.steps.temporal())
  {
    // The data's time steps (copied to the output by the pipeline): the time controls play the
    // data, and the surface follows the flow from the first step on.
    in.followed.clear();
    in.placed.reset();
    this->OfferDefaultPatch(inputVector[0]->GetInformationObject(0));
    return 1;
  }
  // The iterations as time steps: the time controls play the deformation.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int iterations = std::clamp(this->NumberOfIterations, 0, 100000);
  std::vector<double> steps(std::size_t(iterations) + 1);
  for (std::size_t k = 0; k < steps.size(); ++k)
    steps[k] = double(k);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), int(steps.size()));
  const double range[2] = { 0., double(iterations) };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  this->OfferDefaultPatch(inputVector[0]->GetInformationObject(0));
  return 1;
}

void vtkFlowAlignedSurface::SelectSteps(vtkInformationVector* outputVector)
{
  this->Flow->needed.clear();
  if (this->Flow->steps.temporal())
    this->Flow->needed = this->Internal->needed_steps(outputVector->GetInformationObject(0));
}

void vtkFlowAlignedSurface::OfferDefaultPatch(vtkInformation* input_information)
{
  Internals& in = *this->Internal;
  const Velocity_selection selection = selected_velocity(this);
  vtkDataObject* input = input_information != nullptr ? vtkDataObject::GetData(input_information) : nullptr;
  const vtkMTimeType input_time = input != nullptr ? input->GetMTime() : 0;
  if (input_time == in.default_input_time && selection == in.default_selection &&
      this->Alignment == in.default_alignment)
    return;
  in.default_input_time = input_time;
  in.default_selection = selection;
  in.default_alignment = this->Alignment;
  for (vtkDoubleArray* info : { in.center_info.Get(), in.normal_info.Get(), in.size_info.Get() })
    info->SetNumberOfTuples(0);
  // This rank's piece, sampled here once for the update that follows as well.
  in.field.sample_piece(input_information, selection);
  // Where the data at hand are not what the update places the patch in, nothing is offered and
  // Size stays 0, so that the update places it: on several processes a piece is not the data (a
  // placement from rank 0's piece would differ with the number of ranks); a time series is
  // followed from its first step, and the step at hand is the view's.
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  if ((c != nullptr && c->GetNumberOfProcesses() > 1) || in.steps.temporal())
    return;
  const Piece_field* piece_field = in.field.piece_field();
  if (piece_field == nullptr || in.field.piece().data_set->GetNumberOfCells() == 0)
    return;
  double bounds[6];
  in.field.piece().data_set->GetBounds(bounds);
  const std::optional<Default_patch> patch = default_patch(*piece_field, bounds, this->Alignment == ORTHOGONAL);
  if (!patch)
    return;
  set_range_info(in.center_info, patch->center, 8 * patch->size);
  set_range_info(in.normal_info, patch->normal, 1);
  in.size_info->SetNumberOfTuples(2);
  in.size_info->SetValue(0, 0);
  in.size_info->SetValue(1, 2 * patch->size);
}

bool vtkFlowAlignedSurface::Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  const Distributed_input& pieces = this->Flow->pieces;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const bool temporal = in.steps.temporal();
  check_properties(this);
  pieces.require_samples();
  // The field is sampled anew when the input or the array changed; the deformation keeps its
  // factorization (it depends on the patch only).  A temporal input's steps differ from update
  // to update; what it followed is dropped when its data change (RequestInformation).
  const bool data_changed = pieces.changed && !temporal;
  if (data_changed)
  {
    in.restart = true;
    if (!pieces.note.empty())
      vtkOutputWindowDisplayText(("Flow-Aligned Surface: " + pieces.note + "\n").c_str());
  }
  in.prepare_patch(this, in.requested_pose(this, pieces, data_changed));
  if (temporal)
    in.follow_the_flow(this, in.steps.requested_time(outInfo), pieces, outputVector);
  else
  {
    std::size_t requested = std::size_t(this->NumberOfIterations);
    if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      const double k = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      requested = std::size_t(std::lround(std::clamp(k, 0., double(this->NumberOfIterations))));
    }
    in.start_iterations(pieces);
    const std::size_t computed = in.iterate(this, requested);
    in.show_iteration(this, std::min(requested, in.positions.size() - 1), computed, pieces, outputVector);
  }
  return true;
}

std::array<double, 7> vtkFlowAlignedSurface::Internals::requested_pose(vtkFlowAlignedSurface* f, const Distributed_input& pieces,
                                                                      bool data_changed)
{
  Internals& in = *this;
  if (f->Size > 0)
    return { f->Center[0], f->Center[1], f->Center[2], f->Normal[0], f->Normal[1],
      f->Normal[2], f->Size };
  // Size 0: the default patch, placed once per input and alignment (its lattice sampled in one
  // exchange, then a few points alone), not at every time step played.
  const bool orthogonal = f->Alignment == vtkFlowAlignedSurface::ORTHOGONAL;
  if (!in.placed || data_changed || in.placed_alignment != f->Alignment)
  {
    in.placed.reset();
    if (in.steps.temporal())
      in.field.set_time(in.steps.times().front()); // placed where following the flow starts
    in.placed = default_patch(in.field, pieces.bounds.data(), orthogonal);
    in.placed_alignment = f->Alignment;
    if (!in.placed)
      throw std::invalid_argument("Size is 0 (place the patch from the data), but the Input has no flow sample "
                                  "on a lattice over its bounds (" + bounds_text(pieces.bounds.data()) +
                                  "); set Center, Normal and Size");
    vtkOutputWindowDisplayText(("Flow-Aligned Surface: Size 0: the patch placed " + in.placed->description +
      ", centre " + point_text(in.placed->center.data()) + ", normal " + point_text(in.placed->normal.data()) +
      ", size " + std::to_string(in.placed->size) + "\n").c_str());
  }
  const Default_patch* patch = &*in.placed;
  return { patch->center[0], patch->center[1], patch->center[2], patch->normal[0], patch->normal[1],
    patch->normal[2], patch->size };
}

void vtkFlowAlignedSurface::Internals::prepare_patch(vtkFlowAlignedSurface* f, const std::array<double, 7>& requested_pose)
{
  Internals& in = *this;
  Patch_pose pose;
  std::copy(requested_pose.begin(), requested_pose.begin() + 3, pose.center.begin());
  std::copy(requested_pose.begin() + 3, requested_pose.begin() + 6, pose.normal.begin());
  pose.size = requested_pose[6];
  const Patch_key key{ f->PatchShape, pose.size, f->NumberOfFaces };
  const std::array<double, 6> center_normal{ pose.center[0], pose.center[1], pose.center[2], pose.normal[0],
    pose.normal[1], pose.normal[2] };
  if (!in.key || !(*in.key == key))
  {
    // A new patch: new operators, one factorization.
    if (f->NumberOfFaces >= 1000000)
      vtkOutputWindowDisplayText(("Flow-Aligned Surface: " + std::to_string(f->NumberOfFaces) +
        " faces: the factorization and each iteration take seconds to minutes; the progress bar "
        "shows the iterations\n").c_str());
    in.factorizations_before = in.factorizations();
    in.deformation.reset();
    in.key.reset();
    make_patch(in.tm, f->PatchShape, pose, f->NumberOfFaces);
    f->UpdateProgress(0.01);
    in.deformation = std::make_unique<Deformation>(in.tm, in.field,
      f->Alignment == vtkFlowAlignedSurface::ORTHOGONAL ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL,
      FAS::parameters::use_parallelism(true));
    in.key = key;
    in.pose = center_normal;
    in.alignment = f->Alignment;
    in.initial = in.current_positions();
    in.positions.clear();
    in.restart = true;
  }
  else if (center_normal != in.pose)
  {
    // A rigid move of the same patch: the positions of the patch at the new pose, and the
    // factorization stays (the operators of a rigidly moved mesh are the same).
    Mesh moved;
    make_patch(moved, f->PatchShape, pose, f->NumberOfFaces);
    if (moved.number_of_vertices() != in.tm.number_of_vertices())
      throw std::logic_error("the patch at the new pose has another connectivity");
    for (Mesh::Vertex_index v : in.tm.vertices())
      in.tm.point(v) = moved.point(v);
    in.pose = center_normal;
    in.initial = in.current_positions();
    in.positions.clear();
    in.restart = true;
  }
  // η, θmax and ε do not enter L + W: set anew, the iterations restart with the factorization kept.
  Deformation& d = *in.deformation;
  if (f->MaxRotationAngle != d.max_rotation_angle() || f->MaxDihedralAngle != d.max_dihedral_angle() ||
    f->ConvergenceAngle != d.convergence_angle())
  {
    d.set_max_rotation_angle(f->MaxRotationAngle);
    d.set_max_dihedral_angle(f->MaxDihedralAngle);
    d.set_convergence_angle(f->ConvergenceAngle);
    in.restart = true;
  }
  if (f->Alignment != in.alignment)
  {
    in.deformation->set_alignment(
      f->Alignment == vtkFlowAlignedSurface::ORTHOGONAL ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL);
    in.alignment = f->Alignment;
    in.restart = true;
  }
}

void vtkFlowAlignedSurface::Internals::start_iterations(const Distributed_input& pieces)
{
  Internals& in = *this;
  if (!in.restart)
    return;
  if (!in.positions.empty())
    in.set_positions(in.positions.front()); // back to the patch at this pose (the iterations moved it)
  in.positions.assign(1, in.current_positions());
  in.reports.clear();
  in.converged = false;
  in.restart = false;
  const FAS::Normalized_flux start = FAS::normalized_flux(in.tm, in.field);
  if (!start.value)
  {
    in.restart = true; // nothing of this pose is kept
    throw std::invalid_argument("the patch at Center " + point_text(in.pose.data()) +
      " has no flow sample: it lies outside the Input (bounds " + bounds_text(pieces.bounds.data()) +
      "); move it into the data");
  }
}

std::size_t vtkFlowAlignedSurface::Internals::iterate(vtkFlowAlignedSurface* f, std::size_t requested)
{
  // Only the pose of the patch and the first positions were set when the reports are empty;
  // the iterations up to the requested one are computed once and kept.  On several ranks each
  // iteration's samples are probed first, in one exchange.  Abort (AbortExecute) stops after the
  // iteration in progress; the next update goes on from there.
  Internals& in = *this;
  in.exchange_ms = in.step_ms = 0;
  const std::size_t first = in.positions.size();
  std::size_t computed = 0;
  const auto started = std::chrono::steady_clock::now();
  while (in.positions.size() <= requested && !in.converged)
  {
    if (f->GetAbortExecute())
    {
      abort_handled(f);
      vtkWarningWithObjectMacro(f, << "Flow-Aligned Surface: cancelled after iteration " << in.positions.size() - 1 << " of "
                      << requested << "; the output shows it, and the next update goes on from there");
      break;
    }
    if (in.positions.size() != in.reports.size() + 1)
      throw std::logic_error("iterations out of step");
    const FAS::Iteration_report r = in.one_iteration();
    ++computed;
    in.reports.push_back(r);
    in.positions.push_back(in.current_positions());
    in.converged = r.converged;
    const double done = double(in.positions.size() - first) / double(requested + 1 - first);
    f->UpdateProgress(0.02 + 0.98 * done);
    if (computed == 1 && requested + 1 > in.positions.size())
      expect_duration(milliseconds_since(started), requested + 1 - in.positions.size());
  }
  return computed;
}

void vtkFlowAlignedSurface::Internals::show_iteration(vtkFlowAlignedSurface* f, std::size_t k, std::size_t computed, const Distributed_input& pieces,
                                          vtkInformationVector* outputVector)
{
  const bool converged = in_converged_state(k);
  show(f, positions[k], Shown{ k, converged, k == 0 ? 0. : reports[k - 1].max_rotation_angle }, computed, pieces,
       outputVector);
}

void vtkFlowAlignedSurface::Internals::show(vtkFlowAlignedSurface* f, const std::vector<Point>& x, const Shown& shown,
                                            std::size_t computed, const Distributed_input& pieces,
                                            vtkInformationVector* outputVector)
{
  Internals& in = *this;
  Mesh surface = in.tm;
  {
    std::size_t i = 0;
    for (Mesh::Vertex_index v : surface.vertices())
      surface.point(v) = x[i++];
  }
  const auto [result, flux] = aligned_surface_output(surface, in.field);
  add_field_value(result, "iteration", double(shown.iteration));
  add_field_value(result, "converged", shown.converged ? 1. : 0.);
  add_field_value(result, "max_rotation_angle", shown.max_rotation_angle);
  add_field_value(result, "number_of_factorizations", double(in.factorizations()));
  add_field_value(result, "size", in.key->size);
  if (in.steps.temporal())
  {
    add_field_value(result, "time", in.field.time());
    add_field_value(result, "time_steps_followed_in_update", double(in.followed_in_update));
  }
  if (in.field.distributed())
  {
    // How the input was spread and what the exchanges cost (for the benchmark and the tests).
    add_distribution_values(result, pieces, in.field);
    add_field_value(result, "iterations_computed", double(computed));
    if (computed > 0)
    {
      add_field_value(result, "exchange_ms_per_iteration", in.exchange_ms / double(computed));
      add_field_value(result, "step_ms_per_iteration", in.step_ms / double(computed));
    }
  }
  if (const std::string warning = unsampled_area_warning(flux); !warning.empty())
    vtkWarningWithObjectMacro(f, << "Flow-Aligned Surface: " << warning);
  vtkPolyData::GetData(outputVector, 0)->ShallowCopy(result);
}

FAS::Iteration_report vtkFlowAlignedSurface::Internals::one_iteration()
{
  // On several ranks the iteration's samples are probed first, in one exchange.
  if (field.distributed())
  {
    const auto exchange_start = std::chrono::steady_clock::now();
    std::vector<Point> points;
    deformation->next_sample_points(std::back_inserter(points));
    field.probe(points);
    exchange_ms += milliseconds_since(exchange_start);
  }
  const auto step_start = std::chrono::steady_clock::now();
  const FAS::Iteration_report r = deformation->step();
  step_ms += milliseconds_since(step_start);
  return r;
}

std::vector<std::size_t> vtkFlowAlignedSurface::Internals::needed_steps(vtkInformation* output_information) const
{
  // The steps not followed yet up to the requested time, and the steps around it.
  const double t = steps.requested_time(output_information);
  const std::size_t k = steps.step_at_or_before(t);
  std::vector<std::size_t> needed;
  for (std::size_t i = first_step_to_follow(k); i <= k; ++i)
    needed.push_back(i);
  for (std::size_t i : steps.steps_around(t))
    needed.push_back(i);
  std::sort(needed.begin(), needed.end());
  needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
  return needed;
}

vtkFlowAlignedSurface::Internals::Followed vtkFlowAlignedSurface::Internals::align_at(vtkFlowAlignedSurface* f, double t)
{
  // Up to Number Of Iterations iterations in the flow at time t, from the surface as it is.
  field.set_time(t);
  Followed result;
  while (result.iterations < std::size_t(f->NumberOfIterations) && !result.converged && !f->GetAbortExecute())
  {
    const FAS::Iteration_report r = one_iteration();
    ++result.iterations;
    result.converged = r.converged;
    result.max_rotation_angle = r.max_rotation_angle;
  }
  result.positions = current_positions();
  return result;
}

void vtkFlowAlignedSurface::Internals::follow_the_flow(vtkFlowAlignedSurface* f, double t, const Distributed_input& pieces,
                                                       vtkInformationVector* outputVector)
{
  // The surface at time t has followed the flow from the patch at the first step through every
  // step up to t, whatever the way the user came to t (played, stepped back, jumped): the steps
  // not followed yet are followed now, in order; between two steps it is aligned at t from the
  // surface of the step before.
  Internals& in = *this;
  if (in.restart)
  {
    in.followed.clear();
    in.restart = false;
  }
  in.exchange_ms = in.step_ms = 0;
  const std::vector<double>& times = in.steps.times();
  const std::size_t k = in.steps.step_at_or_before(t);
  const std::size_t first = in.first_step_to_follow(k);
  std::size_t computed = 0;
  in.followed_in_update = 0;
  for (std::size_t i = first; i <= k; ++i)
  {
    in.set_positions(i == 0 ? in.initial : in.followed.at(i - 1).positions);
    Followed step = in.align_at(f, times[i]);
    computed += step.iterations;
    if (f->GetAbortExecute())
    {
      abort_handled(f);
      vtkWarningWithObjectMacro(f, << "Flow-Aligned Surface: cancelled while following the flow to time step " << i
                      << "; the output shows the surface of time " << (i == 0 ? times[0] : times[i - 1])
                      << ", and the next update goes on from there");
      const Shown shown{ step.iterations, false, step.max_rotation_angle };
      in.field.set_time(i == 0 ? times[0] : times[i - 1]);
      show(f, i == 0 ? in.initial : in.followed.at(i - 1).positions, shown, computed, pieces, outputVector);
      return;
    }
    in.followed[i] = std::move(step);
    ++in.followed_in_update;
    f->UpdateProgress(double(i + 1 - first) / double(k + 2 - first));
  }
  Followed shown = in.followed.at(k);
  if (t > times[k])
  {
    in.set_positions(shown.positions);
    shown = in.align_at(f, t);
    computed += shown.iterations;
  }
  in.field.set_time(t);
  show(f, shown.positions, Shown{ shown.iterations, shown.converged, shown.max_rotation_angle }, computed, pieces,
       outputVector);
}

void vtkFlowAlignedSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Center: " << this->Center[0] << " " << this->Center[1] << " " << this->Center[2] << "\n";
  os << indent << "Normal: " << this->Normal[0] << " " << this->Normal[1] << " " << this->Normal[2] << "\n";
  os << indent << "PatchShape: " << this->PatchShape << "\n";
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "NumberOfFaces: " << this->NumberOfFaces << "\n";
  os << indent << "Alignment: " << this->Alignment << "\n";
  os << indent << "MaxRotationAngle: " << this->MaxRotationAngle << "\n";
  os << indent << "MaxDihedralAngle: " << this->MaxDihedralAngle << "\n";
  os << indent << "ConvergenceAngle: " << this->ConvergenceAngle << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
}
