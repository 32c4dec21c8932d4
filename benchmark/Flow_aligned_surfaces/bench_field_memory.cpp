// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Heap bytes held by a loaded field (target: <= 1.3 x its raw arrays), measured with glibc's
// mallinfo2() (in-use arena bytes + mmapped bytes) before the input arrays exist and after the
// field is built and the inputs are released, so the figure is what the field keeps, not the
// temporaries of its construction.  "Raw arrays" are the arrays as a legacy VTK file stores
// them (the bytes of the data sections, headers excluded):
//   - UNSTRUCTURED_GRID, legacy 3.0/4.2 (the layout of the CFD files in ../shared/data):
//     POINTS float (12 B per point), VECTORS float (12 B per point), CELLS int32 (4 B for the
//     count + 4 B per point index, per cell), CELL_TYPES int32 (4 B per cell);
//   - UNSTRUCTURED_GRID, legacy 5.1 (what VTK 9 writes): POINTS float, VECTORS float,
//     OFFSETS vtktypeint64 (8 B per cell + 8), CONNECTIVITY vtktypeint64 (8 B per index),
//     CELL_TYPES int32;
//   - STRUCTURED_POINTS: VECTORS float (12 B per node) + SCALARS unsigned_char mask (1 B per
//     node).
// Meshes: bench_meshes.h (1 M hexahedra, 998,250 tetrahedra); grid: 128^3 nodes with a mask.
//
//   bench_field_memory

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "bench_meshes.h"

#include <malloc.h>

#include <cstddef>
#include <cstdio>
#include <optional>
#include <vector>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

double heap_bytes()
{
  malloc_trim(0);
  const struct mallinfo2 m = mallinfo2();
  return double(m.uordblks) + double(m.hblkhd);
}

// `arrays`: the bytes of the arrays the field returns (points(), vectors(), connectivity(),
// offsets(), cell_types(), values(), mask()); the rest is the acceleration.
void report(const char* name, double field, double arrays, double raw_legacy, double raw_51)
{
  std::printf("| %s | %.1f | %.1f | %.1f | %.1f | %.2f | %s | %.1f | %.2f | %s |\n", name, field / 1e6,
              arrays / 1e6, (field - arrays) / 1e6, raw_legacy / 1e6, field / raw_legacy,
              field <= 1.3 * raw_legacy ? "**met**" : "missed", raw_51 / 1e6, field / raw_51,
              field <= 1.3 * raw_51 ? "**met**" : "missed");
}

void unstructured(bool tetrahedra)
{
  const double before = heap_bytes();
  std::optional<FAS::Unstructured_flow_field_3<K>> field;
  double np = 0, nc = 0, refs = 0;
  {
    fas_bench::Block_mesh m = fas_bench::make_block_mesh(tetrahedra ? 55 : 100, tetrahedra);
    np = double(m.points.size() / 3);
    nc = double(m.types.size());
    refs = double(m.connectivity.size());
    // Float points, as read from a legacy file with POINTS float; 64-bit indices as a reader
    // that builds vtkIdType arrays passes them (the field narrows them to 32 bits).
    field.emplace(std::vector<float>(m.points.begin(), m.points.end()), std::move(m.connectivity),
                  std::move(m.offsets), std::move(m.types), std::move(m.vectors));
  }
  const double bytes = heap_bytes() - before;
  const double point_bytes = field->points().float_data() != nullptr ? 4. : 8.;
  const double arrays = point_bytes * double(field->points().size()) +
                        4. * double(field->vectors().capacity()) +
                        4. * double(field->connectivity().capacity() + field->offsets().capacity()) +
                        double(field->cell_types().capacity());
  const double raw_legacy = 24. * np + 4. * (nc + refs) + 4. * nc;
  const double raw_51 = 24. * np + 8. * (nc + 1) + 8. * refs + 4. * nc;
  char name[128];
  std::snprintf(name, sizeof name, "Unstructured_flow_field_3, %.0f %s, %.0f points", nc,
                tetrahedra ? "tetrahedra" : "hexahedra", np);
  report(name, bytes, arrays, raw_legacy, raw_51);
}

void grid()
{
  const std::size_t n = 128, nodes = n * n * n;
  const double before = heap_bytes();
  std::optional<FAS::Regular_grid_flow_field_3<K>> field;
  {
    std::vector<float> values(3 * nodes, 1.f);
    std::vector<unsigned char> mask(nodes, 1);
    field.emplace(K::Point_3(0, 0, 0), K::Vector_3(1, 1, 1),
                  FAS::Regular_grid_flow_field_3<K>::Dimensions{{n, n, n}}, std::move(values),
                  std::move(mask));
  }
  const double bytes = heap_bytes() - before;
  const double raw = 13. * double(nodes);
  const double arrays = 4. * double(field->values().capacity()) + double(field->mask().capacity());
  report("Regular_grid_flow_field_3, 128^3 nodes with a mask", bytes, arrays, raw, raw);
}

} // namespace

int main()
{
  std::printf(
      "| field | heap MB | of which arrays | acceleration | raw MB (legacy 3.0/4.2 file) | ratio | <= 1.3x "
      "| raw MB (legacy 5.1 file) | ratio | <= 1.3x |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---|---:|---:|---|\n");
  unstructured(false);
  unstructured(true);
  grid();
  return 0;
}
