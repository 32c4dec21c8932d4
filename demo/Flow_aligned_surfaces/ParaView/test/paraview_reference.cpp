// The library called directly, for the plugin's tests: what each filter of the plugin must
// reproduce, computed without ParaView and written as files the test scripts compare with.
//
//   paraview_reference field OUT.vti
//       the potential flow past the unit cylinder (axis z), sampled on a regular grid
//   paraview_reference align FIELD.vti OUT.vtp CX CY CZ NX NY NZ SIZE FACES planar|disk
//                      tangential|orthogonal ITERATIONS
//       the patch after ITERATIONS iterations (fewer when it converged)
//   paraview_reference parametrize ..., paraview_reference texture ...
//       Parametrize And Seed, Flow Texture on that patch (see the functions for the arguments)
//   paraview_reference stream FIELD.vti SEEDS.txt OUT.vtp defaults|backward_time|both_length
//       the stream surfaces of the seed curves of SEEDS.txt (one curve a line: x y z x y z ...),
//       with the named parameters of the case (see stream_surfaces()); point data u and t, and
//       OUT.vtp.txt: one line per curve, "TERMINATION [BACKWARD_TERMINATION]"
//   paraview_reference grow FIELD.vti IN.vtp OUT.vtp <the arguments of align after OUT.vtp>
//                      DISTANCE all|across|DX,DY,DZ STEPS GROW_ITERATIONS
//       the patch of align, written to IN.vtp, then grown STEPS times (each followed by at most
//       GROW_ITERATIONS iterations) by a deformation made on it; point data growth_step, and
//       OUT.vtp.txt: the summed Growth_report and the deformation's counts, "name value" a line
//   paraview_reference unsteady_field OUT.pvd
//       a swirl whose axis drifts, v(x, y, z, t) = (-y, x - 0.2 t, 0.3), sampled on a regular
//       grid at t = 0, 0.25, ..., 1: a .pvd and its .vti steps beside it
//   paraview_reference follow FIELD.pvd OUT.vtp <align's 11 patch arguments> T
//       the patch aligned at the first step, then re-aligned at every later step up to T and
//       at T (each time at most ITERATIONS iterations): the surface that followed the flow
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

int usage()
{
  std::cerr << "usage: paraview_reference field OUT.vti\n"
               "       paraview_reference align FIELD.vti OUT.vtp CX CY CZ NX NY NZ SIZE FACES "
               "planar|disk tangential|orthogonal ITERATIONS\n"
               "       paraview_reference parametrize FIELD.vti PREFIX <align's 11 patch arguments> "
               "tangential|orthogonal|circular default|normalized|unnormalized ALPHA centroid|X,Y,Z CURVES SPACING "
               "SEED delaunay|direct\n"
               "       paraview_reference texture FIELD.vti PREFIX <align's 11 patch arguments> SCALE OFFSET "
               "MIN_RELATIVE_SPEED noise|arrows WIDTH HEIGHT FILTER_LENGTH NOISE_SEED ALONG ACROSS\n"
               "       paraview_reference stream FIELD.vti SEEDS.txt OUT.vtp forward_time|backward_time|both_length\n"
               "       paraview_reference grow FIELD.vti IN.vtp OUT.vtp CX CY CZ NX NY NZ SIZE FACES "
               "planar|disk tangential|orthogonal ITERATIONS DISTANCE all|across|DX,DY,DZ STEPS "
               "GROW_ITERATIONS\n"
               "       paraview_reference unsteady_field OUT.pvd\n"
               "       paraview_reference follow FIELD.pvd OUT.vtp <align's 11 patch arguments> T\n";
  return 2;
}

double number(const char* text) { return std::strtod(text, nullptr); }

FAS::Alignment alignment_of(const std::string& text)
{
  return text == "orthogonal" ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL;
}

int write_field(const std::string& out)
{
  const FAS::Cylinder_potential_flow<K> flow;
  const auto grid = FAS::Regular_grid_flow_field_3<K>::sample(
      flow, K::Point_3(-3, -2, -1), K::Vector_3(0.1, 0.1, 0.1), {{61, 41, 21}});
  std::string error;
  if (!FAS::IO::write_VTI_flow_field(out, grid, FAS::parameters::error_message(&error))) {
    std::cerr << error << "\n";
    return 1;
  }
  return 0;
}

