// IO::write_VTP_polylines(): the file read back by VTK's own vtkXMLPolyDataReader (the peer).

#include "../polylines_test_data.h"
#include "../test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_write_VTP_polylines_VTK {

namespace {

using namespace fas_test;

const std::vector<std::vector<Point_3>>& lines = test_polylines();

TEST(write_VTP_polylines, read_back_by_VTK)
{
  const auto path = polylines_scratch("lines.vtp");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTP_polylines(path.string(), lines, {{"t", 1, {0., 1., 2., 0., std::nan("")}}},
                                           {{"id", 1, {10., 11.}}}, FAS::parameters::error_message(&error)))
      << error;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkPolyData* pd = reader->GetOutput();
  ASSERT_EQ(pd->GetNumberOfPoints(), 5);
  ASSERT_EQ(pd->GetNumberOfLines(), 2);
  ASSERT_EQ(pd->GetNumberOfPolys(), 0);
  vtkNew<vtkIdList> ids;
  vtkIdType k = 0;
  for (vtkIdType c = 0; c < 2; ++c) {
    pd->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), vtkIdType(lines[std::size_t(c)].size()));
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i, ++k) {
      EXPECT_EQ(ids->GetId(i), k);
      double p[3];
      pd->GetPoint(ids->GetId(i), p);
      const Point_3& q = lines[std::size_t(c)][std::size_t(i)];
      EXPECT_EQ(p[0], q.x());
      EXPECT_EQ(p[1], q.y());
      EXPECT_EQ(p[2], q.z());
    }
  }
  vtkDataArray* t = pd->GetPointData()->GetArray("t");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->GetTuple1(2), 2.);
  EXPECT_TRUE(std::isnan(t->GetTuple1(4)));
  vtkDataArray* id = pd->GetCellData()->GetArray("id");
  ASSERT_NE(id, nullptr);
  EXPECT_EQ(id->GetTuple1(1), 11.);
}

} // namespace

} // namespace test_write_VTP_polylines_VTK
