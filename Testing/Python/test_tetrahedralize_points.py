"""pvpython: the VolGrid plugin loads and VolGrid Tetrahedralize meshes point clouds correctly.

What a user relies on: every output cell is a positive tetrahedron, the tets fill the convex hull
exactly (volume), they form a triangulated ball (Euler characteristic 1), duplicates are merged with a
map back to the input, point data passes through, and bad input yields an error and an empty output.
"""
import os
import random
import sys

from paraview.simple import LoadPlugin, ProgrammableSource, PointSource
from paraview import servermanager

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())

from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellTypes

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def tet_volume(p):
    a, b, c, d = p
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0


def mesh_of(script_points):
    """Runs VolGrid Tetrahedralize on a ProgrammableSource emitting the given points; returns the grid."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray\n"
        "pts = vtkPoints(); pts.SetDataTypeToDouble()\n"
        "data = vtkDoubleArray(); data.SetName('Temperature')\n"
        f"for i, p in enumerate({script_points!r}):\n"
        "    pts.InsertNextPoint(p); data.InsertNextValue(float(i))\n"
        "out = self.GetPolyDataOutput(); out.SetPoints(pts); out.GetPointData().AddArray(data)\n")
    tet = VolGridTetrahedralize(Input=source)
    tet.CheckOutput = 1
    tet.UpdatePipeline()
    return servermanager.Fetch(tet)


def analyse(grid):
    tets = []
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        check(cell.GetCellType() == 10, f"cell {c} is not a tetrahedron")
        ids = [cell.GetPointId(i) for i in range(4)]
        tets.append(ids)
    volumes = [tet_volume([grid.GetPoint(i) for i in ids]) for ids in tets]
    edges, faces = set(), set()
    for ids in tets:
        for i in range(4):
            for j in range(i + 1, 4):
                edges.add(tuple(sorted((ids[i], ids[j]))))
            faces.add(tuple(sorted(ids[:i] + ids[i + 1:])))
    used = {i for ids in tets for i in ids}
    euler = len(used) - len(edges) + len(faces) - len(tets)
    return tets, volumes, euler


# 1) A 6x6x6 regular grid (every cube cospherical) plus random interior points: the hull is the unit cube.
random.seed(3)
grid_points = [(i / 5.0, j / 5.0, k / 5.0) for i in range(6) for j in range(6) for k in range(6)]
interior = [(random.random(), random.random(), random.random()) for _ in range(300)]
points = grid_points + interior
mesh = mesh_of(points)
tets, volumes, euler = analyse(mesh)
check(len(tets) > 0, "no tetrahedra for a valid point cloud")
check(min(volumes) > 0, f"non-positive tet volume {min(volumes)}")
check(abs(sum(volumes) - 1.0) < 1e-12, f"tets do not fill the unit cube: volume {sum(volumes)!r}")
check(euler == 1, f"Euler characteristic {euler}, expected 1 for a ball")
check(mesh.GetNumberOfPoints() == len(points), "points were dropped or added")
check(mesh.GetPointData().GetArray("Temperature") is not None, "point data not passed through")

# 2) Duplicates: every point twice. They merge, and InputPointId maps output points to input points.
doubled = points[:100] + points[:100]
mesh = mesh_of(doubled)
ids = mesh.GetPointData().GetArray("InputPointId")
check(ids is not None, "no InputPointId array")
if ids is not None:
    check(mesh.GetNumberOfPoints() == 100, f"{mesh.GetNumberOfPoints()} points kept, 100 expected")
    for i in range(mesh.GetNumberOfPoints()):
        check(mesh.GetPoint(i) == tuple(doubled[int(ids.GetValue(i))]), f"InputPointId wrong at {i}")

# 3) All points on one plane: an error and an empty output, not a crash.
flat = [(random.random(), random.random(), 0.5) for _ in range(50)]
mesh = mesh_of(flat)
check(mesh.GetNumberOfCells() == 0, "coplanar input should give an empty output")

# 4) The filter accepts any vtkPointSet from ParaView's own sources.
src = PointSource(NumberOfPoints=2000, Radius=1.0)
tet = VolGridTetrahedralize(Input=src)
tet.UpdatePipeline()
check(servermanager.Fetch(tet).GetNumberOfCells() > 2000 * 5, "PointSource cloud badly tetrahedralized")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all pvpython tetrahedralize checks passed")
