#!/usr/bin/env bash
# scripts/build-paraview-plugin.sh without a second build of the plugin: on a clean folder with
# --configure-only it configures, builds nothing and prints where the plugin will be and the
# PV_PLUGIN_PATH line; on the tests' own, already built folder it reconfigures nothing and the
# PV_PLUGIN_PATH line it prints loads the plugin (in pvbatch, as check_plugin_loaded.py checks);
# a folder configured without the plugin is refused with ParaView named.
# Run as: test_build_plugin_script.sh SCRIPT BUILD_DIR PVBATCH CHECK_SCRIPT
set -euo pipefail
script=$1 build=$2 pvbatch=$3 check=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { printf 'test_build_plugin_script: %b\n' "$*" >&2; exit 1; }
# The tests run where the dependencies are: the script's apt step is left out.
export FAS_SKIP_INSTALL_DEPS=1
layout=lib/paraview-5.11/plugins/FlowAlignedSurfaces

# 1. A clean folder, --configure-only.
clean="$work/plugin"
output=$(bash "$script" "$clean" --configure-only 2>&1) || fail "--configure-only failed:\n$output"
[ -f "$clean/CMakeCache.txt" ] || fail "$clean was not configured:\n$output"
grep -qx "  $clean/$layout/FlowAlignedSurfaces.so" <<<"$output" || fail "the plugin's path is not printed:\n$output"
grep -qx "  PV_PLUGIN_PATH=$clean/$layout paraview" <<<"$output" || fail "no PV_PLUGIN_PATH line:\n$output"
grep -q "Tools > Manage Plugins > Load New" <<<"$output" || fail "the GUI's route is not printed:\n$output"
# CMakeFiles/ holds the configuration's own probes (HDF5's package compiles a test program).
built=$(find "$clean" -path "$clean/CMakeFiles" -prune -o \( -name '*.so' -o -name '*.o' \) -print | head -3)
[ -z "$built" ] || fail "--configure-only built something:\n$built"

# 2. The built folder: used as it is, and the printed line loads the plugin.
before=$(stat -c %Y "$build/CMakeCache.txt")
output=$(bash "$script" "$build" --configure-only 2>&1) || fail "failed on $build:\n$output"
[ "$(stat -c %Y "$build/CMakeCache.txt")" = "$before" ] || fail "$build was configured again"
line=$(grep -x "  PV_PLUGIN_PATH=/.* paraview" <<<"$output") || fail "no PV_PLUGIN_PATH line:\n$output"
plugin_path=$(sed 's/^  PV_PLUGIN_PATH=\(.*\) paraview$/\1/' <<<"$line")
[ "$plugin_path" = "$build/$layout" ] || fail "PV_PLUGIN_PATH=$plugin_path, expected $build/$layout"
PV_PLUGIN_PATH="$plugin_path" "$pvbatch" "$check" "$plugin_path"

# 3. A folder configured without the plugin (no ParaView there): refused, ParaView named.
mkdir "$work/no_plugin" && touch "$work/no_plugin/CMakeCache.txt" "$work/no_plugin/Makefile"
if output=$(bash "$script" "$work/no_plugin" 2>&1); then fail "a folder without the plugin was accepted:\n$output"; fi
grep -q "ParaView 5.11 was not found" <<<"$output" || fail "ParaView is not named:\n$output"
echo "test_build_plugin_script: configure-only builds nothing, the printed PV_PLUGIN_PATH line loads the plugin, a folder without it is refused"
