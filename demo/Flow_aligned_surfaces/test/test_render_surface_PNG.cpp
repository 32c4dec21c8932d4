// Pictures rendered by VTK (render_surface_PNG), read back by libpng, against known geometry:
// the texture of a planar stream surface in a uniform flow shows structure along the flow (the
// structure tensor's dominant orientation within 5 degrees of the projected flow), two views
// show the same texture at the same surface points (sampled at their projections, computed here
// from the camera independently of VTK), and a NaN region of the parametrization is drawn in
// the texture's mean colour.  Without a display and without Xvfb the tests skip and say why.
// The renderer is the demo's (demo/Flow_aligned_surfaces/render_surface_PNG.h), and so is this
// executable: VTK's rendering and X11 stay out of the core test executable.

#include "png_test_reader.h"
#include "skip_without_tool.h"
#include "test_files.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#if defined(FAS_DEMO_HAVE_RENDERING) && defined(CGAL_FLOW_ALIGNED_SURFACES_USE_PNG)
#include "render_scene_PNG.h"
#include "render_surface_PNG.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>
#include <limits>
#include <optional>
#include <random>

// This file's tests and helpers in a namespace of their own, as in the core suite.
namespace test_render_surface_PNG {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;


// A 2 x 2 square in z = 0 in the uniform flow (cos theta, sin theta, 0), with the texture
// coordinates of the unnormalized tangential parametrization at `scale` repeats per unit.
struct Textured_plane {
  Mesh tm;
  fas_demo::Surface_rendering what;
};

Textured_plane textured_plane(double theta, const FAS::Texture_image& texture, double scale)
{
  Textured_plane p;
  FAS::make_planar_patch(p.tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 2.0, 2.0, 2000);
  const auto flow = [=](const Point_3&) {
    return std::optional<Vector_3>(Vector_3(std::cos(theta), std::sin(theta), 0));
  };
  auto r = p.tm.add_property_map<Vertex, double>("v:r").first;
  auto s = p.tm.add_property_map<Vertex, double>("v:s").first;
  FAS::parametrize_tangential(p.tm, flow, r, s, FAS::parameters::normalized(false));
  auto uv = p.tm.add_property_map<Vertex, std::array<double, 2>>("v:uv").first;
  FAS::compute_flow_texture_coordinates(p.tm, r, s, uv, scale);
  for (Vertex v : p.tm.vertices())
    p.what.texture_coordinates.push_back(uv[v]);
  p.what.texture = &texture;
  p.what.width = p.what.height = 300;
  return p;
}

fas_demo::Render_camera camera(const std::array<double, 3>& position, const std::array<double, 3>& up)
{
  fas_demo::Render_camera c;
  c.position = position;
  c.focal_point = {0, 0, 0};
  c.view_up = up;
  c.parallel_scale = 0.7; // only the inside of the square is in the picture
  return c;
}

// Renders; skips the test (returns nothing) when there is no display.
std::optional<Png_picture> render(const std::string& name, const Mesh& tm,
                                  const fas_demo::Surface_rendering& what)
{
  const std::string file = temporary_file("render_", name);
  std::string error;
  if (!fas_demo::render_surface_PNG(file, tm, what, CGAL::parameters::default_values(), &error)) {
    EXPECT_NE(error.find("no X display"), std::string::npos) << error;
    return std::nullopt;
  }
  Png_picture picture = read_png(file);
  EXPECT_EQ(picture.width, what.width);
  EXPECT_EQ(picture.height, what.height);
  return picture;
}

// The orientation (degrees in [0, 180)) along which the picture varies least: the eigenvector
// of the smallest eigenvalue of the structure tensor J = sum grad I grad I^T, and the
// coherence (l1 - l2) / (l1 + l2).
std::pair<double, double> structure_orientation(const Png_picture& p)
{
  double jxx = 0, jxy = 0, jyy = 0;
  for (std::size_t y = 1; y + 1 < p.height; ++y)
    for (std::size_t x = 1; x + 1 < p.width; ++x) {
      // Scharr's derivatives, the most rotation-invariant 3 x 3 ones (central differences favour
      // the axes by a few degrees on texel-sized detail).
      auto l = [&](int dx, int dy) {
        return p.luminance(std::size_t(int(x) + dx), std::size_t(int(y) + dy));
      };
      const double ix =
          (3 * (l(1, -1) - l(-1, -1)) + 10 * (l(1, 0) - l(-1, 0)) + 3 * (l(1, 1) - l(-1, 1))) / 32;
      const double iy =
          (3 * (l(-1, 1) - l(-1, -1)) + 10 * (l(0, 1) - l(0, -1)) + 3 * (l(1, 1) - l(1, -1))) / 32;
      jxx += ix * ix;
      jxy += ix * iy;
      jyy += iy * iy;
    }
  const double gradient = 0.5 * std::atan2(2 * jxy, jxx - jyy) * 180 / CGAL_PI; // the dominant gradient
  const double root = std::sqrt((jxx - jyy) * (jxx - jyy) + 4 * jxy * jxy);
  return {std::fmod(gradient + 90 + 360, 180.0), root / (jxx + jyy)};
}

double orientation_difference(double a, double b)
{
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180 - d);
}

