// An outside application of the package's component VTK: samples a uniform flow stored in a
// vtkImageData through VTK_flow_field_3, aligns a tilted patch tangentially to it (the exact
// answer is a plane containing the flow direction, flux 0), and prints the flux and the VTK it
// runs with.  Returns nonzero when the flux is off.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/VTK_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkVersion.h>

#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 5, 5);
  image->SetOrigin(-1, -1, -1);
  image->SetSpacing(0.5, 0.5, 0.5);
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    velocity->InsertNextTuple3(1, 0.5, 0);
  image->GetPointData()->AddArray(velocity);

  const FAS::VTK_flow_field_3<K> field(image);
  CGAL::Surface_mesh<K::Point_3> tm;
  FAS::make_planar_patch(tm, K::Point_3(0, 0, 0), K::Vector_3(1, 0.2, 0.4), 0.8, 0.8, 300);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, field, FAS::Alignment::TANGENTIAL);
  std::cout << "VTK version: " << vtkVersion::GetVTKVersion() << "\n"
            << "normalized flux after: " << report.normalized_flux.value.value_or(-1) << "\n";
  return report.normalized_flux.value && *report.normalized_flux.value < 1e-3 ? 0 : 1;
}
