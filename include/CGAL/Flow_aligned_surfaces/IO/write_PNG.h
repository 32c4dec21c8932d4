// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A Texture_image as an 8-bit RGB PNG file: channel value c in [0, 1] -> round(255 c), clamped;
// the image's top row (y = height - 1) first, as PNG stores it.  Needs libpng (the macro
// CGAL_FLOW_ALIGNED_SURFACES_USE_PNG, set by the CMake target when libpng is found); without
// it, write_PNG() writes nothing and returns false with the reason.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_PNG_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_PNG_H

#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/write_file_atomically.h>

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_PNG
#include <png.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Writes `image` to `filename` as an 8-bit RGB PNG file (each channel
\f$ c \in [0, 1] \f$ becomes \f$ \mathrm{round}(255\, c) \f$; values outside are clamped and
NaN becomes 0).

The file is written beside `filename` and renamed over it when complete, so an existing file
is never left half-written.  Needs libpng: the package's CMake target defines
`CGAL_FLOW_ALIGNED_SURFACES_USE_PNG` when it finds it (Debian: `libpng-dev`); without it the
function writes nothing and returns `false` with the reason.

\param filename the output file
\param image the image; its `pixels` must hold `3 * width * height` values
\param error if not null, receives the reason of a failure

\returns `true` on success, `false` if the image is empty or inconsistent, libpng is not
available, or the file could not be written.
\sa `make_noise_texture()`, `write_textured_OBJ()`
*/
inline bool write_PNG(const std::string& filename, const Texture_image& image, std::string* error = nullptr)
{
  auto fail = [&](const std::string& reason) {
    if (error)
      *error = "write_PNG: " + filename + ": " + reason;
    return false;
  };
  if (image.width == 0 || image.height == 0 || image.pixels.size() != 3 * image.width * image.height)
    return fail("the image is empty or its pixels do not match width x height = " +
                std::to_string(image.width) + " x " + std::to_string(image.height));
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_PNG
  std::vector<unsigned char> bytes(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), bytes.begin(),
                 Flow_aligned_surfaces::internal::texel_byte);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // A negative row stride: the buffer's first row (y = 0) is the bottom of the picture.
  const png_int_32 stride = -png_int_32(3 * image.width);
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, bytes.data(), stride, nullptr))
    return fail(std::string("libpng: ") + png.message);
  std::vector<char> encoded(size);
  if (!png_image_write_to_memory(&png, encoded.data(), &size, 0, bytes.data(), stride, nullptr))
    return fail(std::string("libpng: ") + png.message);
  std::string reason;
  if (!internal::write_file_atomically(
          filename, reason, [&](std::ostream& os) { os.write(encoded.data(), std::streamsize(size)); }))
    return fail(reason);
  return true;
#else
  return fail("built without libpng (CGAL_FLOW_ALIGNED_SURFACES_USE_PNG is not defined; Debian: "
              "libpng-dev), so no PNG is written");
#endif
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_PNG_H
