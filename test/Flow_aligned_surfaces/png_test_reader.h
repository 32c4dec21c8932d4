// libpng's own reader, the peer of the PNG files the package writes: a file as 8-bit RGB, rows
// from the top of the picture down.

#ifndef FAS_TEST_PNG_TEST_READER_H
#define FAS_TEST_PNG_TEST_READER_H

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_PNG
#include <png.h>

#include <string>
#include <vector>

struct Png_picture {
  std::size_t width = 0, height = 0;
  std::vector<unsigned char> rgb; // 3 bytes per pixel, rows top first; empty if unreadable

  /// The luminance in [0, 1] of the pixel in column x, row y counted from the bottom.
  double luminance(std::size_t x, std::size_t y_up) const
  {
    const unsigned char* p = &rgb[3 * ((height - 1 - y_up) * width + x)];
    return (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255;
  }
};

inline Png_picture read_png(const std::string& filename)
{
  Png_picture picture;
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, filename.c_str()))
    return picture;
  png.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> bytes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr))
    return picture;
  picture.width = png.width;
  picture.height = png.height;
  picture.rgb = std::move(bytes);
  return picture;
}
#endif

#endif // FAS_TEST_PNG_TEST_READER_H
