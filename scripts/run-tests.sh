#!/usr/bin/env bash
# Builds everything (library checks, examples, benchmarks, manual) and runs every test
# through ctest: the GoogleTest suite, the examples, the Doxygen build and the
# find_package consumer project; then the test suite again under ASan+UBSan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

"$root/scripts/install-deps.sh"
# ccache hashes paths relative to the clone, so a fresh clone reuses an earlier clone's objects.
export CCACHE_BASEDIR="$root"

build="$root/build/release"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$jobs"
(cd "$build" && ctest --output-on-failure -j"$jobs")

if [ "${FAS_SKIP_SANITIZERS:-0}" != 1 ]; then
  sanitized="$root/build/sanitize"
  # -O1 -g1: the sanitizers need no more, and it compiles in half the time of -O2 -g.
  cmake -S "$root" -B "$sanitized" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DFAS_SANITIZE=ON \
    -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_BENCHMARKS=OFF -DFAS_BUILD_DOC_TEST=OFF
  cmake --build "$sanitized" --target test_flow_aligned_surfaces -j"$jobs"
  (cd "$sanitized" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions="$root/test/Flow_aligned_surfaces/ubsan.supp" \
    ctest --output-on-failure -j"$jobs" -E consumer)
fi
