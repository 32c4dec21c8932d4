#include "vtkGrowBoundary.h"

#include "fas_flow_state.h"
#include "fas_paraview_support.h"
#include "fas_paraview_surface_input.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

using namespace fas_paraview;

vtkStandardNewMacro(vtkGrowBoundary);

namespace {

using Deformation = FAS::Flow_aligned_deformation<Mesh, Distributed_velocity_field>;

// Iterates until an iteration converges or `max_iterations` were made, as
// Flow_aligned_deformation::run() does; on several ranks each iteration's samples are exchanged
// first, in one go.  Returns the number of iterations, whether the last converged and its
// largest rotation.
FAS::Alignment_report iterate(Deformation& deformation, const Distributed_velocity_field& field,
                              std::size_t max_iterations)
{
  FAS::Alignment_report result;
  std::vector<Point> points;
  for (std::size_t k = 0; k < max_iterations && !result.converged; ++k)
  {
    if (field.distributed())
    {
      points.clear();
      deformation.next_sample_points(std::back_inserter(points));
      field.probe(points);
    }
    const FAS::Iteration_report r = deformation.step();
    ++result.number_of_iterations;
    result.max_rotation_angle = r.max_rotation_angle;
    result.converged = r.converged;
  }
  return result;
}

// The largest side of the bounding box of `surface`.
double largest_extent(vtkPolyData* surface)
{
  double b[6];
  surface->GetBounds(b);
  return std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
}

} // namespace


vtkGrowBoundary::vtkGrowBoundary()
  : Distance(0)
  , GrowthMode(ALL)
  , GrowthDirection{ 1, 0, 0 }
  , NumberOfGrowthSteps(1)
  , Alignment(TANGENTIAL)
  , MaxRotationAngle(0.1)
  , MaxDihedralAngle(vtkMath::Pi() / 2)
  , ConvergenceAngle(1e-6)
  , NumberOfIterations(100)
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::VECTORS);
}

vtkGrowBoundary::~vtkGrowBoundary() = default;

int vtkGrowBoundary::FillInputPortInformation(int port, vtkInformation* info)
{
  return fill_surface_filter_input_port(port, info);
}

const char* vtkGrowBoundary::GetLabel()
{
  return "Grow Boundary";
}

