#!/usr/bin/env bash
# Element quality benchmark (issue 4): VolGrid with default settings against TetGen `-pYq1.414` (Debian's
# tetgen program) and Gmsh HXT (`gmsh -3 -algo hxt`) on the same closed surfaces, side by side:
#   1. the sphere-in-sphere domain: an icosphere body (r = 1, 20,480 triangles) inside an icosphere far
#      field (r = 10, Core/Surface/Enclosures.h's default spacing), written with `volgrid prep`;
#   2. the clean corpus (VolGrid against TetGen -pYq1.414): the selection of Testing/Core/Mesher/TestMesherCorpus.cxx's
#      cleanClosedFiles() (SOURCES.md rows with watertight YES and no defect other than polygon faces or
#      inconsistent orientation), models above 300,000 triangles skipped for runtime (listed as such; the
#      largest corpus model, igea.ply, has 268,686 and takes VolGrid about 20 s).
#      Each model goes through `volgrid prep` once (polygons fanned, shells oriented away from the domain,
#      coordinates written with 17 digits) and both engines mesh that same triangulated file, so both must
#      keep the same triangles. Per model: the SURFACE BOUND on the minimum dihedral angle of any mesh that
#      keeps these triangles, the smaller of
#        e: the smallest dihedral angle between two adjacent input triangles measured inside the domain
#           (every tet holding that edge has its dihedral angle there no larger), halved for an edge that
#           no single tet can hold: the only candidate, the tet of its two triangles, would create an edge
#           crossing an input segment or triangle (exact rational test, for the 300 sharpest edges), so
#           at least two tets share that angle;
#        t: the tet that holds a boundary triangle has it as a face and lies inside the domain's wedges at
#           its three edges: the largest minimum dihedral angle over all such tets (fourth vertex free),
#           estimated numerically for the 40 triangles of worst shape or on the sharpest edges;
#      and the verdict:
#        better    VolGrid's minimum dihedral angle is larger than TetGen's (by 0.005 deg or more);
#        bound     VolGrid reaches the surface bound (within 0.01 deg), which TetGen cannot exceed either;
#        tie       equal minima (within 0.005 deg) below the bound: not better, not shown optimal;
#        WORSE     VolGrid's minimum is smaller;
#        FAILED    an engine did not mesh the model (e.g. RecoveryFailed), with its message.
# Figures: minimum and maximum dihedral angle, share of tets under 10 degrees, tets, meshing time
# (VolGrid: meshSurface; TetGen: its total running time less its output time; Gmsh: its 3D meshing wall
# time; file reading and writing excluded everywhere). Angles of the TetGen and Gmsh meshes come from
# `volgrid quality --json` (share under 10 degrees from a 10,000-bin histogram: an upper bound within one
# bin). VolGrid's boundary check is independent of the mesher (`volgrid mesh --json`).
#
#   Testing/Benchmarks/bench_quality_mesh.sh [BUILD_DIR] [--quick] [--models a.off,b.stl,...]
#        [--match SUBSTRING] [--no-corpus] [--no-sis] [--max-triangles N] [--timeout S] [--repeat R] [--out FILE]
# --quick: sphere-in-sphere skipped, eight mid-size corpus models only (a few minutes); --models: these
# corpus paths only; --match: corpus paths containing SUBSTRING; --no-sis: skip the sphere-in-sphere case.
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
import json, math, os, re, shutil, subprocess, sys, tempfile, time
from fractions import Fraction

volgrid = os.environ["VOLGRID_BIN"]
build_dir = os.environ["VOLGRID_BUILD_DIR"]
repo = os.environ["VOLGRID_REPO"]
corpus_dir = os.path.join(repo, "..", "shared", "data", "real")
quick_models = ["tetgen-tests/cgal/pinion.off", "tetgen-tests/cgal/handle.off", "tetgen-tests/cgal/dino.off",
                "tetgen-tests/cgal/femur.off", "tetgen-tests/meshlab/casting.off", "gmsh-benchmarks/skull.stl",
                "tetgen-tests/testingdrafts/stanfordbunny.smesh", "tetgen-tests/cgal/bear_bis.off"]