bool read_field(const char* filename, FAS::Sampled_flow_field_3<K>& field)
{
  std::string error;
  if (!FAS::IO::read_flow_field(filename, field, FAS::parameters::error_message(&error))) {
    std::cerr << error << "\n";
    return false;
  }
  return true;
}

bool write_surface(const std::string& filename, const Mesh& tm, const std::vector<FAS::IO::Data_array>& point_data)
{
  std::string error;
  if (!FAS::IO::write_VTP(filename, tm, point_data, {}, FAS::parameters::error_message(&error))) {
    std::cerr << error << "\n";
    return false;
  }
  return true;
}

// The patch of the 11 arguments CX CY CZ NX NY NZ SIZE FACES planar|disk tangential|orthogonal
// ITERATIONS after ITERATIONS iterations (fewer when it converged).
Mesh aligned_surface(const FAS::Sampled_flow_field_3<K>& field, char** spec)
{
  const K::Point_3 center(number(spec[0]), number(spec[1]), number(spec[2]));
  const K::Vector_3 normal(number(spec[3]), number(spec[4]), number(spec[5]));
  const double size = number(spec[6]);
  const std::size_t faces = std::size_t(number(spec[7]));
  Mesh tm;
  if (std::string(spec[8]) == "disk")
    FAS::make_disk_patch(tm, center, normal, size / 2, faces);
  else
    FAS::make_planar_patch(tm, center, normal, size, size, faces);
  FAS::Flow_aligned_deformation<Mesh, FAS::Sampled_flow_field_3<K>> deformation(tm, field, alignment_of(spec[9]));
  const std::size_t iterations = std::size_t(number(spec[10]));
  for (std::size_t k = 0; k < iterations; ++k)
    if (deformation.step().converged)
      break;
  return tm;
}

int align(char** argv)
{
  FAS::Sampled_flow_field_3<K> field;
  if (!read_field(argv[2], field))
    return 1;
  return write_surface(argv[3], aligned_surface(field, argv + 4), {}) ? 0 : 1;
}

// ---- Stream Surface From Curve and Grow Boundary ----

// The seed curves of a text file, one a line: x y z x y z ...
std::vector<std::vector<K::Point_3>> read_seed_curves(const char* filename)
{
  std::vector<std::vector<K::Point_3>> curves;
  std::ifstream in(filename);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream is(line);
    std::vector<K::Point_3> curve;
    double x, y, z;
    while (is >> x >> y >> z)
      curve.emplace_back(x, y, z);
    if (!curve.empty())
      curves.push_back(curve);
  }
  return curves;
}

// Every case spells out the named parameters it gives: the library treats a given parameter
// otherwise than an absent one, which is what the filter's properties at 0 must reproduce.
template <class Field, class UMap, class TMap>
FAS::Stream_surface_report stream_surface(const std::string& name, const Field& field,
                                          const std::vector<K::Point_3>& seed, Mesh& tm, UMap u, TMap t)
{
  namespace P = FAS::parameters;
  const auto maps = P::seed_parameter_map(u, P::integration_time_map(t));
  if (name == "backward_time")
    return FAS::integrate_stream_surface(
        field, seed, tm,
        P::integration_direction(FAS::Integration_direction::BACKWARD,
                                 P::max_time(2.0, P::time_line_step(0.1, maps))));
  if (name == "forward_time")
    return FAS::integrate_stream_surface(field, seed, tm, P::max_time(2.0, P::time_line_step(0.1, maps)));
  if (name == "both_length") {
    const auto tolerances = P::relative_tolerance(1e-9, P::absolute_tolerance(1e-11, maps));
    const auto front = P::front_spacing(0.06, P::tear_angle(0.6, tolerances));
    return FAS::integrate_stream_surface(
        field, seed, tm,
        P::integration_direction(FAS::Integration_direction::BOTH,
                                 P::arc_length_time_lines(true, P::max_length(2.5, P::max_number_of_time_lines(
                                                                                       std::size_t(30), front)))));
  }
  throw std::invalid_argument("unknown case " + name);
}

