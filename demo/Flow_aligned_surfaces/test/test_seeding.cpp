// The main job's seeding (the paper's Figure 4, top) against answers known without the code:
// - in the potential flow past a cylinder, a seed segment along z at (x0, y0) has as stream
//   surface the level set psi = psi(x0, y0) of the exact stream function, between the segment's
//   z; two such segments on one level set are integrated once, a third on another level set
//   (or on the same one moved off by 0.1) again;
// - a tangential patch grown across the flow is larger, across the flow (along z), and still
//   tangential;
// - stream lines carry VTK's arrays: IntegrationTime 0 at the seed and increasing along the
//   line, the velocity of the flow at each point, SeedIds naming the seed (a seed inside the
//   cylinder gives no line);
// - the VTP files are binary, inline (no appended data, which ParaView 5.11's VTK cannot parse
//   with the current expat) and zlib-compressed with their active scalars, read back by VTK's
//   own reader; a wrong array is refused and nothing is written.

#include "test_files.h"

#include "distinct_stream_surfaces.h"
#include "grow_across_flow.h"
#include "stream_lines_with_arrays.h"
#include "write_polydata_VTP.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#endif

#include <cmath>
#include <filesystem>
#include <vector>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyline = std::vector<Point>;
using Cylinder = FAS::Cylinder_potential_flow<K>;

// psi = y (1 - 1 / (x^2 + y^2)) for R = U = 1.
double psi(double x, double y)
{
  return y * (1 - 1 / (x * x + y * y));
}

