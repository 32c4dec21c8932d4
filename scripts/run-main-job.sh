#!/usr/bin/env bash
# Usage: scripts/run-main-job.sh [OUTPUT_DIR] [OPTION...]
#
# The main job: installs what is missing from Debian's packages (scripts/install-deps.sh), builds
# the application align_patch (demo/Flow_aligned_surfaces/) and runs it: it places a patch in a
# flow (default: the potential flow past a cylinder), aligns it tangentially and orthogonally, and
# writes the initial and aligned surfaces (PLY, VTP), the flux per iteration (CSV), seed curves,
# stream surfaces and stream lines (VTP), pictures (PNG) and summary.json into OUTPUT_DIR.
#
#   OUTPUT_DIR  the output folder (default: ./flow_aligned_surfaces_output); the first argument is
#               taken for it only when it does not start with "-" (or give --output DIR)
#   OPTION...   align_patch's options: --flow NAME | --field FILE [--array NAME],
#               --alignment MODE, --faces N, --center X,Y,Z, --normal X,Y,Z, --size S,
#               --overwrite (a non-empty OUTPUT_DIR is refused without it), --quiet
#   --help      prints this help, and align_patch's own when it is built; does nothing else
#
# Exit status: align_patch's (0 on success, 1 when the run fails, 2 for a bad command line), or
# the failing step's.  An up-to-date machine reaches the job in about a second: the
# dependency check is one dpkg-query call, and CMake configures the build folder only the first
# time (the build reconfigures by itself when a CMakeLists.txt changed).  FAS_BUILD_DIR chooses
# the build folder (default: build/release in the clone).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FAS_BUILD_DIR:-$root/build/release}
align_patch="$build/demo/Flow_aligned_surfaces/align_patch"
source "$root/scripts/lib/help.sh"
for arg in "$@"; do
  if [ "$arg" = --help ] || [ "$arg" = -h ]; then
    print_help "$0"
    echo
    if [ -x "$align_patch" ]; then
      "$align_patch" --help || true   # an old build may not know --help
    else
      echo "(align_patch is not built yet; its options are in the README's main-job section.)"
    fi
    exit 0
  fi
done

# The output folder: the first argument unless it is an option, else align_patch's --output.
out=
if [ $# -gt 0 ] && [[ $1 != -* ]]; then
  out=$1
  shift
fi
output_option=false
for arg in "$@"; do
  case $arg in --output|--output=*) output_option=true ;; esac
done
if $output_option && [ -n "$out" ]; then
  echo "run-main-job: the output folder is given twice, as OUTPUT_DIR ($out) and as --output" >&2
  exit 2
fi
if ! $output_option; then
  set -- --output "${out:-$PWD/flow_aligned_surfaces_output}" "$@"
fi

"$root/scripts/install-deps.sh"
if [ ! -f "$build/CMakeCache.txt" ] || { [ ! -f "$build/Makefile" ] && [ ! -f "$build/build.ninja" ]; }; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target align_patch -j"$(nproc)"
exec "$align_patch" "$@"
