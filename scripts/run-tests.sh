#!/usr/bin/env bash
# Usage: scripts/run-tests.sh          (--help: this help)
#
# Builds what the tests run and runs every test through ctest:
#  1. Release: the core GoogleTest executable (no VTK), the VTK one, the examples and the demo
#     programs (run as tests), the ParaView plugin (pvbatch scripts, the GUI under Xvfb, 2 MPI
#     ranks), the Doxygen manual, the find_package consumer project, the install-deps guard.  The
#     benchmarks are not built: scripts/build-benchmarks.sh builds them.
#  2. AddressSanitizer + UndefinedBehaviorSanitizer: the core executable, and the readers'
#     libFuzzer targets (clang++).  Rendering and VTK are not sanitized.
#  Both passes are compiled by clang++ when there is one, the consumer project by g++.
#     The package is configured without CHOLMOD here (FAS_WITH_CHOLMOD=OFF): the core suite runs once
#     with the solver of a machine without SuiteSparse, and the CHOLMOD solver's own tests run
#     sanitized with CHOLMOD from an executable of their own (test_flow_aligned_surfaces_cholmod).
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

# Both passes are compiled by clang++ when there is one (installed for the fuzz targets), and the
# outside project of consumer_find_package by g++: every run compiles the package with both
# compilers (each rejects some of what the other lets pass: clang a structured binding captured
# by a lambda, for one), and clang's front end takes the package's templates in about
# half of GCC's time (measured, cold, -O3: the examples 213 s of CPU against 390 s).
compilers=()
consumer_compiler=()
if command -v clang++ > /dev/null && command -v clang > /dev/null; then
  compilers=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang)
  if command -v g++ > /dev/null; then
    consumer_compiler=(-DFAS_CONSUMER_CXX_COMPILER="$(command -v g++)")
  fi
fi

build="$root/build/release"
cmake -S "$root" -B "$build" "${compilers[@]}" "${consumer_compiler[@]}" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$jobs"
(cd "$build" && ctest --output-on-failure -j"$jobs")

if [ "${FAS_SKIP_SANITIZERS:-0}" != 1 ]; then
  sanitized="$root/build/sanitize"
  # -O0, no debug information: the core suite compiles in a quarter of the time of -O1
  # (measured with clang: one unity batch 80 s of CPU at -O0, 334 s at -O1) and still runs in
  # minutes.  ASan's reports name the functions from the symbols; add -g1 for line numbers.
  # Without CHOLMOD: the Release pass above runs the suite with it, so the fallback solver (Eigen's
  # SimplicialLDLT) gets its run here at no cost in build time; the CHOLMOD solver's test file is
  # compiled alone with CHOLMOD, so that its sweeps stay sanitized.
  cmake -S "$root" -B "$sanitized" "${compilers[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -DNDEBUG" -DFAS_SANITIZE=ON -DFAS_WITH_CHOLMOD=OFF \
    -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_DEMO=OFF -DFAS_BUILD_DOC_TEST=OFF
  cmake --build "$sanitized" --target fas_core_tests -j"$jobs"
  (cd "$sanitized" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions="$root/test/Flow_aligned_surfaces/ubsan.supp" \
    ctest --output-on-failure -j"$jobs")
fi
