"""ParaView's Save Data for the solver formats (pvpython SaveData, the same writer proxies as File > Save
Data): the wing-in-sphere mesh of VolGrid Tetrahedralize saved as gmsh 4.1 and 2.2, SU2, Medit, TetGen, an
OpenFOAM case, CGNS and Exodus II, each read back by a reader VolGrid did not write (gmsh's API, meshio,
OpenFOAM's checkMesh, ParaView's CGNS and Exodus readers), which must report the tets, points and patch
names with the face counts of Tetrahedralize's own outputs; the same with boundary layers (prisms and
pyramids) for every format that takes them. A save into a missing directory fails with a clear error and
leaves no file. Usage: pvpython test_savedata.py WORKDIR (plugin in $VOLGRID_PLUGIN)."""
import collections
import json
import os
import re
import shutil
import subprocess
import sys

import meshio

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paraview_readers as PV  # noqa: E402
import solver_readers as R  # noqa: E402
from test_solver_export import write_potential_case  # noqa: E402

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
# Cells by type of a CGNS or Exodus II file as ParaView's readers see them (run under pvpython).
READERS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Apps", "mixed_mesh_readers.py")
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


work = sys.argv[1]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
w = lambda name: os.path.join(work, name)

wing = STLReader(FileNames=[os.path.join(os.environ["VOLGRID_TEST_DATA_DIR"], "straight_wing.stl")])
domain = VolGridSurfacePrep(Input=[wing], Enclosure="Sphere", EnclosureScale=10.0)
mesh = VolGridTetrahedralize(Input=domain, PatchAssignment="wing=0,farfield=1")
mesh.UpdatePipeline()
volume = servermanager.Fetch(mesh, idx=0)
boundary = servermanager.Fetch(mesh, idx=1)
ids = boundary.GetCellData().GetArray("PatchId")
names = boundary.GetFieldData().GetAbstractArray("PatchNames")
faces = dict(collections.Counter(names.GetValue(int(ids.GetValue(i))) for i in range(ids.GetNumberOfValues())))
expected = (volume.GetNumberOfPoints(), volume.GetNumberOfCells(), faces)
print("Tetrahedralize: %d points, %d tets, patches %s" % expected)

for name in ("mesh.msh", "mesh.su2", "mesh.mesh", "mesh.node", "case.foam", "mesh.cgns", "mesh.exo"):
    writer = CreateWriter(w(name), mesh)
    check(writer.GetXMLName().startswith(("VolGrid", "CGNSVolGrid")), "SaveData('%s') uses %s" % (name, writer.GetXMLName()))
    del writer
    SaveData(w(name), proxy=mesh)
SaveData(w("mesh22.msh"), proxy=mesh, Format="gmsh22")

check(R.gmsh_api(w("mesh.msh")) == expected, "gmsh API on the saved .msh: same points, tets, patches, faces")
check(R.gmsh_api(w("mesh22.msh")) == expected, "gmsh API on the saved gmsh 2.2 file: same")
check(R.meshio_su2(w("mesh.su2")) == (expected[0], expected[1], sum(faces.values())), "meshio on the saved .su2: same counts")
medit = R.meshio_medit(w("mesh.mesh"), {})
check(medit[:2] == expected[:2] and sorted(medit[2].values()) == sorted(faces.values()),
      "meshio on the saved .mesh: same counts, same faces per ref")
check(R.meshio_tetgen(w("mesh.node")) == expected[:2], "meshio on the saved TetGen files: same counts")
write_potential_case(w("case"))  # checkMesh needs system/controlDict
foam = R.check_mesh(w("case"))
check((foam["points"], foam["cells"], foam["patches"]) == expected, "checkMesh on the saved OpenFOAM case: same")
check(PV.cgns(w("mesh.cgns")) == expected, "ParaView's CGNS reader on the saved .cgns: same")
check(PV.exodus(w("mesh.exo")) == expected, "ParaView's Exodus II reader on the saved .exo: same")

# Adaptivity on a solver's mesh: a target-size field saved with the mesh as an Exodus II nodal variable,
# `volgrid refine` reads it back, refines where the target is finer and writes Exodus II and CGNS with the
# same patches (the boundary is kept exactly).
volgrid = os.environ["VOLGRID_CLI"]
target = PythonCalculator(Input=mesh, ArrayName="TargetSize", Expression="0.1 + 0.2 * mag(inputs[0].Points)")
SaveData(w("solver.exo"), proxy=target)
for out, reader in (("finer.exo", PV.exodus), ("finer.cgns", PV.cgns)):
    p = subprocess.run([volgrid, "refine", w("solver.exo"), w(out), "--size-array", "TargetSize"],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout, end="")
    finer = reader(w(out)) if p.returncode == 0 else (0, 0, {})
    check(finer[0] > expected[0] and finer[1] > expected[1] and finer[2] == faces,
          "refine solver.exo %s: more points and tets (%d, %d), same patches and faces %s" % (out, finer[0], finer[1], finer[2]))
