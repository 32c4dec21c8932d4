#!/usr/bin/env bash
# The plugin's five filters on 1 rank, 2 ranks and 4 ranks (oversubscribed on 2 cores) of the
# same pipeline (RESULTS.md, "ParaView plugin under MPI"): runs paraview_mpi_filters.py on each
# form of the CYLINDER data, in ROUNDS rounds of 1, 2 and 4 ranks one after the other (so that a
# machine that slows down or speeds up weighs on every number of ranks alike); then
# summarize_mpi_filters.py (the medians, and the median over the rounds of each round's ratio to
# 1 rank) and compare_mpi_outputs.py (every output the same to 1e-9 on every number of ranks).
# About 3 minutes per round on 2 cores; run it with nothing else on the machine.
#
#   [ROUNDS=3] benchmark/Flow_aligned_surfaces/run_mpi_filters.sh BUILD_DIR [DATA_DIR] [FORM ...]
#
# BUILD_DIR: a Release build with the plugin (scripts/build-paraview-plugin.sh, or the tests' tree);
# DATA_DIR: ../shared/data by default; FORM: cells image unsteady_cells unsteady_cells_cached
# unsteady_image by default.
# The outputs and each run's lines (BUILD_DIR/mpi_filters/FORM_runs.txt) go to
# BUILD_DIR/mpi_filters/; the tables to stdout.
set -euo pipefail
source "$(dirname "$0")/../../scripts/lib/help.sh"
exit_if_help_asked "$@"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:?usage: run_mpi_filters.sh BUILD_DIR [DATA_DIR] [FORM ...]}" && pwd)"
data="$(cd "${2:-$root/../shared/data}" && pwd)"
shift $(( $# >= 2 ? 2 : 1 ))
forms=("$@")
[ ${#forms[@]} -gt 0 ] || forms=(cells image unsteady_cells unsteady_cells_cached unsteady_image)
plugin="$build/lib/paraview-5.11/plugins/FlowAlignedSurfaces/FlowAlignedSurfaces.so"
reference="$build/demo/Flow_aligned_surfaces/ParaView/test/paraview_reference"
work="$build/mpi_filters"
mkdir -p "$work"
script="$here/paraview_mpi_filters.py"
# ParaView 5.11's VTK reads appended VTK XML (the .vti, RedistributeDataSet's pieces) only with the
# expat compatibility library preloaded (the manual, "Installing the plugin").
preload="LD_PRELOAD=$build/lib/libFlowAlignedSurfacesExpatCompat.so"
echo "load before: $(cat /proc/loadavg)"
rounds="${ROUNDS:-3}"
status=0
for form in "${forms[@]}"; do
  runs="$work/${form}_runs.txt"
  : >"$runs"
  for round in $(seq "$rounds"); do
    env "$preload" pvbatch "$script" "$plugin" "$reference" "$work" "$data" "$form" | grep "^$form " >>"$runs"
    for ranks in 2 4; do
      OMPI_MCA_mpi_yield_when_idle=1 mpiexec --allow-run-as-root --oversubscribe -n "$ranks" -x "$preload" \
        pvbatch --mpi "$script" "$plugin" "$reference" "$work" "$data" "$form" | grep "^$form " >>"$runs"
    done
  done
  python3 "$here/summarize_mpi_filters.py" "$runs"
  python3 "$here/compare_mpi_outputs.py" "$work" "$form" 1 2 4 || status=1
done
exit $status
