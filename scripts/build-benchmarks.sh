#!/usr/bin/env bash
# Builds the benchmarks (benchmark/Flow_aligned_surfaces/), which the tests do not run, into
# BUILD_DIR (default build/benchmark), Release.  The scripts beside the benchmarks
# (run_table1.sh, run_field_benchmarks.sh) build what they run themselves; this builds all of them,
# for instance to check that they still compile after a change.
#   scripts/build-benchmarks.sh [BUILD_DIR] [TARGET...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/benchmark}
shift || true
"$root/scripts/install-deps.sh"
export CCACHE_BASEDIR="$root"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFAS_BUILD_BENCHMARKS=ON \
  -DFAS_BUILD_TESTS=OFF -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_DEMO=OFF -DFAS_BUILD_DOC_TEST=OFF -DBUILD_TESTING=OFF
if [ $# -gt 0 ]; then
  cmake --build "$build" -j"$(nproc)" --target "$@"
else
  cmake --build "$build" -j"$(nproc)"
fi
echo "build-benchmarks: the programs are in $build/benchmark/Flow_aligned_surfaces"
