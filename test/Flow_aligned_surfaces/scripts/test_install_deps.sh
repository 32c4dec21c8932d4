#!/usr/bin/env bash
# scripts/install-deps.sh never removes a package: with a fake apt-get whose simulated install
# would remove python3-vtk9 (as python3-paraview does on Debian bookworm), the script must name
# the package, install nothing and fail; with a simulation that removes nothing it installs the
# ParaView set (with Qt's help tools for the plugin's help pages) by default and Debian's VTK
# (without them) with --debian-vtk; it upgrades an installed libexpat1
# older than the lists offer; --check lists what is missing or outdated and calls no apt-get.
# Run as: test_install_deps.sh <path of install-deps.sh>
set -euo pipefail
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin"

# dpkg-query -W -f='${Package} ${Version} ${Status}\n' PACKAGE...: nothing is installed except
# what FAKE_INSTALLED lists, each at version 1.0.
cat > "$work/bin/dpkg-query" <<'EOF'
#!/usr/bin/env bash
for package in "$@"; do
  for p in $FAKE_INSTALLED; do
    if [ "$p" = "$package" ]; then echo "$p 1.0 install ok installed"; fi
  done
done
exit 1
EOF
# apt-cache policy PACKAGE: the lists offer FAKE_CANDIDATE (default 1.0, what is installed).
cat > "$work/bin/apt-cache" <<'EOF'
#!/usr/bin/env bash
echo "$2:"
echo "  Installed: 1.0"
echo "  Candidate: ${FAKE_CANDIDATE:-1.0}"
EOF
# apt-get: records every call; a simulation prints FAKE_SIMULATION.
cat > "$work/bin/apt-get" <<'EOF'
#!/usr/bin/env bash
echo "apt-get $*" >> "$FAKE_LOG"
if [[ " $* " == *" -s "* ]]; then printf '%b' "$FAKE_SIMULATION"; fi
exit 0
EOF
printf '#!/usr/bin/env bash\n"$@"\n' > "$work/bin/sudo"
chmod +x "$work/bin/"*

fail() { printf 'test_install_deps: %b\n' "$*" >&2; exit 1; }

# 1. The default (ParaView) set where Debian's VTK is installed: the simulation would remove
#    python3-vtk9; stop, name it, say how to go on, install nothing.
export FAKE_LOG="$work/log1" FAKE_INSTALLED="libvtk9-dev python3-vtk9" \
  FAKE_SIMULATION='Inst python3-paraview (5.11.0)\nRemv python3-vtk9 [9.1.0]\nRemv libvtk9-dev [9.1.0]\n'
if output=$(PATH="$work/bin:$PATH" bash "$script" 2>&1); then
  fail "the script succeeded although apt would remove python3-vtk9:\n$output"
fi
grep -q "would REMOVE" <<<"$output" || fail "no message about the removal:\n$output"
grep -q "python3-vtk9" <<<"$output" || fail "the package to be removed is not named:\n$output"
grep -q -- "--debian-vtk" <<<"$output" || fail "the way on (--debian-vtk) is not named:\n$output"
if grep -q "install -y" "$FAKE_LOG"; then fail "apt-get install -y was called:\n$(cat "$FAKE_LOG")"; fi

# 2. The default set on a fresh machine: ParaView with its Python, no libvtk9-dev.
export FAKE_LOG="$work/log2" FAKE_INSTALLED="" FAKE_SIMULATION='Inst cmake (3.25)\n'
output=$(PATH="$work/bin:$PATH" bash "$script" 2>&1) || fail "the default set failed:\n$output"
grep "install -y" "$FAKE_LOG" | grep -q " python3-paraview " || fail "python3-paraview was not installed:\n$(cat "$FAKE_LOG")"
grep "install -y" "$FAKE_LOG" | grep -q "libvtk9-dev" && fail "libvtk9-dev was installed with the ParaView set"
for tool in qttools5-dev qttools5-dev-tools qtxmlpatterns5-dev-tools; do
  grep "install -y" "$FAKE_LOG" | grep -q " $tool\b" || fail "$tool (the plugin's help pages) was not installed:\n$(cat "$FAKE_LOG")"
done

