#!/usr/bin/env python3
"""VolGrid's boundary layers against Gmsh 4.8's extrudeBoundaryLayer on the ONERA M6 wing.

Both grow 15 layers, first height 1e-4 (root chord 1), ratio 1.2 from the wing patches 3..12 of the
half-sphere domain. Per mesher: coverage (VolGrid: its JSON's share of wall faces at full height; Gmsh: prisms /
(15 * wing faces)), prisms whose corner tets are not all
positive (floating point, sign fixed by the mesh's majority), cells, CPU time, and checkMesh's verdict
(gmsh 2.2 -> gmshToFoam -> checkMesh) when OpenFOAM is installed. Gmsh's layers are the extrusion only:
4.8's discrete-surface extrusion does not fill the rest of the domain here, so its checkMesh sees the layers.
Writes a markdown table to build/bench/layers.md.  Usage: bench_layers_gmsh.py VOLGRID_BINARY [OUT_DIR]
"""
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
MESH = os.path.join(HERE, "..", "..", "..", "shared", "data", "real", "derived-onera-m6",
                    "onera_m6_halfsphere_domain.mesh")
PATCHES = list(range(3, 13))
LAYERS, FIRST, RATIO = 15, 1e-4, 1.2

GMSH_SCRIPT = r'''
import sys, time, gmsh
mesh, out, layers, first, ratio = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
patches = [int(p) for p in sys.argv[6].split(",")]
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.merge(mesh)
t0 = time.process_time()
gmsh.model.mesh.createTopology()  # without boundary curves the extrusion fails ("Could not find extruded node")
heights, s = [], 0.0
for k in range(layers):
    s += first * ratio ** k
    heights.append(-s)  # gmsh extrudes along the surface's normals, which point into the wing here
gmsh.model.geo.extrudeBoundaryLayer([(2, t) for t in patches], [1] * layers, heights, True)
gmsh.model.geo.synchronize()
gmsh.model.mesh.generate(3)
print("GMSH_CPU", time.process_time() - t0)
gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
gmsh.write(out)
gmsh.finalize()
'''


def read_msh22(path):
    """Nodes and cells (by gmsh type) of an ASCII gmsh 2.2 file."""
    lines = open(path).read().split("\n")
    i = lines.index("$Nodes")
    n = int(lines[i + 1])
    nodes = {}
    for line in lines[i + 2:i + 2 + n]:
        v = line.split()
        nodes[int(v[0])] = tuple(map(float, v[1:4]))
    i = lines.index("$Elements")
    cells = {}
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        v = list(map(int, line.split()))
        cells.setdefault(v[1], []).append(v[3 + v[2]:])
    return nodes, cells


def vol(a, b, c, d):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    w = [d[k] - a[k] for k in range(3)]
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])


def wing_faces(path):
    """Triangles of the Medit file whose reference is a wing patch."""
    words = open(path).read().split()
    i = words.index("Triangles")
    n = int(words[i + 1])
    return sum(1 for k in range(n) if int(words[i + 2 + 4 * k + 3]) in PATCHES)


CORNERS = ((0, 1, 2, 3), (1, 2, 0, 4), (2, 0, 1, 5), (3, 5, 4, 0), (4, 3, 5, 1), (5, 4, 3, 2))


def inverted(nodes, cells):
    """Prisms (type 6) and tets (type 4) with a non-positive corner, the sign fixed by the majority."""
    signs = []
    for c in cells.get(6, []):
        p = [nodes[i] for i in c]
        signs.append([vol(*[p[i] for i in t]) for t in CORNERS])
    for c in cells.get(4, []):
        p = [nodes[i] for i in c]
        signs.append([vol(*p)])
    positive = sum(1 for s in signs if min(s) > 0)
    negative = sum(1 for s in signs if max(s) < 0)
    flip = negative > positive
    return sum(1 for s in signs if (max(s) >= 0 if flip else min(s) <= 0))


