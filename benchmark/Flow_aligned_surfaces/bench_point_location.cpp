// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cost of one query (point location + interpolation) of Unstructured_flow_field_3 on 1 M cells
// (target: <= 1 us per coherent query), against a peer built in the same run from CGAL's
// AABB_tree over the cells' bounding boxes followed by the same cell inversion
// (`evaluate_in_cell()`), with and without the same last-cell hint (the last cell and its face
// neighbours).  Meshes (bench_meshes.h): a graded, rotated and jittered block of 100^3
// hexahedra, and 6 * 55^3 = 998,250 tetrahedra of the same kind of block.  Queries: coherent
// (4096 random paths of 256 points, 0.1 cell apart, as integration and deformation make) or
// random (uniform in the block's parameters).  One benchmark iteration is one query, so the
// reported time is ns/query:
//
//   bench_point_location --benchmark_repetitions=5
//
// Variants: Package (the field's operator(): the walk from the hint, else the hierarchy),
// Package_two_steps (each point in the same field and in a second one on the same cells in turn,
// as an unsteady field interpolating between two time steps asks them),
// AABB_hint (the peer with the same hint), AABB (the peer without hint).

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <benchmark/benchmark.h>

#include "bench_meshes.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef K::Iso_cuboid_3 Iso_cuboid_3;
typedef FAS::Unstructured_flow_field_3<K> Field;

constexpr std::size_t kQueries = std::size_t(1) << 20; // 4096 paths x 256 steps

struct Box_input {
  std::uint32_t cell;
  Iso_cuboid_3 box;
};

// A cell's bounding box as an AABB_tree primitive.
struct Cell_box {
  typedef std::uint32_t Id;
  typedef Point_3 Point;
  typedef Iso_cuboid_3 Datum;
  Id cell;
  Datum box;
  Cell_box() = default;
  explicit Cell_box(std::vector<Box_input>::const_iterator it) : cell(it->cell), box(it->box) {}
  Id id() const { return cell; }
  const Datum& datum() const { return box; }
  Point reference_point() const { return CGAL::midpoint(box.min(), box.max()); }
};
typedef CGAL::AABB_traits<K, Cell_box> Traits;
typedef CGAL::AABB_tree<Traits> Tree;

// Traversal that stops at the first box whose cell contains the point.
struct First_containing_cell {
  const Field* field;
  std::optional<Vector_3> value;
  std::uint32_t cell = 0;
  bool go_further() const { return !value; }
  void intersection(const Point_3& p, const Cell_box& b)
  {
    if ((value = field->evaluate_in_cell(b.cell, p)))
      cell = b.cell;
  }
  template <class Node>
  bool do_intersect(const Point_3& p, const Node& node) const
  {
    const CGAL::Bbox_3& b = node.bbox();
    return p.x() >= b.xmin() && p.x() <= b.xmax() && p.y() >= b.ymin() && p.y() <= b.ymax() &&
           p.z() >= b.zmin() && p.z() <= b.zmax();
  }
};

// The peer: AABB tree over the cell boxes, the package's cell inversion, optionally the hint.
struct Peer {
  const Field* field;
  Tree tree;
  std::vector<std::size_t> neighbour_begin;
  std::vector<std::uint32_t> neighbours;
  std::uint32_t last = 0;

  explicit Peer(const Field& f) : field(&f)
  {
    const Field::Point_coordinates x = f.points();
    std::vector<Box_input> boxes;
    boxes.reserve(f.number_of_cells());
    neighbour_begin.push_back(0);
    for (std::size_t c = 0; c < f.number_of_cells(); ++c) {
      double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
      for (auto k = f.offsets()[c]; k < f.offsets()[c + 1]; ++k)
        for (int a = 0; a < 3; ++a) {
          lo[a] = (std::min)(lo[a], x[3 * std::size_t(f.connectivity()[k]) + a]);
          hi[a] = (std::max)(hi[a], x[3 * std::size_t(f.connectivity()[k]) + a]);
        }
      boxes.push_back(Box_input{std::uint32_t(c), Iso_cuboid_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2])});
      for (std::size_t n : f.face_neighbours(c))
        neighbours.push_back(std::uint32_t(n));
      neighbour_begin.push_back(neighbours.size());
    }
    tree.insert(boxes.cbegin(), boxes.cend());
    tree.build();
  }

  std::optional<Vector_3> operator()(const Point_3& p, bool hint)
  {
    if (hint) {
      if (auto v = field->evaluate_in_cell(last, p))
        return v;
      for (std::size_t k = neighbour_begin[last]; k < neighbour_begin[last + 1]; ++k)
        if (auto v = field->evaluate_in_cell(neighbours[k], p)) {
          last = neighbours[k];
          return v;
        }
    }
    First_containing_cell t{field, std::nullopt, 0};
    tree.traversal(p, t);
    if (t.value)
      last = t.cell;
    return t.value;
  }
};

