#!/usr/bin/env bash
# Regenerates the user manual's figures that the examples draw (doc/Flow_aligned_surfaces/fig/):
# the LIC-like and arrow textures of a stream surface (the paper's Figure 8) and the stream
# surface with its seed curves, from examples/Flow_aligned_surfaces/flow_texture.cpp, rendered
# by VTK off screen (under a private Xvfb when there is no display).  The schematic SVG figures
# come from doc/Flow_aligned_surfaces/fig/make_figures.py, the session plot from replay_session.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/release"
fig="$root/doc/Flow_aligned_surfaces/fig"
export CCACHE_BASEDIR="$root"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target flow_texture -j"$(nproc)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/examples/Flow_aligned_surfaces/flow_texture" --faces 3000 --picture-width 320 --output "$work" | tee "$work/log"
if ! grep -q "wrote the pictures" "$work/log"; then
  echo "make-figures: the pictures were not rendered (see above); figures unchanged" >&2
  exit 1
fi
cp "$work/textured.png" "$fig/fas_texture_noise.png"
cp "$work/arrows_rendered.png" "$fig/fas_texture_arrows.png"
cp "$work/aligned_flux.png" "$fig/fas_texture_seed_curves.png"
echo "make-figures: wrote $fig/fas_texture_noise.png, fas_texture_arrows.png, fas_texture_seed_curves.png"
