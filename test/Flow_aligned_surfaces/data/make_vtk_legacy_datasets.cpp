// Writes the vtk_*.vtk files beside it with VTK's own legacy writers (VTK 9.1), so that the
// reader is tested on files written by VTK and not only by hand: a small mesh of a hexahedron, a
// pyramid, a wedge and a tetrahedron (UNSTRUCTURED_GRID, file versions 4.2 and 5.1, ASCII and
// binary), a 3 x 3 x 4 curvilinear STRUCTURED_GRID and a 4 x 3 x 5 RECTILINEAR_GRID, each with
// the linear field v(p) = (1 + x + 2y - z, -2 + x/2 - 3y + 2z, 1/2 - 2x + y + z/4) as the point
// data VECTORS "velocity" and a 1-component "pressure" beside it.  test_read_VTK_legacy_datasets.cpp
// reads them.  Build and run (from this directory):
//   g++ -std=c++17 make_vtk_legacy_datasets.cpp -I/usr/include/vtk-9.1 -lvtkIOLegacy-9.1 \
//       -lvtkCommonDataModel-9.1 -lvtkCommonCore-9.1 -lvtkIOCore-9.1 -o /tmp/make && /tmp/make

#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridWriter.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredGridWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>

#include <array>
#include <string>
#include <vector>

namespace {

std::array<double, 3> linear(const double* p)
{
  return {{1. + p[0] + 2. * p[1] - p[2], -2. + 0.5 * p[0] - 3. * p[1] + 2. * p[2],
           0.5 - 2. * p[0] + p[1] + 0.25 * p[2]}};
}

void add_point_data(vtkDataSet* d)
{
  vtkNew<vtkFloatArray> v, pressure;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  pressure->SetName("pressure");
  for (vtkIdType i = 0; i < d->GetNumberOfPoints(); ++i) {
    double p[3];
    d->GetPoint(i, p);
    const std::array<double, 3> w = linear(p);
    v->InsertNextTuple(w.data());
    pressure->InsertNextValue(static_cast<float>(p[0] * p[1]));
  }
  d->GetPointData()->AddArray(pressure);
  d->GetPointData()->SetVectors(v);
}

template <class Writer>
void write(vtkDataObject* d, const std::string& name, bool binary, int version = 51)
{
  vtkNew<Writer> w;
  w->SetInputData(d);
  w->SetFileName(name.c_str());
  w->SetFileVersion(version);
  if (binary)
    w->SetFileTypeToBinary();
  else
    w->SetFileTypeToASCII();
  w->Write();
}

} // namespace

int main()
{
  // The points of test_read_VTK_legacy_datasets.cpp's kPoints and the same four cells.
  const double pts[19][3] = {{0, 0, 0},   {1, 0, -0.125}, {1.125, 1, 0},    {0, 1, 0}, {0, 0, 1},
                             {1, 0, 1},   {1, 1, 1},      {0, 1, 1},        {0.5, 0.5, 1.75},
                             {2, 0, 0},   {3, 0, 0},      {2, 1, 0},        {2, 0, 1}, {3, 0, 1.25},
                             {2, 1, 1},   {2, 0, 2},      {3, 0, 2},        {2, 1, 2}, {2.25, 0.25, 3}};
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : pts)
    points->InsertNextPoint(p);
  vtkNew<vtkUnstructuredGrid> u;
  u->SetPoints(points);
  const vtkIdType hex[8] = {0, 1, 2, 3, 4, 5, 6, 7}, pyramid[5] = {4, 5, 6, 7, 8},
                  wedge[6] = {9, 10, 11, 12, 13, 14}, tet[4] = {15, 16, 17, 18};
  u->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  u->InsertNextCell(VTK_PYRAMID, 5, pyramid);
  u->InsertNextCell(VTK_WEDGE, 6, wedge);
  u->InsertNextCell(VTK_TETRA, 4, tet);
  add_point_data(u);
  write<vtkUnstructuredGridWriter>(u, "vtk_unstructured_5.1_binary.vtk", true);
  write<vtkUnstructuredGridWriter>(u, "vtk_unstructured_5.1_ascii.vtk", false);
  write<vtkUnstructuredGridWriter>(u, "vtk_unstructured_4.2_binary.vtk", true, 42);
  write<vtkUnstructuredGridWriter>(u, "vtk_unstructured_4.2_ascii.vtk", false, 42);

  // The curvilinear grid of curvilinear_node() in test_read_VTK_legacy_datasets.cpp.
  vtkNew<vtkStructuredGrid> s;
  s->SetDimensions(3, 3, 4);
  vtkNew<vtkPoints> sp;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        sp->InsertNextPoint(i + 0.25 * j + 0.125 * ((i * k) % 2), j + 0.125 * i * i - 0.0625 * k,
                            0.75 * k + 0.125 * ((i + j) % 2));
  s->SetPoints(sp);
  add_point_data(s);
  write<vtkStructuredGridWriter>(s, "vtk_structured_grid_binary.vtk", true);

  // The rectilinear grid of kAxes.
  vtkNew<vtkRectilinearGrid> r;
  r->SetDimensions(4, 3, 5);
  const std::vector<std::vector<double>> axes = {{0., 0.5, 1.25, 3.}, {-1., 0., 0.25}, {0., 1., 1.5, 2., 4.}};
  vtkNew<vtkDoubleArray> x, y, z;
  for (double c : axes[0])
    x->InsertNextValue(c);
  for (double c : axes[1])
    y->InsertNextValue(c);
  for (double c : axes[2])
    z->InsertNextValue(c);
  r->SetXCoordinates(x);
  r->SetYCoordinates(y);
  r->SetZCoordinates(z);
  add_point_data(r);
  write<vtkRectilinearGridWriter>(r, "vtk_rectilinear_grid_ascii.vtk", false);
  return 0;
}
