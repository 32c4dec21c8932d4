// Grow Boundary: grows an aligned surface at its boundary and re-aligns it to the flow
// (Section 4 of Martinez Esturo et al., "Poisson-based Tools for Flow Visualization", 2013):
// Flow_aligned_deformation::grow() on the input surface, then iterations.
#ifndef vtkGrowBoundary_h
#define vtkGrowBoundary_h

#include "FlowAlignedSurfacesFiltersModule.h"
#include "vtkFlowAlignedFilter.h"

/// Input port 0: any data set with a 3-component point or cell array (the velocity, chosen with
/// `SetInputArrayToProcess(0, ...)`).  Input port 1: a triangulated surface with a boundary,
/// typically Flow-Aligned Surface's output; it is the reference mesh M0 of a new deformation.
/// Each of NumberOfGrowthSteps steps grows the boundary by Distance (0: a tenth of the surface's
/// largest extent; all of it, the edges across
/// the flow, or the edges facing GrowthDirection) and iterates the alignment up to
/// NumberOfIterations times (until converged).
///
/// Output: the grown surface (the input's points first, in their order, then the new ones) with
/// the arrays of Flow-Aligned Surface (point data `velocity`, `velocity_sampled`; cell data
/// `normalized_flux`; field data `normalized_flux`, `sampled_area_fraction`, `converged`,
/// `max_rotation_angle`, `number_of_factorizations`), point data `growth_step` (0 for the
/// input's points, k for those added by the k-th growth), and field data of the growth summed
/// over the steps: `number_of_new_vertices`, `number_of_new_faces`, `number_of_grown_edges`,
/// `grown_boundary_length`, `added_area`, and `number_of_iterations`.
///
/// On bad input (no 3-component array, a surface that is closed, not a manifold triangle
/// surface, outside the data, or a growth the library refuses) it reports the library's reason
/// and keeps its previous output.
class FLOWALIGNEDSURFACESFILTERS_EXPORT vtkGrowBoundary : public vtkFlowAlignedFilter
{
public:
  static vtkGrowBoundary* New();
  vtkTypeMacro(vtkGrowBoundary, vtkFlowAlignedFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum GrowthModes
  {
    ALL = 0,
    ACROSS_FLOW = 1,
    DIRECTION = 2
  };
  enum Alignments
  {
    TANGENTIAL = 0,
    ORTHOGONAL = 1
  };

  /// The offset of each growth step, in the surface's tangent plane.
  vtkSetMacro(Distance, double);
  vtkGetMacro(Distance, double);
  /// ALL (the whole boundary), ACROSS_FLOW (the edges whose outward direction is within 60
  /// degrees of across the flow; tangential surfaces only) or DIRECTION (those within 60 degrees
  /// of GrowthDirection).
  vtkSetClampMacro(GrowthMode, int, ALL, DIRECTION);
  vtkGetMacro(GrowthMode, int);
  vtkSetVector3Macro(GrowthDirection, double);
  vtkGetVector3Macro(GrowthDirection, double);
  /// The number of growth steps, each followed by the iterations.
  vtkSetMacro(NumberOfGrowthSteps, int);
  vtkGetMacro(NumberOfGrowthSteps, int);
  /// TANGENTIAL (a stream surface) or ORTHOGONAL (a seeding surface).
  vtkSetClampMacro(Alignment, int, TANGENTIAL, ORTHOGONAL);
  vtkGetMacro(Alignment, int);
  /// eta (0.1), theta_max (pi/2), epsilon (1e-6), as in Flow-Aligned Surface.
  vtkSetMacro(MaxRotationAngle, double);
  vtkGetMacro(MaxRotationAngle, double);
  vtkSetMacro(MaxDihedralAngle, double);
  vtkGetMacro(MaxDihedralAngle, double);
  vtkSetMacro(ConvergenceAngle, double);
  vtkGetMacro(ConvergenceAngle, double);
  /// The largest number of iterations after each growth step (100).
  vtkSetMacro(NumberOfIterations, int);
  vtkGetMacro(NumberOfIterations, int);

protected:
  vtkGrowBoundary();
  ~vtkGrowBoundary() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  const char* GetLabel() override;
  bool Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Distance;
  int GrowthMode;
  double GrowthDirection[3];
  int NumberOfGrowthSteps;
  int Alignment;
  double MaxRotationAngle;
  double MaxDihedralAngle;
  double ConvergenceAngle;
  int NumberOfIterations;

private:
  vtkGrowBoundary(const vtkGrowBoundary&) = delete;
  void operator=(const vtkGrowBoundary&) = delete;
};

#endif
