// Flow-Aligned Surface: a planar or disk patch placed in the flow of the input data set and
// deformed until it is tangential (a stream surface) or orthogonal (a seeding surface) to it;
// Section 4 of Martinez Esturo et al., "Poisson-based Tools for Flow Visualization" (2013).
#ifndef vtkFlowAlignedSurface_h
#define vtkFlowAlignedSurface_h

#include "FlowAlignedSurfacesFiltersModule.h"
#include "vtkFlowAlignedFilter.h"

class vtkDoubleArray;

/// Input: any data set with a 3-component point or cell array (the velocity, chosen with
/// `SetInputArrayToProcess(0, ...)`).  Output: the surface after the requested iteration.
///
/// A steady input (no time steps): the iterations are the output's time steps 0, 1, ...,
/// NumberOfIterations, so that ParaView's time controls play the deformation; every computed
/// iteration is kept.  A new pose (Center or Normal) restarts the iterations from the patch at
/// that pose with the factorization already computed (a rigid move changes nothing the
/// factorization depends on); only a new patch (shape, size, faces) or new parameters factor
/// again.
///
/// A temporal input (a .pvd, an OpenFOAM case with several times): the output has the data's
/// time steps, so that the time controls play the data, and the surface follows the flow.  It
/// is aligned at the first step (up to NumberOfIterations iterations, or until it converges),
/// then re-aligned at each later step from the surface of the step before (a warm start with
/// the same factorization); between two steps, at the requested time from the surface of the
/// step before, in the flow interpolated linearly in time.  The surface at a time therefore does
/// not depend on how the user came to it: a jump follows the steps in between (the pipeline
/// reads them one after the other), and the steps followed are kept until the input or a
/// property changes.  Field data `time`, `iteration` (the iterations made at that time) and
/// `time_steps_followed_in_update` tell what was done.
///
/// Output arrays: point data `velocity`, `velocity_sampled`; cell data `normalized_flux`
/// (|n.v|/|v| per face, NaN where the field has no sample); field data `normalized_flux` (absent
/// when no face has a sample), `sampled_area_fraction`, `iteration`, `converged`,
/// `max_rotation_angle` and `number_of_factorizations`.
///
/// Defaults that work on the first Apply: when the input's information is requested (ParaView
/// does when the filter is created), the filter places a patch where the main job would
/// (fas_default_patch.h) and offers it through GetCenterInfo(), GetNormalInfo() and
/// GetSizeInfo(), from which ParaView's panel takes the defaults of Center, Normal and Size.
/// Size 0 asks for that placement when the filter runs (for a script whose input had no data yet
/// when the filter was created).
///
/// Progress and Abort: the filter reports its progress per iteration and stops after the
/// iteration in progress when AbortExecute is set (ParaView's Abort button), keeping the
/// iterations computed so far; the next update goes on from there.
///
/// On bad input (a property out of its range, no 3-component array, a patch outside the data, a
/// surface leaving the data) it reports the error, naming the property or the input, and keeps
/// its previous output.
///
/// Under MPI (pvbatch --mpi, pvserver on several processes) with the input spread over the ranks,
/// the surface and its factorization live on rank 0, which outputs it; the other ranks output an
/// empty polydata.  Before every iteration rank 0 probes the face centroids the iteration will
/// sample from every rank's piece in one collective exchange (fas_distributed_field.h), so the
/// surface is the serial one (to rounding where pieces share points).  A rank without cells only
/// contributes no samples; no cells on any rank, or a piece that cannot be sampled, is reported
/// (naming the rank) with the previous output kept.  Then the field data also holds
/// `number_of_ranks`, `number_of_ranks_with_cells`, `number_of_sampling_ranks` (ranks that
/// supplied samples of the output), `iterations_computed` and, when iterations were computed,
/// `exchange_ms_per_iteration` and `step_ms_per_iteration` (see benchmark/.../RESULTS.md,
/// "ParaView plugin under MPI").
class FLOWALIGNEDSURFACESFILTERS_EXPORT vtkFlowAlignedSurface : public vtkFlowAlignedFilter
{
public:
  static vtkFlowAlignedSurface* New();
  vtkTypeMacro(vtkFlowAlignedSurface, vtkFlowAlignedFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum PatchShapes
  {
    PLANAR = 0,
    DISK = 1
  };
  enum Alignments
  {
    TANGENTIAL = 0,
    ORTHOGONAL = 1
  };

  /// The centre of the patch.
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  /// The normal of the patch (need not be unit).
  vtkSetVector3Macro(Normal, double);
  vtkGetVector3Macro(Normal, double);
  /// PLANAR (a square of side Size) or DISK (of diameter Size).
  vtkSetClampMacro(PatchShape, int, PLANAR, DISK);
  vtkGetMacro(PatchShape, int);
  vtkSetMacro(Size, double);
  vtkGetMacro(Size, double);
  /// The number of triangles the patch is built with (approximately).
  /// From 2 to 10^7; a value out of range is reported when the filter runs (never clamped).
  vtkSetMacro(NumberOfFaces, int);
  vtkGetMacro(NumberOfFaces, int);
  /// TANGENTIAL (a stream surface) or ORTHOGONAL (a seeding surface).
  vtkSetClampMacro(Alignment, int, TANGENTIAL, ORTHOGONAL);
  vtkGetMacro(Alignment, int);
  /// eta: the largest rotation per face and iteration (radians), 0.1 as in the paper.
  vtkSetMacro(MaxRotationAngle, double);
  vtkGetMacro(MaxRotationAngle, double);
  /// theta_max: the dihedral angle above which the fold correction acts (radians), pi/2.
  vtkSetMacro(MaxDihedralAngle, double);
  vtkGetMacro(MaxDihedralAngle, double);
  /// epsilon: converged when the largest rotation is below it (radians), 1e-6.
  vtkSetMacro(ConvergenceAngle, double);
  vtkGetMacro(ConvergenceAngle, double);
  /// The number of iterations, and of time steps after the initial patch.
  vtkSetMacro(NumberOfIterations, int);
  vtkGetMacro(NumberOfIterations, int);

  /// The number of factorizations of the Poisson system since this filter was created.
  int GetNumberOfFactorizations();

  /// The default patch for the current input, array and alignment, as ranges for ParaView's
  /// panel: Center and Normal are the minima of their ranges (c, c + extent per component), Size
  /// the middle of its range (0, 2 size); empty arrays while the input has no data.
  vtkDoubleArray* GetCenterInfo();
  vtkDoubleArray* GetNormalInfo();
  vtkDoubleArray* GetSizeInfo();

protected:
  vtkFlowAlignedSurface();
  ~vtkFlowAlignedSurface() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  const char* GetLabel() override;
  bool Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void SelectSteps(vtkInformationVector* outputVector) override;

  double Center[3];
  double Normal[3];
  int PatchShape;
  double Size;
  int NumberOfFaces;
  int Alignment;
  double MaxRotationAngle;
  double MaxDihedralAngle;
  double ConvergenceAngle;
  int NumberOfIterations;

private:
  vtkFlowAlignedSurface(const vtkFlowAlignedSurface&) = delete;
  // Computes the default patch for `input` (when it, the array or the alignment changed).
  void OfferDefaultPatch(vtkInformation* inputInformation);
  void operator=(const vtkFlowAlignedSurface&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
