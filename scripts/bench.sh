#!/usr/bin/env bash
# make bench: every VolGrid benchmark, each against its references, in one run.
#   scripts/bench.sh [BUILD_DIR] [--quick]
# Sections (each also runs alone):
#   1. Delaunay kernel vs TetGen, CGAL, vtkDelaunay3D     scripts/bench_delaunay.sh BUILD_DIR [options]
#   2. Grid quality (all metrics) vs vtkMeshQuality       BUILD_DIR/bin/volgrid_bench_quality
#   3. Boundary-conforming meshing vs TetGen -pY           scripts/bench_mesher.sh BUILD_DIR
#   4. Element quality vs TetGen -pYq1.414 and Gmsh HXT    Testing/Benchmarks/bench_quality_mesh.sh BUILD_DIR
#   5. Scale: ONERA M6 (default, ~1M, ~5M tets), sphere-in-sphere, a wing at ~10M tets; VolGrid (1 and all
#      threads), TetGen -pYq1.414a, Gmsh HXT                Testing/Benchmarks/bench_scale.sh BUILD_DIR
#      (--quick: the two default cases only)
#   6. Boundary layers on the ONERA M6 wing vs Gmsh 4.8's extrudeBoundaryLayer
#                                                          Testing/Benchmarks/bench_layers_gmsh.py VOLGRID OUT_DIR
# Results go to BUILD_DIR/bench/ (section 6: layers.md). Timings are wall-clock on this machine: run on an idle machine.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="build"
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then build="$1"; shift; fi
quick=0
for a in "$@"; do [ "$a" = "--quick" ] && quick=1; done
mkdir -p "$build/bench"
status=0

echo "=== 1. Delaunay kernel ==="
if [ "$quick" -eq 1 ]; then
  "$root/scripts/bench_delaunay.sh" "$build" --quick || status=1
else
  "$root/scripts/bench_delaunay.sh" "$build" || status=1
fi

echo
echo "=== 2. Grid quality: VolGrid Quality (all metrics) vs vtkMeshQuality (min dihedral only) ==="
tets=5000000
[ "$quick" -eq 1 ] && tets=1000000
if "$build/bin/volgrid_bench_quality" --tets "$tets" --repeat 3 > "$build/bench/quality.jsonl"; then
  python3 - "$build/bench/quality.jsonl" <<'PYTHON'
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip().startswith("{")]
for r in rows:
    print("  " + "  ".join(f"{k}={v}" for k, v in r.items()))
def seconds(engine, threads):
    for r in rows:
        if r.get("engine") == engine and r.get("threads") == threads:
            return r.get("seconds")
vg1, vg2, mq1 = seconds("vtkVolGridQuality", 1), seconds("vtkVolGridQuality", 2), seconds("vtkMeshQuality", 1)
if vg1 and vg2:
    print(f"  VolGrid all metrics: 1 thread {vg1:.3f} s, 2 threads {vg2:.3f} s, speed-up {vg1 / vg2:.2f}x")
if vg2 and mq1:
    print(f"  VolGrid all metrics (2 threads) / vtkMeshQuality one metric (1 thread): {vg2 / mq1:.2f}")
PYTHON
else
  echo "  volgrid_bench_quality FAILED"; status=1
fi

echo
"$root/scripts/bench_mesher.sh" "$build" || status=1
echo
echo "=== 4. Element quality with default settings: VolGrid vs TetGen -pYq1.414 vs Gmsh HXT ==="
bash "$root/Testing/Benchmarks/bench_quality_mesh.sh" "$build" || status=1
echo
echo "=== 5. Scale: VolGrid (1 and all threads) vs TetGen -pYq1.414a vs Gmsh HXT, up to ~10M tets ==="
if [ "$quick" -eq 1 ]; then
  bash "$root/Testing/Benchmarks/bench_scale.sh" "$build" --cases m6-default,sis || status=1
else
  bash "$root/Testing/Benchmarks/bench_scale.sh" "$build" || status=1
fi
echo
echo "=== 6. Boundary layers: VolGrid vs Gmsh 4.8 extrudeBoundaryLayer on the ONERA M6 wing (15 layers) ==="
/usr/bin/python3 "$root/Testing/Benchmarks/bench_layers_gmsh.py" "$build/bin/volgrid" "$build/bench" || status=1
exit $status
