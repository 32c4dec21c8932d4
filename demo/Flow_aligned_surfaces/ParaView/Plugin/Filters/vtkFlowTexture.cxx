#include "vtkFlowTexture.h"

#include "fas_flow_state.h"
#include "fas_paraview_surface_input.h"

#include <CGAL/Flow_aligned_surfaces/Path_surface_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>

#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <tuple>

using namespace fas_paraview;

vtkStandardNewMacro(vtkFlowTexture);

namespace {

using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;

// The texture as an RGB image of unsigned chars (texel (x, y) is point y * width + x, as in
// Texture_image), each channel round(255 c).
vtkSmartPointer<vtkImageData> to_image(const FAS::Texture_image& texture)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(int(texture.width), int(texture.height), 1);
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetName("texture");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(vtkIdType(texture.width * texture.height));
  for (std::size_t i = 0; i < texture.pixels.size(); ++i)
    rgb->SetValue(vtkIdType(i),
      (unsigned char)std::lround(255 * std::clamp(double(texture.pixels[i]), 0., 1.)));
  image->GetPointData()->SetScalars(rgb);
  return image;
}

// The texture chosen by the filter's properties.
FAS::Texture_image make_texture(vtkFlowTexture* filter)
{
  const auto width = std::size_t(filter->GetTextureWidth()), height = std::size_t(filter->GetTextureHeight());
  return filter->GetTexture() == vtkFlowTexture::ARROWS
    ? FAS::make_arrow_texture(width, height, std::size_t(filter->GetArrowsAlong()),
        std::size_t(filter->GetArrowsAcross()))
    : FAS::make_noise_texture(width, height, filter->GetFilterLength(), std::uint32_t(filter->GetNoiseSeed()));
}


// The time at which a path surface of Stream Surface From Curve passed each of its points:
// start_time (field data) + t (point data).  \throws std::invalid_argument naming what is missing.
std::vector<double> path_surface_times(vtkPolyData* surface, const Temporal_flow_input& steps)
{
  if (!steps.temporal())
    throw std::invalid_argument("Path Surface is on, but the Input has no time steps (a steady flow: turn it off)");
  vtkDataArray* start = surface != nullptr ? surface->GetFieldData()->GetArray("start_time") : nullptr;
  vtkDataArray* t = surface != nullptr ? surface->GetPointData()->GetArray("t") : nullptr;
  if (start == nullptr || t == nullptr || t->GetNumberOfTuples() != surface->GetNumberOfPoints())
    throw std::invalid_argument("Path Surface is on, but the Surface input (port 1) has no field data start_time "
                                "and point array t: give it the output of Stream Surface From Curve with Surface "
                                "Type Path Surface");
  std::vector<double> times(std::size_t(t->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
    times[std::size_t(i)] = start->GetComponent(0, 0) + t->GetComponent(i, 0);
  return times;
}

} // namespace

// The texture does not depend on the flow: every rank gives the part of it that it is asked for
// (ParaView asks each rank for a piece of an image output).
static vtkSmartPointer<vtkImageData> texture_piece(vtkFlowTexture* filter, vtkInformationVector* outputVector)
{
  vtkSmartPointer<vtkImageData> image = to_image(make_texture(filter));
  vtkInformation* info = outputVector->GetInformationObject(1);
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
    image->Crop(info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()));
  return image;
}

vtkFlowTexture::vtkFlowTexture()
  : Scale(0)
  , Offset(0)
  , MinRelativeSpeed(0)
  , Texture(NOISE)
  , TextureWidth(128)
  , TextureHeight(128)
  , FilterLength(24)
  , NoiseSeed(0)
  , ArrowsAlong(4)
  , ArrowsAcross(4)
  , PathSurface(false)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::VECTORS);
}

vtkFlowTexture::~vtkFlowTexture() = default;

int vtkFlowTexture::FillInputPortInformation(int port, vtkInformation* info)
{
  return fill_surface_filter_input_port(port, info);
}

