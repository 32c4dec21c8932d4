#!/usr/bin/env bash
# The main job: installs the dependencies, builds the application `align_patch` (demo/), places a
# patch in a built-in flow (potential flow past a cylinder), aligns it tangentially
# and orthogonally, and writes PLY and VTP meshes, a CSV of the normalized flux per
# iteration and a JSON summary into the output folder (default: ./flow_aligned_surfaces_output).
# Extra arguments go to align_patch (see --help).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$PWD/flow_aligned_surfaces_output}
shift || true

"$root/scripts/install-deps.sh"
build="$root/build/release"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target align_patch -j"$(nproc)"
"$build/demo/Flow_aligned_surfaces/align_patch" --output "$out" "$@"
