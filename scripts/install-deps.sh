#!/usr/bin/env bash
# Usage: scripts/install-deps.sh [--debian-vtk] [--check]
#
# Installs every dependency of Flow_aligned_surfaces from Debian's packages.
#
#   scripts/install-deps.sh               the full set: the library, its tests, the demo and the
#                                         ParaView plugin (ParaView 5.11 and its own VTK 9.2)
#   scripts/install-deps.sh --debian-vtk  Debian's VTK 9.1 (libvtk9-dev) instead of ParaView: the
#                                         same without the plugin, for a machine that keeps
#                                         python3-vtk9
#   scripts/install-deps.sh --check       lists what is missing or outdated, installs nothing
#                                         (exit status 1 when something is); with --debian-vtk,
#                                         for that set
#
#   scripts/install-deps.sh --help        this help
#
# Idempotent: packages already present are skipped, and apt is not touched at all when
# everything is there (one dpkg-query call checks them all, in a fraction of a second).
#
# Current, not only present: libexpat1 is brought to the distribution's current version (an
# upgrade, never a removal).  Its security updates change what ParaView 5.11's VTK can parse
# (2.5.0-1+deb12u2 and later: no VTK XML file with appended data), and a fresh machine gets the
# current one, so the project's own machines must see what its users' machines see.  "Current"
# is the version apt's package lists offer; they are refreshed (apt-get update) whenever this
# script installs something.
#
# It never removes a package.  apt-get install can remove packages silently to resolve a
# conflict: on Debian bookworm, python3-paraview (ParaView's Python, needed to build a plugin)
# conflicts with python3-vtk9, which libvtk9-dev depends on.  So the installation is first
# simulated; if apt would remove anything, this script names what and why, installs nothing,
# and fails.  One VTK per process: the package's VTK parts build against ParaView's VTK when
# ParaView is installed, so the full set needs no libvtk9-dev.
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"

vtk_set=paraview
check_only=0
for arg in "$@"; do
  case "$arg" in
    --debian-vtk) vtk_set=debian ;;
    --check) check_only=1 ;;
    *) echo "usage: scripts/install-deps.sh [--debian-vtk] [--check] (--help says more)" >&2; exit 2 ;;
  esac
done

packages=(
  cmake g++ make pkg-config ccache
  libcgal-dev libgmp-dev libmpfr-dev   # CGAL 5.5 (header-only) and its number types
  libeigen3-dev                         # Eigen 3.4
  libboost-dev                          # Boost (graph, property maps)
  libboost-program-options-dev          # the demo programs' command line
  nlohmann-json3-dev                    # the main job's summary.json (Debian's Boost.JSON needs Boost 1.81)
  libopenmesh-dev                       # OpenMesh, tested through CGAL's graph traits
  libsuitesparse-dev                    # CHOLMOD sparse Cholesky
  libopenblas-dev                       # an optimized BLAS for CHOLMOD (Debian defaults to the reference one)
  libtbb-dev                            # parallel loops
  zlib1g-dev liblz4-dev liblzma-dev     # compressed VTK XML (zlib, LZ4, LZMA), AmiraMesh (HxZip) and NRRD (gzip) data
  libpng-dev                            # PNG textures, optional
  libx11-dev xvfb xauth                 # the demo's pictures off screen (VTK under Xvfb where no display exists)
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev              # the readers' libFuzzer targets (clang++ -fsanitize=fuzzer), run by the tests
  doxygen graphviz libjs-mathjax        # documentation, built in the tests; formulas rendered offline
  gnuplot-nox                           # the flux plot of replayed sessions (Figure 6)
)

if [ "$vtk_set" = paraview ]; then
  packages+=(
    paraview paraview-dev python3-paraview   # ParaView 5.11 with its VTK 9.2: the plugin, and VTK for everything else
    openmpi-bin libopenmpi-dev               # mpiexec and MPI's C headers (ParaView's CMake package asks for them)
    libqt5svg5                               # the GUI's icons
    # The plugin's help pages (ParaView's "?" button): Qt's Help CMake package (qttools5-dev, which
    # pulls in qtbase5-dev), qhelpgenerator and xmlpatterns; without them the plugin has no help.
    qttools5-dev qttools5-dev-tools qtxmlpatterns5-dev-tools
    # The plugin's GUI side links ParaView's pqCore, whose link interface names Qt5::OpenGL and
    # VTK's libxml2, HDF5 and NetCDF modules.
    libqt5opengl5-dev libxml2-dev libhdf5-dev libnetcdf-dev
    # What ParaView's CMake package and its VTK modules look for (paraview-dev does not depend on them):
    libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libswresample-dev
    libexpat1-dev libdouble-conversion-dev libutfcpp-dev python3-dev
    libglew-dev libgl-dev libjpeg-dev libtiff-dev libfreetype-dev
  )
else
  packages+=(libvtk9-dev)                    # VTK 9.1: XML readers (.vti, .vtu, .vts, .pvd), the VTK tests, the demo's pictures
