#!/usr/bin/env bash
# Installs every rfmems dependency from Debian packages (Debian 12 "bookworm").
# Idempotent: when everything is present it only checks and returns in about a second.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  clang-format                          # the C++ style check in the tests
  libsundials-dev                       # SUNDIALS 6.4: IDA, KINSOL, SUNLinSol_KLU, SPGMR
  libsuitesparse-dev                    # KLU; UMFPACK (large static solves and modal analyses)
  libopenblas0-serial                   # the BLAS and LAPACK behind UMFPACK's dense fronts
                                        # (3-5x the reference BLAS; serial: no threads beside
                                        # the MPI ranks)
  libeigen3-dev                         # dense small blocks, least-squares gradients
  libspectra-dev                        # Arnoldi eigensolver (modal analysis), header-only
  libmetis-dev                          # mesh partitioning
  libhypre-dev                          # BoomerAMG: algebraic multigrid for large structures
  libopenmpi-dev openmpi-bin            # MPI
  libhdf5-dev hdf5-tools                # results; h5dump for inspection
  libyaml-cpp-dev                       # case files
  libcli11-dev                          # command lines
  libspdlog-dev libfmt-dev              # logging and formatting
  nlohmann-json3-dev                    # JSON summaries
  libgtest-dev googletest               # unit tests
  libnanoflann-dev                      # KD-trees (mesh motion)
  libboost-dev                          # Boost.Geometry R-tree: immersed-boundary cell marking
  gmsh                                  # unstructured meshes from cases/*.geo
  python3 python3-matplotlib python3-h5py python3-numpy python3-yaml  # plots, docs (call /usr/bin/python3)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
