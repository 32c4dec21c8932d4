#!/usr/bin/env bash
# Installs every dependency of Flow_aligned_surfaces from Debian's packages.
# Idempotent: packages already present are skipped, and apt is not touched at all when
# everything is there.
#
# It never removes a package.  apt-get install can remove packages silently to resolve a
# conflict: on Debian bookworm, libvtk9-dev depends on python3-vtk9, which conflicts with
# python3-paraview (ParaView's Python).  So the installation is first simulated; if apt would
# remove anything, this script names what and why, installs nothing, and fails.
set -euo pipefail

packages=(
  cmake g++ make pkg-config ccache
  libcgal-dev libgmp-dev libmpfr-dev   # CGAL 5.5 (header-only) and its number types
  libeigen3-dev                         # Eigen 3.4
  libboost-dev                          # Boost (graph, property maps)
  libopenmesh-dev                       # OpenMesh, tested through CGAL's graph traits
  libsuitesparse-dev                    # CHOLMOD sparse Cholesky
  libopenblas-dev                       # an optimized BLAS for CHOLMOD (Debian defaults to the reference one)
  libtbb-dev                            # parallel loops
  libvtk9-dev                           # VTK XML readers (.vti, .vtu, .vts, .pvd), optional
  zlib1g-dev                            # compressed AmiraMesh (HxZip) and NRRD (gzip) data, optional
  libpng-dev                            # PNG textures, optional
  libx11-dev xvfb xauth                 # the demo's pictures off screen (VTK under Xvfb where no display exists)
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev              # the readers' libFuzzer targets (clang++ -fsanitize=fuzzer), run by the tests
  doxygen graphviz libjs-mathjax        # documentation, built in the tests; formulas rendered offline
  gnuplot-nox                           # the flux plot of replayed sessions (Figure 6)
)

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }

# ParaView's Python is there: keep it, and leave Debian's VTK out (its python3-vtk9 conflicts).
if installed python3-paraview && ! installed libvtk9-dev; then
  echo "install-deps: python3-paraview is installed and conflicts with libvtk9-dev (through python3-vtk9);"
  echo "  libvtk9-dev is left out, so the VTK XML readers, the VTK tests and the demo's pictures are not built."
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

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all dependencies present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq

# Simulate first: "Remv <package> [...]" lines are what a real run would remove.
simulation=$(apt-get install -s --no-install-recommends "${missing[@]}" 2>&1) || {
  echo "install-deps: apt cannot install ${missing[*]}:" >&2
  echo "$simulation" >&2
  exit 1
}
removals=$(printf '%s\n' "$simulation" | awk '$1 == "Remv" { print $2 }')
if [ -n "$removals" ]; then
  {
    echo "install-deps: stopped, nothing installed: installing ${missing[*]} would REMOVE these packages:"
    printf '  %s\n' $removals
    echo "If you want that change, run apt-get install yourself and read what it says it removes."
  } >&2
  exit 1
fi
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
