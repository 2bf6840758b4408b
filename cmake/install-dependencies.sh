#!/usr/bin/env bash
# Installs the Debian 12 packages railfe builds and tests with. Idempotent: when every package is
# already installed it only runs dpkg-query and returns in well under a second.
set -euo pipefail

packages=(
  build-essential cmake ninja-build git clang-format
  trilinos-all-dev libptscotch-dev libscotch-dev   # Trilinos 13.2 and what its CMake targets link
  libexodusii-dev libnetcdf-dev netcdf-bin          # Exodus II 6.02 over netCDF (ncdump for checks)
  libsuitesparse-dev libmetis-dev                   # CHOLMOD supernodal Cholesky with METIS ordering
  libopenblas0-pthread                              # optimized, threaded BLAS/LAPACK (CHOLMOD: 10x over reference BLAS; rank 0 borrows idle cores)
  libeigen3-dev libmuparser-dev                     # small dense element math; deck expressions
  libfftw3-dev                                      # FFTs of the exact contact solver
  libopenmpi-dev openmpi-bin libgtest-dev
  gmsh python3 python3-matplotlib python3-numpy     # meshing; charts and studies
  python3-scipy                                     # modal benchmark reference (eigsh)
)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "railfe: all ${#packages[@]} dependencies are installed"
  exit 0
fi

echo "railfe: installing ${#missing[@]} missing packages: ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
