#!/usr/bin/env bash
# Installs the Debian 12 packages VolGrid needs, only those missing (idempotent, quiet when all are there).
#   scripts/install-deps.sh build   what `make build` needs: compilers, CMake, ParaView's SDK, GoogleTest
#   scripts/install-deps.sh test    + what the tests compare against (TetGen, CGAL) and the independent
#                                   readers of the solver formats (gmsh, meshio, OpenFOAM), clang for the fuzzers
#   scripts/install-deps.sh bench   + what the benchmarks compare against
set -euo pipefail
level="${1:-build}"

# ParaView 5.11's CMake package needs MPI, double-conversion and utfcpp headers, and python3-paraview
# (its targets name the vtkmodules .so files). Never add libvtk9-dev: it removes python3-paraview/pvpython.
# zlib1g-dev: Core reads gzip-compressed surfaces (.stl.gz ...). qttools5-dev(-tools), qtxmlpatterns5-dev-tools:
# Qt5Help, qhelpgenerator and xmlpatterns, for the plugin's XML documentation (the "?" button of each filter's panel).
# libcgns-dev, libexodusii-dev: Core's CGNS and Exodus II writers and readers.
packages=(build-essential cmake pkg-config libgtest-dev
  paraview paraview-dev python3-paraview libopenmpi-dev libdouble-conversion-dev libutfcpp-dev
  zlib1g-dev qttools5-dev qttools5-dev-tools qtxmlpatterns5-dev-tools libcgns-dev libexodusii-dev)
case "$level" in
  build) ;;
  # openmpi-bin: the pvbatch tests under mpiexec; xvfb, xauth: the ParaView GUI test on a headless machine;
  # gmsh, python3-gmsh, python3-meshio (+ python3-netcdf4 for Exodus), openfoam, cgns-convert (cgnscheck):
  # independent readers of the solver formats;
  # clang, libclang-rt-14-dev: the libFuzzer reader targets (Testing/Fuzz, -fsanitize=fuzzer,address,undefined).
  test) packages+=(libtet1.5-dev tetgen libcgal-dev libgmp-dev openmpi-bin xvfb xauth
    gmsh python3-gmsh python3-meshio python3-netcdf4 openfoam cgns-convert clang libclang-rt-14-dev) ;;
  bench) packages+=(libtet1.5-dev tetgen libcgal-dev libgmp-dev time gmsh python3-gmsh openfoam) ;;
  *) echo "usage: $0 build|test|bench" >&2; exit 2 ;;
esac

# Libraries the build links whose Debian 12 updates change behaviour: kept at the version a new machine
# gets, so that developers, CI and users run alike (libexpat1 2.5.0-1+deb12u2 and later defer re-parsing,
# which VTK 9.2's XML readers trip over; VolGrid's readers and writers handle it).
current=(libexpat1)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
apt_get() { $SUDO apt-get -o DPkg::Lock::Timeout=600 "$@"; }

# Package lists older than a day are refreshed before versions are compared.
lists_stamp=/var/cache/apt/pkgcache.bin
if [ ! -f "$lists_stamp" ] || [ -n "$(find "$lists_stamp" -mmin +1440 2>/dev/null)" ]; then
  apt_get update -q >/dev/null || echo "install-deps: apt-get update failed; comparing with the lists at hand" >&2
fi
outdated=()
for p in "${current[@]}"; do
  installed=$(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || true)
  candidate=$(apt-cache policy "$p" 2>/dev/null | awk '/Candidate:/ {print $2}')
  if [ -n "$installed" ] && [ -n "$candidate" ] && [ "$candidate" != "(none)" ] && [ "$installed" != "$candidate" ]; then
    outdated+=("$p")
  fi
done
if [ "${#outdated[@]}" -gt 0 ]; then
  echo "install-deps: updating ${outdated[*]} to the current Debian 12 version"
  apt_get install -y -q --only-upgrade "${outdated[@]}"
fi

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
apt_get update -q
apt_get install -y -q --no-install-recommends "${missing[@]}"