bool vtkGrowBoundary::Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const Distributed_input& pieces = this->Flow->pieces;
  const vtkSmartPointer<vtkPolyData>& surface = this->Flow->gathered;
  require_property(std::isfinite(this->Distance) && this->Distance >= 0, "Distance", this->Distance,
                   ">= 0 (the width of each grown strip, in the data's units; 0: a tenth of the surface's largest extent)");
  require_property(this->NumberOfGrowthSteps >= 1 && this->NumberOfGrowthSteps <= 1000, "Number Of Growth Steps",
                   this->NumberOfGrowthSteps, "from 1 to 1,000");
  require_alignment_properties(this->MaxRotationAngle, this->MaxDihedralAngle, this->ConvergenceAngle,
                               this->NumberOfIterations);
  pieces.require_samples();
  const Distributed_velocity_field& field = this->Flow->field; // outlives the deformation, as tm does
  Mesh tm = mesh_from_polydata(surface, "the surface (input 1)");
  const double distance = this->Distance > 0 ? this->Distance : 0.1 * largest_extent(surface);
  const std::size_t input_vertices = tm.number_of_vertices();
  if (!FAS::normalized_flux(tm, field).value)
    throw std::invalid_argument("the surface (input 1) has no flow sample: it lies outside the input "
                                "data set (bounds " + bounds_text(pieces.bounds.data()) + "); move it into the data");

  const FAS::Alignment alignment =
    this->Alignment == ORTHOGONAL ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL;
  Deformation deformation(tm, field, alignment,
    FAS::parameters::max_rotation_angle(this->MaxRotationAngle,
      FAS::parameters::max_dihedral_angle(this->MaxDihedralAngle,
        FAS::parameters::convergence_angle(
          this->ConvergenceAngle, FAS::parameters::use_parallelism(true)))));

  FAS::Growth_report grown;
  FAS::Alignment_report aligned;
  std::size_t iterations = 0;
  std::vector<double> growth_step(input_vertices, 0.);
  // Progress per growth step; Abort (AbortExecute) stops before the next one, keeping the
  // steps done.
  int done = 0;
  for (int step = 1; step <= this->NumberOfGrowthSteps; ++step)
  {
    if (this->GetAbortExecute())
    {
      abort_handled(this);
      vtkWarningMacro(<< "Grow Boundary: cancelled after growth step " << done << " of "
                      << this->NumberOfGrowthSteps << "; the output shows the surface grown so far");
      break;
    }
    FAS::Growth_report r;
    if (this->GrowthMode == ACROSS_FLOW)
      r = deformation.grow(distance, FAS::parameters::across_flow(true));
    else if (this->GrowthMode == DIRECTION)
      r = deformation.grow(distance,
        FAS::parameters::growth_direction(
          Vector(this->GrowthDirection[0], this->GrowthDirection[1], this->GrowthDirection[2])));
    else
      r = deformation.grow(distance);
    grown.number_of_new_vertices += r.number_of_new_vertices;
    grown.number_of_new_faces += r.number_of_new_faces;
    grown.number_of_grown_edges += r.number_of_grown_edges;
    grown.grown_boundary_length += r.grown_boundary_length;
    grown.added_area += r.added_area;
    growth_step.resize(tm.number_of_vertices(), double(step));
    aligned = iterate(deformation, field, std::size_t(this->NumberOfIterations));
    iterations += aligned.number_of_iterations;
    done = step;
    this->UpdateProgress(double(step) / double(this->NumberOfGrowthSteps));
  }

  const auto [result, flux] = aligned_surface_output(tm, field);
  auto step_array = make_array("growth_step", 1, vtkIdType(growth_step.size()));
  for (std::size_t i = 0; i < growth_step.size(); ++i)
    step_array->SetValue(vtkIdType(i), growth_step[i]);
  result->GetPointData()->AddArray(step_array);
  add_field_value(result, "distance", distance);
  add_field_value(result, "number_of_iterations", double(iterations));
  add_field_value(result, "converged", aligned.converged ? 1. : 0.);
  add_field_value(result, "max_rotation_angle", aligned.max_rotation_angle);
  add_field_value(result, "number_of_factorizations", double(deformation.number_of_factorizations()));
  add_field_value(result, "number_of_new_vertices", double(grown.number_of_new_vertices));
  add_field_value(result, "number_of_new_faces", double(grown.number_of_new_faces));
  add_field_value(result, "number_of_grown_edges", double(grown.number_of_grown_edges));
  add_field_value(result, "grown_boundary_length", grown.grown_boundary_length);
  add_field_value(result, "added_area", grown.added_area);
  add_distribution_values(result, pieces, field);
  if (const std::string warning = unsampled_area_warning(flux); !warning.empty())
    vtkWarningMacro(<< "Grow Boundary: " << warning);
  vtkPolyData::GetData(outputVector, 0)->ShallowCopy(result);
  return true;
}

void vtkGrowBoundary::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Distance: " << this->Distance << "\n";
  os << indent << "GrowthMode: " << this->GrowthMode << "\n";
  os << indent << "GrowthDirection: " << this->GrowthDirection[0] << " " << this->GrowthDirection[1]
     << " " << this->GrowthDirection[2] << "\n";
  os << indent << "NumberOfGrowthSteps: " << this->NumberOfGrowthSteps << "\n";
  os << indent << "Alignment: " << this->Alignment << "\n";
  os << indent << "MaxRotationAngle: " << this->MaxRotationAngle << "\n";
  os << indent << "MaxDihedralAngle: " << this->MaxDihedralAngle << "\n";
  os << indent << "ConvergenceAngle: " << this->ConvergenceAngle << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
}
