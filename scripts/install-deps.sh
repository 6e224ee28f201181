#!/usr/bin/env bash
# Installs the Debian 12 packages VolGrid needs, only those missing (idempotent, quiet when all are there).
#   scripts/install-deps.sh build   what `make build` needs: compilers, CMake, ParaView's SDK, GoogleTest
#   scripts/install-deps.sh test    + what the tests compare against (TetGen, CGAL)
#   scripts/install-deps.sh bench   + what the benchmarks compare against
set -euo pipefail
level="${1:-build}"

# ParaView 5.11's CMake package needs MPI, double-conversion and utfcpp headers, and python3-paraview
# (its targets name the vtkmodules .so files). Never add libvtk9-dev: it removes python3-paraview/pvpython.
# zlib1g-dev: Core reads gzip-compressed surfaces (.stl.gz ...). qttools5-dev(-tools), qtxmlpatterns5-dev-tools: Qt5Help, qhelpgenerator and xmlpatterns, for the
# plugin's XML documentation (the "?" button of each filter's panel).
packages=(build-essential cmake pkg-config libgtest-dev
  paraview paraview-dev python3-paraview libopenmpi-dev libdouble-conversion-dev libutfcpp-dev
  zlib1g-dev qttools5-dev qttools5-dev-tools qtxmlpatterns5-dev-tools)
case "$level" in
  build) ;;
  # openmpi-bin: the pvbatch tests under mpiexec; xvfb, xauth: the ParaView GUI test on a headless machine.
  test) packages+=(libtet1.5-dev tetgen libcgal-dev libgmp-dev openmpi-bin xvfb xauth) ;;
  bench) packages+=(libtet1.5-dev tetgen libcgal-dev libgmp-dev time gmsh) ;;
  *) echo "usage: $0 build|test|bench" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
