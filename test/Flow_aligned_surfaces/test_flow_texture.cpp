// flow_texture.h against known answers: the autocorrelation of box-filtered white noise (the
// triangle 1 - |k|/L along the filter, zero across it), seamless tiling (differences across the
// wrap edge distributed as interior ones), the mask on planar stream surfaces in uniform flows
// (gamma = 0 exactly, or 90 degrees when r is replaced by the across-flow s), the cubic sigmoid's
// closed form, determinism, and bad input.

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_flow_texture {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;

// The normalized autocorrelation of channel c at lag (dx, dy), periodic.
double autocorrelation(const FAS::Texture_image& t, std::size_t c, std::size_t dx, std::size_t dy)
{
  double mean = 0;
  for (std::size_t y = 0; y < t.height; ++y)
    for (std::size_t x = 0; x < t.width; ++x)
      mean += t(x, y, c);
  mean /= double(t.width * t.height);
  double covariance = 0, variance = 0;
  for (std::size_t y = 0; y < t.height; ++y)
    for (std::size_t x = 0; x < t.width; ++x) {
      const double a = t(x, y, c) - mean;
      covariance += a * (t((x + dx) % t.width, (y + dy) % t.height, c) - mean);
      variance += a * a;
    }
  return covariance / variance;
}

// The lag (interpolated linearly) at which the autocorrelation along x (or y) first drops to 1/2.
double correlation_length(const FAS::Texture_image& t, bool along_x)
{
  double previous = 1;
  for (std::size_t k = 1; k < (along_x ? t.width : t.height); ++k) {
    double rho = 0;
    for (std::size_t c = 0; c < 3; ++c)
      rho += autocorrelation(t, c, along_x ? k : 0, along_x ? 0 : k) / 3;
    if (rho < 0.5)
      return double(k - 1) + (previous - 0.5) / (previous - rho);
    previous = rho;
  }
  return std::numeric_limits<double>::infinity();
}

TEST(FlowTexture, NoiseIsCorrelatedAlongTheFilterAsABoxPredicts)
{
  const double L = 16;
  const auto t = FAS::make_noise_texture(128, 64, L, 7);
  ASSERT_EQ(t.pixels.size(), 3u * 128 * 64);
  const double along = correlation_length(t, true), across = correlation_length(t, false);
  EXPECT_GE(along, 4 * across) << "along " << along << ", across " << across;
  // Box-filtered white noise: rho(k) = 1 - k/L, so rho = 1/2 at k = L/2 = 8 (the contrast
  // clamp and a finite sample move it a little: 15%); across, rho(1) = 0, so the length is 1/2.
  EXPECT_NEAR(along, L / 2, 0.15 * L / 2);
  EXPECT_NEAR(across, 0.5, 0.1);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(autocorrelation(t, c, 24, 0), 0, 0.1) << "beyond the box (lag 1.5 L) there is no correlation";
  // High contrast: the channels span most of [0, 1].
  const auto [lo, hi] = std::minmax_element(t.pixels.begin(), t.pixels.end());
  EXPECT_LT(*lo, 0.05f);
  EXPECT_GT(*hi, 0.95f);
}

// Mean |T(p) - T(q)| over the pairs of neighbours (p, q) that cross the wrap edge of x (or y),
// and over all interior pairs in the same direction.
std::pair<double, double> wrap_and_interior_differences(const FAS::Texture_image& t, bool along_x)
{
  double wrap = 0, interior = 0;
  std::size_t wraps = 0, interiors = 0;
  for (std::size_t y = 0; y < t.height; ++y)
    for (std::size_t x = 0; x < t.width; ++x) {
      const std::size_t nx = along_x ? (x + 1) % t.width : x, ny = along_x ? y : (y + 1) % t.height;
      const bool crosses = along_x ? nx == 0 : ny == 0;
      for (std::size_t c = 0; c < 3; ++c) {
        const double d = std::abs(t(x, y, c) - t(nx, ny, c));
        (crosses ? wrap : interior) += d;
        ++(crosses ? wraps : interiors);
      }
    }
  return {wrap / double(wraps), interior / double(interiors)};
}

TEST(FlowTexture, NoiseTilesWithoutASeam)
{
  // 3 x 256 differences on the wrap edge: the standard error of their mean is ~4% of it, so a
  // ratio in [0.8, 1.25] is 5 standard errors; a texture filtered without wrap-around has
  // unfiltered white-noise jumps at the edge, ~5 x the interior ones along x.
  const auto t = FAS::make_noise_texture(256, 256, 20, 3);
  for (bool along_x : {true, false}) {
    const auto [wrap, interior] = wrap_and_interior_differences(t, along_x);
    EXPECT_GT(wrap / interior, 0.8) << (along_x ? "x" : "y");
    EXPECT_LT(wrap / interior, 1.25) << (along_x ? "x" : "y");
  }
}

TEST(FlowTexture, NoiseIsDeterministicForASeed)
{
  const auto a = FAS::make_noise_texture(64, 32, 8.5, 42), b = FAS::make_noise_texture(64, 32, 8.5, 42);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_NE(a.pixels, FAS::make_noise_texture(64, 32, 8.5, 43).pixels);
}

TEST(FlowTexture, ArrowsRepeatWithTheCellsAndPointAlongX)
{
  const auto t = FAS::make_arrow_texture(128, 64, 4, 2); // 32 x 32 texel cells
  for (std::size_t y = 0; y < 64; ++y)
    for (std::size_t x = 0; x < 128; ++x)
      for (std::size_t c = 0; c < 3; ++c) {
        ASSERT_EQ(t(x, y, c), t((x + 32) % 128, y, c)) << x << ' ' << y; // hence no seam at x = 0
        ASSERT_EQ(t(x, y, c), t(x, (y + 32) % 64, c)) << x << ' ' << y;
      }
  // The arrow is dark: across the head (at 70% of the cell) more of the column is dark than
  // across the shaft (at 40%), and nothing is dark at 5% (before the tail) or 95% (past the tip).
  auto dark = [&](double a) {
    int n = 0;
    const std::size_t x = std::size_t(a * 32);
    for (std::size_t y = 0; y < 32; ++y)
      n += t(x, y, 0) < 0.5f;
    return n;
  };
  EXPECT_GT(dark(0.7), 2 * dark(0.4));
  EXPECT_GT(dark(0.4), 0);
  EXPECT_EQ(dark(0.05), 0);
  EXPECT_EQ(dark(0.95), 0);
}

TEST(FlowTexture, BlendingIsTheCubicSigmoid)
{
  EXPECT_EQ(FAS::flow_texture_blending(0), 0);
  EXPECT_DOUBLE_EQ(FAS::flow_texture_blending(CGAL_PI / 2), 1);
  EXPECT_DOUBLE_EQ(FAS::flow_texture_blending(CGAL_PI / 4), 0.5);
  EXPECT_DOUBLE_EQ(FAS::flow_texture_blending(CGAL_PI / 6), 3.0 / 9 - 2.0 / 27); // x = 1/3
  EXPECT_EQ(FAS::flow_texture_blending(2.5), 1);
  EXPECT_EQ(FAS::flow_texture_blending(std::nan("")), 1);
  const double h = 1e-6; // b'(0) = b'(pi/2) = 0: the one-sided slopes are O(h)
  EXPECT_LT(FAS::flow_texture_blending(h) / h, 1e-5);
  EXPECT_LT((1 - FAS::flow_texture_blending(CGAL_PI / 2 - h)) / h, 1e-5);
}

struct Planar_stream_surface {
  Mesh tm;
  Mesh::Property_map<Vertex, double> r, s;
  Mesh::Property_map<Face, double> mask;
};

// A 2 x 1 square in z = 0 in the uniform flow (1, 0.5, 0), with the unnormalized tangential
// parametrization: grad r = v exactly (a linear r fits a constant guidance with zero residual).
Planar_stream_surface planar_stream_surface()
{
  Planar_stream_surface p;
  FAS::make_planar_patch(p.tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 2.0, 1.0, 400);
  p.r = p.tm.add_property_map<Vertex, double>("v:r", 0).first;
  p.s = p.tm.add_property_map<Vertex, double>("v:s", 0).first;
  p.mask = p.tm.add_property_map<Face, double>("f:mask", -7).first;
  return p;
}

const auto uniform_flow = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(1, 0.5, 0)); };

