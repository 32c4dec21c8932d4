// Integrates the stream surface of a seed curve by an advancing front: the seed segment is
// resampled into particles, the particles follow the flow (here the Burgers vortex) from time
// line to time line, and particles are inserted where neighbours diverge.  Each vertex gets its
// seed parameter u and its time t: the curves of constant t are the time lines, those of
// constant u the stream lines.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef Surface_mesh::Vertex_index vertex_descriptor;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  const FAS::Burgers_vortex<Kernel> flow;
  const std::vector<Point_3> seed = {Point_3(0.8, 0, 0.5), Point_3(1.2, 0, 0.5)};

  Surface_mesh sm;
  auto u = sm.add_property_map<vertex_descriptor, double>("v:u", 0).first;
  auto t = sm.add_property_map<vertex_descriptor, double>("v:t", 0).first;
  // Particles at most 0.02 apart, integrated for one unit of time.
  const FAS::Stream_surface_report report = FAS::integrate_stream_surface(
      flow, seed, sm,
      FAS::parameters::front_spacing(
          0.02, FAS::parameters::max_time(
                    1.0, FAS::parameters::seed_parameter_map(u, FAS::parameters::integration_time_map(t)))));

  std::cout << report.number_of_faces << " triangles on " << report.number_of_time_lines << " time lines, "
            << report.number_of_inserted_particles << " particles inserted, " << report.number_of_tears
            << " tears (" << report.message << ")" << std::endl;
  std::cout << "normalized flux " << FAS::normalized_flux(sm, flow) << " (0: tangential)" << std::endl;
  CGAL::IO::write_polygon_mesh("stream_surface.off", sm, CGAL::parameters::stream_precision(17));
  return 0;
}
