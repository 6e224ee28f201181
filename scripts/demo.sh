#!/usr/bin/env bash
# The main job on a bundled example: a wing inside a far-field sphere, meshed with its boundary kept
# exactly, checked, and analysed. Writes files ParaView opens (build/demo/*.vtu, *.vtp).
set -euo pipefail
build="${1:-build}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
volgrid="$build/bin/volgrid"
out="$build/demo"
mkdir -p "$out"

echo "== 1. Surface preparation: the wing (Testing/Data/straight_wing.stl) inside a sphere 5x its size =="
"$volgrid" prep "$root/Testing/Data/straight_wing.stl" "$out/wing_in_sphere.vtp" \
  --enclosure sphere --enclosure-scale 5
echo
echo "== 2. Volume mesh between the wing and the sphere, boundary kept exactly, checked =="
"$volgrid" mesh "$out/wing_in_sphere.vtp" "$out/wing_in_sphere.vtu" --boundary "$out/wing_boundary.vtp" --check
echo
echo "== 3. Grid quality =="
"$volgrid" quality "$out/wing_in_sphere.vtu"
echo
echo "== 4. The exact Delaunay kernel on 200,000 random points, checked =="
"$volgrid" delaunay --random 200000 --seed 7 --check
echo
echo "Open $out/wing_in_sphere.vtu (Region), $out/wing_boundary.vtp (PatchId) in ParaView,"
echo "or load build/lib/paraview-5.11/plugins/VolGrid/VolGrid.so and use Filters > VolGrid."