int stream_surfaces(char** argv)
{
  FAS::Sampled_flow_field_3<K> field;
  if (!read_field(argv[2], field))
    return 1;
  Mesh tm;
  auto u = tm.add_property_map<Mesh::Vertex_index, double>("v:u", 0.).first;
  auto t = tm.add_property_map<Mesh::Vertex_index, double>("v:t", 0.).first;
  std::ofstream report(std::string(argv[4]) + ".txt");
  for (const std::vector<K::Point_3>& seed : read_seed_curves(argv[3])) {
    const FAS::Stream_surface_report r = stream_surface(argv[5], field, seed, tm, u, t);
    report << FAS::to_string(r.termination);
    if (r.backward)
      report << " " << FAS::to_string(r.backward->termination);
    report << "\n";
  }
  FAS::IO::Data_array u_array{"u", 1, {}}, t_array{"t", 1, {}};
  for (Mesh::Vertex_index v : tm.vertices()) {
    u_array.values.push_back(u[v]);
    t_array.values.push_back(t[v]);
  }
  return write_surface(argv[4], tm, {u_array, t_array}) ? 0 : 1;
}

// `tm` built anew as the plugin builds a surface it reads: the vertices in index order, then
// the faces in index order, each from its halfedge's vertices (as to_polydata and write_VTP
// write them), so that both have the same halfedges.
Mesh rebuilt(const Mesh& tm)
{
  Mesh copy;
  for (Mesh::Vertex_index v : tm.vertices())
    copy.add_vertex(tm.point(v));
  for (Mesh::Face_index f : tm.faces()) {
    std::vector<Mesh::Vertex_index> corners;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(tm.halfedge(f), tm))
      corners.push_back(v);
    copy.add_face(corners);
  }
  return copy;
}

int grow(char** argv)
{
  FAS::Sampled_flow_field_3<K> field;
  if (!read_field(argv[2], field))
    return 1;
  char** patch = argv + 5; // align's 11 patch arguments, after IN.vtp and OUT.vtp
  Mesh tm = rebuilt(aligned_surface(field, patch));
  if (!write_surface(argv[3], tm, {}))
    return 1;
  const std::size_t input_vertices = tm.number_of_vertices();
  const double distance = number(argv[16]);
  const std::string mode = argv[17];
  const int steps = int(number(argv[18]));
  const std::size_t iterations = std::size_t(number(argv[19]));
  FAS::Flow_aligned_deformation<Mesh, FAS::Sampled_flow_field_3<K>> deformation(tm, field, alignment_of(patch[9]));
  FAS::Growth_report sum;
  std::size_t iterations_made = 0;
  FAS::Alignment_report last;
  FAS::IO::Data_array growth_step{"growth_step", 1, std::vector<double>(input_vertices, 0.)};
  for (int step = 1; step <= steps; ++step) {
    FAS::Growth_report r;
    if (mode == "all")
      r = deformation.grow(distance);
    else if (mode == "across")
      r = deformation.grow(distance, FAS::parameters::across_flow(true));
    else {
      double d[3];
      if (std::sscanf(mode.c_str(), "%lf,%lf,%lf", &d[0], &d[1], &d[2]) != 3)
        throw std::invalid_argument("growth mode " + mode + ": expected all, across or DX,DY,DZ");
      r = deformation.grow(distance, FAS::parameters::growth_direction(K::Vector_3(d[0], d[1], d[2])));
    }
    sum.number_of_new_vertices += r.number_of_new_vertices;
    sum.number_of_new_faces += r.number_of_new_faces;
    sum.number_of_grown_edges += r.number_of_grown_edges;
    sum.grown_boundary_length += r.grown_boundary_length;
    sum.added_area += r.added_area;
    growth_step.values.resize(tm.number_of_vertices(), double(step));
    last = deformation.run(iterations);
    iterations_made += last.number_of_iterations;
  }
  std::ofstream report(std::string(argv[4]) + ".txt");
  report.precision(17);
  report << "number_of_new_vertices " << sum.number_of_new_vertices << "\n"
         << "number_of_new_faces " << sum.number_of_new_faces << "\n"
         << "number_of_grown_edges " << sum.number_of_grown_edges << "\n"
         << "grown_boundary_length " << sum.grown_boundary_length << "\n"
         << "added_area " << sum.added_area << "\n"
         << "number_of_iterations " << iterations_made << "\n"
         << "converged " << (last.converged ? 1 : 0) << "\n"
         << "number_of_factorizations " << deformation.number_of_factorizations() << "\n";
  return write_surface(argv[4], tm, {growth_step}) ? 0 : 1;
}

