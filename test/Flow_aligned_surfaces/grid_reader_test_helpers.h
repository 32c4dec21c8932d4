// What the tests of the uniform-grid readers share: files written byte by byte, numbers
// appended in either byte order, a sentinel field that a failed read must leave as it was, and
// the checks of one reader (success; failure = false, a message naming the file and every given
// part, the field kept).

#ifndef FAS_TEST_GRID_READER_TEST_HELPERS_H
#define FAS_TEST_GRID_READER_TEST_HELPERS_H

#include "test_files.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>

#include <gtest/gtest.h>

#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
#include <zlib.h>
#endif

#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace fas_test {

typedef CGAL::Flow_aligned_surfaces::Regular_grid_flow_field_3<K> Grid;

using ::write_bytes;

/// Appends the bytes of `v` (an arithmetic value) in the given byte order.
template <class T>
void append_binary(std::string& s, T v, bool big_endian)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  const unsigned one = 1;
  const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    s += static_cast<char>(b[host_little == big_endian ? sizeof(T) - 1 - i : i]);
}

/// The vectors `f(i, j, k)` at the nodes of an `n[0] x n[1] x n[2]` grid, x fastest: as text, one
/// node a line, 6 decimals (exact for quarters)...
template <class F>
std::string node_values_text(const Grid::Dimensions& n, const F& f)
{
  std::string s;
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        const Grid::Vector_3 v = f(i, j, k);
        s += std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z()) + "\n";
      }
  return s;
}

/// ... or as binary numbers of type `T` in the given byte order.
template <class T, class F>
std::string node_values_binary(const Grid::Dimensions& n, const F& f, bool big_endian)
{
  std::string s;
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        const Grid::Vector_3 v = f(i, j, k);
        for (int c = 0; c < 3; ++c)
          append_binary(s, static_cast<T>(v[c]), big_endian);
      }
  return s;
}

#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
/// `bytes` compressed by zlib itself, in the zlib format (`gzip = false`) or the gzip one.
inline std::string zlib_compress(const std::string& bytes, bool gzip)
{
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, gzip ? 15 + 16 : 15, 8, Z_DEFAULT_STRATEGY),
            Z_OK);
  std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(&out[0]);
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  return out;
}
#endif

/// A grid unlike the ones read, to detect that a failed read changed nothing.
inline Grid sentinel_grid()
{
  return Grid(Grid::Point_3(7, 7, 7), Grid::Vector_3(1, 1, 1), Grid::Dimensions{{2, 2, 2}},
              std::vector<float>(24, 3.f));
}

inline void expect_untouched(const Grid& g)
{
  const Grid s = sentinel_grid();
  EXPECT_EQ(g.dimensions(), s.dimensions());
  EXPECT_EQ(g.origin(), s.origin());
  EXPECT_EQ(g.spacing(), s.spacing());
  EXPECT_EQ(g.values(), s.values());
  EXPECT_FALSE(g.has_mask());
}

/// The checks of one reader: `Reader` is a functor `bool(file, Grid&, np, std::string* error)`
/// calling it; the files go to the test's temporary folder, their names starting with `prefix`.
template <class Reader>
class Grid_reader_checks {
public:
  explicit Grid_reader_checks(std::string prefix) : prefix_(std::move(prefix)) {}

  std::string temporary(const std::string& name) const { return temporary_file(prefix_, name); }

  /// Writes `contents` to a file, reads it and expects success.
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  Grid read_ok(const std::string& name, const std::string& contents,
               const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    const std::string file = temporary(name);
    write_bytes(file, contents);
    Grid g = sentinel_grid();
    std::string error;
    EXPECT_TRUE(Reader()(file, g, np, &error)) << error;
    return g;
  }

  /// Writes `contents` to a file, reads it into a sentinel grid and expects `false`, a message
  /// naming the file and holding every one of `parts`, and the grid untouched.
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  void expect_failure(const std::string& name, const std::string& contents,
                      std::initializer_list<std::string> parts,
                      const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    const std::string file = temporary(name);
    write_bytes(file, contents);
    Grid g = sentinel_grid();
    std::string error;
    EXPECT_FALSE(Reader()(file, g, np, &error)) << name;
    EXPECT_NE(error.find(file), std::string::npos) << "the message does not name the file: " << error;
    for (const std::string& part : parts)
      EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' is not in the message: " << error;
    expect_untouched(g);
  }

  /// Every prefix of `contents` shorter than `until` bytes (one every `step`) fails with a
  /// message, the grid untouched.
  void expect_every_cut_fails(const std::string& contents, std::size_t until, std::size_t step) const
  {
    const std::string file = temporary("every_cut");
    for (std::size_t cut = 0; cut < until; cut += step) {
      write_bytes(file, contents.substr(0, cut));
      Grid g = sentinel_grid();
      std::string error;
      EXPECT_FALSE(Reader()(file, g, CGAL::parameters::default_values(), &error)) << "cut at " << cut;
      EXPECT_FALSE(error.empty());
      expect_untouched(g);
    }
  }

private:
  std::string prefix_;
};

} // namespace fas_test

#endif // FAS_TEST_GRID_READER_TEST_HELPERS_H
