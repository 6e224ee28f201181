"""Independent readers of VolGrid's solver files: each returns (points, tets, {patch name: faces}) as the
reader saw them. None of this code parses the files itself: meshio, gmsh's own API and OpenFOAM do."""
import collections
import json
import os
import re
import subprocess

import meshio


def _named_faces(mesh, tag_key, names):
    """Triangle counts per name from meshio cell data `tag_key` and a tag -> name map."""
    faces = collections.Counter()
    for block, tags in zip(mesh.cells, mesh.cell_data[tag_key]):
        if block.type == "triangle":
            for tag, count in collections.Counter(int(t) for t in tags).items():
                faces[names.get(tag, str(tag))] += count
    return dict(faces)


def _count(mesh, kind):
    return sum(len(b.data) for b in mesh.cells if b.type == kind)


def meshio_gmsh(path):
    m = meshio.read(path)
    names = {int(v[0]): k for k, v in m.field_data.items() if int(v[1]) == 2}
    return len(m.points), _count(m, "tetra"), _named_faces(m, "gmsh:physical", names)


def meshio_medit(path, names):
    m = meshio.read(path)
    return len(m.points), _count(m, "tetra"), _named_faces(m, "medit:ref", names)


def meshio_su2(path):
    m = meshio.read(path)
    # meshio keeps SU2 marker tags as integers in cell data "su2:tag" when the tags are numbers; VolGrid's
    # are names, so count the boundary triangles per marker from the file's MARKER_TAG order instead.
    return len(m.points), _count(m, "tetra"), _count(m, "triangle")


def meshio_tetgen(path):
    m = meshio.read(path)
    return len(m.points), _count(m, "tetra")


def meshio_exodus(path):
    """meshio 7.0 reads Exodus element blocks (not side sets): points and tets."""
    m = meshio.read(path)
    return len(m.points), _count(m, "tetra")


PVPYTHON = os.environ.get("VOLGRID_PVPYTHON", "/usr/bin/pvpython")


def paraview_reader(kind, path):
    """ParaView's CGNS or Exodus II reader (paraview_readers.py under pvpython): (points, tets, faces)."""
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_readers.py")
    p = subprocess.run([PVPYTHON, script, kind, path], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    lines = [l for l in p.stdout.splitlines() if l.startswith("{")]
    if p.returncode != 0 or not lines:
        print(p.stdout + p.stderr)
        return None
    r = json.loads(lines[-1])
    return r["points"], r["tets"], r["patches"]


def cgnscheck(path):
    """cgns-convert's cgnscheck: (exit code, output); a valid file prints no ERROR line."""
    p = subprocess.run(["cgnscheck", path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def gmsh_api(path):
    """Reads with gmsh's own Python API (gmsh 4.8, Debian's python3-gmsh)."""
    import gmsh
    gmsh.initialize(["-v", "0"])
    try:
        gmsh.open(path)
        nodes = len(gmsh.model.mesh.getNodes()[0])
        tets = 0
        for dim, tag in gmsh.model.getEntities(3):
            types, elems, _ = gmsh.model.mesh.getElements(dim, tag)
            tets += sum(len(e) for t, e in zip(types, elems) if t == 4)
        faces = {}
        for dim, tag in gmsh.model.getPhysicalGroups(2):
            name = gmsh.model.getPhysicalName(dim, tag)
            n = 0
            for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
                types, elems, _ = gmsh.model.mesh.getElements(2, entity)
                n += sum(len(e) for t, e in zip(types, elems) if t == 2)
            faces[name] = n
        return nodes, tets, faces
    finally:
        gmsh.finalize()


FOAM_BASHRC = "/usr/share/openfoam/etc/bashrc"


def foam(case, *command):
    """Runs an OpenFOAM utility in `case` with Debian's environment; returns (exit code, output)."""
    script = "source %s >/dev/null 2>&1 || true; cd '%s' && %s" % (FOAM_BASHRC, case, " ".join(command))
    p = subprocess.run(["bash", "-c", script], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def check_mesh(case):
    """checkMesh's verdict, counts, patches and CFD figures."""
    code, out = foam(case, "checkMesh")
    result = {"code": code, "output": out, "ok": "Mesh OK." in out}
    m = re.search(r"^\s*points:\s+(\d+)", out, re.M)
    result["points"] = int(m.group(1)) if m else -1
    m = re.search(r"^\s*cells:\s+(\d+)", out, re.M)
    result["cells"] = int(m.group(1)) if m else -1
    patches = {}
    section = out.split("Checking patch topology", 1)[-1].split("Checking", 1)[0]
    for line in section.splitlines():
        f = line.split()
        if len(f) >= 3 and f[1].isdigit() and f[2].isdigit() and f[0] != "Patch":
            patches[f[0]] = int(f[1])
    result["patches"] = patches
    m = re.search(r"Mesh non-orthogonality Max:\s*([0-9.eE+-]+)", out)
    result["max_non_orthogonality"] = float(m.group(1)) if m else None
    m = re.search(r"Number of severely non-orthogonal \(> 70 degrees\) faces:\s*(\d+)", out)
    result["severe_faces"] = int(m.group(1)) if m else 0
    m = re.search(r"Max skewness = ([0-9.eE+-]+)", out)
    result["max_skewness"] = float(m.group(1)) if m else None
    return result
