#!/usr/bin/env bash
# The speed and memory figures of the flow fields read from data (RESULTS.md, "Sampling fields", "Memory of a loaded field", "Readers"): configures a Release build,
# builds the four programs, runs them one after the other and keeps their output in results/:
#   bench_grid_sampling   trilinear sampling, ns/query (target <= 50 ns at coherent positions)
#   bench_point_location  1 M unstructured cells, package vs CGAL AABB_tree peer (<= 1 us coherent)
#   bench_field_memory    heap bytes of loaded fields vs their raw arrays (<= 1.3 x)
#   bench_read_VTK        100 MB binary legacy VTK file vs cat (<= 2 x)
# then prints the tables (field_benchmarks_summary.py).  About 3-5 minutes on 2 cores.
#
#   benchmark/Flow_aligned_surfaces/run_field_benchmarks.sh [BUILD_DIR]      (default ${TMPDIR:-/tmp}/fas-benchmark-build)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-${TMPDIR:-/tmp}/fas-benchmark-build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DFAS_BUILD_TESTS=OFF -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_DEMO=OFF -DFAS_BUILD_DOC_TEST=OFF -DBUILD_TESTING=OFF \
  -DFAS_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target bench_grid_sampling bench_point_location bench_field_memory bench_read_VTK \
  -j"${JOBS:-2}"
bin="$build/benchmark/Flow_aligned_surfaces"
out="$here/results"
mkdir -p "$out"
{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) hardware threads"
  echo "compiler: $(c++ --version | head -1)"
  echo "load before: $(cat /proc/loadavg)"
} >"$out/fields_machine.txt"
"$bin/bench_grid_sampling" --benchmark_filter='Grid_(coherent|random)' \
  --benchmark_out="$out/fields_grid_sampling.json" --benchmark_out_format=json
"$bin/bench_point_location" --benchmark_enable_random_interleaving=true \
  --benchmark_out="$out/fields_point_location.json" --benchmark_out_format=json
"$bin/bench_field_memory" | tee "$out/fields_field_memory.md"
"$bin/bench_read_VTK" 7 | tee "$out/fields_read_VTK.txt"
echo "load after: $(cat /proc/loadavg)" >>"$out/fields_machine.txt"
python3 "$here/field_benchmarks_summary.py" "$out"
