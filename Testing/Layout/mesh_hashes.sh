#!/bin/sh
# Meshes a fixed set of inputs with fixed options and prints one SHA-256 per output mesh (Medit .mesh,
# text: every coordinate, tet, boundary triangle and reference). A restructuring that keeps the mesher's
# behaviour keeps every line of this output; compare it with the lines recorded before the change:
#   Testing/Layout/mesh_hashes.sh build/bin/volgrid > after.txt && diff before.txt after.txt
# Corpus inputs are skipped (with a line saying so) where ../shared/data/real is absent.
set -eu
volgrid=${1:-build/bin/volgrid}
here=$(cd "$(dirname "$0")/../.." && pwd)
corpus=${VOLGRID_SHARED_DATA_DIR:-$here/../shared/data/real}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

hash_of() { sha256sum "$1" | cut -c1-64; }

# name, input, options
run() {
  name=$1 input=$2
  shift 2
  if [ ! -f "$input" ]; then
    echo "$name skipped (no $input)"
    return
  fi
  "$volgrid" mesh "$input" "$out/$name.mesh" --threads 1 "$@" > /dev/null
  echo "$name $(hash_of "$out/$name.mesh")"
}

run wing-default "$here/Testing/Data/straight_wing.stl"
run wing-fine "$here/Testing/Data/straight_wing.stl" --alpha 0.6 --beta 0.3 --gradation 1.3 --target-angle 20
run wing-threads2 "$here/Testing/Data/straight_wing.stl" --threads 2
run wing-no-quality "$here/Testing/Data/straight_wing.stl" --no-optimize --no-field-points
run spot "$corpus/common-3d-test-models/spot.obj" --max-edge 0.05
run onera-m6 "$corpus/derived-onera-m6/onera_m6_halfsphere_domain.mesh"
run button "$corpus/gmsh-benchmarks/button_ascii.stl"

# clustering: three points with their own sizes (text 'x y z size' lines)
printf '0.2 0.1 0.05 0.01\n0.5 0.1 0.05 0.02\n0.8 0.1 0.05 0.01\n' > "$out/cluster.txt"
run wing-cluster "$here/Testing/Data/straight_wing.stl" --cluster "$out/cluster.txt" --cluster-size 0.02
# the Delaunay kernel alone
"$volgrid" delaunay --random 20000 --seed 7 --out "$out/random.vtu" --threads 1 > /dev/null 2>&1 &&
  echo "delaunay-random $(hash_of "$out/random.vtu")" || true
