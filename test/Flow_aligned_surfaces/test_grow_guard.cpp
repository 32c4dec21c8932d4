// The two pieces of the guard of grow_boundary() (internal/grow_boundary/check_grown_surface.h)
// against independent answers: Box_cell_index finds exactly the boxes a brute-force overlap
// test finds, each once; faces_cross() says of every pair of faces of crumpled meshes what
// CGAL's Polygon_mesh_processing::self_intersections() says of them.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/internal/Box_cell_index.h>
#include <CGAL/Flow_aligned_surfaces/internal/faces_cross.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace grow_guard_test {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace FASI = CGAL::Flow_aligned_surfaces::internal;

CGAL::Bbox_3 random_box(CGAL::Random& random, double largest)
{
  const double x = random.get_double(0, 10), y = random.get_double(0, 10), z = random.get_double(0, 2);
  return CGAL::Bbox_3(x, y, z, x + random.get_double(0, largest), y + random.get_double(0, largest),
                      z + random.get_double(0, largest));
}

// An n x n grid of the unit square, two triangles per cell, its vertices moved at random by up
// to `amount` cells in the plane and `lift` out of it: from a few crossings to many.
Mesh crumpled_grid(int n, double amount, double lift, CGAL::Random& random)
{
  Mesh tm;
  std::vector<Mesh::Vertex_index> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      v.push_back(tm.add_vertex(K::Point_3((i + random.get_double(-amount, amount)) / n,
                                           (j + random.get_double(-amount, amount)) / n,
                                           lift > 0 ? random.get_double(-lift, lift) : 0.)));
  auto at = [&](int i, int j) { return v[std::size_t(j * (n + 1) + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tm.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      tm.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return tm;
}

} // namespace grow_guard_test

TEST(BoxCellIndex, FindsTheOverlappingBoxesEachOnce)
{
  using namespace grow_guard_test;
  CGAL::Random random(7);
  std::vector<CGAL::Bbox_3> indexed;
  for (int i = 0; i < 400; ++i)
    indexed.push_back(random_box(random, 0.3));
  indexed.push_back(CGAL::Bbox_3(5, 5, 1, 5, 5, 1)); // a point
  FASI::Box_cell_index index(indexed);
  std::size_t meetings = 0, large_queries = 0;
  for (int q = 0; q < 2000; ++q) {
    // Queries of the indexed boxes' size, larger ones, and some much larger (tested against all).
    const double largest = q % 10 == 0 ? 4.0 : (q % 3 == 0 ? 1.0 : 0.3);
    const CGAL::Bbox_3 query = random_box(random, largest);
    std::multiset<std::size_t> found;
    index.find_meeting(query, [&](std::size_t j) {
      found.insert(j);
      return false;
    });
    std::multiset<std::size_t> expected;
    for (std::size_t j = 0; j < indexed.size(); ++j)
      if (CGAL::do_overlap(query, indexed[j]))
        expected.insert(j);
    ASSERT_EQ(found, expected) << "query " << q;
    EXPECT_EQ(index.meets_any(query), !expected.empty());
    meetings += expected.size();
    large_queries += largest > 1;
  }
  EXPECT_GT(meetings, 1000u); // the queries do meet boxes, often
  EXPECT_GT(large_queries, 100u);
  // Touching boxes meet (closed boxes), as in CGAL's box intersection.
  EXPECT_TRUE(index.meets_any(CGAL::Bbox_3(5, 5, 1, 6, 6, 2)));
  EXPECT_FALSE(index.meets_any(CGAL::Bbox_3(20, 20, 20, 21, 21, 21)));
}

TEST(BoxCellIndex, StopsWhenAsked)
{
  using namespace grow_guard_test;
  const std::vector<CGAL::Bbox_3> indexed(5, CGAL::Bbox_3(0, 0, 0, 1, 1, 1));
  FASI::Box_cell_index index(indexed);
  int calls = 0;
  EXPECT_TRUE(index.find_meeting(CGAL::Bbox_3(0.5, 0.5, 0.5, 2, 2, 2), [&](std::size_t) { return ++calls == 2; }));
  EXPECT_EQ(calls, 2);
}

TEST(FacesCross, AgreesWithCGALsSelfIntersectionsOnCrumpledMeshes)
{
  using namespace grow_guard_test;
  CGAL::Random random(11);
  // What each kind of pair (0, 1 or 2 shared vertices) gave: crossings and not, so that every
  // branch of faces_cross() is compared with CGAL's answer both ways.
  std::array<std::array<std::size_t, 2>, 3> outcomes{};
  for (int trial = 0; trial < 12; ++trial) {
    const double amount = 0.3 + 0.1 * (trial % 4), lift = trial < 4 ? 0.0 : 0.02 * (trial % 5);
    Mesh tm = crumpled_grid(8, amount, lift, random);
    std::set<std::pair<std::size_t, std::size_t>> cgal;
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    CGAL::Polygon_mesh_processing::self_intersections(tm, std::back_inserter(pairs));
    bool degenerate = false;
    for (const auto& [f, g] : pairs) {
      degenerate = degenerate || f == g;
      cgal.insert(std::minmax(std::size_t(f), std::size_t(g)));
    }
    if (degenerate) // a collinear face: outside faces_cross()'s domain
      continue;
    std::vector<std::array<std::size_t, 3>> faces;
    for (auto f : tm.faces()) {
      std::array<std::size_t, 3> fv;
      int i = 0;
      for (auto v : vertices_around_face(tm.halfedge(f), tm))
        fv[i++] = std::size_t(v);
      faces.push_back(fv);
    }
    auto point = [&](std::size_t v) { return tm.point(Mesh::Vertex_index(Mesh::size_type(v))); };
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (std::size_t g = f + 1; g < faces.size(); ++g) {
        const bool crosses = FASI::faces_cross(faces[f], faces[g], point);
        ASSERT_EQ(crosses, cgal.count({f, g}) > 0) << "trial " << trial << ", faces " << f << " and " << g;
        int shared = 0;
        for (std::size_t a : faces[f])
          shared += int(std::count(faces[g].begin(), faces[g].end(), a));
        ++outcomes[std::size_t(shared)][crosses];
      }
  }
  for (int shared = 0; shared < 3; ++shared) {
    EXPECT_GT(outcomes[std::size_t(shared)][0], 0u) << shared << " shared vertices, apart";
    EXPECT_GT(outcomes[std::size_t(shared)][1], 0u) << shared << " shared vertices, crossing";
  }
}

TEST(FacesCross, ClosedFormCases)
{
  using namespace grow_guard_test;
  const std::vector<K::Point_3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.2, 0.2, 0},
                                     {0.3, 0.3, -1}, {0.3, 0.3, 1}, {0.5, -1, 0}};
  auto point = [&](int v) { return p[std::size_t(v)]; };
  using F = std::array<int, 3>;
  // A shared edge: the triangles on either side of it, or folded onto each other.
  EXPECT_FALSE(FASI::faces_cross(F{0, 1, 2}, F{2, 1, 3}, point));
  EXPECT_TRUE(FASI::faces_cross(F{0, 1, 2}, F{1, 0, 4}, point));
  // A shared vertex: a triangle whose opposite edge pierces the other, or that stays beside it.
  EXPECT_TRUE(FASI::faces_cross(F{0, 1, 2}, F{0, 5, 6}, point));
  EXPECT_FALSE(FASI::faces_cross(F{0, 1, 2}, F{0, 7, 5}, point));
  // No shared vertex.
  EXPECT_TRUE(FASI::faces_cross(F{0, 1, 2}, F{5, 6, 3}, point));
  EXPECT_FALSE(FASI::faces_cross(F{0, 1, 4}, F{3, 6, 5}, point));
}