// ---- Parametrize And Seed, Flow Texture ----

using Vertex = Mesh::Vertex_index;

// Writes `text` to `filename`; false with a message on failure.
bool write_text(const std::string& filename, const std::string& text)
{
  std::ofstream out(filename);
  out << text;
  if (!out) {
    std::cerr << "cannot write " << filename << "\n";
    return false;
  }
  return true;
}

// The values of a vertex map in vertex index order, as a data array.
template <class Map>
FAS::IO::Data_array vertex_data(const Mesh& tm, const std::string& name, int components, Map map)
{
  FAS::IO::Data_array array{name, components, {}};
  for (Vertex v : tm.vertices()) {
    if constexpr (std::is_arithmetic_v<typename boost::property_traits<Map>::value_type>)
      array.values.push_back(get(map, v));
    else
      for (double x : get(map, v))
        array.values.push_back(x);
  }
  return array;
}

// The source of the circular parametrization: the vertex nearest to the area-weighted centroid
// of the faces ("centroid") or to the point "X,Y,Z".
Vertex source_vertex(const Mesh& tm, const std::string& where)
{
  K::Point_3 p;
  if (where == "centroid") {
    double area = 0, x = 0, y = 0, z = 0;
    for (Mesh::Face_index f : tm.faces()) {
      const auto h = tm.halfedge(f);
      const K::Point_3 a = tm.point(tm.source(h)), b = tm.point(tm.target(h)), c = tm.point(tm.target(tm.next(h)));
      const double w = std::sqrt(CGAL::cross_product(b - a, c - a).squared_length()) / 2;
      area += w;
      x += w * (a.x() + b.x() + c.x()) / 3;
      y += w * (a.y() + b.y() + c.y()) / 3;
      z += w * (a.z() + b.z() + c.z()) / 3;
    }
    p = K::Point_3(x / area, y / area, z / area);
  }
  else {
    double c[3];
    std::sscanf(where.c_str(), "%lf,%lf,%lf", &c[0], &c[1], &c[2]);
    p = K::Point_3(c[0], c[1], c[2]);
  }
  Vertex best = *tm.vertices().begin();
  for (Vertex v : tm.vertices())
    if (CGAL::squared_distance(tm.point(v), p) < CGAL::squared_distance(tm.point(best), p))
      best = v;
  return best;
}