args = sys.argv[1:]
models, match, corpus, sis, repeat = None, None, True, True, 1
max_triangles, timeout = 300000, 600
out = os.path.join(build_dir, "bench", "quality_mesh.jsonl")
i = 0
while i < len(args):
    a = args[i]
    if a == "--models": models = args[i + 1].split(","); i += 1
    elif a == "--quick": models, sis = quick_models, False
    elif a == "--match": match = args[i + 1]; i += 1
    elif a == "--no-corpus": corpus = False
    elif a == "--no-sis": sis = False
    elif a == "--max-triangles": max_triangles = int(args[i + 1]); i += 1
    elif a == "--timeout": timeout = float(args[i + 1]); i += 1
    elif a == "--repeat": repeat = max(1, int(args[i + 1])); i += 1
    elif a == "--out": out = args[i + 1]; i += 1
    else: sys.exit("bench_quality_mesh.sh: unknown option %s" % a)
    i += 1
os.makedirs(os.path.dirname(out), exist_ok=True)
work = tempfile.mkdtemp(prefix="volgrid-quality-bench-")

def run(cmd, cwd=work):
    try:
        return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(cmd, -1, "", "TIMEOUT after %g s" % timeout)

def clean_closed_files():
    """Testing/Core/Mesher/TestMesherCorpus.cxx's cleanClosedFiles(), same rule."""
    files = []
    with open(os.path.join(corpus_dir, "SOURCES.md")) as f:
        for line in f:
            if len(line) < 2 or line[0] != "|":
                continue
            cols = [c.strip() for c in line.rstrip("\n").split("|")]
            if len(cols) < 10 or cols[6] != "YES":
                continue
            d = cols[9]
            if d == "none found" or all("non-triangle faces" in it or "inconsistently oriented edges" in it
                                        for it in d.split(";")):
                files.append(cols[1])
    return files

def read_off(path):
    with open(path) as f:
        toks = f.read().split()
    assert toks[0] == "OFF"
    nv, nf = int(toks[1]), int(toks[2])
    k = 4
    pts = [(float(toks[k + 3 * j]), float(toks[k + 3 * j + 1]), float(toks[k + 3 * j + 2])) for j in range(nv)]
    k += 3 * nv
    tris = []
    for _ in range(nf):
        n = int(toks[k])
        ids = [int(x) for x in toks[k + 1:k + 1 + n]]
        k += 1 + n
        for j in range(1, n - 1):
            tris.append((ids[0], ids[j], ids[j + 1]))
    return pts, tris

def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return math.sqrt(dot(a, a))

def surface_bound(pts, tris):
    """Smallest dihedral angle (degrees) between two adjacent triangles measured inside the domain (the
    triangles are oriented with normals pointing away from the domain, as `volgrid prep` writes them).
    Every tet holding such an edge has its dihedral angle there no larger than this interior angle."""
    half = {}
    for t, (a, b, c) in enumerate(tris):
        for x, y, z in ((a, b, c), (b, c, a), (c, a, b)):
            half[(x, y)] = z
    best = 180.0
    angle = {}
    for (x, y), z in half.items():
        if x > y or (y, x) not in half:
            continue
        w = half[(y, x)]
        a, b, c, d = pts[x], pts[y], pts[z], pts[w]
        e = sub(b, a)
        le = norm(e)
        if le == 0:
            continue
        e = (e[0] / le, e[1] / le, e[2] / le)
        u, v = sub(c, a), sub(d, a)
        u = sub(u, tuple(dot(u, e) * k for k in e))
        v = sub(v, tuple(dot(v, e) * k for k in e))
        phi = math.degrees(math.atan2(norm(cross(u, v)), dot(u, v)))
        outward = cross(sub(b, a), sub(c, a))
        # d on the domain side of (a, b, c): the convex wedge is inside, else the reflex one.
        angle[(x, y)] = angle[(y, x)] = phi if dot(outward, sub(d, a)) < 0 else 360.0 - phi
        best = min(best, angle[(x, y)])
    # The triangles' own shapes: the tet on a boundary triangle is bounded by the triangle (and by the
    # interior angles at its edges). Estimated for the worst-shaped triangles and those on the sharpest
    # edges (the others are far from binding).
    def shape(t):
        a, b, c = (pts[v] for v in tris[t])
        ang = []
        for p, q, r in ((a, b, c), (b, c, a), (c, a, b)):
            u, v = sub(q, p), sub(r, p)
            ang.append(math.degrees(math.atan2(norm(cross(u, v)), dot(u, v))))
        return min(min(ang), 180 - max(ang))
    lim = lambda t: tuple(angle.get((tris[t][k], tris[t][(k + 1) % 3]), 360.0) for k in range(3))
    cands = sorted(range(len(tris)), key=shape)[:24]
    cands += sorted(range(len(tris)), key=lambda t: min(lim(t)))[:16]
    tri_best = 180.0
    for t in set(cands):
        tri_best = min(tri_best, triangle_bound(*(pts[v] for v in tris[t]), lim(t)))
    split = split_edge_bound(pts, tris, half, angle, min(best, tri_best))
    if split is not None:
        best = min(best, split)
    return best, tri_best

