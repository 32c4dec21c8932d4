#!/usr/bin/env bash
# Builds the benchmarks (benchmark/Flow_aligned_surfaces/), which the tests do not run, into
# BUILD_DIR (default build/benchmark), Release.  The scripts beside the benchmarks
# (run_table1.sh, run_field_benchmarks.sh) build what they run themselves; this builds all of them,
# for instance to check that they still compile after a change.
#
# Usage: scripts/build-benchmarks.sh [BUILD_DIR] [TARGET...]    (--help: this help)
# The first argument is the build folder only when it does not start with "-".
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build/benchmark
if [ $# -gt 0 ]; then
  case $1 in
    -*) echo "build-benchmarks: unknown option '$1' (--help says how to call it)" >&2; exit 2 ;;
    *) build=$1; shift ;;
  esac
fi
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
