// What the tests on the real CFD data of ../shared/data share: where the files are (empty
// when absent, so that the caller skips visibly), and the check asked of every
// field read from them: a patch placed in the fluid aligns, tangentially to normalized flux
// <= 0.02 and orthogonally to >= 0.9.

#ifndef FAS_TEST_REAL_DATA_H
#define FAS_TEST_REAL_DATA_H

#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

/// The path of `name` in FAS_SHARED_DATA_DIR, or the empty string if it is not there.
inline std::string shared_data_file(const std::string& name)
{
#ifdef FAS_SHARED_DATA_DIR
  const std::string file = std::string(FAS_SHARED_DATA_DIR) + "/" + name;
  if (std::ifstream(file).good())
    return file;
#endif
  return std::string();
}

/// Aligns a square patch of side `size` (800 faces) centred at `center`, first with the normal
/// `tangential_normal` to the flow's stream surfaces, then with `orthogonal_normal` orthogonally
/// to the flow; expects the starting fluxes to be far from the targets (so that the test
/// shows the deformation at work) and the targets reached.  `label` prefixes the recorded
/// properties.
template <class FlowField>
void expect_patches_align(
    const FlowField& field, const std::string& label,
    const CGAL::Exact_predicates_inexact_constructions_kernel::Point_3& center,
    const CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3& tangential_normal,
    const CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3& orthogonal_normal, double size)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  for (const bool tangential : {true, false}) {
    Mesh tm;
    FAS::make_planar_patch(tm, center, tangential ? tangential_normal : orthogonal_normal, size, size, 800);
    const double before = FAS::normalized_flux(tm, field).value.value();
    const FAS::Alignment_report r =
        FAS::align_to_flow(tm, field, tangential ? FAS::Alignment::TANGENTIAL : FAS::Alignment::ORTHOGONAL);
    const std::string what = label + (tangential ? "_tangential_flux" : "_orthogonal_flux");
    if (tangential) {
      EXPECT_GT(before, 0.3) << what;
      EXPECT_LE(r.normalized_flux.value.value(), 0.02)
          << what << ": from " << before << " in " << r.number_of_iterations << " iterations";
    }
    else {
      EXPECT_LT(before, 0.8) << what;
      EXPECT_GE(r.normalized_flux.value.value(), 0.9)
          << what << ": from " << before << " in " << r.number_of_iterations << " iterations";
    }
    ::testing::Test::RecordProperty(what, std::to_string(before) + " -> " +
                                              std::to_string(r.normalized_flux.value.value()) + " in " +
                                              std::to_string(r.number_of_iterations) + " iterations");
  }
}

#endif // FAS_TEST_REAL_DATA_H
