#!/usr/bin/env bash
# Usage: scripts/build-paraview-plugin.sh [BUILD_DIR] [--configure-only]
#
# The ParaView plugin alone: installs what is missing from Debian's packages
# (scripts/install-deps.sh), configures BUILD_DIR, builds the plugin (its five filters and the
# help pages of ParaView's "?" button) and the expat compatibility library, nothing else, and
# prints the plugin's path and how to load it in ParaView.
#
#   BUILD_DIR         the build folder (default: build/plugin in the clone); one that is already
#                     configured, such as build/release, is used as it is
#   --configure-only  configures BUILD_DIR and prints the same, builds nothing
#   --help            this help
#
# Then `cmake --install BUILD_DIR --prefix PREFIX` installs the plugin as
# PREFIX/lib/paraview-5.11/plugins/FlowAlignedSurfaces/FlowAlignedSurfaces.so, which
# PV_PLUGIN_PATH=PREFIX/lib/paraview-5.11/plugins/FlowAlignedSurfaces loads.
# FAS_SKIP_INSTALL_DEPS=1 skips the dependency step (the tests, which run where they are).
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"
root=$(cd "$(dirname "$0")/.." && pwd)

build=
configure_only=false
for arg in "$@"; do
  case $arg in
    --configure-only) configure_only=true ;;
    -*) echo "usage: scripts/build-paraview-plugin.sh [BUILD_DIR] [--configure-only] (--help says more)" >&2; exit 2 ;;
    *)
      if [ -n "$build" ]; then
        echo "build-paraview-plugin: one build folder only (got $build and $arg)" >&2
        exit 2
      fi
      build=$arg ;;
  esac
done
build=${build:-$root/build/plugin}
mkdir -p "$build"
build=$(cd "$build" && pwd)

if [ "${FAS_SKIP_INSTALL_DEPS:-0}" != 1 ]; then
  "$root/scripts/install-deps.sh"
fi
# ccache hashes paths relative to the clone, so a fresh clone reuses an earlier clone's objects.
export CCACHE_BASEDIR="$root"

# A new folder gets the plugin's configuration only: no tests, examples, demo or manual, whose
# dependencies the plugin does not need.  An existing one keeps its own.
if [ ! -f "$build/CMakeCache.txt" ] || { [ ! -f "$build/Makefile" ] && [ ! -f "$build/build.ninja" ]; }; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFAS_BUILD_PARAVIEW_PLUGIN=ON \
    -DBUILD_TESTING=OFF -DFAS_BUILD_TESTS=OFF -DFAS_BUILD_EXAMPLES=OFF -DFAS_BUILD_DEMO=OFF \
    -DFAS_BUILD_DOC_TEST=OFF
fi
# Written by CMake when it configures the plugin (demo/Flow_aligned_surfaces/ParaView).
if [ ! -f "$build/paraview_plugin_file.txt" ]; then
  echo "build-paraview-plugin: $build has no ParaView plugin: ParaView 5.11 was not found when it was" >&2
  echo "  configured, or FAS_BUILD_PARAVIEW_PLUGIN is OFF there (Debian: paraview-dev python3-paraview;" >&2
  echo "  scripts/install-deps.sh installs them)" >&2
  exit 1
fi
plugin=$(cat "$build/paraview_plugin_file.txt")
plugin_dir=$(dirname "$plugin")
# The build tree holds the plugin where the installation puts it below the prefix.
installed_dir="PREFIX/${plugin_dir#"$build"/}"

if ! $configure_only; then
  cmake --build "$build" --target FlowAlignedSurfaces FlowAlignedSurfacesExpatCompat -j"$(nproc)"
  if [ ! -f "$plugin" ]; then
    echo "build-paraview-plugin: the build ended without $plugin" >&2
    exit 1
  fi
  echo "build-paraview-plugin: the plugin is built:"
else
  echo "build-paraview-plugin: $build is configured (--configure-only: nothing built); the plugin will be:"
fi
cat <<EOF
  $plugin

Load it in ParaView 5.11, every filter under Filters > Flow-Aligned Surfaces:
  PV_PLUGIN_PATH=$plugin_dir paraview
(pvpython and pvbatch load it the same way), or in the GUI: Tools > Manage Plugins > Load New,
choose $plugin; tick Auto Load (expand the plugin's entry) to load it in every session.

Install it elsewhere: cmake --install $build --prefix PREFIX, then
  PV_PLUGIN_PATH=$installed_dir paraview
EOF
