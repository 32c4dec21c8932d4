// Parametrize and Seed: the Poisson parametrizations of a surface in the flow (tangential,
// orthogonal, or circular = geodesic distance), their iso-contours as seed curves and evenly
// spread seed points; Section 5 of Martinez Esturo et al., "Poisson-based Tools for Flow
// Visualization" (2013).
#ifndef vtkFlowAlignedParametrize_h
#define vtkFlowAlignedParametrize_h

#include "FlowAlignedSurfacesFiltersModule.h"
#include "vtkFlowAlignedFilter.h"

/// Input port 0: any data set with a 3-component point or cell array (the velocity, chosen with
/// `SetInputArrayToProcess(0, ...)`); input port 1: a triangulated surface (for instance the
/// output of vtkFlowAlignedSurface).
///
/// Output port 0: the surface with the point arrays `r` and `s` (tangential, orthogonal) or
/// `geodesic_distance` (circular; field data `source_point_id`).  Output port 1: the
/// iso-contours of `r` (or of the distance) at NumberOfSeedCurves values evenly spaced inside its
/// range, as polylines with the iso-value as point and cell array of the same name.  Output
/// port 2: seed points on the surface, no two closer than SeedPointSpacing (vertex cells; 0: a
/// twentieth of the surface's largest extent).
///
/// On bad input (no 3-component array, no triangles on port 1, a surface outside the data) it
/// reports the error and keeps its previous outputs.
class FLOWALIGNEDSURFACESFILTERS_EXPORT vtkFlowAlignedParametrize : public vtkFlowAlignedFilter
{
public:
  static vtkFlowAlignedParametrize* New();
  vtkTypeMacro(vtkFlowAlignedParametrize, vtkFlowAlignedFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Parametrizations
  {
    TANGENTIAL = 0,
    ORTHOGONAL = 1,
    CIRCULAR = 2
  };
  enum Normalizations
  {
    LIBRARY_DEFAULT = 0, // tangential normalized, orthogonal not
    NORMALIZED = 1,
    UNNORMALIZED = 2
  };

  /// The surface (input port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// TANGENTIAL, ORTHOGONAL or CIRCULAR.
  vtkSetClampMacro(Parametrization, int, TANGENTIAL, CIRCULAR);
  vtkGetMacro(Parametrization, int);
  /// Whether the guidance field is normalized per face (tangential, orthogonal).
  vtkSetClampMacro(Normalization, int, LIBRARY_DEFAULT, UNNORMALIZED);
  vtkGetMacro(Normalization, int);
  /// alpha of the orthogonal parametrization (radians).
  vtkSetMacro(Angle, double);
  vtkGetMacro(Angle, double);
  /// Circular: the distance is measured from the vertex nearest to SourcePoint, or to the
  /// surface's area-weighted centroid when SourceAtCentroid is on.
  vtkSetVector3Macro(SourcePoint, double);
  vtkGetVector3Macro(SourcePoint, double);
  vtkSetMacro(SourceAtCentroid, vtkTypeBool);
  vtkGetMacro(SourceAtCentroid, vtkTypeBool);
  vtkBooleanMacro(SourceAtCentroid, vtkTypeBool);
  /// Circular: the heat method on the intrinsic Delaunay triangulation (on) or on the surface's
  /// own triangles (off).
  vtkSetMacro(IntrinsicDelaunay, vtkTypeBool);
  vtkGetMacro(IntrinsicDelaunay, vtkTypeBool);
  vtkBooleanMacro(IntrinsicDelaunay, vtkTypeBool);
  /// The number of iso-contours (seed curves); 0 for none.
  vtkSetMacro(NumberOfSeedCurves, int);
  vtkGetMacro(NumberOfSeedCurves, int);
  /// The smallest distance between two seed points; 0 for no seed points.
  vtkSetMacro(SeedPointSpacing, double);
  vtkGetMacro(SeedPointSpacing, double);
  /// The seed of the random generator of the seed points.
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);

protected:
  vtkFlowAlignedParametrize();
  ~vtkFlowAlignedParametrize() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  const char* GetLabel() override;
  bool Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Parametrization;
  int Normalization;
  double Angle;
  double SourcePoint[3];
  vtkTypeBool SourceAtCentroid;
  vtkTypeBool IntrinsicDelaunay;
  int NumberOfSeedCurves;
  double SeedPointSpacing;
  int RandomSeed;

private:
  vtkFlowAlignedParametrize(const vtkFlowAlignedParametrize&) = delete;
  void operator=(const vtkFlowAlignedParametrize&) = delete;
};

#endif