TEST(RenderSurfacePNG, TextureStructureFollowsTheProjectedFlow)
{
  const auto texture = FAS::make_noise_texture(256, 256, 32, 11);
  for (double degrees : {30.0, -65.0}) {
    auto p = textured_plane(degrees * CGAL_PI / 180, texture, 0.25); // a texel: 3.3 pixels
    p.what.camera = camera({0, 0, 5}, {0, 1, 0}); // looking down: the picture's x, y are the plane's
    const auto picture = render("flow_" + std::to_string(int(degrees)) + ".png", p.tm, p.what);
    if (!picture)
      FAS_SKIP_WITHOUT_TOOL("no display and no Xvfb");
    const auto [orientation, coherence] = structure_orientation(*picture);
    EXPECT_LT(orientation_difference(orientation, degrees), 5)
        << "flow at " << degrees << " degrees, structure at " << orientation;
    EXPECT_GT(coherence, 0.3) << "the picture has oriented structure";
  }
}

TEST(RenderSurfacePNG, TwoViewsShowTheSameTextureAtTheSameSurfacePoints)
{
  const auto texture = FAS::make_noise_texture(64, 64, 8, 5); // texels of 1/32 unit: ~7 pixels
  auto p = textured_plane(0.5, texture, 0.5);
  const double tilt = 40 * CGAL_PI / 180;
  const std::array<fas_demo::Render_camera, 2> cameras{
      camera({0, 0, 5}, {0, 1, 0}),
      camera({0, -5 * std::sin(tilt), 5 * std::cos(tilt)}, {0, std::cos(tilt), std::sin(tilt)})};
  std::array<Png_picture, 2> pictures;
  for (std::size_t i = 0; i < 2; ++i) {
    p.what.camera = cameras[i];
    auto picture = render("view_" + std::to_string(i) + ".png", p.tm, p.what);
    if (!picture)
      FAS_SKIP_WITHOUT_TOOL("no display and no Xvfb");
    pictures[i] = std::move(*picture);
  }
  // The luminance at the projection of (x, y, 0) by a parallel camera: right = d x up.
  auto sample = [&](std::size_t i, double x, double y) {
    const auto& c = cameras[i];
    const Vector_3 d = Vector_3(Point_3(c.position[0], c.position[1], c.position[2]), CGAL::ORIGIN);
    const Vector_3 dir = d / std::sqrt(d.squared_length());
    Vector_3 up(c.view_up[0], c.view_up[1], c.view_up[2]);
    up = up - (up * dir) * dir;
    up = up / std::sqrt(up.squared_length());
    const Vector_3 right = CGAL::cross_product(dir, up), q(x, y, 0);
    const double pixels_per_unit = double(pictures[i].height) / 2 / c.parallel_scale;
    const double px = double(pictures[i].width) / 2 + (q * right) * pixels_per_unit;
    const double py = double(pictures[i].height) / 2 + (q * up) * pixels_per_unit;
    return pictures[i].luminance(std::size_t(px), std::size_t(py));
  };
  auto correlation = [&](double shift) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coordinate(-0.55, 0.55);
    std::vector<std::array<double, 2>> values;
    for (int k = 0; k < 400; ++k) {
      const double x = coordinate(random), y = coordinate(random);
      values.push_back({sample(0, x, y), sample(1, x + shift, y)});
    }
    double m0 = 0, m1 = 0;
    for (const auto& v : values) {
      m0 += v[0] / double(values.size());
      m1 += v[1] / double(values.size());
    }
    double c01 = 0, c00 = 0, c11 = 0;
    for (const auto& v : values) {
      c01 += (v[0] - m0) * (v[1] - m1);
      c00 += (v[0] - m0) * (v[0] - m0);
      c11 += (v[1] - m1) * (v[1] - m1);
    }
    return c01 / std::sqrt(c00 * c11);
  };
  // The lighting differs between the views by a factor, which correlation ignores; a texel is
  // ~7 pixels, so the sub-pixel rounding of the projection barely matters.
  EXPECT_GT(correlation(0), 0.85);
  // The control: points 0.15 apart (several texels across the flow) are unrelated.
  EXPECT_LT(std::abs(correlation(0.15)), 0.3);
}