// paraview_reference parametrize FIELD.vti PREFIX <patch: 11 arguments as align>
//     tangential|orthogonal|circular default|normalized|unnormalized ALPHA centroid|X,Y,Z
//     CURVES SPACING SEED delaunay|direct
// writes PREFIX_surface.vtp (point data r, s or geodesic_distance), PREFIX_curves.vtp (the
// iso-contours, point and cell data of the same name) and PREFIX_seeds.txt (x y z per line).
int parametrize(char** argv)
{
  FAS::Sampled_flow_field_3<K> field;
  if (!read_field(argv[2], field))
    return 1;
  const std::string prefix = argv[3], method = argv[15], normalization = argv[16];
  Mesh tm = aligned_surface(field, argv + 4);
  auto f = tm.add_property_map<Vertex, double>("v:f", 0.).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0.).first;
  std::vector<FAS::IO::Data_array> point_data;
  std::string name = "r";
  try {
    if (method == "circular") {
      name = "geodesic_distance";
      FAS::compute_geodesic_distance(tm, source_vertex(tm, argv[18]), f,
                                     FAS::parameters::intrinsic_delaunay(std::string(argv[22]) == "delaunay"));
      point_data.push_back(vertex_data(tm, name, 1, f));
    }
    else {
      const bool orthogonal = method == "orthogonal";
      const bool normalized = normalization == "default" ? !orthogonal : normalization == "normalized";
      if (orthogonal)
        FAS::parametrize_orthogonal(tm, field, f, s, FAS::parameters::angle(number(argv[17]), FAS::parameters::normalized(normalized)));
      else
        FAS::parametrize_tangential(tm, field, f, s, FAS::parameters::normalized(normalized));
      point_data.push_back(vertex_data(tm, "r", 1, f));
      point_data.push_back(vertex_data(tm, "s", 1, s));
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  std::vector<std::vector<K::Point_3>> curves;
  FAS::IO::Data_array point_values{name, 1, {}}, cell_values{name, 1, {}};
  for (double value : FAS::evenly_spaced_iso_values(tm, f, std::size_t(number(argv[19])))) {
    const std::size_t before = curves.size();
    FAS::extract_iso_contours(tm, f, std::vector<double>{value}, std::back_inserter(curves));
    for (std::size_t i = before; i < curves.size(); ++i) {
      cell_values.values.push_back(value);
      point_values.values.insert(point_values.values.end(), curves[i].size(), value);
    }
  }
  std::vector<K::Point_3> seeds;
  FAS::sample_seed_points(tm, number(argv[20]), std::back_inserter(seeds),
                          CGAL::parameters::random_seed(unsigned(number(argv[21]))));
  std::ostringstream seed_text;
  seed_text.precision(17);
  for (const K::Point_3& p : seeds)
    seed_text << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  std::string error;
  if (!FAS::IO::write_VTP(prefix + "_surface.vtp", tm, point_data, {},
                          FAS::parameters::error_message(&error)) ||
      !FAS::IO::write_VTP_polylines(prefix + "_curves.vtp", curves, {point_values}, {cell_values},
                                    FAS::parameters::error_message(&error))) {
    std::cerr << error << "\n";
    return 1;
  }
  return write_text(prefix + "_seeds.txt", seed_text.str()) ? 0 : 1;
}

// paraview_reference texture FIELD.vti PREFIX <patch: 11 arguments as align> SCALE OFFSET
//     MIN_RELATIVE_SPEED noise|arrows WIDTH HEIGHT FILTER_LENGTH NOISE_SEED ALONG ACROSS
// writes PREFIX_surface.vtp (point data r, s, texture_coordinates; cell data texture_mask) and
// PREFIX_texture.txt (the texels' channels in [0, 1], one texel per line, row by row from y = 0).
int texture(char** argv)
{
  FAS::Sampled_flow_field_3<K> field;
  if (!read_field(argv[2], field))
    return 1;
  const std::string prefix = argv[3];
  Mesh tm = aligned_surface(field, argv + 4);
  auto r = tm.add_property_map<Vertex, double>("v:r", 0.).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0.).first;
  auto uv = tm.add_property_map<Vertex, std::array<double, 2>>("v:uv").first;
  auto mask = tm.add_property_map<Mesh::Face_index, double>("f:mask", 1.).first;
  FAS::Texture_image image;
  try {
    FAS::parametrize_tangential(tm, field, r, s, FAS::parameters::normalized(false));
    FAS::compute_flow_texture_coordinates(tm, r, s, uv, number(argv[15]), number(argv[16]));
    FAS::compute_flow_texture_mask(tm, field, r, mask, FAS::parameters::min_relative_speed(number(argv[17])));
    const std::size_t width = std::size_t(number(argv[19])), height = std::size_t(number(argv[20]));
    image = std::string(argv[18]) == "arrows"
                ? FAS::make_arrow_texture(width, height, std::size_t(number(argv[23])), std::size_t(number(argv[24])))
                : FAS::make_noise_texture(width, height, number(argv[21]), std::uint32_t(number(argv[22])));
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  FAS::IO::Data_array coordinates = vertex_data(tm, "texture_coordinates", 2, uv);
  coordinates.texture_coordinates = true;
  FAS::IO::Data_array face_mask{"texture_mask", 1, {}};
  for (Mesh::Face_index f : tm.faces())
    face_mask.values.push_back(mask[f]);
  std::string error;
  if (!FAS::IO::write_VTP(prefix + "_surface.vtp", tm,
                          {vertex_data(tm, "r", 1, r), vertex_data(tm, "s", 1, s), coordinates}, {face_mask},
                          FAS::parameters::error_message(&error))) {
    std::cerr << error << "\n";
    return 1;
  }
  std::ostringstream texels;
  texels.precision(9);
  for (std::size_t i = 0; i < image.pixels.size(); i += 3)
    texels << image.pixels[i] << ' ' << image.pixels[i + 1] << ' ' << image.pixels[i + 2] << '\n';
  return write_text(prefix + "_texture.txt", texels.str()) ? 0 : 1;
}

// ---- end of Parametrize And Seed, Flow Texture ----

} // namespace