fi

# Kept at the distribution's current version where installed (see the opening comment); the
# -dev package goes with its library, whose exact version it depends on.
kept_current=(libexpat1 libexpat1-dev)

# Which packages are installed, and their versions, in one dpkg-query call (a call per package
# took 2 s): its lines are "NAME VERSION WANT OK STATUS"; unknown names are left out (with an
# exit status of 1).
declare -A is_installed=() installed_version=()
while read -r name version _ _ status; do
  if [ "$status" = installed ]; then is_installed[$name]=1; installed_version[$name]=$version; fi
done < <(dpkg-query -W -f='${Package} ${Version} ${Status}\n' "${packages[@]}" "${kept_current[@]}" \
           python3-paraview libvtk9-dev 2>/dev/null || true)
installed() { [ -n "${is_installed[$1]:-}" ]; }

# The installed packages of kept_current older than the version apt's package lists offer
# (read from the lists on disk: no download), as "NAME INSTALLED CANDIDATE" lines.
outdated_packages() {
  local p candidate
  for p in "${kept_current[@]}"; do
    installed "$p" || continue
    candidate=$(apt-cache policy "$p" 2>/dev/null | awk '$1 == "Candidate:" { print $2 }')
    if [ -n "$candidate" ] && [ "$candidate" != "(none)" ] &&
       dpkg --compare-versions "${installed_version[$p]}" lt "$candidate"; then
      echo "$p ${installed_version[$p]} $candidate"
    fi
  done
}

# --debian-vtk where ParaView's Python is there: keep it, and leave Debian's VTK out (its
# python3-vtk9 conflicts).
if [ "$vtk_set" = debian ] && installed python3-paraview && ! installed libvtk9-dev; then
  echo "install-deps: python3-paraview is installed and conflicts with libvtk9-dev (through python3-vtk9);"
  echo "  libvtk9-dev is left out: the package's VTK parts use ParaView's VTK where paraview-dev is installed,"
  echo "  and are not built where it is not (run this script without --debian-vtk to install it)."
  kept=()
  for p in "${packages[@]}"; do [ "$p" = libvtk9-dev ] || kept+=("$p"); done
  packages=("${kept[@]}")
fi

missing=()
for p in "${packages[@]}"; do
  if ! installed "$p"; then
    missing+=("$p")
  fi
done

outdated=$(outdated_packages)

if [ "$check_only" = 1 ]; then
  if [ ${#missing[@]} -eq 0 ] && [ -z "$outdated" ]; then
    echo "install-deps --check: all dependencies present and current"
    exit 0
  fi
  if [ ${#missing[@]} -gt 0 ]; then
    echo "install-deps --check: missing: ${missing[*]}"
  fi
  while read -r p have offered; do
    [ -n "$p" ] && echo "install-deps --check: outdated: $p $have is installed, $offered is current"
  done <<< "$outdated"
  rerun=scripts/install-deps.sh
  if [ "$vtk_set" = debian ]; then rerun+=" --debian-vtk"; fi
  echo "install-deps --check: nothing installed; $rerun installs and upgrades them"
  exit 1
fi

if [ ${#missing[@]} -eq 0 ] && [ -z "$outdated" ]; then
  echo "install-deps: all dependencies present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq

# The refreshed lists may offer newer versions than the old ones did.
outdated=$(outdated_packages)
upgrades=()
while read -r p _; do
  if [ -n "$p" ]; then upgrades+=("$p"); fi
done <<< "$outdated"
wanted=("${missing[@]}" "${upgrades[@]}")
if [ ${#wanted[@]} -eq 0 ]; then
  echo "install-deps: all dependencies present"
  exit 0
fi
echo "install-deps: installing ${missing[*]:-nothing new}${upgrades[*]:+; upgrading ${upgrades[*]}}"

# Simulate first: "Remv <package> [...]" lines are what a real run would remove.
simulation=$(apt-get install -s --no-install-recommends "${wanted[@]}" 2>&1) || {
  echo "install-deps: apt cannot install ${wanted[*]}:" >&2
  echo "$simulation" >&2
  exit 1
}
removals=$(printf '%s\n' "$simulation" | awk '$1 == "Remv" { print $2 }')
if [ -n "$removals" ]; then
  {
    echo "install-deps: stopped, nothing installed: installing ${wanted[*]} would REMOVE these packages:"
    printf '  %s\n' $removals
    if printf '%s\n' $removals | grep -qx python3-vtk9; then
      echo "python3-vtk9 (pulled in by libvtk9-dev) and python3-paraview cannot be installed together."
      echo "Either remove Debian's VTK yourself once (apt-get remove libvtk9-dev python3-vtk9) and run this"
      echo "script again, or keep it and run scripts/install-deps.sh --debian-vtk (no ParaView plugin)."
    fi
    echo "If you want that change, run apt-get install yourself and read what it says it removes."
  } >&2
  exit 1
fi
$SUDO apt-get install -y -qq --no-install-recommends "${wanted[@]}"
