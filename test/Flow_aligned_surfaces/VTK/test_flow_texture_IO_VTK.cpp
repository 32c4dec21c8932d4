// The VTP file of a textured patch read back by VTK's vtkXMLPolyDataReader, which must find the
// texture coordinates as TCoords (a NaN kept) and the texture mask as cell data.

#include "../test_files.h"
#include "../test_kernel.h"
#include "../textured_patch.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_flow_texture_IO_VTK {

namespace {

using namespace fas_test;
using Mesh = Textured_mesh;
using Vertex = Mesh::Vertex_index;

TEST(FlowTextureIO, VTKFindsTheTextureCoordinatesAndTheMaskInTheVTP)
{
  Mesh tm;
  const auto uv = textured_patch(tm);
  std::vector<double> tcoords, mask;
  for (Vertex v : tm.vertices())
    tcoords.insert(tcoords.end(), {uv[v][0], uv[v][1]});
  for (auto f : tm.faces())
    mask.push_back(double(f) / double(tm.number_of_faces()));
  FAS::IO::Data_array texture{"texture_coordinates", 2, tcoords};
  texture.texture_coordinates = true;
  const std::string file = temporary_file("flow_texture_io_", "patch.vtp");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTP(file, tm,
                                 {{"r", 1, std::vector<double>(tm.number_of_vertices(), 1.0)}, texture},
                                 {{"texture_mask", 1, mask}}, FAS::parameters::error_message(&error)))
      << error;
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* polydata = reader->GetOutput();
  ASSERT_EQ(polydata->GetNumberOfPoints(), vtkIdType(tm.number_of_vertices()));
  vtkDataArray* t = polydata->GetPointData()->GetTCoords();
  ASSERT_NE(t, nullptr) << "no TCoords";
  EXPECT_STREQ(t->GetName(), "texture_coordinates");
  ASSERT_EQ(t->GetNumberOfComponents(), 2);
  EXPECT_TRUE(std::isnan(t->GetComponent(0, 0)));
  for (Vertex v : tm.vertices())
    if (v != Vertex(0)) {
      EXPECT_EQ(t->GetComponent(vtkIdType(v), 0), uv[v][0]);
      EXPECT_EQ(t->GetComponent(vtkIdType(v), 1), uv[v][1]);
    }
  vtkDataArray* m = polydata->GetCellData()->GetArray("texture_mask");
  ASSERT_NE(m, nullptr);
  for (auto f : tm.faces())
    EXPECT_EQ(m->GetComponent(vtkIdType(f), 0), mask[f]);
}

} // namespace

} // namespace test_flow_texture_IO_VTK
