// libFuzzer target: read_VTK_flow_field() on arbitrary bytes, into a regular grid, with the default
// arrays and with named ones; it must return (true or false) without a sanitizer report.

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>

#include <CGAL/Simple_cartesian.h>

#include "fuzz_input_file.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

typedef CGAL::Simple_cartesian<double> K;
namespace FAS = CGAL::Flow_aligned_surfaces;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string file = fuzz_input_file(data, size, ".vtk");
  std::optional<FAS::Regular_grid_flow_field_3<K>> field;
  std::string error;
  if (FAS::IO::read_VTK_flow_field(file, field, CGAL::parameters::default_values(), &error)) {
    // A field read must answer at its own nodes.
    const auto n = field->dimensions();
    (void)(*field)(field->node_point(n[0] / 2, n[1] / 2, n[2] / 2));
  }
  else if (error.empty())
    __builtin_trap(); // a failure must say why
  FAS::IO::read_VTK_flow_field(
      file, field, FAS::parameters::array_name("velocity", FAS::parameters::mask_array_name("inside")),
      &error);
  return 0;
}