def check_mesh(msh, case):
    foam = "/usr/share/openfoam/etc/bashrc"
    if not os.path.exists(foam):
        return "not run (no OpenFOAM)"
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    for name, body in (("controlDict", "application checkMesh;\nstartTime 0;\nendTime 1;\ndeltaT 1;\nwriteInterval 1;\n"),
                       ("fvSchemes", "ddtSchemes { default steadyState; }\ngradSchemes { default Gauss linear; }\n"
                        "divSchemes { default none; }\nlaplacianSchemes { default Gauss linear corrected; }\n"
                        "interpolationSchemes { default linear; }\nsnGradSchemes { default corrected; }\n"),
                       ("fvSolution", "")):
        with open(os.path.join(case, "system", name), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n%s" % (name, body))
    r = subprocess.run(["bash", "-c", "source %s >/dev/null 2>&1; cd '%s' && gmshToFoam '%s' && checkMesh"
                        % (foam, case, msh)], capture_output=True, text=True, timeout=900)
    if "Mesh OK." in r.stdout:
        return "Mesh OK"
    failed = re.search(r"Failed (\d+) mesh checks", r.stdout)
    skew = re.search(r"Max skewness = ([0-9.e+-]+), (\d+) highly skew", r.stdout)
    text = "Failed %s checks" % failed.group(1) if failed else "did not run: " + (r.stdout + r.stderr)[-200:]
    if skew:
        text += " (%s skew faces, max %s)" % (skew.group(2), skew.group(1))
    print("checkMesh failures of %s:\n  " % os.path.basename(msh)
          + "\n  ".join(l.strip() for l in r.stdout.splitlines() if l.strip().startswith("***")))
    return text


def cpu_of(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=1800)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r, after.ru_utime - before.ru_utime


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    if not os.path.exists(MESH):
        print("skipped: %s is absent" % MESH)
        return 0
    volgrid = os.path.abspath(sys.argv[1])
    out_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join("build", "bench")
    work = tempfile.mkdtemp(prefix="volgrid-bench-layers-")
    rows = []

    vmsh = os.path.join(work, "volgrid.msh")
    r, cpu = cpu_of([volgrid, "mesh", MESH, vmsh, "--format", "gmsh22", "--json", "--layers", str(LAYERS),
                     "--first-height", str(FIRST), "--growth", str(RATIO),
                     "--layer-patches", ",".join(map(str, PATCHES))])
    if r.returncode != 0:
        sys.exit("volgrid failed: " + r.stderr)
    j = json.loads(r.stdout.strip().splitlines()[-1])
    faces = wing_faces(MESH)  # the input's: VolGrid may split a few beside skewed edges first (layered_faces)
    nodes, cells = read_msh22(vmsh)
    rows.append(("VolGrid", "%.2f%%" % (100 * j["coverage"]), inverted(nodes, cells), len(cells.get(6, [])),
                 len(cells.get(4, [])), cpu, check_mesh(vmsh, os.path.join(work, "volgrid_foam"))))

    gmsh_py = os.path.join(work, "gmsh_layers.py")
    with open(gmsh_py, "w") as f:
        f.write(GMSH_SCRIPT)
    gmsh_msh = os.path.join(work, "gmsh.msh")
    r, cpu = cpu_of(["/usr/bin/python3", gmsh_py, MESH, gmsh_msh, str(LAYERS), str(FIRST), str(RATIO),
                     ",".join(map(str, PATCHES))])
    if r.returncode != 0 or not os.path.exists(gmsh_msh):
        rows.append(("Gmsh 4.8", "failed: " + (r.stderr.strip().splitlines() or ["?"])[-1], "-", "-", "-", cpu, "-"))
    else:
        nodes, cells = read_msh22(gmsh_msh)
        prisms = len(cells.get(6, []))
        rows.append(("Gmsh 4.8 (layers only)", "%.2f%%" % (100.0 * prisms / (LAYERS * faces)), inverted(nodes, cells),
                     prisms, len(cells.get(4, [])), cpu, check_mesh(gmsh_msh, os.path.join(work, "gmsh_foam"))))

    table = ["| mesher | coverage | inverted | prisms | tets | CPU s | checkMesh |", "|---|---|---|---|---|---|---|"]
    for row in rows:
        table.append("| %s | %s | %s | %s | %s | %.2f | %s |" % row)
    text = ("ONERA M6 wing (%d faces; VolGrid's wall after splitting beside skewed edges: %d), %d layers, first "
            "height %g, ratio %g\n\n" % (faces, j["layered_faces"], LAYERS, FIRST, RATIO) + "\n".join(table) + "\n")
    print(text)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "layers.md"), "w") as f:
        f.write(text)
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