TEST(FlowTexture, MaskIsZeroOnAPlanarStreamSurfaceInAUniformFlow)
{
  auto p = planar_stream_surface();
  FAS::parametrize_tangential(p.tm, uniform_flow, p.r, p.s, FAS::parameters::normalized(false));
  FAS::compute_flow_texture_mask(p.tm, uniform_flow, p.r, p.mask);
  for (Face f : p.tm.faces())
    EXPECT_LT(p.mask[f], 1e-12) << f;
}

TEST(FlowTexture, MaskIsOneWhereTheGradientCrossesTheFlow)
{
  auto p = planar_stream_surface();
  FAS::parametrize_tangential(p.tm, uniform_flow, p.r, p.s, FAS::parameters::normalized(false));
  // s grows across the flow (grad s = v x n): gamma = 90 degrees on every face.
  FAS::compute_flow_texture_mask(p.tm, uniform_flow, p.s, p.mask);
  for (Face f : p.tm.faces())
    EXPECT_GT(p.mask[f], 1 - 1e-12) << f;
}

TEST(FlowTexture, NonFiniteParametrizationIsMasked)
{
  auto p = planar_stream_surface();
  FAS::parametrize_tangential(p.tm, uniform_flow, p.r, p.s, FAS::parameters::normalized(false));
  const Vertex nan_vertex(0), inf_vertex(Vertex(Mesh::size_type(p.tm.number_of_vertices() - 1)));
  p.r[nan_vertex] = std::nan("");
  p.r[inf_vertex] = std::numeric_limits<double>::infinity();
  FAS::compute_flow_texture_mask(p.tm, uniform_flow, p.r, p.mask);
  std::size_t masked = 0;
  for (Face f : p.tm.faces()) {
    bool touches = false;
    for (Vertex v : vertices_around_face(p.tm.halfedge(f), p.tm))
      touches = touches || v == nan_vertex || v == inf_vertex;
    if (touches)
      EXPECT_EQ(p.mask[f], 1.0) << f;
    else
      EXPECT_LT(p.mask[f], 1e-12) << f;
    masked += touches;
  }
  EXPECT_GT(masked, 0u);
  // Outside the domain (no sample): masked too.
  const auto nowhere = [](const Point_3&) { return std::optional<Vector_3>(); };
  FAS::compute_flow_texture_mask(p.tm, nowhere, p.r, p.mask);
  for (Face f : p.tm.faces())
    EXPECT_EQ(p.mask[f], 1.0);
}

