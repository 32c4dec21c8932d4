// LIC-like textures of a stream surface (Section 6 of the paper): a patch above a cylinder in
// the potential flow past it is aligned tangentially (it becomes a stream surface bending over
// the cylinder), parametrized tangentially without normalization (r along the flow, like a
// time of flight; s across), and textured with seamless anisotropic noise and with arrows at
// (u, v) = (r * scale + offset, s * scale); faces where grad r leaves the flow are blended to
// the texture's mean colour by b(gamma).  Moving the offset animates the texture along the flow.
//
//   flow_texture [--faces N] [--picture-width W] [--output DIR] [--overwrite] [--quiet]
//
// writes into DIR: surface.vtp (r, s, texture coordinates as TCoords, velocity; per face the
// mask, the alignment angle and the flux), noise.obj/.mtl/.png and arrows.obj/.mtl/.png, and
// the pictures flux.png (the placed patch, coloured by flux), aligned_flux.png (the stream
// surface with seed curves, iso-contours of r), noise.png's rendering textured.png, arrows.png's
// arrows_rendered.png and frame_0.png ... frame_3.png.  Without a display (and no Xvfb) the
// pictures are skipped with the reason and everything else is written.  (The test
// FlowTextureWorkflow of test/Flow_aligned_surfaces/test_workflows.cpp checks that this surface
// is a stream surface, flux <= 0.01, with less than a tenth of it masked.)

#include "command_line.h"
#include "demo_support.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_textured_OBJ.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>

#include <filesystem>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using namespace fas_demo;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;

// The pictures' width in pixels (the height is 3/4 of it).
std::size_t picture_width = 640;

// One picture of the example's view (an oblique parallel view of the surface above the cylinder).
bool render(const std::filesystem::path& file, const Mesh& tm, Surface_rendering what)
{
  what.width = picture_width;
  what.height = picture_width * 3 / 4;
  what.camera = Render_camera{{-2.0, -1.0, 5.0}, {0.0, 2.2, 0.0}, {0, 1, 0}, 1.5, 30};
  return write_picture(file, tm, what);
}

