#include "vtkFlowAlignedParametrize.h"

#include "fas_flow_state.h"
#include "fas_paraview_surface_input.h"

#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <functional>
#include <tuple>
#include <utility>

using namespace fas_paraview;

vtkStandardNewMacro(vtkFlowAlignedParametrize);

namespace {

using Vertex = Mesh::Vertex_index;
using Scalar_map = Mesh::Property_map<Vertex, double>;

// The area-weighted centroid of the triangles of `tm`.
Point area_centroid(const Mesh& tm)
{
  Vector sum = CGAL::NULL_VECTOR;
  double area = 0;
  for (Mesh::Face_index f : tm.faces()) {
    const auto h = tm.halfedge(f);
    const Point &a = tm.point(tm.source(h)), &b = tm.point(tm.target(h)),
                &c = tm.point(tm.target(tm.next(h)));
    const double w = std::sqrt(CGAL::cross_product(b - a, c - a).squared_length()) / 2;
    sum = sum + w * (CGAL::centroid(a, b, c) - CGAL::ORIGIN);
    area += w;
  }
  return CGAL::ORIGIN + sum / area;
}

// The vertex of `tm` nearest to `p` (the first one of equal distance).
Vertex nearest_vertex(const Mesh& tm, const Point& p)
{
  Vertex nearest;
  double best = std::numeric_limits<double>::infinity();
  for (Vertex v : tm.vertices())
    if (const double d = CGAL::squared_distance(tm.point(v), p); d < best) {
      best = d;
      nearest = v;
    }
  return nearest;
}

// The named parameters of the guidance's normalization: none (the library's default) or
// normalized(yes).
template <class Call>
bool with_normalization(int normalization, const std::function<bool(double)>& progress, const Call& call)
{
  const auto base = CGAL::parameters::callback(progress);
  if (normalization == vtkFlowAlignedParametrize::LIBRARY_DEFAULT)
    return call(base);
  return call(FAS::parameters::normalized(normalization == vtkFlowAlignedParametrize::NORMALIZED, base));
}

// The iso-contours of `f` at `n` evenly spaced values, as polylines with the value as point and
// cell array `name`.
vtkSmartPointer<vtkPolyData> iso_contours(const Mesh& tm, Scalar_map f, std::size_t n, const char* name)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  std::vector<double> point_values, cell_values;
  for (double value : FAS::evenly_spaced_iso_values(tm, f, n)) {
    std::vector<Polyline> polylines;
    FAS::extract_iso_contours(tm, f, std::vector<double>{value}, std::back_inserter(polylines));
    for (const Polyline& polyline : polylines) {
      lines->InsertNextCell(vtkIdType(polyline.size()));
      for (const Point& p : polyline) {
        lines->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
        point_values.push_back(value);
      }
      cell_values.push_back(value);
    }
  }
  auto curves = vtkSmartPointer<vtkPolyData>::New();
  curves->SetPoints(points);
  curves->SetLines(lines);
  auto point_array = make_array(name, 1, vtkIdType(point_values.size()));
  for (std::size_t i = 0; i < point_values.size(); ++i)
    point_array->SetValue(vtkIdType(i), point_values[i]);
  auto cell_array = make_array(name, 1, vtkIdType(cell_values.size()));
  for (std::size_t i = 0; i < cell_values.size(); ++i)
    cell_array->SetValue(vtkIdType(i), cell_values[i]);
  curves->GetPointData()->AddArray(point_array);
  curves->GetPointData()->SetActiveScalars(name);
  curves->GetCellData()->AddArray(cell_array);
  return curves;
}

// Points as vertex cells.
vtkSmartPointer<vtkPolyData> point_cloud(const std::vector<Point>& seeds)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (const Point& p : seeds) {
    const vtkIdType id = points->InsertNextPoint(p.x(), p.y(), p.z());
    verts->InsertNextCell(1, &id);
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->SetVerts(verts);
  return cloud;
}

} // namespace

vtkFlowAlignedParametrize::vtkFlowAlignedParametrize()
  : Parametrization(TANGENTIAL)
  , Normalization(LIBRARY_DEFAULT)
  , Angle(0)
  , SourcePoint{ 0, 0, 0 }
  , SourceAtCentroid(1)
  , IntrinsicDelaunay(1)
  , NumberOfSeedCurves(10)
  , SeedPointSpacing(0)
  , RandomSeed(0)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::VECTORS);
}

vtkFlowAlignedParametrize::~vtkFlowAlignedParametrize() = default;

int vtkFlowAlignedParametrize::FillInputPortInformation(int port, vtkInformation* info)
{
  return fill_surface_filter_input_port(port, info);
}

const char* vtkFlowAlignedParametrize::GetLabel()
{
  return "Parametrize And Seed";
}

