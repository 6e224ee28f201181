# pvpython test of "VolGrid Surface Prep" and "VolGrid Enclosure": straight_wing.stl (ParaView's STL
# reader) inside a sphere enclosure comes out closed with two PatchIds and a summary table; the enclosure
# source; values set from Python are clamped; and the CLI's `volgrid check` / `volgrid prep` exit codes
# and JSON lines.
import json
import os
import subprocess
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
DATA = os.environ["VOLGRID_SHARED_DATA_DIR"]
CLI = os.environ["VOLGRID_CLI"]
WING = os.path.join(os.environ["VOLGRID_TEST_DATA_DIR"], "straight_wing.stl")  # the corpus file, bundled

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def fetch(proxy, port=0):
    return servermanager.Fetch(proxy, idx=port)


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    return array.GetValue(0) if array is not None else None


def boundary_edges(proxy):
    edges = FeatureEdges(Input=proxy, BoundaryEdges=1, FeatureEdges=0, NonManifoldEdges=0, ManifoldEdges=0)
    return fetch(edges).GetNumberOfCells()


def non_manifold_edges(proxy):
    edges = FeatureEdges(Input=proxy, BoundaryEdges=0, FeatureEdges=0, NonManifoldEdges=1, ManifoldEdges=0)
    return fetch(edges).GetNumberOfCells()


# ----- the wing inside a sphere enclosure -----
wing = STLReader(FileNames=[WING])
prep = VolGridSurfacePrep(Input=[wing])
prep.Enclosure = "Sphere"
prep.EnclosureScale = 10.0
prep.UpdatePipeline()
surface = fetch(prep, 0)
wing_cells = fetch(wing).GetNumberOfCells()
check(surface.GetNumberOfCells() > wing_cells, "the enclosure adds triangles (%d)" % surface.GetNumberOfCells())
check(boundary_edges(prep) == 0, "closed: no boundary edge (vtkFeatureEdges)")
check(non_manifold_edges(prep) == 0, "manifold: no non-manifold edge (vtkFeatureEdges)")
patch = surface.GetCellData().GetArray("PatchId")
check(patch is not None, "PatchId cell array")
if patch is not None:
    values = set(int(patch.GetValue(i)) for i in range(patch.GetNumberOfTuples()))
    check(values == {0, 1}, "two PatchId values, wing 0 and enclosure 1 (%s)" % sorted(values))
    wing_patch = sum(1 for i in range(patch.GetNumberOfTuples()) if patch.GetValue(i) == 0)
    check(wing_patch == wing_cells, "the wing keeps its %d triangles (%d)" % (wing_cells, wing_patch))
check(surface.GetCellData().GetArray("ShellId") is not None, "cell array ShellId")
check(surface.GetCellData().GetScalars() is not None and surface.GetCellData().GetScalars().GetName() == "PatchId",
      "coloured by PatchId")
for name in ["DefectFlags", "OpenEdge", "NonManifoldEdge", "SelfIntersecting", "Degenerate"]:
    check(surface.GetCellData().GetArray(name) is None, "no diagnostic cell array %s unless asked" % name)
check(surface.GetPointData().GetArray("NonManifoldVertex") is None, "no NonManifoldVertex unless asked")
prep.DiagnosticArrays = 1
diagnosed = fetch(prep, 0)
for name in ["DefectFlags", "OpenEdge", "NonManifoldEdge", "SelfIntersecting", "Degenerate", "ShellId"]:
    check(diagnosed.GetCellData().GetArray(name) is not None, "cell array %s on request" % name)
prep.DiagnosticArrays = 0
check(field(surface, "Meshable") == 1, "meshable")
check(field(surface, "Shells") == 2, "two shells (%s)" % field(surface, "Shells"))
check(field(surface, "InwardShells") == 1, "the wing faces away from the domain (inward shells %s)"
      % field(surface, "InwardShells"))
check(field(surface, "MisorientedShells") == 0, "no misoriented shell")
check(field(surface, "EnclosurePatchId") == 1, "EnclosurePatchId 1")
check(surface.GetFieldData().GetAbstractArray("SurfacePrepReport") is not None, "report text in the field data")

table = fetch(prep, 1)
check(table is not None and table.IsA("vtkTable"), "the summary output is a table")
if table is not None and table.IsA("vtkTable"):
    check(table.GetNumberOfRows() > 10, "summary rows (%d)" % table.GetNumberOfRows())
    for column in ["Category", "Item", "Input", "Output", "FirstIds"]:
        check(table.GetColumnByName(column) is not None, "summary column %s" % column)
    items = table.GetColumnByName("Item")
    names = [items.GetValue(i) for i in range(items.GetNumberOfValues())] if items else []
    check("Self-intersecting pairs" in names and "Open edges" in names, "summary defect rows")
    inputs = table.GetColumnByName("Input")
    parts_row = names.index("Parts") if "Parts" in names else -1
    check(inputs is not None and parts_row >= 0 and inputs.GetValue(parts_row) == "not computed",
          "a count that was not measured says so in words, not -1")