int vtkFlowTexture::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkImageData");
  return 1;
}

const char* vtkFlowTexture::GetLabel()
{
  return "Flow Texture";
}

int vtkFlowTexture::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestInformation(request, inputVector, outputVector);
  // The texture is one whole image.
  const int extent[6] = { 0, this->TextureWidth - 1, 0, this->TextureHeight - 1, 0, 0 };
  vtkInformation* info = outputVector->GetInformationObject(1);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

void vtkFlowTexture::SelectSteps(vtkInformationVector* outputVector)
{
  // The flow at the view's time; along a path surface, from the first step to it.
  const Temporal_flow_input& steps = this->Flow->steps;
  this->Flow->needed.clear();
  if (!steps.temporal())
    return;
  const double t = steps.requested_time(outputVector->GetInformationObject(0));
  this->Flow->needed =
    this->PathSurface ? steps.steps_between(steps.times().front(), t) : steps.steps_around(t);
}

void vtkFlowTexture::FillOtherRankOutputs(vtkInformationVector* outputVector)
{
  try
  {
    vtkImageData::GetData(outputVector, 1)->ShallowCopy(texture_piece(this, outputVector));
  }
  catch (const std::exception&)
  {
    // rank 0 reports what is wrong with the properties
  }
}

void vtkFlowTexture::AfterFailure(vtkInformationVector* outputVector, bool kept)
{
  // Without an earlier output the texture is given all the same (it does not depend on the
  // flow): an empty image would not have the extent the pipeline asked for, a second error.
  if (!kept)
    try
    {
      vtkImageData::GetData(outputVector, 1)->ShallowCopy(texture_piece(this, outputVector));
    }
    catch (const std::exception&)
    {
      // a property of the texture itself is wrong: said above
    }
}

