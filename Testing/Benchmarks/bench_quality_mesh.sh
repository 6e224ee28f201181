#!/usr/bin/env bash
# Element quality benchmark (issue 4): VolGrid with default settings against TetGen `-pYq1.414` (Debian's
# tetgen program) and Gmsh HXT (`gmsh -3 -algo hxt`) on the same closed surfaces, side by side:
#   1. the sphere-in-sphere domain: an icosphere body (r = 1, 20,480 triangles) inside an icosphere far
#      field (r = 10, Core/Enclosures.h's default spacing), written with `volgrid prep`;
#   2. a handful of clean corpus models (VolGrid against TetGen -pYq1.414).
# Figures: minimum and maximum dihedral angle, share of tets under 10 degrees, tets, meshing time
# (VolGrid: meshSurface; TetGen: its total running time less its output time; Gmsh: its 3D meshing wall
# time; file reading and writing excluded everywhere). Angles of the TetGen and Gmsh meshes come from
# `volgrid quality --json` (share under 10 degrees from a 10,000-bin histogram: an upper bound within one
# bin). VolGrid's boundary check is independent of the mesher (`volgrid mesh --json`).
#
#   Testing/Benchmarks/bench_quality_mesh.sh [BUILD_DIR] [--models a.off,b.stl,...] [--no-corpus]
#                                            [--repeat R] [--out FILE]
# A missing engine is reported as such. Output: a table on stdout and JSON lines in
# BUILD_DIR/bench/quality_mesh.jsonl (or --out).
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="build"
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then
  build_dir="$1"
  shift
fi
if [ ! -d "$build_dir" ] && [ -d "$repo_root/$build_dir" ]; then
  build_dir="$repo_root/$build_dir"
fi
build_dir="$(cd "$build_dir" 2>/dev/null && pwd || echo "$build_dir")"
volgrid="$build_dir/bin/volgrid"
if [ ! -x "$volgrid" ]; then
  echo "bench_quality_mesh.sh: $volgrid not found: run 'make build' first" >&2
  exit 2
fi
export VOLGRID_BIN="$volgrid" VOLGRID_BUILD_DIR="$build_dir" VOLGRID_REPO="$repo_root"
exec python3 - "$@" <<'PYTHON'
import json, os, re, shutil, subprocess, sys, tempfile, time

volgrid = os.environ["VOLGRID_BIN"]
build_dir = os.environ["VOLGRID_BUILD_DIR"]
repo = os.environ["VOLGRID_REPO"]
corpus_dir = os.path.join(repo, "..", "shared", "data", "real")
default_models = ["tetgen-tests/cgal/pinion.off", "tetgen-tests/cgal/handle.off", "tetgen-tests/cgal/dino.off",
                  "tetgen-tests/cgal/femur.off", "tetgen-tests/meshlab/casting.off", "gmsh-benchmarks/skull.stl",
                  "tetgen-tests/testingdrafts/stanfordbunny.smesh", "tetgen-tests/cgal/bear_bis.off"]
args = sys.argv[1:]
models, corpus, repeat, out = default_models, True, 1, os.path.join(build_dir, "bench", "quality_mesh.jsonl")
i = 0
while i < len(args):
    a = args[i]
    if a == "--models": models = args[i + 1].split(","); i += 1
    elif a == "--no-corpus": corpus = False
    elif a == "--repeat": repeat = max(1, int(args[i + 1])); i += 1
    elif a == "--out": out = args[i + 1]; i += 1
    else: sys.exit("bench_quality_mesh.sh: unknown option %s" % a)
    i += 1
os.makedirs(os.path.dirname(out), exist_ok=True)
work = tempfile.mkdtemp(prefix="volgrid-quality-bench-")
timeout = 900

def run(cmd, cwd=work):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)

def quality(path):
    """min/max dihedral, share under 10 degrees, tets of a volume mesh via volgrid quality --json."""
    r = run([volgrid, "quality", path, "--json", "--bins", "10000"])
    if r.returncode != 0:
        return {"error": (r.stderr or r.stdout).strip()[:200]}
    d = json.loads(r.stdout)
    mn = d["metrics"]["MinDihedralAngle"]
    mx = d["metrics"]["MaxDihedralAngle"]
    below = 0
    edges, counts = mn["bin_edges"], mn["bin_counts"]
    for k, c in enumerate(counts):
        if edges[k] < 10.0:
            below += c
    tets = d["NumberOfTetrahedra"]
    return {"tets": tets, "min_dihedral": mn["min"], "max_dihedral": mx["max"],
            "share_below_10": below / tets if tets else 0.0}

def node_ele_to_vtk(stem, vtk):
    with open(stem + ".node") as f:
        rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    n, first = int(rows[0][0]), None
    pts = rows[1:1 + n]
    first = int(pts[0][0])
    with open(stem + ".ele") as f:
        erows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    m = int(erows[0][0])
    with open(vtk, "w") as o:
        o.write("# vtk DataFile Version 3.0\ntetgen\nASCII\nDATASET UNSTRUCTURED_GRID\n")
        o.write("POINTS %d double\n" % n)
        for p in pts:
            o.write("%s %s %s\n" % (p[1], p[2], p[3]))
        o.write("CELLS %d %d\n" % (m, 5 * m))
        for e in erows[1:1 + m]:
            o.write("4 %d %d %d %d\n" % tuple(int(x) - first for x in e[1:5]))
        o.write("CELL_TYPES %d\n" % m)
        o.write("10\n" * m)

