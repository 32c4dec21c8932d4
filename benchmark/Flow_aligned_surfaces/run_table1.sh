#!/usr/bin/env bash
# Reproduces the paper's Table 1 (and the grid-sampling figures) and writes RESULTS.md:
# configures a Release build, builds bench_deformation and bench_grid_sampling, runs them
# single-threaded, keeps their JSON in results/ beside this script and regenerates the
# generated part of RESULTS.md, "Alignment iterations (Table 1)" (make_results.py).  About 1-3 minutes on 2 cores.
#
#   benchmark/Flow_aligned_surfaces/run_table1.sh [--quick] [BUILD_DIR]
#
#   BUILD_DIR   default: ${TMPDIR:-/tmp}/fas-benchmark-build
#   --quick     smoke test: two small sizes, one repetition; writes only into BUILD_DIR
#
# Environment:
#   FAS_VARIANT_OVERLAY=DIR   also build and run bench_deformation with the headers in DIR
#                             searched first (a candidate change, laid out like include/), and
#                             put its table beside the package's (label: FAS_VARIANT_LABEL)
#   JOBS                      parallel build jobs (default 2)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
quick=0
build=""
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) build="$arg" ;;
  esac
done
build="${build:-${TMPDIR:-/tmp}/fas-benchmark-build}"
jobs="${JOBS:-2}"

configure_and_build() { # build_dir overlay
  cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release \
    -DFAS_BUILD_TESTS=OFF -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_DEMO=OFF -DFAS_BUILD_DOC_TEST=OFF -DBUILD_TESTING=OFF \
    -DFAS_BUILD_BENCHMARKS=ON -DFAS_BENCHMARK_INCLUDE_OVERLAY="$2" >/dev/null
  cmake --build "$1" --target bench_deformation bench_grid_sampling -j"$jobs"
}

configure_and_build "$build" ""
bin="$build/benchmark/Flow_aligned_surfaces"
# One thread everywhere (bench_deformation also re-executes itself with these when unset).
export OMP_NUM_THREADS=1 OMP_THREAD_LIMIT=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1

if [ "$quick" = 1 ]; then
  "$bin/bench_deformation" "$build/table1-quick.json" --quick
  "$bin/bench_grid_sampling" --benchmark_filter=Grid_coherent --benchmark_repetitions=1
  python3 "$here/make_results.py" --table1 "$build/table1-quick.json" --results "$build/RESULTS-quick.md"
  exit 0
fi

out="$here/results"
mkdir -p "$out"
table1_command="OMP_NUM_THREADS=1 OMP_THREAD_LIMIT=1 OPENBLAS_NUM_THREADS=1 bench_deformation results/table1.json"
grid_command="bench_grid_sampling --benchmark_filter=Grid --benchmark_out=results/grid_sampling.json --benchmark_out_format=json"
"$bin/bench_deformation" "$out/table1.json"
variant_args=()
if [ -n "${FAS_VARIANT_OVERLAY:-}" ]; then
  configure_and_build "$build-variant" "$FAS_VARIANT_OVERLAY"
  "$build-variant/benchmark/Flow_aligned_surfaces/bench_deformation" "$out/table1-variant.json"
  variant_args=(--variant "${FAS_VARIANT_LABEL:-overlay $FAS_VARIANT_OVERLAY}=$out/table1-variant.json")
fi
"$bin/bench_grid_sampling" --benchmark_filter=Grid \
  --benchmark_out="$out/grid_sampling.json" --benchmark_out_format=json
python3 "$here/make_results.py" --table1 "$out/table1.json" "${variant_args[@]}" \
  --grid "$out/grid_sampling.json" \
  --command "${FAS_VARIANT_OVERLAY:+FAS_VARIANT_OVERLAY=$FAS_VARIANT_OVERLAY }benchmark/Flow_aligned_surfaces/run_table1.sh${1:+ $*} (runs: $table1_command)" \
  --grid-command "$grid_command" --results "$here/RESULTS.md"