TEST(FlowTexture, TextureCoordinatesAreTheScaledParametrizationWithTheOffset)
{
  auto p = planar_stream_surface();
  FAS::parametrize_tangential(p.tm, uniform_flow, p.r, p.s, FAS::parameters::normalized(false));
  auto uv = p.tm.add_property_map<Vertex, std::array<double, 2>>("v:uv").first;
  FAS::compute_flow_texture_coordinates(p.tm, p.r, p.s, uv, 2.0, 0.25);
  for (Vertex v : p.tm.vertices()) {
    EXPECT_EQ(uv[v][0], p.r[v] * 2.0 + 0.25);
    EXPECT_EQ(uv[v][1], p.s[v] * 2.0);
  }
  // u grows along the flow at |v|^2 per unit length (grad r = v): between two points one unit
  // of length apart along the flow direction, u differs by scale * |v|.
  const Vector_3 v(1, 0.5, 0);
  double max_error = 0;
  for (Vertex a : p.tm.vertices()) {
    const Vector_3 d = p.tm.point(a) - CGAL::ORIGIN;
    max_error = std::max(max_error, std::abs(uv[a][0] - uv[Vertex(0)][0] -
                                             2.0 * (d - (p.tm.point(Vertex(0)) - CGAL::ORIGIN)) * v));
  }
  EXPECT_LT(max_error, 1e-9);
}

