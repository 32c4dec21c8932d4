#include "vtkFlowAlignedSurface.h"

#include "fas_distributed_field.h"
#include "fas_paraview_support.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>

#include <vtkCellData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
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
  double eta, theta_max, epsilon;
  bool operator==(const Patch_key& o) const
  {
    return shape == o.shape && size == o.size && faces == o.faces && eta == o.eta &&
           theta_max == o.theta_max && epsilon == o.epsilon;
  }
};

void make_patch(Mesh& tm, int shape, const double center[3], const double normal[3], double size, int faces)
{
  tm.clear();
  const Point c(center[0], center[1], center[2]);
  const Vector n(normal[0], normal[1], normal[2]);
  if (shape == vtkFlowAlignedSurface::DISK)
    FAS::make_disk_patch(tm, c, n, size / 2, std::size_t(faces));
  else
    FAS::make_planar_patch(tm, c, n, size, size, std::size_t(faces));
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

} // namespace

struct vtkFlowAlignedSurface::Internals {
  // The input's velocity (on several ranks: its samples probed from every rank's piece); the
  // deformation holds a reference to it: never replaced.
  Distributed_velocity_field field;

  Mesh tm;                    // the surface the deformation writes
  std::unique_ptr<Deformation> deformation;
  std::optional<Patch_key> key;
  int factorizations_before = 0; // by the deformations replaced so far

  std::array<double, 6> pose{};  // centre and normal the iterations started from
  int alignment = -1;
  bool restart = true;
  std::vector<std::vector<Point>> positions; // after 0, 1, ... iterations
  std::vector<FAS::Iteration_report> reports;   // reports[k] made positions[k + 1]
  bool converged = false;

  Kept_outputs kept; // the outputs of the last successful run

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
};

vtkFlowAlignedSurface::vtkFlowAlignedSurface()
  : Center{ 0, 0, 0 }
  , Normal{ 1, 0, 0 }
  , PatchShape(PLANAR)
  , Size(1)
  , NumberOfFaces(5000)
  , Alignment(TANGENTIAL)
  , MaxRotationAngle(0.1)
  , MaxDihedralAngle(vtkMath::Pi() / 2)
  , ConvergenceAngle(1e-6)
  , NumberOfIterations(100)
  , Internal(new Internals)
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
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