struct Setup {
  fas_bench::Block_mesh mesh;
  std::unique_ptr<Field> field, next_field;
  std::unique_ptr<Peer> peer;
  std::vector<Point_3> coherent, random;
};

Setup make_setup(bool tetrahedra)
{
  Setup s;
  s.mesh = fas_bench::make_block_mesh(tetrahedra ? 55 : 100, tetrahedra);
  // Float points, as a field read from a legacy file with POINTS float (the CFD data's layout).
  const auto float_field = [&s] {
    return std::make_unique<Field>(std::vector<float>(s.mesh.points.begin(), s.mesh.points.end()),
                                   s.mesh.connectivity, s.mesh.offsets, s.mesh.types, s.mesh.vectors);
  };
  s.field = float_field();
  // A field of its own on the same cells: the next time step of an unsteady flow.
  s.next_field = float_field();
  s.peer = std::make_unique<Peer>(*s.field);
  for (const auto& x : fas_bench::coherent_queries(s.mesh, 4096, 256))
    s.coherent.emplace_back(x[0], x[1], x[2]);
  for (const auto& x : fas_bench::random_queries(s.mesh, kQueries))
    s.random.emplace_back(x[0], x[1], x[2]);
  return s;
}

Setup& setup(bool tetrahedra)
{
  static Setup hex = make_setup(false);
  static Setup tet = make_setup(true);
  return tetrahedra ? tet : hex;
}

enum Variant { PACKAGE, PACKAGE_TWO_STEPS, AABB_HINT, AABB };

// Queries each point `per_point` times in a row, one query per benchmark iteration.
template <class Query>
void run(benchmark::State& state, const std::vector<Point_3>& points, Query&& query,
         std::size_t per_point = 1)
{
  std::size_t q = 0, inside = 0;
  for (auto _ : state) {
    const std::optional<Vector_3> v = query(points[q / per_point]);
    inside += v.has_value();
    benchmark::DoNotOptimize(v);
    q = (q + 1) % (kQueries * per_point);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["inside"] = double(inside) / double(state.iterations());
}

void BM_locate(benchmark::State& state, bool tetrahedra, bool coherent, Variant variant)
{
  Setup& s = setup(tetrahedra);
  const std::vector<Point_3>& points = coherent ? s.coherent : s.random;
  state.counters["cells"] = double(s.field->number_of_cells());
  switch (variant) {
  case PACKAGE: {
    const Field& f = *s.field;
    run(state, points, [&f](const Point_3& p) { return f(p); });
    break;
  }
  case PACKAGE_TWO_STEPS: { // each point in both fields in turn, as an unsteady field between two steps
    const Field &f = *s.field, &g = *s.next_field;
    bool next = false;
    run(
        state, points,
        [&](const Point_3& p) {
          next = !next;
          return next ? g(p) : f(p);
        },
        2);
    break;
  }
  case AABB_HINT:
    run(state, points, [&s](const Point_3& p) { return (*s.peer)(p, true); });
    break;
  case AABB:
    run(state, points, [&s](const Point_3& p) { return (*s.peer)(p, false); });
    break;
  }
}

} // namespace

#define FAS_LOCATE(name, tet, coherent, variant)                                                             \
  BENCHMARK_CAPTURE(BM_locate, name, tet, coherent, variant)->Repetitions(5)->ReportAggregatesOnly(true)

FAS_LOCATE(hex_coherent_Package, false, true, PACKAGE);
FAS_LOCATE(hex_coherent_Package_two_steps, false, true, PACKAGE_TWO_STEPS);
FAS_LOCATE(hex_coherent_AABB_hint, false, true, AABB_HINT);
FAS_LOCATE(hex_coherent_AABB, false, true, AABB);
FAS_LOCATE(hex_random_Package, false, false, PACKAGE);
FAS_LOCATE(hex_random_AABB_hint, false, false, AABB_HINT);
FAS_LOCATE(hex_random_AABB, false, false, AABB);
FAS_LOCATE(tet_coherent_Package, true, true, PACKAGE);
FAS_LOCATE(tet_coherent_AABB_hint, true, true, AABB_HINT);
FAS_LOCATE(tet_coherent_AABB, true, true, AABB);
FAS_LOCATE(tet_random_Package, true, false, PACKAGE);
FAS_LOCATE(tet_random_AABB_hint, true, false, AABB_HINT);
FAS_LOCATE(tet_random_AABB, true, false, AABB);
