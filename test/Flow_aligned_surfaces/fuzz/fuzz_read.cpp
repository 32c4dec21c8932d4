// libFuzzer target for one flow-field reader, chosen at compile time (FAS_FUZZ_VTK_legacy,
// FAS_FUZZ_AmiraMesh or FAS_FUZZ_NRRD): the reader runs on arbitrary bytes into a regular
// grid, with the default arrays and with named ones; it must return (true or false, a false
// with a message) without a sanitizer report.

#if defined(FAS_FUZZ_VTK_legacy)
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#define FAS_FUZZ_READ read_VTK_flow_field
#define FAS_FUZZ_EXTENSION ".vtk"
#define FAS_FUZZ_HAS_MASK 1
#elif defined(FAS_FUZZ_AmiraMesh)
#include <CGAL/Flow_aligned_surfaces/IO/read_AmiraMesh.h>
#define FAS_FUZZ_READ read_AmiraMesh_flow_field
#define FAS_FUZZ_EXTENSION ".am"
#define FAS_FUZZ_HAS_MASK 1
#elif defined(FAS_FUZZ_NRRD)
#include <CGAL/Flow_aligned_surfaces/IO/read_NRRD.h>
#define FAS_FUZZ_READ read_NRRD_flow_field
#define FAS_FUZZ_EXTENSION ".nhdr"
#define FAS_FUZZ_HAS_MASK 0
#else
#error "define FAS_FUZZ_VTK_legacy, FAS_FUZZ_AmiraMesh or FAS_FUZZ_NRRD"
#endif

#include <CGAL/Simple_cartesian.h>

#include "fuzz_input_file.h"

#include <cstddef>
#include <cstdint>
#include <string>

typedef CGAL::Simple_cartesian<double> K;
namespace FAS = CGAL::Flow_aligned_surfaces;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string file = fuzz_input_file(data, size, FAS_FUZZ_EXTENSION);
  FAS::Regular_grid_flow_field_3<K> field;
  std::string error;
  if (FAS::IO::FAS_FUZZ_READ(file, field, FAS::parameters::error_message(&error))) {
    // A field read must answer at its own nodes.
    const auto n = field.dimensions();
    (void)field(field.node_point(n[0] / 2, n[1] / 2, n[2] / 2));
  }
  else if (error.empty())
    __builtin_trap(); // a failure must say why
#if FAS_FUZZ_HAS_MASK
  FAS::IO::FAS_FUZZ_READ(
      file, field,
      FAS::parameters::error_message(
          &error, FAS::parameters::array_name("velocity", FAS::parameters::mask_array_name("inside"))));
#else
  FAS::IO::FAS_FUZZ_READ(file, field,
                         FAS::parameters::error_message(&error, FAS::parameters::array_name("velocity")));
#endif
  return 0;
}