TEST(RenderSurfacePNG, NaNParametrizationIsDrawnInTheMeanColour)
{
  const auto texture = FAS::make_noise_texture(128, 128, 16, 2);
  auto p = textured_plane(0.3, texture, 0.5);
  // r is NaN right of x = 0.2: the mask (from the NaN) hides the garbage coordinates there.
  auto r = p.tm.add_property_map<Vertex, double>("v:r").first;
  for (Vertex v : p.tm.vertices())
    if (p.tm.point(v).x() > 0.2) {
      r[v] = std::nan("");
      p.what.texture_coordinates[v] = {std::nan(""), 0};
    }
  const auto flow = [](const Point_3&) {
    return std::optional<Vector_3>(Vector_3(std::cos(0.3), std::sin(0.3), 0));
  };
  auto mask = p.tm.add_property_map<Face, double>("f:mask").first;
  FAS::compute_flow_texture_mask(p.tm, flow, r, mask);
  for (Face f : p.tm.faces())
    p.what.face_mask.push_back(mask[f]);
  p.what.camera = camera({0, 0, 5}, {0, 1, 0});
  const auto picture = render("masked.png", p.tm, p.what);
  if (!picture)
    FAS_SKIP_WITHOUT_TOOL("no display and no Xvfb");
  // Pixels of x in [0.35, 0.65] (masked) and of x in [-0.65, -0.35] (textured), y in [-0.5, 0.5].
  auto deviation = [&](double x0, double x1) {
    const double ppu = double(picture->height) / 2 / 0.7;
    double sum = 0, squares = 0;
    std::size_t n = 0;
    for (double x = x0; x < x1; x += 0.01)
      for (double y = -0.5; y < 0.5; y += 0.01) {
        const double l = picture->luminance(std::size_t(150 + x * ppu), std::size_t(150 + y * ppu));
        sum += l;
        squares += l * l;
        ++n;
      }
    return std::sqrt(std::max(0.0, squares / double(n) - (sum / double(n)) * (sum / double(n))));
  };
  EXPECT_LT(deviation(0.35, 0.65), 0.01) << "masked: one colour";
  EXPECT_GT(deviation(-0.65, -0.35), 0.1) << "textured: high contrast";
}

// The defined/undefined lattice of a solid (`inside(x, y, z)`) on n^3 samples of spacing 1.
template <class Inside>
fas_demo::Flow_domain_lattice solid_lattice(int n, const Inside& inside)
{
  fas_demo::Flow_domain_lattice lattice;
  lattice.dimensions = {n, n, n};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        lattice.defined.push_back(inside(double(i), double(j), double(k)) ? 0.0 : 1.0);
  return lattice;
}

