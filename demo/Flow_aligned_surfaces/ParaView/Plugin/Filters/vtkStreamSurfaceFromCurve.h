// Stream Surface from Curve: the stream surface of the input data set's flow seeded by every
// line and polyline of a second input (the seed curves of Parametrize And Seed, ParaView's Line
// source, a contour, ...), integrated by the package's advancing front
// (integrate_stream_surface.h).
#ifndef vtkStreamSurfaceFromCurve_h
#define vtkStreamSurfaceFromCurve_h

#include "FlowAlignedSurfacesFiltersModule.h"
#include "vtkFlowAlignedFilter.h"

/// Input port 0: any data set with a 3-component point or cell array (the velocity, chosen with
/// `SetInputArrayToProcess(0, ...)`).  Input port 1: polygonal data whose lines and polylines
/// are the seed curves.  Output: the stream surfaces as triangles, one per seed curve, with
/// point data `u` (the seed parameter: arc length along the seed curve), `t` and
/// `IntegrationTime` (the time-line parameter tau: integration time, or arc length with
/// ArcLengthTimeLines; negative on the backward half of a BOTH surface), `seed_curve` and `SeedIds` (the
/// index of the seed curve); field data with one tuple per seed curve: `termination` and
/// `termination_message` (why the integration stopped; with BOTH, of the forward half, and
/// `backward_termination`, `backward_termination_message` of the backward half),
/// `number_of_time_lines`, `final_parameter`, `seed_length`, `front_spacing`, `time_line_step`,
/// `number_of_tears`, `number_of_lost_particles`.
///
/// A parameter at 0 takes the library's default (FrontSpacing, TimeLineStep,
/// MaxNumberOfTimeLines) or no limit (MaxTime, MaxLength).
///
/// On bad input (no 3-component array, no seed line, a seed curve the library refuses, no seed
/// curve inside the data) it reports the error and keeps its previous output.
class FLOWALIGNEDSURFACESFILTERS_EXPORT vtkStreamSurfaceFromCurve : public vtkFlowAlignedFilter
{
public:
  static vtkStreamSurfaceFromCurve* New();
  vtkTypeMacro(vtkStreamSurfaceFromCurve, vtkFlowAlignedFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Directions
  {
    FORWARD = 0,
    BACKWARD = 1,
    BOTH = 2
  };

  /// FORWARD (along v), BACKWARD (along -v) or BOTH (one surface joined at the seed curve).
  vtkSetClampMacro(IntegrationDirection, int, FORWARD, BOTH);
  vtkGetMacro(IntegrationDirection, int);
  /// h: the largest distance between neighbouring particles of the front; 0: the mean segment
  /// length of each seed curve.
  vtkSetMacro(FrontSpacing, double);
  vtkGetMacro(FrontSpacing, double);
  /// Delta: the step between time lines; 0: h over the median speed at the seed (h with
  /// ArcLengthTimeLines), and thin strips of sheared fronts are left out.
  vtkSetMacro(TimeLineStep, double);
  vtkGetMacro(TimeLineStep, double);
  /// Whether the time-line parameter is the arc length (the field is normalized).
  vtkSetMacro(ArcLengthTimeLines, bool);
  vtkGetMacro(ArcLengthTimeLines, bool);
  vtkBooleanMacro(ArcLengthTimeLines, bool);
  /// The largest integration time (time time lines); 0: no limit.
  vtkSetMacro(MaxTime, double);
  vtkGetMacro(MaxTime, double);
  /// The largest arc length (with ArcLengthTimeLines); 0: no limit.
  vtkSetMacro(MaxLength, double);
  vtkGetMacro(MaxLength, double);
  /// The largest number of time lines per direction; 0: no limit when MaxTime (MaxLength with
  /// ArcLengthTimeLines) is given, else 100.
  vtkSetMacro(MaxNumberOfTimeLines, int);
  vtkGetMacro(MaxNumberOfTimeLines, int);
  /// The largest number of vertices of each surface (1000000).
  vtkSetMacro(MaxNumberOfVertices, int);
  vtkGetMacro(MaxNumberOfVertices, int);
  /// The angle between the flow directions of neighbouring particles above which the front is
  /// refined or torn (radians, pi/4).
  vtkSetMacro(TearAngle, double);
  vtkGetMacro(TearAngle, double);
  /// The Dormand-Prince integrator's relative (1e-10) and absolute (1e-12) tolerances, and its
  /// largest number of steps per particle (100000).
  vtkSetMacro(RelativeTolerance, double);
  vtkGetMacro(RelativeTolerance, double);
  vtkSetMacro(AbsoluteTolerance, double);
  vtkGetMacro(AbsoluteTolerance, double);
  vtkSetMacro(MaxNumberOfSteps, int);
  vtkGetMacro(MaxNumberOfSteps, int);

  enum SurfaceTypes
  {
    STREAM_SURFACE = 0,
    PATH_SURFACE = 1
  };
  /// STREAM_SURFACE: in the flow at the view's time (a temporal input: interpolated between the
  /// two steps around it).  PATH_SURFACE (a temporal input): the seed curve released at
  /// StartTime and integrated forward through the input's time steps up to the view's time (at
  /// most MaxTime after StartTime), so that playing the time grows the surface.
  vtkSetClampMacro(SurfaceType, int, STREAM_SURFACE, PATH_SURFACE);
  vtkGetMacro(SurfaceType, int);
  /// The release time of a path surface, within the input's time range (a time before the
  /// first step releases at the first step).
  vtkSetMacro(StartTime, double);
  vtkGetMacro(StartTime, double);

protected:
  vtkStreamSurfaceFromCurve();
  ~vtkStreamSurfaceFromCurve() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  const char* GetLabel() override;
  bool Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void SelectSteps(vtkInformationVector* outputVector) override;

  int IntegrationDirection;
  double FrontSpacing;
  double TimeLineStep;
  bool ArcLengthTimeLines;
  double MaxTime;
  double MaxLength;
  int MaxNumberOfTimeLines;
  int MaxNumberOfVertices;
  double TearAngle;
  double RelativeTolerance;
  double AbsoluteTolerance;
  int MaxNumberOfSteps;
  int SurfaceType;
  double StartTime;

private:
  // Every property in its range, or std::invalid_argument naming it as the panel does.
  void CheckProperties();
  vtkStreamSurfaceFromCurve(const vtkStreamSurfaceFromCurve&) = delete;
  void operator=(const vtkStreamSurfaceFromCurve&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
