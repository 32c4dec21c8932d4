// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// LIC-like textures mapped by the unnormalized tangential parametrization (Section 6 of the
// paper).  With r, s the vertex fields of parametrize_tangential(normalized(false)):
//
//   texture coordinates   (u, v) = (r * scale + offset, s * scale)   (offset animates, per frame)
//   per-face mask         b_j = b(gamma_j),  b(g) = 3 x^2 - 2 x^3,  x = min(g / (pi/2), 1)
//   shown colour          c = (1 - b) T(u, v) + b * mean(T)
//
// gamma_j in [0, pi] is the angle between the field at the centroid of face j and the gradient of
// r on it; b(0) = 0, b(pi/2) = 1, b'(0) = b'(pi/2) = 0 (the paper's "smooth cubic sigmoid").
// Faces where gamma is undefined (r not finite, zero gradient, no usable sample) get b = 1.
//
// The textures are periodic in both axes (width x height texels, RGB in [0, 1]):
//   noise:  N(x, y) = white noise, each channel uniform in [0, 1] from std::mt19937(seed);
//           F = N convolved along x (the time axis, u) with a periodic box of length L texels;
//           T = clamp(0.5 + 0.25 (F - mean F) / std F, 0, 1) per channel (contrast restored);
//   arrows: a grid of arrows pointing along +x, dark on light, 4 x 4 supersampled.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_FLOW_TEXTURE_H
#define CGAL_FLOW_ALIGNED_SURFACES_FLOW_TEXTURE_H

#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/*!
\ingroup PkgFlowAlignedSurfacesRef

A small RGB image with `float` channels in \f$ [0, 1] \f$, stored row by row from the bottom
row (\f$ y = 0 \f$) up, as OpenGL, VTK and OBJ address textures: the texel \f$ (x, y) \f$ has
its red, green and blue channels at `pixels[3 * (y * width + x) + c]`, \f$ c = 0, 1, 2 \f$, and
the texture coordinates \f$ (u, v) \f$ address the texel
\f$ (\lfloor u\, \mathrm{width} \rfloor, \lfloor v\, \mathrm{height} \rfloor) \f$, repeated
outside \f$ [0, 1)^2 \f$.  `IO::write_PNG()` writes the top row first, as PNG stores it.
*/
struct Texture_image {
  std::size_t width = 0;     ///< the number of texels per row
  std::size_t height = 0;    ///< the number of rows
  std::vector<float> pixels; ///< `3 * width * height` channel values in \f$ [0, 1] \f$

  /// The channel `c` of texel `(x, y)`.
  float& operator()(std::size_t x, std::size_t y, std::size_t c) { return pixels[3 * (y * width + x) + c]; }
  /// The channel `c` of texel `(x, y)`.
  float operator()(std::size_t x, std::size_t y, std::size_t c) const
  {
    return pixels[3 * (y * width + x) + c];
  }
  /// The mean colour of the image, the colour masked regions blend to.
  std::array<double, 3> mean_color() const
  {
    std::array<double, 3> mean{0, 0, 0};
    for (std::size_t i = 0; i < pixels.size(); ++i)
      mean[i % 3] += pixels[i];
    for (double& m : mean)
      m /= double(std::max<std::size_t>(1, width * height));
    return mean;
  }
};

