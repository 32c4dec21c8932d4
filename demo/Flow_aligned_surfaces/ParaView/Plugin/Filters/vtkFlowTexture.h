// Flow Texture: texture coordinates that make a texture follow the flow on a stream surface,
// the mask b(gamma) that fades it where the parametrization does not follow the flow, and the
// LIC-like noise (or arrow) texture itself; Section 6 of Martinez Esturo et al.,
// "Poisson-based Tools for Flow Visualization" (2013).
#ifndef vtkFlowTexture_h
#define vtkFlowTexture_h

#include "FlowAlignedSurfacesFiltersModule.h"
#include "vtkFlowAlignedFilter.h"

/// Input port 0: any data set with a 3-component point or cell array (the velocity, chosen with
/// `SetInputArrayToProcess(0, ...)`); input port 1: a triangulated surface, ideally a stream
/// surface (the tangential output of vtkFlowAlignedSurface).
///
/// Output port 0: the surface with the point arrays `r`, `s` (the unnormalized tangential
/// parametrization) and `texture_coordinates` = (r Scale + Offset, s Scale) (Scale 0: three
/// repeats along the flow over the surface, `flow_texture_scale()`), which is the point data's
/// TCoords (ParaView's texture mapping uses it), and the cell array `texture_mask`, the
/// mask b(gamma) in [0, 1] per face (0: the texture follows the flow, 1: show the texture's mean
/// colour).  Output port 1: the texture, an RGB image (unsigned char) of TextureWidth x
/// TextureHeight texels whose x axis runs along the flow once mapped.
///
/// On bad input (no 3-component array, no triangles on port 1, a surface outside the data) it
/// reports the error and keeps its previous outputs.
class FLOWALIGNEDSURFACESFILTERS_EXPORT vtkFlowTexture : public vtkFlowAlignedFilter
{
public:
  static vtkFlowTexture* New();
  vtkTypeMacro(vtkFlowTexture, vtkFlowAlignedFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Textures
  {
    NOISE = 0,
    ARROWS = 1
  };

  /// The surface (input port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// Texture repeats per unit of r and s (finite, not zero).
  vtkSetMacro(Scale, double);
  vtkGetMacro(Scale, double);
  /// Added to u: increase it from frame to frame to move the texture along the flow.
  vtkSetMacro(Offset, double);
  vtkGetMacro(Offset, double);
  /// Faces slower than this fraction of the fastest face are masked too (in [0, 1]).
  vtkSetMacro(MinRelativeSpeed, double);
  vtkGetMacro(MinRelativeSpeed, double);
  /// NOISE (filtered along x) or ARROWS (pointing along x).
  vtkSetClampMacro(Texture, int, NOISE, ARROWS);
  vtkGetMacro(Texture, int);
  vtkSetMacro(TextureWidth, int);
  vtkGetMacro(TextureWidth, int);
  vtkSetMacro(TextureHeight, int);
  vtkGetMacro(TextureHeight, int);
  /// Noise: the length of the box filter along x, in texels, in [1, TextureWidth].
  vtkSetMacro(FilterLength, double);
  vtkGetMacro(FilterLength, double);
  /// Noise: the seed of the noise.
  vtkSetMacro(NoiseSeed, int);
  vtkGetMacro(NoiseSeed, int);
  /// Arrows: the number of arrows per tile along x and across (y).
  vtkSetMacro(ArrowsAlong, int);
  vtkGetMacro(ArrowsAlong, int);
  vtkSetMacro(ArrowsAcross, int);
  vtkGetMacro(ArrowsAcross, int);
  /// Whether the surface is a path surface of vtkStreamSurfaceFromCurve (point array `t`, field
  /// data `start_time`) on a temporal input: the texture then follows its path lines, the flow at
  /// the time start_time + t at which the surface passed each point (Path_surface_flow_field_3),
  /// and the filter asks for the input's steps from the first one to the view's time.
  vtkSetMacro(PathSurface, bool);
  vtkGetMacro(PathSurface, bool);
  vtkBooleanMacro(PathSurface, bool);

protected:
  vtkFlowTexture();
  ~vtkFlowTexture() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  const char* GetLabel() override;
  bool Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void SelectSteps(vtkInformationVector* outputVector) override;
  void FillOtherRankOutputs(vtkInformationVector* outputVector) override;
  void AfterFailure(vtkInformationVector* outputVector, bool kept) override;

  double Scale;
  double Offset;
  double MinRelativeSpeed;
  int Texture;
  int TextureWidth;
  int TextureHeight;
  double FilterLength;
  int NoiseSeed;
  int ArrowsAlong;
  int ArrowsAcross;
  bool PathSurface;

private:
  vtkFlowTexture(const vtkFlowTexture&) = delete;
  void operator=(const vtkFlowTexture&) = delete;
};

#endif
