#!/usr/bin/env bash
# Usage: scripts/run-tests.sh          (--help: this help)
#
# Builds what the tests run and runs every test through ctest:
#  1. Release: the core GoogleTest executable (no VTK), the VTK one, the examples and the demo
#     programs (run as tests), the ParaView plugin (pvbatch scripts, the GUI under Xvfb, 2 MPI
#     ranks), the Doxygen manual, the find_package consumer project, the install-deps guard.  The benchmarks are not built: scripts/build-benchmarks.sh builds them.
#  2. AddressSanitizer + UndefinedBehaviorSanitizer: the core executable, and the readers'
#     libFuzzer targets (clang++).  Rendering and VTK are not sanitized.
# Under CI=true a missing tool fails the run instead of skipping tests (FAS_REQUIRE_ALL_TOOLS).
# FAS_SKIP_SANITIZERS=1 skips step 2.
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"
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
  # -O0, no debug information: the core suite compiles in less than half the time of -O1
  # (measured: one unity batch 245 s of CPU at -O0, over 540 s at -O1) and still runs in
  # minutes.  ASan's reports name the functions from the symbols; add -g1 for line numbers.
  cmake -S "$root" -B "$sanitized" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -DNDEBUG" -DFAS_SANITIZE=ON \
    -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_DEMO=OFF -DFAS_BUILD_DOC_TEST=OFF
  cmake --build "$sanitized" --target test_flow_aligned_surfaces -j"$jobs"
  (cd "$sanitized" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions="$root/test/Flow_aligned_surfaces/ubsan.supp" \
    ctest --output-on-failure -j"$jobs")
fi