bool vtkFlowAlignedParametrize::Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  FlowState& in = *this->Flow;
  const Distributed_input& pieces = in.pieces;
  const vtkSmartPointer<vtkPolyData>& input_surface = in.gathered;
  require_property(std::isfinite(this->Angle), "Angle", this->Angle, "finite (radians)");
  require_property(this->NumberOfSeedCurves >= 0 && this->NumberOfSeedCurves <= 100000, "Number Of Seed Curves",
                   this->NumberOfSeedCurves, "from 0 to 100,000");
  require_property(this->SeedPointSpacing >= 0, "Seed Point Spacing", this->SeedPointSpacing,
                   ">= 0 (0: a twentieth of the surface's largest extent)");
  require_property(this->RandomSeed >= 0, "Random Seed", this->RandomSeed, ">= 0");
  Mesh tm = surface_mesh(input_surface);
  // Progress per stage of the parametrization; Abort (AbortExecute) stops before the next stage.
  const std::function<bool(double)> progress = [this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  };
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(input_surface);
  const char* contoured = "r";
  Scalar_map f;
  if (this->Parametrization == CIRCULAR)
  {
    const Point source = this->SourceAtCentroid
      ? area_centroid(tm)
      : Point(this->SourcePoint[0], this->SourcePoint[1], this->SourcePoint[2]);
    const Vertex source_vertex = nearest_vertex(tm, source);
    f = tm.add_property_map<Vertex, double>("v:distance", 0.).first;
    if (!FAS::compute_geodesic_distance(tm, source_vertex, f,
          FAS::parameters::intrinsic_delaunay(this->IntrinsicDelaunay != 0, CGAL::parameters::callback(progress))))
      return this->CancelledBeforeParametrization(outputVector);
    contoured = "geodesic_distance";
    add_vertex_array(surface, tm, contoured, 1, [&](Vertex v) { return f[v]; });
    add_field_value(surface, "source_point_id", double(source_vertex.idx()));
  }
  else
  {
    pieces.require_samples();
    // The parameters along and across the flow (on several ranks the library's batch of face
    // samples is one exchange).
    const auto parametrize = [&](Mesh& m, const std::function<bool(double)>& report) {
      Scalar_map r = m.add_property_map<Vertex, double>("v:r", 0.).first;
      Scalar_map s = m.add_property_map<Vertex, double>("v:s", 0.).first;
      const bool done = this->Parametrization == ORTHOGONAL
        ? with_normalization(this->Normalization, report, [&](const auto& np) {
            return FAS::parametrize_orthogonal(m, in.field, r, s, FAS::parameters::angle(this->Angle, np));
          })
        : with_normalization(this->Normalization, report,
            [&](const auto& np) { return FAS::parametrize_tangential(m, in.field, r, s, np); });
      return std::make_tuple(done, r, s);
    };
    Scalar_map s;
    bool done = false;
    std::tie(done, f, s) = parametrize(tm, progress);
    if (!done)
      return this->CancelledBeforeParametrization(outputVector);
    add_vertex_array(surface, tm, "r", 1, [&](Vertex v) { return f[v]; });
    add_vertex_array(surface, tm, "s", 1, [&](Vertex v) { return s[v]; });
  }
  surface->GetPointData()->SetActiveScalars(contoured);
  add_distribution_values(surface, pieces, in.field);

  vtkSmartPointer<vtkPolyData> curves =
    iso_contours(tm, f, std::size_t(this->NumberOfSeedCurves), contoured);
  // Spacing 0: a twentieth of the surface's largest extent, taken when the filter runs (the
  // surface has no bounds yet when a script creates the filter).
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
  const double spacing = this->SeedPointSpacing > 0
    ? this->SeedPointSpacing
    : 0.05 * std::max({ box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin() });
  std::vector<Point> seeds;
  FAS::sample_seed_points(tm, spacing, std::back_inserter(seeds),
    CGAL::parameters::random_seed(unsigned(this->RandomSeed)));

  vtkPolyData::GetData(outputVector, 0)->ShallowCopy(surface);
  vtkPolyData::GetData(outputVector, 1)->ShallowCopy(curves);
  vtkPolyData::GetData(outputVector, 2)->ShallowCopy(point_cloud(seeds));
  return true;
}

void vtkFlowAlignedParametrize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Parametrization: " << this->Parametrization << "\n";
  os << indent << "Normalization: " << this->Normalization << "\n";
  os << indent << "Angle: " << this->Angle << "\n";
  os << indent << "SourcePoint: " << this->SourcePoint[0] << " " << this->SourcePoint[1] << " "
     << this->SourcePoint[2] << "\n";
  os << indent << "SourceAtCentroid: " << this->SourceAtCentroid << "\n";
  os << indent << "IntrinsicDelaunay: " << this->IntrinsicDelaunay << "\n";
  os << indent << "NumberOfSeedCurves: " << this->NumberOfSeedCurves << "\n";
  os << indent << "SeedPointSpacing: " << this->SeedPointSpacing << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
}