def orient_exact(a, b, c, d):
    """Sign of det[b - a, c - a, d - a] in exact rational arithmetic (the doubles converted exactly)."""
    a = [Fraction(v) for v in a]
    u = [Fraction(b[k]) - a[k] for k in range(3)]
    v = [Fraction(c[k]) - a[k] for k in range(3)]
    w = [Fraction(d[k]) - a[k] for k in range(3)]
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
           u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)

def crosses_surface(z, w, pts, tris, near):
    """Whether the open segment z-w (two input vertices, not an input edge) certainly crosses the input
    surface: through the interior of a triangle or of one of its edges, exactly. `near`: candidate
    triangles (bounding boxes overlapping the segment's)."""
    P, Q = pts[z], pts[w]
    for t in near:
        tri = tris[t]
        if z in tri and w in tri:
            continue
        A, B, C = (pts[v] for v in tri)
        s1, s2 = orient_exact(A, B, C, P), orient_exact(A, B, C, Q)
        if s1 * s2 < 0:
            o = [orient_exact(P, Q, X, Y) for X, Y in ((A, B), (B, C), (C, A))]
            if (all(x >= 0 for x in o) or all(x <= 0 for x in o)) and o.count(0) <= 1:
                return True  # through the interior of the triangle or of one of its edges
        elif s1 == 0 and s2 == 0:
            # Coplanar: a proper crossing with an edge of the triangle that shares no end with z-w.
            n = [abs(x) for x in cross(sub(B, A), sub(C, A))]
            drop = n.index(max(n))
            keep = [k for k in range(3) if k != drop]
            def o2(a, b, c):
                d = ((Fraction(b[keep[0]]) - Fraction(a[keep[0]])) * (Fraction(c[keep[1]]) - Fraction(a[keep[1]])) -
                     (Fraction(b[keep[1]]) - Fraction(a[keep[1]])) * (Fraction(c[keep[0]]) - Fraction(a[keep[0]])))
                return (d > 0) - (d < 0)
            for i in range(3):
                u, v = tri[i], tri[(i + 1) % 3]
                if u in (z, w) or v in (z, w):
                    continue
                U, V = pts[u], pts[v]
                if o2(U, V, P) * o2(U, V, Q) < 0 and o2(P, Q, U) * o2(P, Q, V) < 0:
                    return True
    return False

def split_edge_bound(pts, tris, half, angle, below, max_edges=300):
    """The edge bound refined: an input edge x-y with interior angle phi lies in one tet only if that tet
    is {x, y, z, w}, z and w the third vertices of its two triangles; when the new edge z-w would cross
    the input surface, at least two tets share the angle and one has at most phi / 2 there. Checks the
    sharpest edges (ascending phi) while phi / 2 is below `below`; None when none lowers it."""
    edges = sorted((phi, x, y) for (x, y), phi in angle.items() if x < y and phi < 2 * below)
    if not edges:
        return None
    boxes = [tuple(min(pts[v][k] for v in t) for k in range(3)) + tuple(max(pts[v][k] for v in t) for k in range(3))
             for t in tris]
    for phi, x, y in edges[:max_edges]:
        if phi >= 180.0:
            return phi / 2  # no tet has a dihedral angle of 180 degrees or more
        z, w = half[(x, y)], half[(y, x)]
        lo = [min(pts[z][k], pts[w][k]) for k in range(3)]
        hi = [max(pts[z][k], pts[w][k]) for k in range(3)]
        near = [t for t, b in enumerate(boxes) if all(b[k] <= hi[k] and b[3 + k] >= lo[k] for k in range(3))]
        if crosses_surface(z, w, pts, tris, near):
            return phi / 2  # ascending: no later edge gives less
    return None

def dihedrals(p):
    """The six dihedral angles (degrees) of tet p[0..3], edges (0,1) (0,2) (0,3) (1,2) (1,3) (2,3)."""
    faces = ((1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1))  # face k is opposite vertex k
    n = []
    for a, b, c in faces:
        v = cross(sub(p[b], p[a]), sub(p[c], p[a]))
        l = norm(v)
        if l == 0:
            return None
        n.append((v[0] / l, v[1] / l, v[2] / l))
    out = []
    for i, j in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)):
        k, l = [m for m in range(4) if m != i and m != j]
        out.append(180.0 - math.degrees(math.acos(max(-1.0, min(1.0, dot(n[k], n[l]))))))
    return out