namespace internal {

/// Texture sizes above this many texels are refused (a 16384^2 RGB float image is 3 GB).
constexpr std::size_t max_texture_texels = std::size_t(1) << 26;

inline Texture_image make_texture_or_throw(std::size_t width, std::size_t height, const std::string& caller)
{
  if (width == 0 || height == 0)
    throw std::invalid_argument(caller + ": width and height must be positive (got width " +
                                std::to_string(width) + ", height " + std::to_string(height) + ")");
  if (width > max_texture_texels / height)
    throw std::invalid_argument(caller + ": width x height = " + std::to_string(width) + " x " +
                                std::to_string(height) + " exceeds " + std::to_string(max_texture_texels) +
                                " texels");
  Texture_image image;
  image.width = width;
  image.height = height;
  image.pixels.assign(3 * width * height, 0.0f);
  return image;
}

/// A channel value in [0, 1] as a byte: round(255 c), clamped, NaN -> 0.
inline unsigned char texel_byte(float c)
{
  return (unsigned char)(std::isnan(c) ? 0 : std::lround(255 * std::clamp(c, 0.0f, 1.0f)));
}

/// The weights of a periodic box of length `length` texels centered on a texel: 1 inside,
/// fractional at the two ends, summing to `length`.
inline std::vector<double> box_weights(double length)
{
  const double half = length / 2;
  const int reach = int(std::ceil(half + 0.5));
  std::vector<double> w(std::size_t(2 * reach + 1));
  for (int k = -reach; k <= reach; ++k)
    w[std::size_t(k + reach)] = std::clamp(half + 0.5 - std::abs(k), 0.0, 1.0);
  return w;
}

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Makes a seamless high-contrast coloured noise texture, low-pass filtered along its
\f$ x \f$ axis (the texture's time axis \f$ u \f$, which `compute_flow_texture_coordinates()`
maps to \f$ r \f$, along the flow): the LIC-like texture of the paper's Section 6.

Each channel of each texel is white noise, uniform in \f$ [0, 1] \f$, drawn from
`std::mt19937(seed)` (whose sequence the C++ standard fixes, so a seed gives the same
texture everywhere).  Each row is convolved with a box of `filter_length` texels (fractional
weights at its two ends) with periodic wrap, so the texture tiles without a seam in both
directions; the contrast lost in the filter is restored per channel,
\f$ T = \mathrm{clamp}(1/2 + (F - \bar F) / (4 \sigma_F), 0, 1) \f$.  The autocorrelation of
\f$ F \f$ along \f$ x \f$ is the triangle \f$ 1 - |k| / L \f$ (zero from \f$ |k| \ge L \f$),
across it it is zero from lag 1.

\param width, height the size in texels
\param filter_length \f$ L \f$, the length of the box in texels, in \f$ [1, \mathrm{width}] \f$
       (1: unfiltered noise)
\param seed the seed of the noise

\returns the texture.
\throws std::invalid_argument naming `width`, `height` or `filter_length` if a size is zero or
the image would exceed \f$ 2^{26} \f$ texels, or `filter_length` is not finite or outside
\f$ [1, \mathrm{width}] \f$.
\sa `make_arrow_texture()`, `compute_flow_texture_coordinates()`, `compute_flow_texture_mask()`
*/
inline Texture_image make_noise_texture(std::size_t width, std::size_t height, double filter_length,
                                        std::uint32_t seed = 0)
{
  const std::string caller = "make_noise_texture";
  Texture_image image = internal::make_texture_or_throw(width, height, caller);
  if (!std::isfinite(filter_length) || filter_length < 1 || filter_length > double(width))
    throw std::invalid_argument(caller + ": filter_length must be finite and in [1, width = " +
                                std::to_string(width) + "] (got " + std::to_string(filter_length) + ")");
  std::mt19937 random(seed);
  std::vector<double> noise(image.pixels.size());
  for (double& n : noise)
    n = double(random()) / 4294967296.0; // mt19937 gives 32 uniform bits

  const std::vector<double> weights = internal::box_weights(filter_length);
  const long reach = long(weights.size() / 2), w = long(width);
  std::vector<double> filtered(noise.size(), 0.0);
  for (std::size_t y = 0; y < height; ++y)
    for (long x = 0; x < w; ++x)
      for (long k = -reach; k <= reach; ++k) {
        const double weight = weights[std::size_t(k + reach)];
        if (weight == 0)
          continue;
        const std::size_t source = y * width + std::size_t(((x + k) % w + w) % w);
        for (std::size_t c = 0; c < 3; ++c)
          filtered[3 * (y * width + std::size_t(x)) + c] += weight * noise[3 * source + c] / filter_length;
      }

  for (std::size_t c = 0; c < 3; ++c) {
    double mean = 0, variance = 0;
    for (std::size_t i = c; i < filtered.size(); i += 3)
      mean += filtered[i];
    mean /= double(width * height);
    for (std::size_t i = c; i < filtered.size(); i += 3)
      variance += (filtered[i] - mean) * (filtered[i] - mean);
    const double deviation = std::sqrt(variance / double(width * height));
    for (std::size_t i = c; i < filtered.size(); i += 3)
      image.pixels[i] =
          float(std::clamp(0.5 + (deviation > 0 ? (filtered[i] - mean) / (4 * deviation) : 0.0), 0.0, 1.0));
  }
  return image;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Makes a seamless texture of arrows pointing along \f$ +x \f$ (the texture's time axis
\f$ u \f$, along the flow once mapped by `compute_flow_texture_coordinates()`): the paper's
illustrative texture.

The tile is divided into `arrows_along` \f$ \times \f$ `arrows_across` equal cells; each cell
holds one dark arrow (a shaft over the middle 60% of the cell's length, a triangular head over
the last 25%) on a light background, antialiased by 4 \f$ \times \f$ 4 supersampling.  Since
every cell is inside the tile, the texture repeats without a seam.

\param width, height the size in texels
\param arrows_along, arrows_across the number of arrows per tile along \f$ x \f$ and \f$ y \f$,
       at least 1 and at most width / 4 (height / 4)

\returns the texture.
\throws std::invalid_argument naming the parameter if a size is zero or too large, or a number
of arrows is outside its range.
\sa `make_noise_texture()`
*/
inline Texture_image make_arrow_texture(std::size_t width, std::size_t height, std::size_t arrows_along = 4,
                                        std::size_t arrows_across = 4)
{
  const std::string caller = "make_arrow_texture";
  Texture_image image = internal::make_texture_or_throw(width, height, caller);
  if (arrows_along < 1 || arrows_along > width / 4)
    throw std::invalid_argument(caller + ": arrows_along must be in [1, width / 4 = " +
                                std::to_string(width / 4) + "] (got " + std::to_string(arrows_along) + ")");
  if (arrows_across < 1 || arrows_across > height / 4)
    throw std::invalid_argument(caller + ": arrows_across must be in [1, height / 4 = " +
                                std::to_string(height / 4) + "] (got " + std::to_string(arrows_across) + ")");
  // Whether the point (a, b) of a cell in [0, 1)^2 (a along the arrow) is inside the arrow.
  auto inside = [](double a, double b) {
    const double across = std::abs(b - 0.5);
    if (a >= 0.15 && a < 0.65)
      return across < 0.06;
    if (a >= 0.65 && a < 0.9)
      return across < 0.25 * (0.9 - a) / 0.25;
    return false;
  };
  const std::array<double, 3> background{0.95, 0.93, 0.85}, arrow{0.1, 0.15, 0.35};
  const int samples = 4;
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t x = 0; x < width; ++x) {
      int covered = 0;
      for (int i = 0; i < samples; ++i)
        for (int j = 0; j < samples; ++j) {
          const double u = (double(x) + (i + 0.5) / samples) * double(arrows_along) / double(width);
          const double v = (double(y) + (j + 0.5) / samples) * double(arrows_across) / double(height);
          covered += inside(u - std::floor(u), v - std::floor(v)) ? 1 : 0;
        }
      const double t = double(covered) / (samples * samples);
      for (std::size_t c = 0; c < 3; ++c)
        image(x, y, c) = float((1 - t) * background[c] + t * arrow[c]);
    }
  return image;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief The blending function of the paper's Section 6: the cubic sigmoid
\f$ b(\gamma) = 3 x^2 - 2 x^3 \f$, \f$ x = \min(\gamma / (\pi/2), 1) \f$, with \f$ b(0) = 0 \f$,
\f$ b(\pi/2) = 1 \f$ and \f$ b'(0) = b'(\pi/2) = 0 \f$; 1 for \f$ \gamma \ge \pi/2 \f$ and
for a \f$ \gamma \f$ that is negative or not finite (undefined angle).

\param gamma the angle between the flow and \f$ \nabla r \f$, radians
*/
inline double flow_texture_blending(double gamma)
{
  if (!(gamma >= 0)) // negative or NaN
    return 1;
  const double x = std::min(gamma / (CGAL_PI / 2), 1.0);
  return x * x * (3 - 2 * x);
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes the mask \f$ b(\gamma_j) \f$ of `flow_texture_blending()` of every face of `tm`
into `mask_map`, where \f$ \gamma_j \f$ is the angle between the field at the centroid of face
\f$ j \f$ and the gradient of the piecewise linear `r_map` on it (the angle of
`compute_face_alignment_angles()`): 0 where the texture follows the flow, 1 where it is
replaced by its mean colour.

Faces where \f$ \gamma_j \f$ is undefined get 1: a value of \f$ r \f$ that is not finite
(NaN or infinite), a zero gradient, a centroid sample that is outside the domain, zero or not
finite, and degenerate faces.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam RMap a model of `ReadablePropertyMap` with the vertices as key type and a number type
convertible to `double` as value type
\tparam MaskMap a model of `WritablePropertyMap` with the faces as key type and `double` as
value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param r_map the \f$ r \f$ of `parametrize_tangential()` (unnormalized for LIC)
\param mask_map receives \f$ b \in [0, 1] \f$ for every face
\param np the same named parameters as `compute_face_alignment_angles()` (with
`min_relative_speed`, the slow faces are masked too)

\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh, or if
`min_relative_speed` is not in \f$ [0, 1] \f$; `mask_map` is then untouched.
\sa `compute_face_alignment_angles()`, `compute_flow_texture_coordinates()`, `make_noise_texture()`
*/
template <class TriangleMesh, class FlowField, class RMap, class MaskMap,
          class NamedParameters = parameters::Default_named_parameters>
void compute_flow_texture_mask(const TriangleMesh& tm, const FlowField& field, RMap r_map, MaskMap mask_map,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_triangle_mesh(tm, "compute_flow_texture_mask: tm");
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor, double>> masks(
      num_faces(tm));
  for (auto f : faces(tm))
    masks[get(fim, f)] = {f, 1.0};
  for (const auto& face : internal::face_alignment_angles(tm, field, r_map, np, "compute_flow_texture_mask"))
    masks[get(fim, face.face)].second =
        flow_texture_blending(face.angle < 0 ? -1.0 : face.angle * CGAL_PI / 180);
  for (const auto& m : masks)
    put(mask_map, m.first, m.second);
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes the texture coordinates \f$ (u, v) = (r \cdot \mathrm{scale} + \mathrm{offset},\;
s \cdot \mathrm{scale}) \f$ of every vertex of `tm` into `uv_map`.

With the unnormalized tangential parametrization (`parametrize_tangential()` with
`FAS::parameters::normalized(false)`), \f$ u \f$ runs along the flow, proportional to the
time of flight, and \f$ v \f$ across it; a texture whose structure runs along its \f$ x \f$
axis (`make_noise_texture()`, `make_arrow_texture()`) then follows the flow on the surface,
the same in every view.  Increasing `offset` from frame to frame moves the structure along
the flow (the paper's animation of steady flows): one texture repeat per unit of offset.
Values of \f$ r \f$ or \f$ s \f$ that are not finite give coordinates that are not finite
(such faces are masked by `compute_flow_texture_mask()`).

\tparam TriangleMesh a model of `VertexListGraph`
\tparam RMap, SMap models of `ReadablePropertyMap` with the vertices as key type and a number
type convertible to `double` as value type
\tparam UVMap a model of `WritablePropertyMap` with the vertices as key type and
`std::array<double, 2>` as value type

\param tm the mesh
\param r_map, s_map the parametrization
\param uv_map receives \f$ (u, v) \f$
\param scale texture repeats per unit of \f$ r \f$ and \f$ s \f$ (finite, not zero)
\param offset the animation offset added to \f$ u \f$ (finite)

\throws std::invalid_argument naming `scale` or `offset` if it is not finite or `scale` is zero;
`uv_map` is then untouched.
\sa `compute_flow_texture_mask()`, `parametrize_tangential()`
*/
template <class TriangleMesh, class RMap, class SMap, class UVMap>
void compute_flow_texture_coordinates(const TriangleMesh& tm, RMap r_map, SMap s_map, UVMap uv_map,
                                      double scale, double offset = 0)
{
  const std::string caller = "compute_flow_texture_coordinates";
  if (!std::isfinite(scale) || scale == 0)
    throw std::invalid_argument(caller + ": scale must be finite and not zero (got " + std::to_string(scale) +
                                ")");
  if (!std::isfinite(offset))
    throw std::invalid_argument(caller + ": offset must be finite (got " + std::to_string(offset) + ")");
  for (auto v : vertices(tm))
    put(uv_map, v,
        std::array<double, 2>{CGAL::to_double(get(r_map, v)) * scale + offset,
                              CGAL::to_double(get(s_map, v)) * scale});
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Returns the `scale` of `compute_flow_texture_coordinates()` that puts `repeats` texture
repeats along the flow over the whole surface: `repeats` divided by the range of the finite
values of \f$ r \f$ on the vertices of `tm` (1 when there is no range: no vertex, or \f$ r \f$
constant).

The scale that shows the texture's structure depends on the flow's speed and the surface's size
(with the unnormalized parametrization \f$ r \f$ grows like the time of flight): a fixed scale
shows a few flat bands on one data set and noise on another.  This one shows the same number of
repeats on every surface.

\tparam TriangleMesh a model of `VertexListGraph`
\tparam RMap a model of `ReadablePropertyMap` with the vertices as key type and a number type
convertible to `double` as value type

\param tm the mesh
\param r_map the parametrization's \f$ r \f$
\param repeats the number of repeats along the flow (finite, not zero; negative mirrors the
texture)

\throws std::invalid_argument naming `repeats` if it is not finite or zero.
\sa `compute_flow_texture_coordinates()`
*/
template <class TriangleMesh, class RMap>
double flow_texture_scale(const TriangleMesh& tm, RMap r_map, double repeats)
{
  if (!std::isfinite(repeats) || repeats == 0)
    throw std::invalid_argument("flow_texture_scale: repeats must be finite and not zero (got " +
                                std::to_string(repeats) + ")");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (auto v : vertices(tm)) {
    const double r = CGAL::to_double(get(r_map, v));
    if (std::isfinite(r)) {
      lo = (std::min)(lo, r);
      hi = (std::max)(hi, r);
    }
  }
  return hi > lo ? repeats / (hi - lo) : 1.0;
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_FLOW_TEXTURE_H
