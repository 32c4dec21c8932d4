// A LIC-like texture on a stream surface (Section 6 of the paper), without integrating any line:
// a patch above a cylinder in the potential flow past it is aligned tangentially, parametrized
// tangentially without normalization (r runs along the flow like a time of flight, s across
// it), and a noise texture streaked along its x axis is mapped at (u, v) = scale * (r, s).
// Faces where grad r leaves the flow get a mask b (blend to the texture's mean colour).  The
// surface is written as OBJ + MTL + PNG, which any renderer shows textured.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/IO/write_textured_OBJ.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>

#include <array>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef Surface_mesh::Vertex_index vertex_descriptor;
typedef Surface_mesh::Face_index face_descriptor;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  const FAS::Cylinder_potential_flow<Kernel> flow(1.0, 1.0); // radius 1 along z, speed 1 along x
  Surface_mesh sm;
  FAS::make_planar_patch(sm, Point_3(0, 2.2, 0), Vector_3(0, 0.25, 1), 2.4, 2.0, 3000);
  FAS::align_to_flow(sm, flow, FAS::Alignment::TANGENTIAL); // a stream surface over the cylinder

  auto r = sm.add_property_map<vertex_descriptor, double>("v:r", 0).first;
  auto s = sm.add_property_map<vertex_descriptor, double>("v:s", 0).first;
  FAS::parametrize_tangential(sm, flow, r, s, FAS::parameters::normalized(false));

  // 0.4 texture repeats per unit of r and s; a larger offset moves the texture along the flow.
  auto uv = sm.add_property_map<vertex_descriptor, std::array<double, 2>>("v:uv").first;
  FAS::compute_flow_texture_coordinates(sm, r, s, uv, 0.4);
  auto mask = sm.add_property_map<face_descriptor, double>("f:mask", 1).first;
  FAS::compute_flow_texture_mask(sm, flow, r, mask);
  double masked = 0;
  for (face_descriptor f : sm.faces())
    masked += mask[f] / double(sm.number_of_faces());
  std::cout << "mean mask " << masked << " (0: the texture follows the flow everywhere)" << std::endl;

  // White noise convolved along x over 24 of 128 texels: streaks along the flow.
  const FAS::Texture_image noise = FAS::make_noise_texture(128, 128, 24, 1);
  std::string error;
  if (!FAS::IO::write_textured_OBJ("noise.obj", sm, uv, noise, FAS::parameters::error_message(&error)))
    std::cerr << error << std::endl; // without libpng the OBJ and MTL are written, not the PNG
  return 0;
}