bool vtkFlowTexture::Compute(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  FlowState& in = *this->Flow;
  const Distributed_input& pieces = in.pieces;
  const vtkSmartPointer<vtkPolyData>& input_surface = in.gathered;
  const auto texture_piece = [this, outputVector] { return ::texture_piece(this, outputVector); };
  require_property(std::isfinite(this->Scale), "Scale", this->Scale, "finite (0: three repeats over the surface)");
  require_property(std::isfinite(this->Offset), "Offset", this->Offset, "finite");
  require_property(this->MinRelativeSpeed >= 0 && this->MinRelativeSpeed <= 1, "Min Relative Speed",
                   this->MinRelativeSpeed, "in [0, 1]");
  require_property(this->TextureWidth >= 1 && this->TextureWidth <= 16384, "Texture Width", this->TextureWidth,
                   "from 1 to 16,384 texels");
  require_property(this->TextureHeight >= 1 && this->TextureHeight <= 16384, "Texture Height",
                   this->TextureHeight, "from 1 to 16,384 texels");
  require_property(this->NoiseSeed >= 0, "Noise Seed", this->NoiseSeed, ">= 0");
  require_property(this->ArrowsAlong >= 1 && this->ArrowsAlong <= 4096, "Arrows Along", this->ArrowsAlong,
                   "from 1 to 4,096");
  require_property(this->ArrowsAcross >= 1 && this->ArrowsAcross <= 4096, "Arrows Across", this->ArrowsAcross,
                   "from 1 to 4,096");
  pieces.require_samples();
  if (this->PathSurface && input_surface != nullptr && input_surface->GetNumberOfCells() == 0)
  {
    // A path surface at its release time has no face yet: nothing to texture, nothing wrong.
    vtkPolyData::GetData(outputVector, 0)->ShallowCopy(input_surface);
    vtkImageData::GetData(outputVector, 1)->ShallowCopy(texture_piece());
    return true;
  }
  Mesh tm = surface_mesh(input_surface);
  // The parameter r along the flow and the mask b(gamma) (on several ranks each is one
  // exchange: the library asks for its face samples in one batch).
  const std::vector<double> path_times = this->PathSurface ? path_surface_times(input_surface, in.steps) : std::vector<double>();
  // Progress per stage of the parametrization; Abort (AbortExecute) stops before the next stage.
  const std::function<bool(double)> progress = [this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  };
  const auto parametrize_and_mask = [&](Mesh& m) {
    auto r = m.add_property_map<Vertex, double>("v:r", 0.).first;
    auto s = m.add_property_map<Vertex, double>("v:s", 0.).first;
    auto mask = m.add_property_map<Face, double>("f:mask", 1.).first;
    bool done = false;
    const auto in_flow = [&](const auto& field) {
      done = FAS::parametrize_tangential(
        m, field, r, s, FAS::parameters::normalized(false, CGAL::parameters::callback(progress)));
      if (done)
        FAS::compute_flow_texture_mask(m, field, r, mask, FAS::parameters::min_relative_speed(this->MinRelativeSpeed));
    };
    if (this->PathSurface)
    {
      auto time = m.add_property_map<Vertex, double>("v:time", 0.).first;
      for (Vertex v : m.vertices())
        time[v] = path_times[v.idx()];
      in_flow(FAS::Path_surface_flow_field_3<Unsteady_view, Mesh, decltype(time)>(Unsteady_view{ in.field }, m, time));
    }
    else
      in_flow(in.field);
    return std::make_tuple(done, r, s, mask);
  };
  const auto [done, r, s, mask] = parametrize_and_mask(tm);
  if (!done)
    return this->CancelledBeforeParametrization(outputVector);
  auto uv = tm.add_property_map<Vertex, std::array<double, 2>>("v:uv").first;
  // Scale 0: three repeats along the flow over the surface, whatever the flow's speed and the
  // surface's size.
  const double scale = this->Scale == 0 ? FAS::flow_texture_scale(tm, r, 3) : this->Scale;
  FAS::compute_flow_texture_coordinates(tm, r, s, uv, scale, this->Offset);
  const vtkSmartPointer<vtkImageData> texture = texture_piece();

  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(input_surface);
  // The maps by value: C++17 lets no lambda capture a structured binding (clang refuses it).
  add_vertex_array(surface, tm, "r", 1, [r = r](Vertex v) { return r[v]; });
  add_vertex_array(surface, tm, "s", 1, [s = s](Vertex v) { return s[v]; });
  add_vertex_array(surface, tm, "texture_coordinates", 2, [&](Vertex v) { return uv[v]; });
  surface->GetPointData()->SetTCoords(surface->GetPointData()->GetArray("texture_coordinates"));
  auto face_mask = make_array("texture_mask", 1, vtkIdType(tm.number_of_faces()));
  for (Face f : tm.faces())
    face_mask->SetValue(vtkIdType(f.idx()), mask[f]);
  surface->GetCellData()->AddArray(face_mask);
  surface->GetCellData()->SetActiveScalars("texture_mask");
  add_distribution_values(surface, pieces, in.field);

  vtkPolyData::GetData(outputVector, 0)->ShallowCopy(surface);
  vtkImageData::GetData(outputVector, 1)->ShallowCopy(texture);
  return true;
}

void vtkFlowTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "Offset: " << this->Offset << "\n";
  os << indent << "MinRelativeSpeed: " << this->MinRelativeSpeed << "\n";
  os << indent << "Texture: " << this->Texture << "\n";
  os << indent << "TextureWidth: " << this->TextureWidth << "\n";
  os << indent << "TextureHeight: " << this->TextureHeight << "\n";
  os << indent << "FilterLength: " << this->FilterLength << "\n";
  os << indent << "NoiseSeed: " << this->NoiseSeed << "\n";
  os << indent << "ArrowsAlong: " << this->ArrowsAlong << "\n";
  os << indent << "ArrowsAcross: " << this->ArrowsAcross << "\n";
  os << indent << "PathSurface: " << this->PathSurface << "\n";
}
