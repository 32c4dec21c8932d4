#!/usr/bin/env bash
# `cmake --install BUILD_DIR --prefix PREFIX` puts the plugin where ParaView finds it through
# PV_PLUGIN_PATH: the built tree is installed into a temporary prefix, and pvbatch, given
# PV_PLUGIN_PATH=PREFIX/lib/paraview-5.11/plugins/FlowAlignedSurfaces (the folder the README and
# the manual name), loads the plugin by name from there, without a path into the build tree
# (check_plugin_loaded.py).
# Run as: test_plugin_install.sh CMAKE BUILD_DIR PVBATCH CHECK_SCRIPT
set -euo pipefail
cmake=$1 build=$2 pvbatch=$3 check=$4
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
fail() { printf 'test_plugin_install: %b\n' "$*" >&2; exit 1; }

output=$("$cmake" --install "$build" --prefix "$prefix" 2>&1) || fail "cmake --install failed:\n$output"
plugin_dir="$prefix/lib/paraview-5.11/plugins/FlowAlignedSurfaces"
[ -f "$plugin_dir/FlowAlignedSurfaces.so" ] ||
  fail "no $plugin_dir/FlowAlignedSurfaces.so; installed:\n$(cd "$prefix" && find . -name '*.so')"
PV_PLUGIN_PATH="$plugin_dir" "$pvbatch" "$check" "$plugin_dir"