p = subprocess.run([volgrid, "refine", w("mesh.msh"), w("none.exo"), "--size-array", "TargetSize"],
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
check(p.returncode == 1 and "TargetSize" in p.stdout and not os.path.exists(w("none.exo")),
      "refine on a mesh without the target array: clear error, no file")

# Boundary layers: the prisms and the pyramids of collapsed columns are saved too (the volume's 5-component
# BoundaryFacePatch), each file read back by meshio, checkMesh or ParaView's readers with the cells by type
# and the boundary faces of Tetrahedralize's outputs; TetGen refuses them with a message and writes nothing.
layered = VolGridTetrahedralize(Input=domain, NumberOfLayers=10, FirstLayerHeight=1e-4)
layered.UpdatePipeline()
lv, lb = servermanager.Fetch(layered, idx=0), servermanager.Fetch(layered, idx=1)
types = collections.Counter(lv.GetCellType(i) for i in range(lv.GetNumberOfCells()))
cells = {"tetra": types[10], "wedge": types[13], "pyramid": types[14]}
print("Tetrahedralize with layers: %s, %d boundary faces" % (cells, lb.GetNumberOfCells()))
check(cells["wedge"] > 0 and cells["pyramid"] > 0 and sum(cells.values()) == lv.GetNumberOfCells(),
      "layers: wedges, pyramids and tets only")
for name in ("layers.msh", "layers.su2", "layers.mesh", "layers.cgns", "layers.exo", "layers_case.foam"):
    SaveData(w(name), proxy=layered)
for kind, name in (("gmsh", "layers.msh"), ("su2", "layers.su2"), ("medit", "layers.mesh")):
    m = meshio.read(w(name), file_format=kind)
    got = {k: sum(len(b.data) for b in m.cells if b.type == k) for k in cells}
    faces = sum(len(b.data) for b in m.cells if b.type in ("triangle", "quad"))
    check(got == cells and faces == lb.GetNumberOfCells(),
          "meshio on the saved %s with layers: cells %s, %d boundary faces" % (name, got, faces))
for kind, name in (("cgns", "layers.cgns"), ("exodus", "layers.exo")):
    p = subprocess.run([os.environ["VOLGRID_PVPYTHON"], READERS, kind, w(name)], stdout=subprocess.PIPE, text=True)
    got = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {}
    check({k: got.get(n) for k, n in (("tetra", "tets"), ("wedge", "wedges"), ("pyramid", "pyramids"))} == cells
          and got.get("other") == 0 and got["tet_min_max"][0] > 0 and got["pyramid_min_max"][0] > 0
          and got["wedge_min_max"][1] < 0,  # CGNS's and Exodus's wedge order is VTK's reversed (test_cli_layers)
          "ParaView's reader on the saved %s with layers: the same cells, every one of them valid (%s)" % (name, got))
write_potential_case(w("layers_case"))
foam = R.check_mesh(w("layers_case"))
shapes = {k: int(n) for k, n in re.findall(r"^\s+(prisms|pyramids|tetrahedra):\s+(\d+)", foam["output"], re.M)}
check(shapes == {"prisms": cells["wedge"], "pyramids": cells["pyramid"], "tetrahedra": cells["tetra"]}
      and sum(foam["patches"].values()) == lb.GetNumberOfCells() and "Cell volumes OK" in foam["output"],
      "checkMesh on the saved OpenFOAM case with layers: cells %s, boundary faces, volumes OK" % shapes)
writer = CreateWriter(w("layers.node"), layered)
writer.UpdatePipeline()
check(writer.GetClientSideObject().GetErrorCode() != 0 and not os.path.exists(w("layers.node")),
      "TetGen with layers: an error (printed above, saying to split the prisms), no file")
del writer

# A directory that does not exist: the writer reports it, no file appears.
writer = CreateWriter(w("missing/mesh.cgns"), mesh)
writer.UpdatePipeline()
check(writer.GetClientSideObject().GetErrorCode() != 0 and not os.path.exists(w("missing")),
      "save into a missing directory: an error (printed above, naming the path), no file")
check(not [f for f in os.listdir(work) if "volgrid-tmp" in f], "no temporary file left behind")
if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
