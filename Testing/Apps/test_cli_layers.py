"""volgrid mesh --layers: a sphere in a sphere gets every layer (wedges, coverage, no inverted cell, the
interface shared exactly), the straight wing's tip corners collapse into pyramids that OpenFOAM accepts,
bad parameters are refused with nothing written, and layers that touch a
non-layered patch other than a flat symmetry plane are refused with a message naming it; the ONERA M6
wing gets its 15 layers, marching in the symmetry plane at the root.
usage: test_cli_layers.py VOLGRID DATA_DIR [SHARED_REAL_DATA_DIR]"""
import json
import os
import re
import shutil
import sys
import tempfile

from cli_test_support import refused_cleanly, run

volgrid = sys.argv[1]
shared = sys.argv[3] if len(sys.argv) > 3 else ""
failures = []


def expect(condition, what, r=None):
    if not condition:
        failures.append(what + ("\n  " + r.describe() if r else ""))


work = tempfile.mkdtemp(prefix="volgrid-layers-")
w = lambda name: os.path.join(work, name)
for args in (["--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "1", "--edge-length", "0.1", w("body.off")],
             ["--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "10", w("far.off")],
             [w("body.off"), w("far.off"), w("sis.off")]):
    r = run([volgrid, "prep"] + args)
    assert r.returncode == 0, r.describe()

layers = ["--layers", "10", "--first-height", "1e-3", "--growth", "1.2"]
r = run([volgrid, "mesh", w("sis.off"), w("sis.vtu"), "--json"] + layers)
expect(r.returncode == 0, "sphere in sphere with 10 layers", r)
if r.returncode == 0:
    j = json.loads(r.stdout)
    faces = j["layered_faces"]
    expect(faces > 0 and j["wedges"] == 10 * faces, "10 wedges per body face: %s" % j)
    expect(j["coverage"] == 1.0 and j["thinned_columns"] == 0, "every body face has all 10 layers: %s" % j)
    expect(j["inverted_cells"] == 0, "no inverted cell: %s" % j)
    expect(j["interface_faces_shared"] == faces, "the tets share the last layer's surface: %s" % j)
    expect(j["tets"] > 0, "tets outside the layers: %s" % j)
    header = open(w("sis.vtu"), "rb").read()
    expect(b'Name="LayerIndex"' in header and b'Name="ThinnedReason"' in header, "cell arrays in the .vtu")

FOAM = "/usr/share/openfoam/etc/bashrc"


def foam_case(case):
    """The system/ dictionaries checkMesh needs beside a written constant/polyMesh."""
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    with open(os.path.join(case, "system/controlDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n"
                "application checkMesh;\nstartTime 0;\nendTime 1;\ndeltaT 1;\nwriteInterval 1;\n")
    for name, body in (("fvSchemes", "ddtSchemes { default steadyState; }\ngradSchemes { default Gauss linear; }\n"
                        "divSchemes { default none; }\nlaplacianSchemes { default Gauss linear corrected; }\n"
                        "interpolationSchemes { default linear; }\nsnGradSchemes { default corrected; }\n"),
                       ("fvSolution", "")):
        with open(os.path.join(case, "system", name), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n%s" % (name, body))


def check_mesh(case, before=""):
    """checkMesh on `case` (after the shell command `before`, run in it); None when OpenFOAM is absent."""
    if not os.path.exists(FOAM):
        return None
    foam_case(case)
    return run(["bash", "-c", "source %s >/dev/null 2>&1; cd '%s' && %s checkMesh" % (FOAM, case, before)],
               timeout=900)


def check_mesh_counts(out):
    """checkMesh's cell, face and point counts, cell shapes and failed checks, for comparing two cases."""
    keys = ("points", "faces", "internal faces", "cells", "boundary patches", "tetrahedra", "prisms", "pyramids",
            "polyhedra")
    counts = {k: int(m.group(1)) for k in keys for m in [re.search(r"^\s+%s:\s+(\d+)" % k, out, re.M)] if m}
    failed = re.search(r"Failed (\d+) mesh checks", out)
    counts["failed"] = int(failed.group(1)) if failed else 0
    skew = re.search(r"\*\*\*Max skewness = ([0-9.e+-]+), (\d+) highly skew faces", out)
    counts["skew"] = (round(float(skew.group(1)), 2), int(skew.group(2))) if skew else None
    return counts


def check_mesh_figures(out):
    """checkMesh's non-orthogonality (max, average, faces over 70 deg) and skewness (max, faces over 4)."""
    f = {}
    m = re.search(r"Mesh non-orthogonality Max: ([0-9.e+-]+) average: ([0-9.e+-]+)", out)
    if m:
        f["max_non_orthogonality"], f["average_non_orthogonality"] = float(m.group(1)), float(m.group(2))
    m = re.search(r"severely non-orthogonal \(> 70 degrees\) faces: (\d+)", out)
    f["severe_faces"] = int(m.group(1)) if m else 0
    m = re.search(r"Max skewness = ([0-9.e+-]+)(?:, (\d+) highly skew faces)?", out)
    if m:
        f["max_skewness"], f["skew_faces"] = float(m.group(1)), int(m.group(2) or 0)
    return f


def foam_list(path):
    """The entries of an ASCII OpenFOAM list file (points, faces, a faceSet): each a tuple of numbers."""
    with open(path) as f:
        text = f.read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    body = text[text.index("(") + 1:text.rindex(")")]
    if "(" not in body:  # a list of labels (a set)
        return [(int(x),) for x in body.split()]
    return [tuple(float(x) for x in m.group(1).split()) for m in re.finditer(r"\(([^()]*)\)", body)]


def severe_first_layer_side_faces(case):
    """checkMesh -writeSets on an OpenFOAM case: how many of its severely non-orthogonal faces (> 70 deg) are
    side faces of the first layer (quads with two points on a patch of type wall)."""
    r = run(["bash", "-c", "source %s >/dev/null 2>&1; cd '%s' && checkMesh -writeSets vtk" % (FOAM, case)],
            timeout=900)
    expect(r.returncode == 0, "checkMesh -writeSets", r)
    mesh = os.path.join(case, "constant/polyMesh")
    faces = [tuple(int(x) for x in f) for f in foam_list(os.path.join(mesh, "faces"))]
    wall = set()
    with open(os.path.join(mesh, "boundary")) as f:
        for block in re.findall(r"\{([^{}]*\btype\s+wall;[^{}]*)\}", f.read()):
            start = int(re.search(r"startFace\s+(\d+)", block).group(1))
            count = int(re.search(r"nFaces\s+(\d+)", block).group(1))
            wall.update(p for face in faces[start:start + count] for p in face)
    severe = [faces[int(i[0])] for i in foam_list(os.path.join(mesh, "sets/nonOrthoFaces"))]
    return sum(1 for face in severe if len(face) == 4 and sum(p in wall for p in face) == 2)


def expect_quality_as_check_mesh(vtu, out, what):
    """volgrid quality on the .vtu of the mesh checkMesh printed `out` for: the same CFD figures, every cell
    measured (checkMesh prints 6 significant digits)."""
    r = run([volgrid, "quality", vtu, "--json"])
    expect(r.returncode == 0, what + ": volgrid quality", r)
    if r.returncode != 0:
        return
    q = json.loads(r.stdout.strip().splitlines()[-1])
    f = check_mesh_figures(out)
    mine = {"max_non_orthogonality": q["MaxNonOrthogonality"], "average_non_orthogonality":
            q["AverageNonOrthogonality"], "severe_faces": q["SevereNonOrthogonalFaces"],
            "max_skewness": q["MaxSkewness"], "skew_faces": q["HighlySkewFaces"]}
    print(what + ": checkMesh", f, "\n  volgrid quality", mine)
    same = set(f) == set(mine) and all(
        abs(mine[k] - f[k]) <= 1e-5 * abs(f[k]) + 1e-4 if isinstance(f[k], float) else mine[k] == f[k] for k in f)
    expect(same and q["SkippedCells"] == 0, what + ": volgrid quality's CFD figures are checkMesh's", r)


# Split prisms: a tet-only mesh; checkMesh must say "Mesh OK" when OpenFOAM is installed.
r = run([volgrid, "mesh", w("sis.off"), w("sis_foam"), "--format", "openfoam", "--split-prisms", "--json"] + layers)
expect(r.returncode == 0, "split prisms to OpenFOAM", r)
if r.returncode == 0:
    j = json.loads(r.stdout.strip().splitlines()[-1])
    expect(j["wedges"] == 0 and j["tets"] > 30 * j["layered_faces"], "3 tets per prism: %s" % j)
    c = check_mesh(w("sis_foam"))
    if c is None:
        print("skipped checkMesh: OpenFOAM is not installed")
    else:
        expect("Mesh OK." in c.stdout, "checkMesh on the split layers: Mesh OK", c)

# Prisms written to OpenFOAM directly (no gmshToFoam): checkMesh sees every wedge as a prism.
r = run([volgrid, "mesh", w("sis.off"), w("sis_prisms"), "--format", "openfoam", "--json"] + layers)
expect(r.returncode == 0, "prisms to OpenFOAM", r)
if r.returncode == 0:
    j = json.loads(r.stdout.strip().splitlines()[-1])
    c = check_mesh(w("sis_prisms"))
    if c is not None:
        n = check_mesh_counts(c.stdout)
        expect("Mesh OK." in c.stdout and n.get("prisms") == j["wedges"] and n.get("tetrahedra") == j["tets"]
               and n.get("cells") == j["wedges"] + j["tets"], "checkMesh on the OpenFOAM prisms: Mesh OK, %s" % n, c)
        expect_quality_as_check_mesh(w("sis.vtu"), c.stdout, "sphere in sphere, prisms")

# Wedges in gmsh 2.2 through gmshToFoam: checkMesh on the mixed mesh itself.
r = run([volgrid, "mesh", w("sis.off"), w("sis.msh"), "--format", "gmsh22"] + layers)
expect(r.returncode == 0, "prisms to gmsh 2.2", r)
if r.returncode == 0:
    os.makedirs(w("sis_gmsh"), exist_ok=True)
    c = check_mesh(w("sis_gmsh"), "gmshToFoam ../sis.msh &&")
    if c is not None:
        expect("Mesh OK." in c.stdout and re.search(r"prisms:\s+[1-9]", c.stdout) is not None,
               "gmshToFoam + checkMesh on the wedges: Mesh OK", c)

# Prisms in SU2, CGNS and Exodus II, read back by readers VolGrid did not write (mixed_mesh_readers.py under pvpython):
# cells by type and volumes equal to the .vtu's; cgnscheck finds nothing.
PVPYTHON = shutil.which("pvpython")
READERS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mixed_mesh_readers.py")


def read_mixed(kind, path):
    c = run([PVPYTHON, READERS, kind, path], timeout=600)
    return json.loads(c.stdout.strip().splitlines()[-1]) if c.returncode == 0 else {"error": c.describe()}


def close(a, b, tolerance=1e-9):
    return abs(a - b) <= tolerance * max(abs(a), abs(b))


# meshio (python3-meshio) lives in the system python; meshio_cells.py computes each cell's volume.
MESHIO_PYTHON = "/usr/bin/python3" if run(["/usr/bin/python3", "-c", "import meshio"]).returncode == 0 else None
MESHIO_CELLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "meshio_cells.py")


def meshio_cells(kind, path):
    c = run([MESHIO_PYTHON, MESHIO_CELLS, kind, path], timeout=600)
    return json.loads(c.stdout.strip().splitlines()[-1]) if c.returncode == 0 else {"error": c.describe()}


if not MESHIO_PYTHON:
    print("skipped the meshio read-backs: /usr/bin/python3 has no meshio")
else:
    # The prisms in Medit, read by meshio: 24200 wedges, each of positive volume, as much volume as the split run.
    r = run([volgrid, "mesh", w("sis.off"), w("sis.mesh")] + layers)
    rs = run([volgrid, "mesh", w("sis.off"), w("sis_split.mesh"), "--split-prisms"] + layers)
    expect(r.returncode == 0 and rs.returncode == 0, "prisms to Medit", r)
    if r.returncode == 0 and rs.returncode == 0:
        m, ms = meshio_cells("medit", w("sis.mesh")), meshio_cells("medit", w("sis_split.mesh"))
        print("sphere in sphere, Medit (meshio):", m)
        expect(m.get("cells", {}).get("wedge") == 24200 and min(m["min"].values()) > 0
               and close(m["total_volume"], ms["total_volume"]) and "wedge" not in ms["cells"],
               "Medit read by meshio: 24200 prisms, positive volumes, the split mesh's volume: %s %s" % (m, ms))
    # The size step from the last layer to the tets (--json transition_*), recomputed from the Medit file by
    # layer_transition.py (meshio), for layers far thinner than the wall's triangles (a warning) and for
    # layers whose last one is about as tall as the tets over it (none).
    TRANSITION = os.path.join(os.path.dirname(os.path.abspath(__file__)), "layer_transition.py")
    for name, options, warned in (("thin", layers, True),
                                  ("matched", ["--layers", "5", "--first-height", "0.01", "--growth", "1.5"], False)):
        r = run([volgrid, "mesh", w("sis.off"), w("sis_%s.mesh" % name), "--json"] + options)
        t = run([MESHIO_PYTHON, TRANSITION, w("sis_%s.mesh" % name)])
        expect(r.returncode == 0 and t.returncode == 0, "transition, %s layers" % name, r if r.returncode else t)
        if r.returncode == 0 and t.returncode == 0:
            j, mine = json.loads(r.stdout.strip().splitlines()[-1]), json.loads(t.stdout.strip().splitlines()[-1])
            print("sphere in sphere, %s layers: transition" % name, {k: v for k, v in j.items() if "transition" in k},
                  "\n  meshio:", mine)
            expect(j["transition_faces"] == mine["faces"] == j["layered_faces"]
                   and all(close(j["transition_ratio_" + k], mine[k], 1e-5) for k in ("median", "p90", "max"))
                   and ("times as tall as it" in r.stderr) == warned
                   and (j["transition_ratio_median"] > 4) == warned,
                   "transition, %s layers: the figures meshio's recomputation gives, warned: %s" % (name, warned), r)


for fmt in ("su2", "cgns", "exo"):
    r = run([volgrid, "mesh", w("sis.off"), w("sis." + fmt), "--json"] + layers)
    expect(r.returncode == 0, "prisms to " + fmt, r)
su2_cells = [l.split()[0] for l in open(w("sis.su2")).read().split("NPOIN=")[0].splitlines()[2:]]
expect(su2_cells.count("13") == 24200 and su2_cells.count("10") + su2_cells.count("13") == len(su2_cells),
       "SU2: 24200 prisms (type 13) after the tets")
if PVPYTHON:
    ref = read_mixed("vtu", w("sis.vtu"))
    su2, cgns = read_mixed("su2", w("sis.su2")), read_mixed("cgns", w("sis.cgns"))
    print("sphere in sphere, .vtu:", ref, "\n  SU2:", su2, "\n  CGNS (ParaView):", cgns)
    expect(ref.get("wedges") == 24200 and ref["wedge_min_max"][0] > 0 and ref["tet_min_max"][0] > 0, ".vtu: %s" % ref)
    expect(su2.get("tets") == ref.get("tets") and su2.get("wedges") == 24200 and su2.get("other") == 0
           and close(su2["tet_volume"], ref["tet_volume"]) and close(su2["wedge_volume"], ref["wedge_volume"])
           and su2["wedge_min_max"][0] > 0, "SU2 read as VTK cells: the .vtu's cells and volumes: %s" % su2)
    # PENTA_6 is in CGNS's (and gmsh's) order, the base's normal towards the top; ParaView's CGNS reader
    # passes it on as VTK_WEDGE unchanged, whose first triangle faces away from the top: every wedge of
    # the reader's output has the .vtu wedge's volume with the sign flipped, none of the other sign.
    expect(cgns.get("tets") == ref.get("tets") and cgns.get("wedges") == 24200 and cgns.get("other") == 0
           and close(cgns["tet_volume"], ref["tet_volume"]) and close(-cgns["wedge_volume"], ref["wedge_volume"])
           and cgns["wedge_min_max"][1] < 0, "CGNS read by ParaView: the .vtu's cells and volumes: %s" % cgns)
    # Exodus's WEDGE is CGNS's PENTA_6 (side 4 = 1 3 2 outward) and ParaView's reader passes it on the same way;
    # it reads the coordinates as floats (hence 1e-6).
    exo = read_mixed("exodus", w("sis.exo"))
    print("  Exodus (ParaView):", exo)
    expect(exo.get("tets") == ref.get("tets") and exo.get("wedges") == 24200 and exo.get("other") == 0
           and close(exo["tet_volume"], ref["tet_volume"], 1e-6)
           and close(-exo["wedge_volume"], ref["wedge_volume"], 1e-6) and exo["wedge_min_max"][1] < 0,
           "Exodus read by ParaView: the .vtu's cells and volumes: %s" % exo)
else:
    print("skipped the SU2/CGNS readers: pvpython is not installed")
if shutil.which("cgnscheck"):
    c = run(["cgnscheck", w("sis.cgns")])
    expect(c.returncode == 0 and "error" not in c.stdout.lower() and "warning" not in c.stdout.lower(),
           "cgnscheck on the prisms' CGNS file", c)

# volgrid quality on the mixed .vtu: the wedges measured by type (Core/Quality/PrismQuality.h), none inverted,
# and the total volume the tets' and the wedges' together.
r = run([volgrid, "quality", w("sis.vtu"), "--json"])
expect(r.returncode == 0, "volgrid quality on the layers' .vtu", r)
if r.returncode == 0:
    q = json.loads(r.stdout.strip().splitlines()[-1])
    jac, vol = q["metrics"]["WedgeScaledJacobian"], q["metrics"]["WedgeVolume"]
    print("quality of the layers:", {k: q[k] for k in ("NumberOfTetrahedra", "NumberOfWedges", "InvertedWedges",
                                                      "SkippedCells", "TotalVolume")}, "scaled Jacobian", jac["min"],
          jac["max"])
    expect(q["NumberOfWedges"] == 24200 and q["InvertedWedges"] == 0 and q["SkippedCells"] == 0
           and jac["count"] == 24200 and 0.9 < jac["min"] <= jac["max"] <= 1 and vol["min"] > 0,
           "quality: 24200 wedges, none inverted, near-right prisms: %s %s" % (jac, vol))
    if PVPYTHON:
        expect(close(q["TotalVolume"], ref["tet_volume"] + ref["wedge_volume"]),
               "quality: TotalVolume %s = the .vtu's tets + wedges %s" % (q["TotalVolume"], ref))

# Ten layers from 1e-3 to a total thickness of 0.02: the growth ratio is solved for and reported.
r = run([volgrid, "mesh", w("sis.off"), w("thick.vtu"), "--json", "--layers", "10", "--first-height", "1e-3",
         "--layer-thickness", "0.02"])
expect(r.returncode == 0 and abs(json.loads(r.stdout)["total_thickness"] / 0.02 - 1) < 1e-9
       and 1.146 < json.loads(r.stdout)["growth"] < 1.148, "--layer-thickness solves the growth ratio", r)

# The first height from a target y+ (flat plate, Re 1e6, length 1: 2.35288e-05).
r = run([volgrid, "mesh", w("sis.off"), w("yplus.vtu"), "--json", "--layers", "3", "--y-plus", "1", "--reynolds", "1e6",
         "--reference-length", "1"])
expect(r.returncode == 0 and abs(json.loads(r.stdout)["first_height"] / 2.35288e-05 - 1) < 1e-5, "--y-plus", r)

bad = [(["--layers", "3", "--first-height", "1e-3", "--y-plus", "1", "--reynolds", "1e6", "--reference-length", "1"],
        "not both"),
       (["--layers", "10", "--first-height", "-1e-3"], "--first-height is out of range"),
       (["--layers", "10", "--first-height", "1e-3", "--growth", "0.5"], "growth"),
       (["--layers", "10", "--first-height", "1e-3", "--growth", "1.2", "--layer-thickness", "0.02"], "give two of"),
       (["--layers", "10", "--first-height", "1e-3", "--layer-thickness", "0.005"], "no growth ratio"),
       (["--layers", "10", "--first-height", "5", "--growth", "1"], "more than the domain allows"),
       (["--first-height", "1e-3"], "need --layers"),
       (["--layers", "3", "--first-height", "1e-3", "--layer-patches", "wing"], "'wing' is not a patch")]
for extra, message in bad:
    out = w("bad.vtu")
    r = run([volgrid, "mesh", w("sis.off"), out] + extra)
    expect(refused_cleanly(r) and message in r.stderr and not os.path.exists(out), "refused: " + message, r)
r = run([volgrid, "mesh", w("sis.off"), w("bad.node")] + layers)
expect(refused_cleanly(r) and "--split-prisms" in r.stderr and not os.path.exists(w("bad.node")),
       "prisms in a tet-only format (TetGen) need --split-prisms", r)

# The straight wing of `make demo`: its tip corners, where the thin leading and trailing edges meet the
# tip cap, leave no marching direction that every face there sees well. Those columns collapse onto the
# wall (pyramids and tets around them) instead of failing the run or thinning half the wing; checked by
# OpenFOAM (gmshToFoam + checkMesh): the same cells by type, valid pyramids and volumes, closed boundary.
r = run([volgrid, "prep", os.path.join(sys.argv[2], "straight_wing.stl"), w("wing.off"), "--enclosure", "sphere",
         "--enclosure-scale", "10"])
assert r.returncode == 0, r.describe()
r = run([volgrid, "mesh", w("wing.off"), w("wing.msh"), "--format", "gmsh22", "--json", "--layers", "10",
         "--first-height", "1e-4", "--growth", "1.2"])
expect(r.returncode == 0, "straight wing with 10 layers", r)
if r.returncode == 0:
    j = json.loads(r.stdout.strip().splitlines()[-1])
    print("straight wing:", j)
    expect(j["collapsed_columns"] > 0 and j["pyramids"] > 0 and j["inverted_cells"] == 0,
           "straight wing: collapsed columns give pyramids, none inverted: %s" % j)
    expect(j["all_layers"] >= 0.98 and j["coverage"] >= 0.85,
           "straight wing: 98%% of the faces keep every layer, 85%% their full height: %s" % j)
    expect(j["interface_faces_shared"] == j["layered_faces"], "straight wing: the tets share the layers' surface")
    os.makedirs(w("wing_gmsh"), exist_ok=True)
    c = check_mesh(w("wing_gmsh"), "gmshToFoam ../wing.msh >/dev/null &&")
    if c is not None:
        counts = {kind: int(n) for kind, n in re.findall(r"^\s+(prisms|pyramids|tetrahedra):\s+(\d+)", c.stdout, re.M)}
        expect(counts == {"prisms": j["wedges"], "pyramids": j["pyramids"], "tetrahedra": j["tets"]},
               "straight wing: checkMesh counts our cells: %s" % counts, c)
        expect(re.search(r"Boundary openness .* OK", c.stdout) is not None, "straight wing: closed boundary", c)
        for line in ("Cell volumes OK", "Face pyramids OK", "Upper triangular ordering OK",
                     "Number of regions: 1 (OK)"):
            expect(line in c.stdout, "straight wing: checkMesh: " + line, c)
    # The pyramids written to OpenFOAM directly: checkMesh finds what it finds after gmshToFoam (the same
    # counts by cell shape, failed checks and skew faces), each pyramid a pyramid.
    r = run([volgrid, "mesh", w("wing.off"), w("wing_foam"), "--format", "openfoam", "--json", "--layers", "10",
             "--first-height", "1e-4", "--growth", "1.2"])
    expect(r.returncode == 0, "straight wing with pyramids to OpenFOAM", r)
    rf = r
    if r.returncode == 0 and c is not None:
        jf = json.loads(r.stdout.strip().splitlines()[-1])
        cf = check_mesh(w("wing_foam"))
        nf, ng = check_mesh_counts(cf.stdout), check_mesh_counts(c.stdout)
        print("straight wing checkMesh, direct:", nf, "\n  gmshToFoam:", ng)
        expect(nf == ng and nf.get("pyramids") == jf["pyramids"] > 0 and nf.get("prisms") == jf["wedges"]
               and nf.get("tetrahedra") == jf["tets"] and nf.get("cells") == jf["wedges"] + jf["pyramids"] + jf["tets"],
               "straight wing: checkMesh on the direct OpenFOAM pyramids = gmshToFoam's: %s %s" % (nf, ng), cf)
        for line in ("Cell volumes OK", "Face pyramids OK", "Upper triangular ordering OK", "Number of regions: 1 (OK)"):
            expect(line in cf.stdout, "straight wing, direct OpenFOAM: checkMesh: " + line, cf)
        r = run([volgrid, "mesh", w("wing.off"), w("wing_layers.vtu"), "--layers", "10", "--first-height", "1e-4",
                 "--growth", "1.2"])
        expect(r.returncode == 0, "straight wing with pyramids to .vtu", r)
        expect_quality_as_check_mesh(w("wing_layers.vtu"), cf.stdout, "straight wing, prisms and pyramids")
        expect(re.search(r"Boundary openness .* OK", cf.stdout) is not None, "straight wing, direct: closed boundary", cf)
        # The wing's own triangles (long, thin, sheared) put the centroids of many neighbours along their
        # common edge: the side faces over those edges are severely non-orthogonal in every layer, and the
        # mesher says so before meshing. Its count is checkMesh's in the first layer (the thin-layer limit).
        severe = severe_first_layer_side_faces(w("wing_foam"))
        print("straight wing: wall edges over 70 deg predicted %d, first-layer side faces checkMesh counts %d"
              % (jf["wall_nonortho_edges"], severe))
        expect(jf["wall_nonortho_edges"] > 0 and abs(severe - jf["wall_nonortho_edges"]) <= 0.01 * severe
               and "non-orthogonality above 70 deg" in rf.stderr,
               "straight wing: the predicted non-orthogonal wall edges are checkMesh's first-layer faces: %d, %d"
               % (jf["wall_nonortho_edges"], severe))
    # Pyramids go to every format that takes prisms; TetGen refuses both, nothing written.
    r = run([volgrid, "mesh", w("wing.off"), w("wing.node"), "--layers", "10", "--first-height", "1e-4"])
    expect(refused_cleanly(r) and "--split-prisms" in r.stderr and not os.path.exists(w("wing.node")),
           "straight wing: prisms and pyramids to TetGen refused with a message", r)
    # SU2 and Medit read back by meshio: the cells by type, every cell's volume positive in the format's own
    # order, and the total the volume of the tet-only (--split-prisms) file.
    wing_layers = ["--layers", "10", "--first-height", "1e-4", "--growth", "1.2"]
    for kind, ext in (("su2", "su2"), ("medit", "mesh")):
        r = run([volgrid, "mesh", w("wing.off"), w("wing." + ext), "--json"] + wing_layers)
        rs = run([volgrid, "mesh", w("wing.off"), w("wing_split." + ext), "--split-prisms"] + wing_layers)
        expect(r.returncode == 0 and rs.returncode == 0, "straight wing: prisms and pyramids to " + kind, r)
        if r.returncode == 0 and rs.returncode == 0 and MESHIO_PYTHON:
            jw = json.loads(r.stdout.strip().splitlines()[-1])
            m, ms = meshio_cells(kind, w("wing." + ext)), meshio_cells(kind, w("wing_split." + ext))
            print("straight wing, %s (meshio):" % kind, m)
            expect(m.get("cells", {}).get("wedge") == jw["wedges"] and m["cells"].get("pyramid") == jw["pyramids"] > 0
                   and m["cells"].get("tetra") == jw["tets"] and min(m["min"].values()) > 0
                   and close(m["total_volume"], ms["total_volume"]),
                   "straight wing, %s read by meshio: cells by type, positive volumes, the split mesh's volume: %s %s"
                   % (kind, m, ms))
    # CGNS and Exodus II read by ParaView: PYRA_5 and PYRAMID are VTK's pyramid (positive volumes), PENTA_6
    # and WEDGE the reverse of VTK's wedge (every wedge negative, as for the sphere); the cells and total
    # volume the split file's (Exodus's coordinates read as floats: 1e-6); cgnscheck is silent.
    for kind, ext, tolerance in (("cgns", "cgns", 1e-9), ("exodus", "exo", 1e-6)):
        r = run([volgrid, "mesh", w("wing.off"), w("wing." + ext), "--json"] + wing_layers)
        expect(r.returncode == 0, "straight wing: prisms and pyramids to " + kind, r)
        if r.returncode == 0 and PVPYTHON and MESHIO_PYTHON:
            jw, cg = json.loads(r.stdout.strip().splitlines()[-1]), read_mixed(kind, w("wing." + ext))
            print("straight wing, %s (ParaView):" % kind, cg)
            expect(cg.get("tets") == jw["tets"] and cg.get("wedges") == jw["wedges"]
                   and cg.get("pyramids") == jw["pyramids"] and cg.get("other") == 0 and cg["tet_min_max"][0] > 0
                   and cg["pyramid_min_max"][0] > 0 and cg["wedge_min_max"][1] < 0
                   and close(cg["tet_volume"] - cg["wedge_volume"] + cg["pyramid_volume"],
                             meshio_cells("su2", w("wing_split.su2"))["total_volume"], tolerance),
                   "straight wing: %s read by ParaView: cells by type, pyramids positive, the split volume: %s"
                   % (kind, cg))
    if r.returncode == 0 and shutil.which("cgnscheck"):
        c = run(["cgnscheck", w("wing.cgns")])
        expect(c.returncode == 0 and "error" not in c.stdout.lower() and "warning" not in c.stdout.lower(),
               "cgnscheck on the wing's prisms and pyramids", c)
    # VolGrid's Medit, gmsh, SU2, CGNS and Exodus II readers take the prisms, pyramids and quads: written
    # again, each Medit, gmsh, SU2 and Exodus file is the same byte for byte; the Medit file converted to gmsh
    # 2.2, and the CGNS file converted to Medit, are the files `mesh` wrote; `volgrid quality` on each
    # measures what it measures on the .vtu of the same mesh. The OpenFOAM reader takes them too (below);
    # `refine` refuses layers (it refines tets).
    for src, extra in (("wing.mesh", []), ("wing.su2", []), ("wing.msh", ["--format", "gmsh22"]), ("wing.exo", [])):
        back = w("back_" + src)
        r = run([volgrid, "convert", w(src), back] + extra)
        same = r.returncode == 0 and open(w(src), "rb").read() == open(back, "rb").read()
        expect(same, "convert %s with layers, read and written again: identical" % src, r)
    r = run([volgrid, "convert", w("wing.mesh"), w("medit_to_gmsh.msh"), "--format", "gmsh22"])
    expect(r.returncode == 0 and open(w("wing.msh"), "rb").read() == open(w("medit_to_gmsh.msh"), "rb").read(),
           "convert wing.mesh (layers) to gmsh 2.2: the file `mesh` wrote", r)
    r = run([volgrid, "convert", w("wing.cgns"), w("cgns_to_medit.mesh")])
    expect(r.returncode == 0 and open(w("wing.mesh"), "rb").read() == open(w("cgns_to_medit.mesh"), "rb").read(),
           "convert wing.cgns (layers) to Medit: the file `mesh` wrote", r)
    # HDF5 stamps each object with its creation time: cgnsdiff compares the CGNS rewrite node by node.
    r = run([volgrid, "convert", w("wing.cgns"), w("back_wing.cgns")])
    c = run(["cgnsdiff", "-d", w("wing.cgns"), w("back_wing.cgns")]) if shutil.which("cgnsdiff") else None
    expect(r.returncode == 0 and (c is None or (c.returncode == 0 and c.stdout.strip() == "")),
           "convert wing.cgns with layers, read and written again: the same nodes and data", c or r)
    figures = ("NumberOfTetrahedra", "NumberOfWedges", "NumberOfPyramids", "SkippedCells", "TotalVolume",
               "MaxNonOrthogonality", "SevereNonOrthogonalFaces", "MaxSkewness", "HighlySkewFaces", "InvertedWedges")
    r = run([volgrid, "mesh", w("wing.off"), w("wing_q.vtu")] + wing_layers)
    r = run([volgrid, "quality", w("wing_q.vtu"), "--json"]) if r.returncode == 0 else r
    ref = json.loads(r.stdout.strip().splitlines()[-1]) if r.returncode == 0 else {}
    for src in ("wing.mesh", "wing.su2", "wing.msh", "wing.cgns", "wing.exo"):
        r = run([volgrid, "quality", w(src), "--json"])
        q = json.loads(r.stdout.strip().splitlines()[-1]) if r.returncode == 0 else {}
        expect(ref and all(q.get(k) == ref[k] for k in figures),
               "quality of %s with layers = quality of its .vtu: %s" % (src, {k: q.get(k) for k in figures}), r)
    # The direct OpenFOAM case read back (prism and pyramid cells from their faces): convert writes the same
    # polyMesh files again, and `volgrid quality` counts the .vtu's cells and measures its figures (to 1e-9:
    # the points file holds OpenFOAM's ASCII digits).
    r = run([volgrid, "convert", w("wing_foam"), w("back_foam"), "--format", "openfoam"])
    poly = lambda case, f: open(os.path.join(case, "constant", "polyMesh", f), "rb").read()
    expect(r.returncode == 0 and all(poly(w("wing_foam"), f) == poly(w("back_foam"), f)
                                     for f in ("points", "faces", "owner", "neighbour", "boundary")),
           "convert wing_foam with layers, read and written again: identical", r)
    r = run([volgrid, "quality", w("wing_foam"), "--json"])
    q = json.loads(r.stdout.strip().splitlines()[-1]) if r.returncode == 0 else {}
    expect(ref and q and all(close(q[k], ref[k]) if isinstance(ref[k], float) else q[k] == ref[k] for k in figures),
           "quality of wing_foam with layers = quality of its .vtu: %s" % {k: q.get(k) for k in figures}, r)
    r = run([volgrid, "refine", w("wing.msh"), w("refined.msh"), "--size-array", "none"])
    expect(refused_cleanly(r) and "not a tetrahedron" in r.stderr and not os.path.exists(w("refined.msh")),
           "refine of a mesh with layers refused with a message", r)

m6 = os.path.join(shared, "derived-onera-m6", "onera_m6_halfsphere_domain.mesh")
if shared and os.path.exists(m6):
    # Acceptance 1 of issue 19: 15 layers of 1e-4 root chord (the root chord is 1), ratio 1.2; the wing root
    # marches in the symmetry plane (patch 2).
    r = run([volgrid, "mesh", m6, w("m6.vtu"), "--json", "--layers", "15", "--first-height", "1e-4", "--growth", "1.2",
             "--layer-patches", "3,4,5,6,7,8,9,10,11,12"], timeout=600)
    expect(r.returncode == 0, "M6: 15 layers on the wing", r)
    if r.returncode == 0:
        j = json.loads(r.stdout)
        print("M6:", j)
        expect(j["coverage"] >= 0.98 and j["inverted_cells"] == 0 and j["wedges"] >= 0.98 * 15 * j["layered_faces"],
               "M6: at least 98%% of the wing faces get all 15 layers, none inverted: %s" % j)
        expect(j["interface_faces_shared"] == j["layered_faces"], "M6: the tets share the layers' surface: %s" % j)
        wing = j
        # Without --layer-patches the wing is chosen alone: the unnamed far field and symmetry plane span the
        # domain's box and get no layers.
        r = run([volgrid, "mesh", m6, w("m6default.msh"), "--format", "gmsh22", "--json", "--layers", "15",
                 "--first-height", "1e-4", "--growth", "1.2"], timeout=600)
        expect(r.returncode == 0, "M6: the default layer patches", r)
        if r.returncode == 0:
            j = json.loads(r.stdout.strip().splitlines()[-1])
            expect(j["layered_faces"] == wing["layered_faces"] and j["wedges"] == wing["wedges"],
                   "M6: by default the wing patches only: %s" % j)
            # One input wing edge (the root of the leading edge, between two long fan triangles) has an
            # OpenFOAM skewness of 8.19 in the surface itself. By default the triangles beside it are split
            # first, and checkMesh says "Mesh OK" (issue 19, acceptance 1).
            expect(j["wall_skew_edges_input"] == 1 and j["wall_split_edges"] > 0 and j["wall_skew_edges"] == 0
                   and j["coverage"] >= 0.98 and "were split" in r.stderr,
                   "M6: the skewed wall edge is found and the triangles beside it split: %s" % j, r)
            os.makedirs(w("m6_default"), exist_ok=True)
            c = check_mesh(w("m6_default"), "gmshToFoam ../m6default.msh >/dev/null &&")
            if c is not None:
                expect("Mesh OK." in c.stdout and "highly skew" not in c.stdout,
                       "M6, 15 layers, default options: checkMesh says Mesh OK", c)
        # Kept as it is (--keep-wall-triangles), the edge is reported before meshing, and checkMesh finds
        # exactly that: one skew face per layer there, nothing else failing.
        r = run([volgrid, "mesh", m6, w("m6keep.msh"), "--format", "gmsh22", "--json", "--layers", "15",
                 "--first-height", "1e-4", "--growth", "1.2", "--keep-wall-triangles"], timeout=600)
        j = json.loads(r.stdout.strip().splitlines()[-1]) if r.returncode == 0 else {}
        expect(j.get("wall_skew_edges") == 1 and j.get("wall_split_edges") == 0 and "skewness above 4" in r.stderr
               and 0 < j.get("layered_faces", 0) < wing["layered_faces"],
               "M6 with --keep-wall-triangles: the input's wall, its skewed edge reported: %s" % j, r)
        os.makedirs(w("m6_keep"), exist_ok=True)
        c = check_mesh(w("m6_keep"), "gmshToFoam ../m6keep.msh >/dev/null &&") if j.get("wall_skew_edges") == 1 else None
        if c is not None:
            m = re.search(r"Max skewness = ([0-9.e+-]+), (\d+) highly skew faces", c.stdout)
            expect(m is not None and int(m.group(2)) == 15 and abs(float(m.group(1)) / j["wall_skewness_max"] - 1) < 0.01
                   and "Failed 1 mesh checks" in c.stdout,
                   "M6 with --keep-wall-triangles: checkMesh fails on the 15 faces over the reported edge only "
                   "(predicted %.4g)" % j["wall_skewness_max"], c)
    # checkMesh on the direct OpenFOAM output agrees with gmsh 2.2 -> gmshToFoam: the same counts, cell shapes
    # and checks.
    m6_layers = ["--layers", "15", "--first-height", "1e-4", "--growth", "1.2", "--layer-patches",
                 "3,4,5,6,7,8,9,10,11,12"]
    rf = run([volgrid, "mesh", m6, w("m6_foam"), "--format", "openfoam"] + m6_layers, timeout=600)
    rg = run([volgrid, "mesh", m6, w("m6.msh"), "--format", "gmsh22"] + m6_layers, timeout=600)
    expect(rf.returncode == 0 and rg.returncode == 0, "M6: prisms to OpenFOAM and gmsh 2.2", rf if rf.returncode else rg)
    if rf.returncode == 0 and rg.returncode == 0 and os.path.exists(FOAM):
        os.makedirs(w("m6_gmsh"), exist_ok=True)
        cf, cg = check_mesh(w("m6_foam")), check_mesh(w("m6_gmsh"), "gmshToFoam ../m6.msh &&")
        nf, ng = check_mesh_counts(cf.stdout), check_mesh_counts(cg.stdout)
        print("M6 checkMesh, direct:", nf, "\nM6 checkMesh, gmshToFoam:", ng)
        expect(nf == ng and nf.get("prisms", 0) > 0, "M6: checkMesh agrees on the direct and gmshToFoam cases: %s %s"
               % (nf, ng), cf)
    # The wing root's prism sides on the symmetry plane are boundary quads of its patch in SU2 (type 9), CGNS
    # (a QUAD_4 section in the patch's boundary condition) and Exodus (wedge sides in its side set):
    # ParaView's CGNS and Exodus readers count what SU2 lists.
    for fmt in ("su2", "cgns", "exo"):
        r = run([volgrid, "mesh", m6, w("m6." + fmt)] + m6_layers, timeout=600)
        expect(r.returncode == 0, "M6: prisms to " + fmt, r)
    text = open(w("m6.su2")).read() if os.path.exists(w("m6.su2")) else ""
    markers = {k: int(v) for k, v in re.findall(r"MARKER_TAG= (\S+)\nMARKER_ELEMS= (\d+)", text)}
    quads = sum(1 for l in text.split("NMARK=")[-1].splitlines() if l.startswith("9 "))
    expect(quads > 0, "M6: SU2 boundary quads on the symmetry plane")
    # Medit: the same quads in its Quadrilaterals section (symmetry plane's reference), meshio reads every
    # prism with a positive volume.
    r = run([volgrid, "mesh", m6, w("m6.mesh"), "--json"] + m6_layers, timeout=600)
    expect(r.returncode == 0, "M6: prisms to Medit", r)
    if r.returncode == 0 and MESHIO_PYTHON:
        jm, m = json.loads(r.stdout.strip().splitlines()[-1]), meshio_cells("medit", w("m6.mesh"))
        print("M6, Medit (meshio):", m)
        expect(m.get("cells", {}).get("quad") == quads and m["cells"].get("wedge") == jm["wedges"]
               and m["cells"].get("tetra") == jm["tets"] and min(m["min"].values()) > 0,
               "M6: Medit read by meshio: %d quads, the wedges and tets, positive volumes: %s" % (quads, m))
    export = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Export", "paraview_readers.py")
    for kind, path in (("cgns", w("m6.cgns")), ("exodus", w("m6.exo"))):
        if PVPYTHON and os.path.exists(path):
            c = run([PVPYTHON, export, kind, path], timeout=600)
            seen = json.loads(c.stdout.strip().splitlines()[-1])["patches"] if c.returncode == 0 else {}
            expect(seen == markers and len(seen) == 12,
                   "M6: %s patches (ParaView) = SU2 markers: %s %s" % (kind, seen, markers), c)
    r = run([volgrid, "mesh", m6, w("m6bad.vtu"), "--layers", "15", "--first-height", "1e-4", "--layer-patches", "1,3,4"])
    expect(refused_cleanly(r) and "touch the non-layered patch" in r.stderr and not os.path.exists(w("m6bad.vtu")),
           "M6: layers on part of the wing, touching the rest of it, refused with a message", r)
else:
    print("skipped the ONERA M6 case: %s is absent" % m6)

shutil.rmtree(work, ignore_errors=True)
for f in failures:
    print("FAIL:", f)
print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