def triangle_bound(a, b, c, limits):
    """Largest minimum dihedral angle of a tet on triangle (a, b, c) (oriented away from the domain) whose
    dihedral angles at the triangle's edges ab, bc, ca stay within the domain's interior angles `limits`:
    the tet that holds this boundary triangle can do no better. Numerical: multi-start pattern search over
    the fourth vertex (an estimate from below of the true maximum)."""
    o = cross(sub(b, a), sub(c, a))
    area2 = norm(o)
    if area2 == 0:
        return 0.0
    nrm = (-o[0] / area2, -o[1] / area2, -o[2] / area2)  # into the domain
    e1 = sub(b, a)
    l1 = norm(e1)
    e1 = (e1[0] / l1, e1[1] / l1, e1[2] / l1)
    e2 = cross(nrm, e1)
    g = tuple((a[k] + b[k] + c[k]) / 3 for k in range(3))
    s = math.sqrt(area2 / 2)
    def f(x):
        if x[2] <= 0:
            return -1e9
        w = tuple(g[k] + s * (x[0] * e1[k] + x[1] * e2[k] + x[2] * nrm[k]) for k in range(3))
        d = dihedrals((a, b, c, w))  # edges ab = 0, bc = 3, ca = 1
        if d is None:
            return -1e9
        pen = max(0.0, d[0] - limits[0]) + max(0.0, d[3] - limits[1]) + max(0.0, d[1] - limits[2])
        return min(d) - 1000 * pen
    starts = sorted(((f((x, y, z)), (x, y, z)) for x in (-1, -0.5, 0, 0.5, 1) for y in (-1, -0.5, 0, 0.5, 1)
                     for z in (0.1, 0.3, 0.7, 1.5, 3)), reverse=True)[:3]
    best = -1e9
    for v, x in starts:
        step = 0.25
        while step > 1e-7:
            moved = False
            for k in range(3):
                for sgn in (1, -1):
                    y = list(x)
                    y[k] += sgn * step
                    fy = f(y)
                    if fy > v:
                        v, x, moved = fy, tuple(y), True
            if not moved:
                step /= 2
        best = max(best, v)
    return max(best, 0.0)

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
    n = int(rows[0][0])
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

def first_error_line(text):
    lines = [l for l in text.strip().splitlines() if l.strip()]
    return re.sub(r"^volgrid mesh: \S*: ", "", lines[-1])[:200] if lines else "failed"

def bench_volgrid(surface, name):
    best = None
    for _ in range(repeat):
        r = run([volgrid, "mesh", surface, os.path.join(work, name + ".vg.vtu"), "--json"])
        if r.returncode != 0:
            return {"engine": "volgrid", "error": first_error_line(r.stderr or r.stdout)}
        d = json.loads(r.stdout.strip().splitlines()[-1])
        if best is None or d["seconds"] < best["seconds"]:
            best = d
    os.remove(os.path.join(work, name + ".vg.vtu"))
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
            return {"engine": "tetgen", "error": first_error_line(text)}
        sec = float(tot.group(1)) - (float(outs.group(1)) if outs else 0.0)
        best = sec if best is None else min(best, sec)
    stem = os.path.splitext(local)[0] + ".1"
    vtk = stem + ".vtk"
    node_ele_to_vtk(stem, vtk)
    q = quality(vtk)
    for f in os.listdir(work):
        if f.startswith(name + ".tg"):
            os.remove(os.path.join(work, f))
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