// The y > 1 at which psi(x, y) = level (psi increases with y there), by bisection.
double y_on_level(double x, double level)
{
  double lo = 1, hi = 10;
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2;
    (psi(x, mid) < level ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

Polyline z_segment(double x, double y, double z0, double z1, int n)
{
  Polyline line;
  for (int i = 0; i <= n; ++i)
    line.emplace_back(x, y, z0 + (z1 - z0) * i / n);
  return line;
}

TEST(DistinctStreamSurfaces, TwoCurvesOnOneStreamSurfaceAreIntegratedOnce)
{
  const Cylinder flow(1, 1);
  const double level = psi(-3, 0.8), other_level = psi(-3, 1.6);
  const std::vector<Polyline> seeds{z_segment(-3, 0.8, -0.5, 0.5, 10),
                                    z_segment(-1.5, y_on_level(-1.5, level), -0.4, 0.4, 8),
                                    z_segment(-3, 1.6, -0.5, 0.5, 10),
                                    z_segment(-1.5, y_on_level(-1.5, level) + 0.1, -0.4, 0.4, 8)};
  const auto result = fas_demo::integrate_distinct_stream_surfaces<Mesh>(flow, seeds, 0.05, 3.0);
  ASSERT_EQ(result.surface_of.size(), 4u);
  EXPECT_EQ(result.surface_of[0], 0u);
  EXPECT_EQ(result.surface_of[1], 0u) << "the second curve lies on the first one's stream surface";
  EXPECT_EQ(result.surface_of[2], 2u);
  EXPECT_EQ(result.surface_of[3], 3u) << "0.1 off the level set is another surface";
  EXPECT_EQ(result.number_of_surfaces(), 3u);
  EXPECT_TRUE(result.skipped_reasons.empty());

  // Every vertex lies on its seed's level set of the exact stream function, within its z range;
  // the forward and backward halves are one mesh (t of both signs).
  const Mesh& mesh = result.mesh;
  const auto seed = mesh.property_map<Mesh::Vertex_index, double>("v:seed").first;
  const auto t = mesh.property_map<Mesh::Vertex_index, double>("v:t").first;
  const double levels[] = {level, 0, other_level, psi(-1.5, y_on_level(-1.5, level) + 0.1)};
  double worst = 0, min_t[4] = {0, 0, 0, 0}, max_t[4] = {0, 0, 0, 0};
  for (auto v : mesh.vertices()) {
    const int i = int(seed[v]);
    ASSERT_TRUE(i == 0 || i == 2 || i == 3) << "vertex of seed " << seed[v];
    const Point& p = mesh.point(v);
    worst = std::max(worst, std::abs(psi(p.x(), p.y()) - levels[i]));
    EXPECT_LE(std::abs(p.z()), 0.5 + 1e-9);
    min_t[i] = std::min(min_t[i], t[v]);
    max_t[i] = std::max(max_t[i], t[v]);
  }
  EXPECT_LT(worst, 1e-6);
  for (int i : {0, 2, 3}) {
    EXPECT_LT(min_t[i], -2.5) << i;
    EXPECT_GT(max_t[i], 2.5) << i;
  }
}

TEST(DistinctStreamSurfaces, DistinctCurvesAreAllIntegrated)
{
  // Three segments across the flow at different heights: three surfaces.
  const Cylinder flow(1, 1);
  const std::vector<Polyline> seeds{z_segment(-3, 0.5, 0, 1, 5), z_segment(-3, 1.0, 0, 1, 5),
                                    z_segment(-3, 1.5, 0, 1, 5)};
  const auto result = fas_demo::integrate_distinct_stream_surfaces<Mesh>(flow, seeds, 0.1, 1.0);
  EXPECT_EQ(result.number_of_surfaces(), 3u);
}

TEST(GrowAcrossFlow, GrownPatchIsLargerAndStillTangential)
{
  using Flow = std::function<std::optional<Vector>(const Point&)>;
  const Flow flow = Cylinder(1, 1);
  Mesh tm;
  const double size = 1.2;
  FAS::make_planar_patch(tm, Point(-2.0, 0.8, 0), Vector(0.3, 1.0, 0.4), size, size, 800);
  FAS::Flow_aligned_deformation<Mesh, Flow> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  const FAS::Alignment_report aligned = deformation.run();
  ASSERT_TRUE(aligned.converged);
  const double area = CGAL::Polygon_mesh_processing::area(tm);
  const auto z_extent = [&] {
    const CGAL::Bbox_3 box = CGAL::bbox_3(tm.points().begin(), tm.points().end());
    return box.zmax() - box.zmin();
  };
  const double z_before = z_extent();

  const fas_demo::Growth_across_flow growth = fas_demo::grow_across_flow(deformation, size / 2, 2);
  EXPECT_EQ(growth.number_of_steps, 2u) << growth.stopped_because;
  EXPECT_TRUE(growth.alignment.converged);
  // The flow has no z component: across the flow, in a surface containing it, is along z;
  // each side grew by size / 2.
  EXPECT_GT(z_extent() - z_before, 0.8 * size);
  EXPECT_GT(CGAL::Polygon_mesh_processing::area(tm), 1.5 * area);
  const FAS::Normalized_flux flux = FAS::normalized_flux(tm, flow);
  ASSERT_TRUE(flux.value);
  EXPECT_LT(*flux.value, 0.005);
  EXPECT_GT(flux.sampled_area_fraction, 0.999);
}

TEST(StreamLinesWithArrays, VTKArraysAreThoseOfTheFlow)
{
  const Cylinder flow(1, 1);
  const std::vector<Point> seeds{Point(-2, 0.5, 0), Point(0, 0, 0) /* inside */, Point(-2, -1.0, 0.3)};
  const auto lines = fas_demo::integrate_stream_lines(flow, seeds, 2.0);
  ASSERT_EQ(lines.lines.size(), 2u);
  EXPECT_EQ(lines.seed_ids, (std::vector<double>{0, 2}));
  std::size_t k = 0;
  for (std::size_t l = 0; l < lines.lines.size(); ++l) {
    bool seed_found = false;
    for (std::size_t i = 0; i < lines.lines[l].size(); ++i, ++k) {
      const Point& p = lines.lines[l][i];
      const auto v = flow(p);
      ASSERT_TRUE(v);
      EXPECT_NEAR(lines.velocity[3 * k], v->x(), 1e-12);
      EXPECT_NEAR(lines.velocity[3 * k + 1], v->y(), 1e-12);
      EXPECT_NEAR(lines.velocity[3 * k + 2], v->z(), 1e-12);
      if (i > 0) {
        EXPECT_GT(lines.integration_time[k], lines.integration_time[k - 1]);
      }
      if (p == seeds[std::size_t(lines.seed_ids[l])]) {
        seed_found = true;
        EXPECT_EQ(lines.integration_time[k], 0);
      }
    }
    EXPECT_TRUE(seed_found);
  }
  EXPECT_EQ(k, lines.integration_time.size());
}

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
TEST(WritePolydataVTP, BinaryInlineCompressedWithActiveScalars)
{
  const Cylinder flow(1, 1);
  const auto lines = fas_demo::integrate_stream_lines(flow, std::vector<Point>{Point(-2, 0.5, 0)}, 1.0);
  const std::string file = temporary_file("seeding_", "lines.vtp");
  std::string error;
  ASSERT_TRUE(fas_demo::write_polylines_VTP(file, lines.lines, lines.point_data(), lines.cell_data(),
                                            fas_demo::Active_scalars{"IntegrationTime", ""}, &error))
      << error;
  const std::string bytes = read_bytes(file);
  EXPECT_NE(bytes.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_EQ(bytes.find("AppendedData"), std::string::npos);
  EXPECT_EQ(bytes.find("format=\"appended\""), std::string::npos);
  EXPECT_NE(bytes.find("format=\"binary\""), std::string::npos);
  EXPECT_EQ(bytes.find("format=\"ascii\""), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(temporary_file("seeding_", "lines.partial.vtp")));

  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  ASSERT_EQ(data->GetNumberOfLines(), 1);
  ASSERT_EQ(std::size_t(data->GetNumberOfPoints()), lines.lines[0].size());
  ASSERT_NE(data->GetPointData()->GetScalars(), nullptr);
  EXPECT_STREQ(data->GetPointData()->GetScalars()->GetName(), "IntegrationTime");
  ASSERT_NE(data->GetPointData()->GetArray("velocity"), nullptr);
  EXPECT_EQ(data->GetPointData()->GetArray("velocity")->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    EXPECT_EQ(data->GetPointData()->GetScalars()->GetTuple1(i), lines.integration_time[std::size_t(i)]);
  ASSERT_NE(data->GetCellData()->GetArray("SeedIds"), nullptr);
  EXPECT_EQ(data->GetCellData()->GetArray("SeedIds")->GetTuple1(0), 0);

  // An array of the wrong size: refused with its name, nothing written.
  const std::string bad = temporary_file("seeding_", "bad.vtp");
  std::filesystem::remove(bad);
  EXPECT_FALSE(fas_demo::write_polylines_VTP(bad, lines.lines, {{"r", 1, {1.0}}}, {}, {}, &error));
  EXPECT_NE(error.find("'r'"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(bad));
}
#endif

} // namespace