edges = fetch(prep, 2)
check(edges.GetNumberOfCells() == 0, "no defective edge (%d)" % edges.GetNumberOfCells())

# Values set from Python are clamped in C++.
prep.EnclosureScale = 0.5
prep.UpdatePipeline()
check(boundary_edges(prep) == 0, "scale 0.5 clamped to 1: still closed")

# ----- two parts -----
two = VolGridSurfacePrep(Input=[wing, Sphere(Center=[0.0, 5.0, 0.0], Radius=0.3)])
two.UpdatePipeline()
parts = fetch(two)
patch = parts.GetCellData().GetArray("PatchId")
check(patch is not None and patch.GetRange() == (0.0, 1.0), "two inputs: PatchIds 0 and 1")
check(field(parts, "Parts") == 2, "two parts")

# ----- the enclosure source -----
enclosure = VolGridEnclosure(Enclosure="Cylinder", Center=[0, 0, 0], Dimensions=[1.0, 4.0, 1.0], EdgeLength=0.2)
enclosure.UpdatePipeline()
cylinder = fetch(enclosure)
check(cylinder.GetNumberOfCells() > 100, "the enclosure source makes a cylinder (%d triangles)" % cylinder.GetNumberOfCells())
check(boundary_edges(enclosure) == 0, "the cylinder is closed")
check(field(cylinder, "Meshable") == 1 and field(cylinder, "InwardShells") == 0, "the cylinder is meshable and outward")

# ----- the CLI -----
def run(*args):
    result = subprocess.run([CLI] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True, timeout=300)
    return result.returncode, result.stdout, result.stderr


code, out, err = run("check", WING, "--json")
check(code == 0, "volgrid check on the closed wing exits 0 (%d: %s)" % (code, err))
try:
    report = json.loads(out.strip().splitlines()[-1])
    check(report["boundary_edges"] == 0 and report["triangles"] == wing_cells and report["clean"],
          "volgrid check JSON of the wing: %s" % out.strip())
except (ValueError, IndexError, KeyError) as e:
    check(False, "volgrid check --json prints one JSON line (%s): %r" % (e, out))

bunny = os.path.join(DATA, "common-3d-test-models", "stanford-bunny.obj")
if not os.path.isfile(bunny):
    print("corpus file missing, open-surface check not run:", bunny)
else:
    code, out, err = run("check", bunny, "--json")
    check(code == 1, "volgrid check on the open bunny exits 1 (%d)" % code)
    try:
        report = json.loads(out.strip().splitlines()[-1])
        check(report["boundary_edges"] == 223 and report["boundary_loops"] == 5,
              "bunny: 223 open edges in 5 loops")
    except (ValueError, IndexError, KeyError) as e:
        check(False, "volgrid check --json on the bunny (%s): %r" % (e, out))

code, out, err = run("check")
check(code == 2, "volgrid check without a file exits 2 (%d)" % code)

with tempfile.TemporaryDirectory() as tmp:
    target = os.path.join(tmp, "wing_sphere.vtp")
    code, out, err = run("prep", WING, target, "--enclosure", "sphere", "--enclosure-scale", "10", "--json")
    check(code == 0, "volgrid prep wing + sphere exits 0 (%d: %s)" % (code, err))
    try:
        report = json.loads(out.strip().splitlines()[-1])
        check(report["boundary_edges"] == 0 and report["shells"] == 2 and report["meshable"],
              "volgrid prep JSON: %s" % out.strip())
    except (ValueError, IndexError, KeyError) as e:
        check(False, "volgrid prep --json prints one JSON line (%s): %r" % (e, out))
    check(os.path.exists(target), "volgrid prep wrote %s" % target)
    if os.path.exists(target):
        written = XMLPolyDataReader(FileName=[target])
        written.UpdatePipeline()
        data = fetch(written)
        check(data.GetCellData().GetArray("PatchId") is not None, "the written file has PatchId")
        check(boundary_edges(written) == 0, "the written file is closed")

    if os.path.isfile(bunny):
        closed_bunny = os.path.join(tmp, "bunny.off")
        code, out, err = run("prep", bunny, closed_bunny, "--json")
        check(code == 0, "volgrid prep closes the bunny (%d: %s)" % (code, err))
        code, out, err = run("check", closed_bunny, "--json")
        check(code == 0, "the prepared bunny checks clean (%d: %s)" % (code, out))

    code, out, err = run("prep", WING, os.path.join(tmp, "x.vtp"), "--enclosure", "torus")
    check(code == 2, "volgrid prep with a bad enclosure exits 2 (%d)" % code)

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("test_surface_prep: all checks passed")