int vtkFlowAlignedSurface::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The iterations as time steps: the time controls play the deformation.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  std::vector<double> steps(std::size_t(this->NumberOfIterations) + 1);
  for (std::size_t k = 0; k < steps.size(); ++k)
    steps[k] = double(k);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), int(steps.size()));
  const double range[2] = { 0., double(this->NumberOfIterations) };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkFlowAlignedSurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  std::size_t requested = std::size_t(this->NumberOfIterations);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    requested = std::size_t(std::lround(std::clamp(t, 0., double(this->NumberOfIterations))));
  }

  try
  {
    // The field: sampled anew when the input or the array changed; the deformation keeps its
    // factorization (it depends on the patch only).  On several ranks every rank builds the
    // field of its own piece (none for a piece without cells) and rank 0 learns the pieces'
    // state; then the other ranks only answer rank 0's probes.
    const Distributed_input pieces = in.field.update(inputVector[0]->GetInformationObject(0), selected_array_name(this));
    if (!in.field.is_root())
    {
      serve_rank_0(in.field, outputVector);
      return 1;
    }
    Finish_probes finish_probes(in.field);
    pieces.require_samples();
    if (pieces.changed)
      in.restart = true;

    const Patch_key key{ this->PatchShape, this->Size, this->NumberOfFaces, this->MaxRotationAngle,
      this->MaxDihedralAngle, this->ConvergenceAngle };
    const std::array<double, 6> pose{ this->Center[0], this->Center[1], this->Center[2],
      this->Normal[0], this->Normal[1], this->Normal[2] };
    if (!in.key || !(*in.key == key))
    {
      // A new patch: new operators, one factorization.
      in.factorizations_before = in.factorizations();
      in.deformation.reset();
      in.key.reset();
      make_patch(in.tm, this->PatchShape, this->Center, this->Normal, this->Size, this->NumberOfFaces);
      in.deformation = std::make_unique<Deformation>(in.tm, in.field,
        this->Alignment == ORTHOGONAL ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL,
        FAS::parameters::max_rotation_angle(this->MaxRotationAngle,
          FAS::parameters::max_dihedral_angle(this->MaxDihedralAngle,
            FAS::parameters::convergence_angle(
              this->ConvergenceAngle, FAS::parameters::use_parallelism(true)))));
      in.key = key;
      in.pose = pose;
      in.positions.clear();
      in.restart = true;
    }
    else if (pose != in.pose)
    {
      // A rigid move of the same patch: the positions of the patch at the new pose, and the
      // factorization stays (the operators of a rigidly moved mesh are the same).
      Mesh moved;
      make_patch(moved, this->PatchShape, this->Center, this->Normal, this->Size, this->NumberOfFaces);
      if (moved.number_of_vertices() != in.tm.number_of_vertices())
        throw std::logic_error("the patch at the new pose has another connectivity");
      for (Mesh::Vertex_index v : in.tm.vertices())
        in.tm.point(v) = moved.point(v);
      in.pose = pose;
      in.positions.clear();
      in.restart = true;
    }
    if (this->Alignment != in.alignment)
    {
      in.deformation->set_alignment(
        this->Alignment == ORTHOGONAL ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL);
      in.alignment = this->Alignment;
      in.restart = true;
    }
    if (in.restart)
    {
      if (!in.positions.empty())
      {
        // Back to the patch at this pose (the iterations moved it).
        std::size_t i = 0;
        for (Mesh::Vertex_index v : in.tm.vertices())
          in.tm.point(v) = in.positions.front()[i++];
      }
      in.positions.assign(1, in.current_positions());
      in.reports.clear();
      in.converged = false;
      in.restart = false;
      in.field.probe_points_of([&] { FAS::normalized_flux(in.tm, in.field); });
      const FAS::Normalized_flux start = FAS::normalized_flux(in.tm, in.field);
      if (!start.value)
      {
        in.restart = true; // nothing of this pose is kept
        throw std::invalid_argument("the patch at centre " + point_text(this->Center) +
          " has no flow sample: it lies outside the input data set (bounds " + bounds_text(pieces.bounds.data()) +
          "); move it into the data");
      }
    }
    // Only the pose of the patch and the first positions were set when the reports are empty;
    // the iterations up to the requested one are computed once and kept.  On several ranks each
    // iteration's samples are probed first, in one exchange.
    double exchange_ms = 0, step_ms = 0;
    std::size_t iterations_now = 0;
    while (in.positions.size() <= requested && !in.converged)
    {
      if (in.positions.size() != in.reports.size() + 1)
        throw std::logic_error("iterations out of step");
      if (in.field.distributed())
      {
        const auto exchange_start = std::chrono::steady_clock::now();
        std::vector<Point> points;
        in.deformation->next_sample_points(std::back_inserter(points));
        in.field.probe(points);
        exchange_ms += milliseconds_since(exchange_start);
      }
      const auto step_start = std::chrono::steady_clock::now();
      const FAS::Iteration_report r = in.deformation->step();
      step_ms += milliseconds_since(step_start);
      ++iterations_now;
      in.reports.push_back(r);
      in.positions.push_back(in.current_positions());
      in.converged = r.converged;
    }

    const std::size_t k = std::min(requested, in.positions.size() - 1);
    Mesh shown = in.tm;
    {
      std::size_t i = 0;
      for (Mesh::Vertex_index v : shown.vertices())
        shown.point(v) = in.positions[k][i++];
    }
    const auto [result, flux] = aligned_surface_output(shown, in.field);
    add_field_value(result, "iteration", double(k));
    add_field_value(result, "converged", in.converged && k + 1 >= in.positions.size() ? 1. : 0.);
    add_field_value(result, "max_rotation_angle", k == 0 ? 0. : in.reports[k - 1].max_rotation_angle);
    add_field_value(result, "number_of_factorizations", double(in.factorizations()));
    if (in.field.distributed())
    {
      // How the input was spread and what the exchanges cost (for the benchmark and the tests).
      add_distribution_values(result, pieces, in.field);
      add_field_value(result, "iterations_computed", double(iterations_now));
      if (iterations_now > 0)
      {
        add_field_value(result, "exchange_ms_per_iteration", exchange_ms / double(iterations_now));
        add_field_value(result, "step_ms_per_iteration", step_ms / double(iterations_now));
      }
    }
    if (const std::string warning = unsampled_area_warning(flux); !warning.empty())
      vtkWarningMacro(<< "Flow-Aligned Surface: " << warning);
    output->ShallowCopy(result);
    in.kept.keep(outputVector);
    return 1;
  }
  catch (const std::exception& e)
  {
    const bool kept = in.kept.restore(outputVector);
    vtkErrorMacro(<< "Flow-Aligned Surface: " << e.what() << (kept ? "; the previous output is kept" : ""));
    return 1;
  }
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