int main(int argc, char** argv)
{
  Face_count faces{3000};
  Whole_number<16, 8192> width{picture_width};
  Output_options output;
  po::options_description options = option_group("Options");
  options.add_options()("faces", po::value(&faces)->default_value(faces)->value_name("N"),
                        "the number of triangles of the patch (2 to 10000000)")(
      "picture-width", po::value(&width)->default_value(width)->value_name("W"),
      "the pictures' width in pixels, 16 to 8192 (the height is 3/4 of it)");
  options.add(output_options(output, "flow_texture_output"));
  const Program_help help{
      "flow_texture [options]",
      "LIC-like textures of a stream surface (Section 6 of the paper): a patch above the cylinder of the\n"
      "potential flow past it is aligned tangentially, parametrized tangentially without normalization,\n"
      "and textured with anisotropic noise and with arrows.  Writes into the output folder surface.vtp\n"
      "(r, s, texture coordinates, velocity; per face the mask, the alignment angle and the flux),\n"
      "noise.obj/.mtl/.png, arrows.obj/.mtl/.png and the pictures flux.png, aligned_flux.png,\n"
      "textured.png, arrows_rendered.png and frame_0.png ... frame_3.png (skipped, with the reason, when\n"
      "there is no display and no Xvfb).  Exit status: 0 on success, 1 when the run fails or the output\n"
      "folder is refused (nothing is written then), 2 for a bad command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options))
    return *status;
  picture_width = width.value;
  Output_folder folder;
  if (!folder.open(output))
    return 1;
  const std::filesystem::path& out = folder.path();

  // 1. A stream surface: a tilted patch above the cylinder, aligned tangentially.
  const Flow flow = *make_built_in_flow("cylinder");
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 2.2, 0), Vector(0, 0.25, 1), 2.4, 2.0, faces.value);
  const std::vector<double> placed_flux = face_fluxes(tm, flow);
  const Mesh placed = tm;
  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::TANGENTIAL);
  std::cout << "aligned: flux " << report.normalized_flux << " after " << report.number_of_iterations
            << " iterations\n";

  // 2. The unnormalized tangential parametrization, its texture coordinates and mask.
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  FAS::parametrize_tangential(tm, flow, r, s, FAS::parameters::normalized(false));
  const double scale = 0.4; // texture repeats per unit of r (r grows like |v| times the length)
  auto uv = tm.add_property_map<Vertex, std::array<double, 2>>("v:uv").first;
  FAS::compute_flow_texture_coordinates(tm, r, s, uv, scale);
  auto mask = tm.add_property_map<Face, double>("f:mask", 1).first;
  auto angle = tm.add_property_map<Face, double>("f:angle", -1).first;
  FAS::compute_flow_texture_mask(tm, flow, r, mask);
  FAS::compute_face_alignment_angles(tm, flow, r, angle);
  const FAS::Alignment_angle_statistics angles = FAS::alignment_angle_statistics(tm, flow, r);
  double masked = 0;
  for (Face f : tm.faces())
    masked += mask[f] / double(tm.number_of_faces());
  std::cout << "angle(v, grad r): mean " << angles.mean << " deg, standard deviation "
            << angles.standard_deviation << " deg; mean mask " << masked << "\n";

  // 3. The textures: anisotropic noise (the LIC-like look) and arrows (the illustrative look).
  const FAS::Texture_image noise = FAS::make_noise_texture(128, 128, 24, 1);
  const FAS::Texture_image arrows = FAS::make_arrow_texture(128, 128, 4, 8);

  // 4. The files: VTP for ParaView (select "texture_coordinates" and load noise.png as its
  // Texture), OBJ + MTL + PNG for other renderers.
  std::vector<FAS::IO::Data_array> point_data = {{"r", 1, {}},
                                                 {"s", 1, {}},
                                                 {"texture_coordinates", 2, {}},
                                                 {"velocity", 3, vertex_velocities(tm, flow)}};
  point_data[2].texture_coordinates = true;
  for (Vertex v : tm.vertices()) {
    point_data[0].values.push_back(r[v]);
    point_data[1].values.push_back(s[v]);
    point_data[2].values.insert(point_data[2].values.end(), {uv[v][0], uv[v][1]});
  }
  std::vector<FAS::IO::Data_array> cell_data = {
      {"texture_mask", 1, {}}, {"alignment_angle", 1, {}}, {"normalized_flux", 1, face_fluxes(tm, flow)}};
  for (Face f : tm.faces()) {
    cell_data[0].values.push_back(mask[f]);
    cell_data[1].values.push_back(angle[f]);
  }
  std::string error;
  if (!FAS::IO::write_VTP((out / "surface.vtp").string(), tm, point_data, cell_data,
                          FAS::parameters::error_message(&error))) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  for (const auto& [name, texture] : {std::pair{"noise", &noise}, std::pair{"arrows", &arrows}})
    if (!FAS::IO::write_textured_OBJ((out / (std::string(name) + ".obj")).string(), tm, uv, *texture,
                                     FAS::parameters::error_message(&error)))
      std::cerr << "warning: " << error << "\n";
  std::cout << "wrote surface.vtp, noise.obj/.mtl/.png, arrows.obj/.mtl/.png\n";

  // 5. The pictures of every stage: the placed and aligned surfaces coloured by flux (the
  // aligned one with seed curves, iso-contours of r), the textured surface, animation frames.
  Surface_rendering flux_picture;
  flux_picture.face_scalars = placed_flux;
  bool pictures = render(out / "flux.png", placed, flux_picture);
  if (pictures) {
    std::vector<std::vector<Point>> seed_curves;
    FAS::extract_iso_contours(tm, r, FAS::evenly_spaced_iso_values(tm, r, 6),
                              std::back_inserter(seed_curves));
    Surface_rendering textured;
    for (Face f : tm.faces())
      textured.face_mask.push_back(mask[f]);
    textured.texture = &noise;
    for (Vertex v : tm.vertices())
      textured.texture_coordinates.push_back(uv[v]);
    pictures =
        render(out / "aligned_flux.png", tm, flux_with_polylines(tm, flow, seed_curves)) &&
        render(out / "textured.png", tm, textured);
    for (int frame = 0; pictures && frame < 4; ++frame) {
      FAS::compute_flow_texture_coordinates(tm, r, s, uv, scale, 0.25 * frame); // a quarter repeat per frame
      for (Vertex v : tm.vertices())
        textured.texture_coordinates[std::size_t(v)] = uv[v];
      pictures = render(out / ("frame_" + std::to_string(frame) + ".png"), tm, textured);
    }
    textured.texture = &arrows;
    pictures = pictures && render(out / "arrows_rendered.png", tm, textured);
  }
  if (pictures)
    std::cout << "wrote the pictures flux.png, aligned_flux.png, textured.png, frame_0..3.png, "
                 "arrows_rendered.png\n";
  if (!folder.commit())
    return 1;
  std::cout << "results written to " << folder.destination().string() << "\n";
  return 0;
}