def bench_volgrid(surface, name):
    best = None
    for _ in range(repeat):
        r = run([volgrid, "mesh", surface, os.path.join(work, name + ".vg.vtu"), "--json"])
        if r.returncode != 0:
            return {"engine": "volgrid", "error": (r.stderr or r.stdout).strip()[:200]}
        d = json.loads(r.stdout.strip().splitlines()[-1])
        if best is None or d["seconds"] < best["seconds"]:
            best = d
    return {"engine": "volgrid", "tets": best["tets"], "min_dihedral": best["min_dihedral"],
            "max_dihedral": best["max_dihedral"], "share_below_10": best["share_below_10"],
            "seconds": best["seconds"], "boundary_preserved": best["boundary_preserved"],
            "boundary_forced_below_10": best.get("boundary_forced_below_10")}

def bench_tetgen(surface, name):
    exe = shutil.which("tetgen")
    if not exe:
        return {"engine": "tetgen", "error": "tetgen not installed (scripts/install-deps.sh bench)"}
    ext = os.path.splitext(surface)[1]
    local = os.path.join(work, name + ".tg" + ext)
    shutil.copyfile(surface, local)
    best = None
    for _ in range(repeat):
        r = run([exe, "-pYq1.414", local])
        text = r.stdout + r.stderr
        tot = re.search(r"Total running seconds:\s*([0-9.eE+-]+)", text)
        outs = re.search(r"Output seconds:\s*([0-9.eE+-]+)", text)
        if r.returncode != 0 or not tot:
            return {"engine": "tetgen", "error": text.strip().splitlines()[-1][:200] if text.strip() else "failed"}
        sec = float(tot.group(1)) - (float(outs.group(1)) if outs else 0.0)
        best = sec if best is None else min(best, sec)
    stem = os.path.splitext(local)[0] + ".1"
    vtk = stem + ".vtk"
    node_ele_to_vtk(stem, vtk)
    q = quality(vtk)
    q.update({"engine": "tetgen", "seconds": best})
    return q

def bench_gmsh(body_stl, far_stl, name):
    exe = shutil.which("gmsh")
    if not exe:
        return {"engine": "gmsh-hxt", "error": "gmsh not installed (scripts/install-deps.sh bench)"}
    geo = os.path.join(work, name + ".geo")
    with open(geo, "w") as g:
        g.write('Merge "%s";\nMerge "%s";\nSurface Loop(1) = {1};\nSurface Loop(2) = {2};\n'
                'Volume(1) = {1, 2};\nPhysical Volume(1) = {1};\n' % (far_stl, body_stl))
    vtk = os.path.join(work, name + ".gmsh.vtk")
    best = None
    for _ in range(repeat):
        r = run([exe, "-3", "-algo", "hxt", geo, "-format", "vtk", "-o", vtk])
        m = re.search(r"Done meshing 3D \(Wall ([0-9.eE+-]+)s", r.stdout + r.stderr)
        if r.returncode != 0 or not m:
            return {"engine": "gmsh-hxt", "error": (r.stdout + r.stderr).strip()[-200:]}
        best = float(m.group(1)) if best is None else min(best, float(m.group(1)))
    q = quality(vtk)
    q.update({"engine": "gmsh-hxt", "seconds": best})
    return q

rows = []
def record(case, res):
    res["case"] = case
    res["time"] = time.strftime("%Y-%m-%dT%H:%M:%S")
    rows.append(res)
    with open(out, "a") as f:
        f.write(json.dumps(res) + "\n")

# 1. Sphere in sphere.
body, far, sis = (os.path.join(work, n) for n in ("body.off", "far.off", "sis.off"))
for cmd in ([volgrid, "prep", "--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "1",
             "--edge-length", "0.0329", body],
            [volgrid, "prep", "--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "10", far],
            [volgrid, "prep", body, far, sis],
            [volgrid, "prep", body, os.path.join(work, "body.stl")],
            [volgrid, "prep", far, os.path.join(work, "far.stl")]):
    r = run(cmd)
    if r.returncode != 0:
        sys.exit("bench_quality_mesh.sh: %s failed: %s" % (" ".join(cmd), r.stderr))
case = "sphere-in-sphere (20,480 + 1,620 triangles)"
record(case, bench_volgrid(sis, "sis"))
record(case, bench_tetgen(sis, "sis"))
record(case, bench_gmsh(os.path.join(work, "body.stl"), os.path.join(work, "far.stl"), "sis"))

# 2. Clean corpus models.
if corpus:
    for m in models:
        path = os.path.join(corpus_dir, m)
        if not os.path.exists(path):
            record(m, {"engine": "volgrid", "error": "not found: " + path})
            continue
        name = re.sub(r"[^A-Za-z0-9_]", "_", m)
        record(m, bench_volgrid(path, name))
        record(m, bench_tetgen(path, name))

def fmt(r):
    if "error" in r:
        return "%-9s %s" % (r["engine"], "FAILED: " + r["error"])
    extra = ""
    if r["engine"] == "volgrid":
        extra = "  boundary %s" % ("exact" if r.get("boundary_preserved") else "NOT PRESERVED")
        if r.get("boundary_forced_below_10"):
            extra += ", %d tets < 10 deg with 4 boundary vertices" % r["boundary_forced_below_10"]
    return "%-9s %9.2f %9.2f %9.3f%% %10d %9.3f%s" % (r["engine"], r["min_dihedral"], r["max_dihedral"],
                                                  100 * r["share_below_10"], r["tets"], r["seconds"], extra)

print("%-9s %9s %9s %10s %10s %9s" % ("engine", "min dih", "max dih", "< 10 deg", "tets", "seconds"))
last = None
for r in rows:
    if r["case"] != last:
        print("== " + r["case"])
        last = r["case"]
    print(fmt(r))
print("JSON lines: " + out)
shutil.rmtree(work, ignore_errors=True)
PYTHON
