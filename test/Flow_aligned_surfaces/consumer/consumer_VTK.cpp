// An outside application of the package's component VTK: samples a uniform flow stored in a
// vtkImageData through VTK_flow_field_3 on a tilted planar patch inside the image, and prints the
// patch's normalized flux (exact: |n.v| / (|n| |v|), every face sampled) and the VTK it runs with.
// Returns nonzero when the flux is off.
// It measures rather than aligns: consumer.cpp already has GCC compile the alignment, and
// test_VTK_flow_field_3.cpp deforms a surface over a VTK_flow_field_3; a second instance of the
// deformation here would take two thirds of this program's compile time for no other check.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/VTK_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Surface_mesh.h>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkVersion.h>

#include <cmath>
#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  const K::Vector_3 flow(1, 0.5, 0), normal(1, 0.2, 0.4);
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 5, 5);
  image->SetOrigin(-1, -1, -1);
  image->SetSpacing(0.5, 0.5, 0.5);
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    velocity->InsertNextTuple3(flow.x(), flow.y(), flow.z());
  image->GetPointData()->AddArray(velocity);

  const FAS::VTK_flow_field_3<K> field(image);
  CGAL::Surface_mesh<K::Point_3> tm;
  FAS::make_planar_patch(tm, K::Point_3(0, 0, 0), normal, 0.8, 0.8, 300);
  const FAS::Normalized_flux flux = FAS::normalized_flux(tm, field);
  const double exact = std::abs(normal * flow) / std::sqrt(normal.squared_length() * flow.squared_length());
  std::cout << "VTK version: " << vtkVersion::GetVTKVersion() << "\n"
            << "normalized flux: " << flux << " (exact: " << exact << ")\n";
  return flux.value && std::abs(*flux.value - exact) < 1e-6 && flux.sampled_area_fraction > 1 - 1e-9 ? 0 : 1;
}