// The angle (degrees) between each triangle's normal and `normal_at(centroid)`, sorted.
template <class Normal>
std::vector<double> normal_deviations(vtkPolyData* surface, const Normal& normal_at)
{
  std::vector<double> angles;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {
    vtkIdList* ids = surface->GetCell(c)->GetPointIds();
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      surface->GetPoint(ids->GetId(k), p[k]);
    const double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double c3[3] = {(p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3,
                          (p[0][2] + p[1][2] + p[2][2]) / 3};
    const std::array<double, 3> m = normal_at(c3);
    const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]),
                 lm = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    if (ln == 0 || lm == 0)
      continue;
    const double cosine = std::abs(n[0] * m[0] + n[1] * m[1] + n[2] * m[2]) / (ln * lm);
    angles.push_back(std::acos(std::min(1.0, cosine)) * 180 / 3.141592653589793);
  }
  std::sort(angles.begin(), angles.end());
  return angles;
}

// A ball of radius 8 samples: the obstacle's faces follow the sphere's normals (the plain 0/1
// contour is a staircase of faces up to 45 degrees off), and its points lie on the sphere within
// a third of a sample.
TEST(RenderScenePNG, ObstacleIsASmoothContour)
{
  const double r = 8, c = 15.3;
  const auto lattice = solid_lattice(32, [&](double x, double y, double z) {
    return (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c) < r * r;
  });
  const vtkSmartPointer<vtkPolyData> obstacle = fas_demo::obstacle_polydata(lattice);
  ASSERT_GT(obstacle->GetNumberOfCells(), 500);
  const std::vector<double> angles = normal_deviations(obstacle, [&](const double* p) {
    return std::array<double, 3>{p[0] - c, p[1] - c, p[2] - c};
  });
  // (Marching triangles are not tangent planes: a smooth contour still has faces a few degrees
  // off; the 0/1 staircase has a median of about 20 degrees and faces 45 degrees off.)
  EXPECT_LT(angles[angles.size() / 2], 5.0) << "median";
  EXPECT_LT(angles[angles.size() * 95 / 100], 12.0) << "95% of the faces";
  EXPECT_LT(angles.back(), 25.0);
  for (vtkIdType i = 0; i < obstacle->GetNumberOfPoints(); ++i) {
    double p[3];
    obstacle->GetPoint(i, p);
    const double distance = std::sqrt((p[0] - c) * (p[0] - c) + (p[1] - c) * (p[1] - c) + (p[2] - c) * (p[2] - c));
    ASSERT_NEAR(distance, r, 1.0 / 3) << "point " << i;
  }
}

// A cylinder across the whole lattice (an obstacle larger than the scene): its surface is closed,
// capped on the lattice's box (every edge shared by two triangles), not an open tube.
TEST(RenderScenePNG, ObstacleLeavingTheLatticeIsClosed)
{
  const double r = 6, c = 12.4;
  const auto lattice = solid_lattice(26, [&](double x, double y, double) {
    return (x - c) * (x - c) + (y - c) * (y - c) < r * r;
  });
  const vtkSmartPointer<vtkPolyData> obstacle = fas_demo::obstacle_polydata(lattice);
  ASSERT_GT(obstacle->GetNumberOfCells(), 100);
  std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
  for (vtkIdType cell = 0; cell < obstacle->GetNumberOfCells(); ++cell) {
    vtkIdList* ids = obstacle->GetCell(cell)->GetPointIds();
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % ids->GetNumberOfIds());
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::size_t open = 0;
  for (const auto& edge : edges)
    open += edge.second != 2 ? 1 : 0;
  EXPECT_EQ(open, 0u) << "edges not shared by two triangles";
  double bounds[6];
  obstacle->GetBounds(bounds);
  EXPECT_LT(bounds[4], 0.5) << "the obstacle reaches the lattice's lower face";
  EXPECT_GT(bounds[5], 24.5) << "and its upper face";
}

} // namespace

} // namespace test_render_surface_PNG

#else
TEST(RenderSurfacePNG, NeedsVTKRenderingAndLibpng)
{
  FAS_SKIP_WITHOUT_TOOL("built without the demo's fas_demo_rendering (VTK RenderingOpenGL2, IOImage, X11) or "
                        "libpng: no pictures");
}
#endif