TEST(FlowTexture, BadInputIsNamed)
{
  expect_invalid_argument([] { FAS::make_noise_texture(0, 16, 4); }, {"make_noise_texture", "width", "0"});
  expect_invalid_argument([] { FAS::make_noise_texture(16, 0, 4); }, {"make_noise_texture", "height", "0"});
  expect_invalid_argument([] { FAS::make_noise_texture(16, 16, std::nan("")); },
                          {"make_noise_texture", "filter_length", "nan"});
  expect_invalid_argument([] { FAS::make_noise_texture(16, 16, std::numeric_limits<double>::infinity()); },
                          {"filter_length", "inf"});
  expect_invalid_argument([] { FAS::make_noise_texture(16, 16, 17); }, {"filter_length", "17"});
  expect_invalid_argument([] { FAS::make_noise_texture(std::size_t(1) << 20, std::size_t(1) << 20, 4); },
                          {"make_noise_texture", "exceeds"});
  expect_invalid_argument([] { FAS::make_arrow_texture(0, 16); }, {"make_arrow_texture", "width"});
  expect_invalid_argument([] { FAS::make_arrow_texture(16, 16, 5, 1); }, {"arrows_along", "5"});
  expect_invalid_argument([] { FAS::make_arrow_texture(16, 16, 1, 0); }, {"arrows_across", "0"});
  auto p = planar_stream_surface();
  auto uv = p.tm.add_property_map<Vertex, std::array<double, 2>>("v:uv", {-1, -1}).first;
  expect_invalid_argument([&] { FAS::compute_flow_texture_coordinates(p.tm, p.r, p.s, uv, 0.0); },
                          {"compute_flow_texture_coordinates", "scale"});
  expect_invalid_argument(
      [&] { FAS::compute_flow_texture_coordinates(p.tm, p.r, p.s, uv, 1.0, std::nan("")); },
      {"offset", "nan"});
  for (Vertex v : p.tm.vertices())
    EXPECT_EQ(uv[v][0], -1) << "untouched";
  Mesh empty;
  auto empty_mask = empty.add_property_map<Face, double>("f:mask").first;
  auto empty_r = empty.add_property_map<Vertex, double>("v:r").first;
  expect_invalid_argument([&] { FAS::compute_flow_texture_mask(empty, uniform_flow, empty_r, empty_mask); },
                          {"compute_flow_texture_mask", "tm"});
}

// The automatic scale: `repeats` over the range of the finite values of r, whatever the size.
TEST(FlowTexture, ScaleGivesTheRepeatsOverTheRangeOfR)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(1, 0, 0), Vector_3(0, 0, 1), 2.0, 2.0, 200);
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  for (Vertex v : tm.vertices())
    r[v] = 5 * tm.point(v).x(); // x in [0, 2]: r in [0, 10]
  EXPECT_DOUBLE_EQ(FAS::flow_texture_scale(tm, r, 3), 0.3);
  EXPECT_DOUBLE_EQ(FAS::flow_texture_scale(tm, r, -2), -0.2);
  r[*tm.vertices().begin()] = std::numeric_limits<double>::infinity(); // left out
  for (Vertex v : tm.vertices())
    if (tm.point(v).x() == 2.0)
      r[v] = std::nan("");
  const double range = [&] {
    double lo = 1e300, hi = -1e300;
    for (Vertex v : tm.vertices())
      if (std::isfinite(r[v]))
        lo = std::min(lo, r[v]), hi = std::max(hi, r[v]);
    return hi - lo;
  }();
  EXPECT_DOUBLE_EQ(FAS::flow_texture_scale(tm, r, 3), 3 / range);
  for (Vertex v : tm.vertices())
    r[v] = 7;
  EXPECT_EQ(FAS::flow_texture_scale(tm, r, 3), 1.0) << "no range: scale 1";
  expect_invalid_argument([&] { FAS::flow_texture_scale(tm, r, 0); }, {"flow_texture_scale", "repeats"});
  expect_invalid_argument([&] { FAS::flow_texture_scale(tm, r, std::nan("")); }, {"repeats", "nan"});
}

} // namespace

} // namespace test_flow_texture
