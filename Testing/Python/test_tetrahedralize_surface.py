"""pvpython: a wing inside a far-field sphere, through VolGrid Surface Prep and VolGrid Tetrahedralize.

What a CFD user relies on: output port 0 holds positive tetrahedra (Region array) filling exactly the
volume between the wing and the sphere; output port 1 holds exactly the input triangles on the same points,
with PatchId telling the wing from the far field; a surface with a hole is refused with a clear error.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
WING = os.path.join(os.environ["VOLGRID_SHARED_DATA_DIR"], "aero-pypan", "straight_wing.stl")
if not os.path.exists(WING):
    WING = os.path.join(os.environ["VOLGRID_TEST_DATA_DIR"], "straight_wing.stl")

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def det3(a, b, c, d):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def triangles(poly):
    out = []
    for c in range(poly.GetNumberOfCells()):
        cell = poly.GetCell(c)
        out.append(tuple(cell.GetPointId(i) for i in range(cell.GetNumberOfPoints())))
    return out


def shell_volume(points, tris):
    """|signed volume| enclosed by a closed triangle shell (divergence theorem)."""
    origin = (0.0, 0.0, 0.0)
    return abs(sum(det3(origin, points[a], points[b], points[c]) for a, b, c in tris) / 6.0)


wing = STLReader(FileNames=[WING])
prep = VolGridSurfacePrep(Input=[wing])
prep.Enclosure = "Sphere"
prep.EnclosureScale = 5.0
surface = servermanager.Fetch(prep)
surface_points = [surface.GetPoint(i) for i in range(surface.GetNumberOfPoints())]
surface_tris = triangles(surface)
patch_in = surface.GetCellData().GetArray("PatchId")

mesher = VolGridTetrahedralize(Input=prep)
mesher.CheckOutput = 1
mesher.UpdatePipeline()
volume = servermanager.Fetch(mesher, idx=0)
boundary = servermanager.Fetch(mesher, idx=1)

# Port 0: tetrahedra, positive, with Region; input points first and unchanged.
check(volume.GetNumberOfCells() > 1000, f"only {volume.GetNumberOfCells()} tets")
check(volume.GetCellData().GetArray("Region") is not None, "no Region array")
check(volume.GetNumberOfPoints() >= len(surface_points), "input points lost")
for i in range(len(surface_points)):
    if volume.GetPoint(i) != surface_points[i]:
        check(False, f"input point {i} moved or renumbered")
        break
tet_volume, non_positive = 0.0, 0
for c in range(volume.GetNumberOfCells()):
    cell = volume.GetCell(c)
    check(cell.GetCellType() == 10, f"cell {c} is not a tetrahedron")
    v = det3(*[volume.GetPoint(cell.GetPointId(k)) for k in range(4)]) / 6.0
    non_positive += v <= 0
    tet_volume += v
check(non_positive == 0, f"{non_positive} tets with non-positive volume")

# The tets fill exactly the volume between the two shells: sphere volume minus wing volume.
patches = [int(patch_in.GetValue(c)) for c in range(len(surface_tris))] if patch_in else []
check(sorted(set(patches)) == [0, 1], f"Surface Prep PatchIds {sorted(set(patches))}")
wing_tris = [t for t, p in zip(surface_tris, patches) if p == 0]
far_tris = [t for t, p in zip(surface_tris, patches) if p == 1]
expected = shell_volume(surface_points, far_tris) - shell_volume(surface_points, wing_tris)
check(abs(tet_volume - expected) <= 1e-9 * expected, f"tet volume {tet_volume!r} != enclosed {expected!r}")

# Port 1: exactly the input triangles, on the same point ids, with PatchId wing/far field.
out_tris = triangles(boundary)
check(boundary.GetNumberOfPoints() == volume.GetNumberOfPoints(), "boundary not on the mesh points")
check(sorted(tuple(sorted(t)) for t in out_tris) == sorted(tuple(sorted(t)) for t in surface_tris),
      "boundary triangles differ from the input triangles")
patch_out = boundary.GetCellData().GetArray("PatchId")
check(patch_out is not None, "no PatchId on the boundary output")
if patch_out is not None:
    by_triangle = {tuple(sorted(t)): p for t, p in zip(surface_tris, patches)}
    mismatched = sum(by_triangle.get(tuple(sorted(t))) != int(patch_out.GetValue(c)) for c, t in enumerate(out_tris))
    check(mismatched == 0, f"{mismatched} boundary triangles carry the wrong PatchId")

# A wing with a hole (its first triangle removed) is refused with an error naming the defect.
holed = ProgrammableFilter(Input=wing, OutputDataSetType="vtkPolyData")
holed.Script = (
    "from vtkmodules.vtkCommonDataModel import vtkCellArray\n"
    "src = self.GetPolyDataInput(); out = self.GetPolyDataOutput()\n"
    "cells = vtkCellArray()\n"
    "for c in range(1, src.GetNumberOfCells()):\n"
    "    cells.InsertNextCell(src.GetCell(c).GetPointIds())\n"
    "out.SetPoints(src.GetPoints()); out.SetPolys(cells)\n")
check(servermanager.Fetch(holed).GetNumberOfCells() == len(wing_tris) - 1, "could not make the holed wing")
bad = VolGridTetrahedralize(Input=holed)
bad.UpdatePipeline()
check(servermanager.Fetch(bad, idx=0).GetNumberOfCells() == 0, "an open surface was meshed")
check(servermanager.Fetch(bad, idx=1).GetNumberOfCells() == 0, "an open surface gave a boundary output")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("wing in sphere: all checks passed")
