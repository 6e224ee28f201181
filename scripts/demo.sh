#!/usr/bin/env bash
# The main job on a bundled example: tetrahedralize, check exactly, write a .vtu ParaView opens.
set -euo pipefail
build="${1:-build}"
out="$build/demo"
mkdir -p "$out"
echo "== VolGrid demo: exact Delaunay tetrahedralization of 200,000 random points, checked =="
"$build/bin/volgrid" delaunay --random 200000 --seed 7 --check --json --out "$out/random200k.vtu"
echo "wrote $out/random200k.vtu (open it in ParaView)"
