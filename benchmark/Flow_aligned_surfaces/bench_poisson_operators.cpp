// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The operators a parametrization assembles (L, the per-face data and the divergence D = G^T A),
// with D filled column by column (`Operators_asked::divergence`), beside the same with G from
// triplets (`setFromTriplets()`, `Operators_asked::gradient_and_divergence`) and the sparse
// product G^T A, the way the parametrization assembled D before and Eigen's users would: the
// difference is what the parametrization no longer pays.  A disk patch bent onto a paraboloid, in sizes up to 80 000 faces; median of 15
// assemblies, the two ways alternated in 3 rounds.  Plain main(): prints one row per size and
// round.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <variant>
#include <vector>

namespace FAS = CGAL::Flow_aligned_surfaces;
namespace FASI = FAS::internal;
using K = CGAL::Epick;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

struct Patch {
  FASI::Positions x;
  FASI::Mesh_arrays arrays;
};

Patch bent_disk(std::size_t faces)
{
  Mesh tm;
  FAS::make_disk_patch(tm, K::Point_3(0, 0, 0), K::Vector_3(0.2, 0.1, 1), 1.0, faces);
  Patch patch{FASI::Positions(Eigen::Index(tm.number_of_vertices()), 3),
              FASI::make_mesh_arrays(tm, get(CGAL::vertex_index, tm), get(CGAL::face_index, tm))};
  Eigen::Index i = 0;
  for (Mesh::Vertex_index v : tm.vertices()) {
    const K::Point_3& p = tm.point(v);
    patch.x.row(i++) << p.x(), p.y(), p.z() + 0.3 * (p.x() * p.x() + p.y() * p.y());
  }
  return patch;
}

double median_ms(const std::function<Eigen::Index()>& assemble)
{
  std::vector<double> ms;
  Eigen::Index entries = 0;
  for (int r = 0; r < 15; ++r) {
    const auto start = std::chrono::steady_clock::now();
    entries += assemble();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(ms.begin(), ms.begin() + 7, ms.end());
  return entries > 0 ? ms[7] : -1; // the entries keep the assemblies from being optimized away
}

} // namespace

int main()
{
  std::printf("faces round D_filled_ms with_G_and_product_ms ratio\n");
  for (std::size_t faces : {5000, 20000, 80000}) {
    const Patch patch = bent_disk(faces);
    const auto assembled = [&patch](FASI::Operators_asked asked) {
      return std::get<FASI::Poisson_operators>(FASI::make_poisson_operators(patch.x, patch.arrays.face_vertices, asked));
    };
    for (int round = 0; round < 3; ++round) {
      const double filled = median_ms([&] { return assembled(FASI::Operators_asked::divergence).D.nonZeros(); });
      const double through_g = median_ms([&] {
        // G from triplets as well, then D the way of Eigen's users: the product G^T A.
        const FASI::Poisson_operators ops = assembled(FASI::Operators_asked::gradient_and_divergence);
        const Eigen::SparseMatrix<double> d = ops.G.transpose() * ops.area_matrix();
        return d.nonZeros();
      });
      std::printf("%zu %d %.2f %.2f %.2f\n", faces, round, filled, through_g, through_g / filled);
    }
  }
}
