// An outside application of the installed package: aligns a small planar patch orthogonally
// to a point source (the exact answer is a piece of a sphere, flux 1) and prints the flux.
// Returns nonzero when the flux is off.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_NRRD.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Surface_mesh.h>

#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main(int argc, char** argv)
{
  try {
    CGAL::Surface_mesh<Point> tm;
    FAS::make_planar_patch(tm, Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 1.0, 500);
    const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
    const double before = FAS::normalized_flux(tm, source).value.value();
    const FAS::Alignment_report report = FAS::align_to_flow(tm, source, FAS::Alignment::ORTHOGONAL);
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
    std::cout << "sparse solver: CHOLMOD\n";
#else
    std::cout << "sparse solver: Eigen SimplicialLDLT\n";
#endif
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB
    // A gzip NRRD file (made by Python's gzip module): velocity (i, j, k) at node (i, j, k) of a
    // 2 x 2 x 2 grid; reading it needs the zlib that the exported target brings.
    const std::string gz("\x1f\x8b\x08\x00\x00\x00\x00\x00\x02\x03\x63\x60\x40\x06\x0d\xf6\x0c\x58\xf9"
                         "\x20\x1a\x9b\x1c\xb2\x3c\xb2\x18\x02\x03\x00\x09\x02\xe3\x8f\x60\x00\x00\x00",
                         38);
    const std::string file = (argc > 1 ? std::string(argv[1]) + "/" : std::string()) + "consumer_gzip.nrrd";
    std::ofstream(file, std::ios::binary) << "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\n"
                                             "endian: little\nencoding: gzip\n\n"
                                          << gz;
    FAS::Regular_grid_flow_field_3<K> grid;
    std::string error;
    if (!FAS::IO::read_NRRD_flow_field(file, grid, FAS::parameters::error_message(&error)) ||
        grid.node_value(1, 0, 1) != Vector(1, 0, 1)) {
      std::cerr << "consumer: the gzip NRRD file was not read right: " << error << "\n";
      return 3;
    }
    std::cout << "zlib: gzip NRRD read\n";
#endif
    {
      // A VTK XML image written and read back by the installed package alone, without VTK.
      const std::string vti = (argc > 1 ? std::string(argv[1]) + "/" : std::string()) + "consumer.vti";
      std::vector<float> values(3 * 8);
      for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = float(i);
      const FAS::Regular_grid_flow_field_3<K> written(Point(0, 0, 0), Vector(1, 1, 1), {{2, 2, 2}}, values);
      FAS::Regular_grid_flow_field_3<K> read;
      std::string error;
      if (!FAS::IO::write_VTI_flow_field(vti, written, FAS::parameters::error_message(&error)) ||
          !FAS::IO::read_VTK_XML_flow_field(vti, read, FAS::parameters::error_message(&error)) ||
          read.values() != values) {
        std::cerr << "consumer: the VTK XML image was not written and read back right: " << error << "\n";
        return 4;
      }
      std::cout << "VTK XML: image written and read back without VTK\n";
    }
    std::cout << "faces: " << tm.number_of_faces() << "\n"
              << "normalized flux before: " << before << "\n"
              << "normalized flux after: " << report.normalized_flux.value.value() << " ("
              << report.number_of_iterations
              << " iterations, converged: " << (report.converged ? "yes" : "no") << ")\n";
    if (!report.converged || !(report.normalized_flux.value.value() >= 0.995) || !(before < 0.99)) {
      std::cerr << "consumer: the alignment did not reach the expected flux (>= 0.995 from < 0.99)\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "consumer: " << e.what() << "\n";
    return 2;
  }
}
