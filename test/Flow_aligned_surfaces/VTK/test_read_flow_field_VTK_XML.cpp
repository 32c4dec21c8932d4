// read_flow_field() with the VTK library: a .vti file written by write_VTI_flow_field() lands in
// the uniform grid alternative of Sampled_flow_field_3 and gives back the linear field it holds.

#include "../read_flow_field_test_helpers.h"

#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include <gtest/gtest.h>

#include <string>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_flow_field_VTK_XML {

namespace {

using namespace fas_read_flow_field_test;

TEST(ReadFlowField, VTKXMLFiles)
{
  const std::string vti = scratch("grid.vti");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(vti, linear_grid(), CGAL::parameters::default_values(), &error))
      << error;
  expect_reads_linear_field<Sampled::Regular_grid>(vti);
}

} // namespace

} // namespace test_read_flow_field_VTK_XML