int write_unsteady_field(const std::string& pvd)
{
  const std::string folder = pvd.substr(0, pvd.find_last_of('/') + 1);
  std::ofstream collection(pvd);
  collection << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int i = 0; i <= 4; ++i) {
    const double t = 0.25 * i;
    const auto swirl = [t](const K::Point_3& p) -> std::optional<K::Vector_3> {
      return K::Vector_3(-p.y(), p.x() - 0.2 * t, 0.3);
    };
    const auto grid = FAS::Regular_grid_flow_field_3<K>::sample(
        swirl, K::Point_3(-2, -2, -1), K::Vector_3(0.1, 0.1, 0.1), {{41, 41, 21}});
    const std::string name = "swirl_" + std::to_string(i) + ".vti";
    std::string error;
    if (!FAS::IO::write_VTI_flow_field(folder + name, grid, FAS::parameters::error_message(&error))) {
      std::cerr << error << "\n";
      return 1;
    }
    collection << "<DataSet timestep=\"" << t << "\" file=\"" << name << "\"/>\n";
  }
  collection << "</Collection>\n</VTKFile>\n";
  return collection ? 0 : 1;
}

int follow(char** argv)
{
  using Series = FAS::Unsteady_flow_field_3<FAS::Regular_grid_flow_field_3<K>>;
  Series series;
  std::string error;
  if (!FAS::IO::read_PVD_flow_field(argv[2], series, FAS::parameters::error_message(&error))) {
    std::cerr << error << "\n";
    return 1;
  }
  char** spec = argv + 4;
  const double t = number(argv[15]);
  Mesh tm;
  const K::Point_3 center(number(spec[0]), number(spec[1]), number(spec[2]));
  const K::Vector_3 normal(number(spec[3]), number(spec[4]), number(spec[5]));
  if (std::string(spec[8]) == "disk")
    FAS::make_disk_patch(tm, center, normal, number(spec[6]) / 2, std::size_t(number(spec[7])));
  else
    FAS::make_planar_patch(tm, center, normal, number(spec[6]), number(spec[6]), std::size_t(number(spec[7])));
  FAS::Time_slice_flow_field_3<Series> flow(series, series.start_time());
  FAS::Flow_aligned_deformation<Mesh, decltype(flow)> deformation(tm, flow, alignment_of(spec[9]));
  const std::size_t iterations = std::size_t(number(spec[10]));
  std::vector<double> times;
  for (std::size_t i = 0; i < series.number_of_steps() && series.time(i) <= t; ++i)
    times.push_back(series.time(i));
  if (times.back() < t)
    times.push_back(t);
  for (double time : times) {
    flow.set_time(time);
    deformation.run(iterations);
  }
  return write_surface(argv[3], tm, {}) ? 0 : 1;
}

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "field" && argc == 3)
    return write_field(argv[2]);
  if (command == "align" && argc == 15)
    return align(argv);
  if (command == "parametrize" && argc == 23)
    return parametrize(argv);
  if (command == "texture" && argc == 25)
    return texture(argv);
  if (command == "stream" && argc == 6)
    return stream_surfaces(argv);
  if (command == "grow" && argc == 20)
    return grow(argv);
  if (command == "unsteady_field" && argc == 3)
    return write_unsteady_field(argv[2]);
  if (command == "follow" && argc == 16)
    return follow(argv);
  return usage();
}