# 3. --debian-vtk where python3-paraview is installed: libvtk9-dev is left out, the rest is
#    installed.
export FAKE_LOG="$work/log3" FAKE_INSTALLED="python3-paraview" FAKE_SIMULATION='Inst cmake (3.25)\n'
output=$(PATH="$work/bin:$PATH" bash "$script" --debian-vtk 2>&1) || fail "failed with python3-paraview installed:\n$output"
grep -q "libvtk9-dev is left out" <<<"$output" || fail "no word on leaving libvtk9-dev out:\n$output"
grep "install -y" "$FAKE_LOG" | grep -q "libvtk9-dev" && fail "libvtk9-dev was installed beside python3-paraview"
grep -q "install -y.* clang " "$FAKE_LOG" || fail "clang was not installed:\n$(cat "$FAKE_LOG")"

# 4. --debian-vtk on a fresh machine installs libvtk9-dev and no ParaView.
export FAKE_LOG="$work/log4" FAKE_INSTALLED="" FAKE_SIMULATION='Inst cmake (3.25)\n'
output=$(PATH="$work/bin:$PATH" bash "$script" --debian-vtk 2>&1) || fail "--debian-vtk failed:\n$output"
grep "install -y" "$FAKE_LOG" | grep -q "libvtk9-dev" || fail "libvtk9-dev was not installed with --debian-vtk"
grep "install -y" "$FAKE_LOG" | grep -q "paraview" && fail "ParaView was installed with --debian-vtk"
grep "install -y" "$FAKE_LOG" | grep -q "qttools5" && fail "the plugin's help tools were installed with --debian-vtk"

# 5. Everything there but libexpat1 is older than the lists offer: it is upgraded (installed
#    again at the candidate), nothing else is installed.
all=$(sed -n '/^packages=(/,/^)/p; /packages+=(/,/^  )/p' "$script" | sed 's/#.*//' |
      tr -s ' ()' '\n' | grep -E '^[a-z0-9][a-z0-9.+-]+$' | grep -v -x -e packages -e libvtk9-dev | tr '\n' ' ')
export FAKE_LOG="$work/log5" FAKE_INSTALLED="$all libexpat1" FAKE_CANDIDATE="2.0" FAKE_SIMULATION='Inst libexpat1 [1.0] (2.0)\n'
output=$(PATH="$work/bin:$PATH" bash "$script" 2>&1) || fail "the upgrade of libexpat1 failed:\n$output"
grep -q "install -y.* libexpat1" "$FAKE_LOG" || fail "libexpat1 was not upgraded:\n$output\n$(cat "$FAKE_LOG")"
grep "install -y" "$FAKE_LOG" | grep -q "paraview" && fail "ParaView was installed again:\n$(cat "$FAKE_LOG")"
grep -q "upgrading libexpat1" <<<"$output" || fail "the upgrade is not announced:\n$output"
export FAKE_CANDIDATE="1.0" FAKE_LOG="$work/log5b"
output=$(PATH="$work/bin:$PATH" bash "$script" 2>&1) || fail "a complete, current machine failed:\n$output"
grep -q "all dependencies present" <<<"$output" || fail "a complete machine was not recognized:\n$output"
[ ! -e "$FAKE_LOG" ] || fail "apt-get was called on a complete, current machine:\n$(cat "$FAKE_LOG")"

# 6. --check lists what is missing and what is outdated, calls no apt-get, and fails.
export FAKE_LOG="$work/log6" FAKE_INSTALLED="cmake libexpat1" FAKE_CANDIDATE="2.0"
if output=$(PATH="$work/bin:$PATH" bash "$script" --check 2>&1); then
  fail "--check succeeded on a machine that lacks packages:\n$output"
fi
grep -q "missing: .*libcgal-dev" <<<"$output" || fail "--check does not list libcgal-dev:\n$output"
grep -q "missing: .* cmake " <<<"$output" && fail "--check lists cmake, which is installed:\n$output"
grep -q "outdated: libexpat1 1.0 is installed, 2.0 is current" <<<"$output" || fail "--check does not list libexpat1:\n$output"
[ ! -e "$FAKE_LOG" ] || fail "--check called apt-get:\n$(cat "$FAKE_LOG")"
unset FAKE_CANDIDATE

echo "test_install_deps: the script stops before a removal, installs ParaView's set by default and Debian's VTK on request, upgrades libexpat1, and --check installs nothing"
