// libFuzzer target for the VTK XML readers (no VTK): `read_VTK_XML_flow_field` runs on
// arbitrary bytes into an `Unstructured_flow_field_3` (the file may be a .vti, .vtr, .vtu or
// .vts: the reader tells them by their contents), when the bytes hold "ImageData" into a
// `Regular_grid_flow_field_3`, and when they hold "Grid" or "Image" into a
// `Rectilinear_grid_flow_field_3`; when they hold a "\n--DATA--\n" line, the bytes before it are
// also read by `read_PVD_flow_field` as a .pvd collection whose steps may name `data.raw`,
// the bytes after it (see fuzz_input_file.h).  Each call must return (true, or false with a
// message) without a sanitizer report.

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>

#include <CGAL/Simple_cartesian.h>

#include "fuzz_input_file.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

typedef CGAL::Simple_cartesian<double> K;
namespace FAS = CGAL::Flow_aligned_surfaces;
typedef FAS::Unstructured_flow_field_3<K> Cells;

namespace {

// A failure must say why.
void check(bool read, const std::string& error)
{
  if (!read && error.empty())
    __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string file = fuzz_input_file(data, size, ".vti");
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::string error;
  Cells cells;
  bool read = FAS::IO::read_VTK_XML_flow_field(file, cells, FAS::parameters::error_message(&error));
  check(read, error);
  if (read) // a field read must answer at one of its points
    (void)cells(K::Point_3(cells.points()[0], cells.points()[1], cells.points()[2]));
  if (bytes.find("ImageData") != std::string_view::npos) {
    FAS::Regular_grid_flow_field_3<K> grid;
    error.clear();
    read = FAS::IO::read_VTK_XML_flow_field(
        file, grid,
        FAS::parameters::error_message(
            &error, FAS::parameters::array_name("velocity", FAS::parameters::mask_array_name("inside"))));
    check(read, error);
    if (read) {
      const auto n = grid.dimensions();
      (void)grid(grid.node_point(n[0] / 2, n[1] / 2, n[2] / 2));
    }
  }
  if (bytes.find("Grid") != std::string_view::npos || bytes.find("Image") != std::string_view::npos) {
    FAS::Rectilinear_grid_flow_field_3<K> rectilinear;
    error.clear();
    read = FAS::IO::read_VTK_XML_flow_field(file, rectilinear, FAS::parameters::error_message(&error));
    check(read, error);
  }
  const std::size_t separator = bytes.find("\n--DATA--\n");
  if (separator != std::string_view::npos) {
    const std::string pvd = fuzz_folder() + "/input.pvd";
    fuzz_write(pvd, bytes.substr(0, separator + 1));
    FAS::Unsteady_flow_field_3<Cells> series;
    error.clear();
    read = FAS::IO::read_PVD_flow_field(pvd, series, FAS::parameters::error_message(&error));
    check(read, error);
    if (read)
      (void)series(K::Point_3(0., 0., 0.), series.start_time());
  }
  return 0;
}
