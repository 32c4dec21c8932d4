#!/usr/bin/env bash
# Usage: scripts/make-figures.sh       (--help: this help)
#
# Regenerates the user manual's figures that the demo's applications draw
# (doc/Flow_aligned_surfaces/fig/): the LIC-like and arrow textures of a stream surface (the
# paper's Figure 8) and the stream surface with its seed curves, from
# demo/Flow_aligned_surfaces/flow_texture_demo.cpp, and the seeding workflow (Figures 4 and 5) from
# the main job, demo/Flow_aligned_surfaces/align_patch.cpp (also on the unsteady cylinder: path
# surfaces), rendered
# by VTK off screen (under a private Xvfb when there is no display).  The schematic SVG figures
# come from doc/Flow_aligned_surfaces/fig/make_figures.py, the session plot from replay_session;
# the ParaView screenshots from the plugin's tests (demo/Flow_aligned_surfaces/ParaView/test), the
# tutorial's screenshots of the whole GUI from paraview_tutorial_gui.
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/release"
fig="$root/doc/Flow_aligned_surfaces/fig"
export CCACHE_BASEDIR="$root"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target flow_texture_demo align_patch -j"$(nproc)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/demo/Flow_aligned_surfaces/flow_texture" --faces 3000 --picture-width 320 --output "$work/texture" | tee "$work/log"
if ! grep -q "wrote the pictures" "$work/log"; then
  echo "make-figures: the pictures were not rendered (see above); figures unchanged" >&2
  exit 1
fi
cp "$work/texture/textured.png" "$fig/fas_texture_noise.png"
cp "$work/texture/arrows_rendered.png" "$fig/fas_texture_arrows.png"
cp "$work/texture/aligned_flux.png" "$fig/fas_texture_seed_curves.png"
# The seeding workflow of Figures 4 and 5: the main job's stage pictures (each in its scene's
# obstacle, outline and camera).
"$build/demo/Flow_aligned_surfaces/align_patch" --faces 3000 --output "$work/main_job" | tee "$work/main_job.log"
if [ ! -f "$work/main_job/orthogonal_stream_surfaces.png" ]; then
  echo "make-figures: the main job's pictures were not rendered (see above); seeding figures unchanged" >&2
  exit 1
fi
cp "$work/main_job/orthogonal_seed_curves.png" "$fig/fas_seeding_seed_curves.png"
cp "$work/main_job/orthogonal_stream_surfaces.png" "$fig/fas_seeding_stream_surfaces.png"
cp "$work/main_job/orthogonal_stream_lines.png" "$fig/fas_seeding_stream_lines.png"
# The main job's scene pictures (the initial patch beside the aligned one with what it seeds), on
# the built-in flow and, when the shared data is there, on the CFD cylinder without --center.
cp "$work/main_job/tangential_scene.png" "$fig/fas_main_job_tangential_scene.png"
cp "$work/main_job/orthogonal_scene.png" "$fig/fas_main_job_orthogonal_scene.png"
# Runs the main job on the shared data file $1 into $work/$2 and copies its pictures, each further
# argument PICTURE:FIGURE; when the data is not there, says which figures stay unchanged.
main_job_on_shared_data() {
  local data="$1" name="$2" pair
  shift 2
  if [ ! -f "$data" ]; then
    echo "make-figures: $data not found; ${*#*:} unchanged" >&2
    return
  fi
  "$build/demo/Flow_aligned_surfaces/align_patch" --field "$data" --faces 3000 --output "$work/$name" | tee "$work/$name.log"
  for pair in "$@"; do
    cp "$work/$name/${pair%%:*}" "$fig/${pair#*:}"
  done
}
shared="$root/../shared/data"
cylinder="$shared/CYLINDER_grid.vtk"
main_job_on_shared_data "$cylinder" cfd \
  tangential_scene.png:fas_main_job_cfd_tangential_scene.png orthogonal_scene.png:fas_main_job_cfd_orthogonal_scene.png
# The main job on the unsteady cylinder's time series: path surfaces.
main_job_on_shared_data "$shared/CYLINDER_UNSTEADY_grid.pvd" unsteady \
  tangential_scene.png:fas_main_job_unsteady_tangential_scene.png \
  tangential_path_surfaces.png:fas_main_job_unsteady_path_surfaces.png
# The ParaView pictures, from the plugin's tests (the GUI with the plane widget, the example script).
if [ -d "$build/demo/Flow_aligned_surfaces/ParaView" ]; then
  cmake --build "$build" --target FlowAlignedSurfaces paraview_reference -j"$(nproc)"
  (cd "$build" && ctest -R "paraview_gui|paraview_main_job_script" --output-on-failure)
  cp "$build/demo/Flow_aligned_surfaces/ParaView/test/paraview_gui.png" "$fig/fas_paraview_gui.png"
  cp "$build/demo/Flow_aligned_surfaces/ParaView/test/main_job/main_job.png" "$fig/fas_paraview_main_job.png"
  # The tutorial's screenshots of the whole GUI (needs the cylinder data: the test exists only then).
  if [ -f "$cylinder" ]; then
    (cd "$build" && ctest -R "^paraview_tutorial_gui$" --output-on-failure)
    cp "$build"/demo/Flow_aligned_surfaces/ParaView/test/tutorial/fas_tutorial_*.png "$fig/"
  else
    echo "make-figures: $cylinder not found; fas_tutorial_*.png unchanged" >&2
  fi
else
  echo "make-figures: ParaView not found; fas_paraview_*.png unchanged" >&2
fi
echo "make-figures: wrote $fig/fas_texture_noise.png, fas_texture_arrows.png, fas_texture_seed_curves.png,"
echo "  fas_seeding_seed_curves.png, fas_seeding_stream_surfaces.png, fas_seeding_stream_lines.png,"
echo "  fas_main_job_{tangential,orthogonal}_scene.png, fas_main_job_cfd_{tangential,orthogonal}_scene.png,"
echo "  fas_main_job_unsteady_{tangential_scene,path_surfaces}.png,"
echo "  fas_paraview_gui.png, fas_paraview_main_job.png, fas_tutorial_*.png (with ParaView)"