# 1. Sphere in sphere.
if sis:
    body, far, sisf = (os.path.join(work, n) for n in ("body.off", "far.off", "sis.off"))
    for cmd in ([volgrid, "prep", "--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "1",
                 "--edge-length", "0.0329", body],
                [volgrid, "prep", "--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "10", far],
                [volgrid, "prep", body, far, sisf],
                [volgrid, "prep", body, os.path.join(work, "body.stl")],
                [volgrid, "prep", far, os.path.join(work, "far.stl")]):
        r = run(cmd)
        if r.returncode != 0:
            sys.exit("bench_quality_mesh.sh: %s failed: %s" % (" ".join(cmd), r.stderr))
    case = "sphere-in-sphere (20,480 + 1,620 triangles)"
    record(case, bench_volgrid(sisf, "sis"))
    record(case, bench_tetgen(sisf, "sis"))
    record(case, bench_gmsh(os.path.join(work, "body.stl"), os.path.join(work, "far.stl"), "sis"))
    print("%-9s %9s %9s %10s %10s %9s" % ("engine", "min dih", "max dih", "< 10 deg", "tets", "seconds"))
    print("== " + case)
    for r in rows:
        print(fmt(r))
    sys.stdout.flush()

# 2. The clean corpus: one row per model.
def verdict(vg, tg, bound):
    if "error" in vg:
        return "FAILED (VolGrid)"
    if "error" in tg:
        return "FAILED (TetGen)"
    if vg["min_dihedral"] > tg["min_dihedral"] + 0.005:  # better in the printed figures
        return "better"
    if bound is not None and vg["min_dihedral"] >= bound - 0.01:
        return "bound"
    if vg["min_dihedral"] >= tg["min_dihedral"] - 0.005:
        return "tie"
    return "WORSE"

if corpus:
    selection = models if models is not None else clean_closed_files()
    if match:
        selection = [m for m in selection if match in m]
    print()
    print("Clean corpus: VolGrid defaults vs TetGen -pYq1.414 on the same `volgrid prep` output "
          "(min/max dihedral in degrees, share of tets under 10 deg, seconds; bound: the surface's bound on "
          "the minimum dihedral angle, e = edge, t = triangle, see the script's header)")
    hdr = "%-48s %7s %6s | %6s %7s %7s %8s | %6s %7s %7s %8s | %s" % (
        "model", "tris", "bound", "VG min", "VG max", "VG<10%", "VG s", "TG min", "TG max", "TG<10%", "TG s",
        "verdict")
    print(hdr)
    print("-" * len(hdr))
    sys.stdout.flush()
    counts = {}
    for m in selection:
        path = os.path.join(corpus_dir, m)
        name = re.sub(r"[^A-Za-z0-9_]", "_", m)
        prepped = os.path.join(work, name + ".off")
        res = {"engine": "corpus", "model": m}
        if not os.path.exists(path):
            res["verdict"] = "FAILED (not found)"
        else:
            r = run([volgrid, "prep", path, prepped])
            if r.returncode != 0 or not os.path.exists(prepped):
                res["verdict"] = "FAILED (prep: %s)" % first_error_line(r.stderr or r.stdout)
            else:
                pts, tris = read_off(prepped)
                res["triangles"] = len(tris)
                if len(tris) > max_triangles:
                    res["verdict"] = "skipped (> %d triangles, runtime)" % max_triangles
                else:
                    res["edge_bound"], res["triangle_bound"] = surface_bound(pts, tris)
                    res["bound"] = min(res["edge_bound"], res["triangle_bound"])
                    res["volgrid"] = bench_volgrid(prepped, name)
                    res["tetgen"] = bench_tetgen(prepped, name)
                    res["verdict"] = verdict(res["volgrid"], res["tetgen"], res["bound"])
                    if "error" not in res["volgrid"] and not res["volgrid"]["boundary_preserved"]:
                        res["verdict"] += ", BOUNDARY NOT PRESERVED"
            if os.path.exists(prepped):
                os.remove(prepped)
        record(m, res)
        key = res["verdict"].split(" (")[0].split(",")[0]
        counts[key] = counts.get(key, 0) + 1
        def cols(e):
            if e is None:
                return "%6s %7s %7s %8s" % ("", "", "", "")
            if "error" in e:
                return "%-31s" % ("TIMEOUT" if e["error"].startswith("TIMEOUT") else "FAILED (below)")
            return "%6.2f %7.2f %7.3f %8.3f" % (e["min_dihedral"], e["max_dihedral"], 100 * e["share_below_10"],
                                                e["seconds"])
        line = "%-48s %7s %6s | %s | %s | %s" % (m[-48:], res.get("triangles", ""),
                                                "%.2f%s" % (res["bound"], "e" if res["edge_bound"] <= res["triangle_bound"]
                                                            else "t") if "bound" in res else "",
                                                cols(res.get("volgrid")), cols(res.get("tetgen")), res["verdict"])
        print(line)
        if "error" in res.get("volgrid", {}):
            print("    VolGrid: " + res["volgrid"]["error"])
        if "error" in res.get("tetgen", {}):
            print("    TetGen: " + res["tetgen"]["error"])
        sys.stdout.flush()
    print("Verdicts: " + ", ".join("%s %d" % (k, v) for k, v in sorted(counts.items())))
print("JSON lines: " + out)
shutil.rmtree(work, ignore_errors=True)
PYTHON
