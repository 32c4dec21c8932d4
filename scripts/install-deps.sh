#!/usr/bin/env bash
# Installs every dependency of Flow_aligned_surfaces from Debian's packages.
# Idempotent: packages already present are skipped, and apt is not touched at all
# when everything is there.
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
  libx11-dev xvfb xauth                 # pictures off screen (VTK under Xvfb where no display exists)
  libgtest-dev libgmock-dev libbenchmark-dev
  doxygen graphviz                      # documentation, built in the tests
  gnuplot-nox                           # the flux plot of replayed sessions (Figure 6)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
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
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
