"""Readers VolGrid did not write, on a mixed (prism + tet) mesh, run under pvpython: ParaView's .vtu, CGNS and
Exodus II readers (vtkXMLUnstructuredGridReader, vtkCGNSReader, vtkExodusIIReader), and for SU2 (no reader here) the file's element lines
taken as the VTK cell types they name. Prints one JSON line: cells by type ("tets", "wedges", "pyramids", "other") and
their signed volumes by vtkCellSizeFilter (VTK's wedge: the first triangle's normal points away from the
second, as vtkCellTypeSource makes them; VTK's pyramid: the base's normal towards the apex): "tet_volume",
"wedge_volume", "pyramid_volume", "tet_min_max", "wedge_min_max", "pyramid_min_max".
Usage: pvpython mixed_mesh_readers.py vtu|cgns|exodus|su2 FILE"""
import json
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
from vtkmodules.vtkIOCGNSReader import vtkCGNSReader
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def vtu(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return [r.GetOutput()]


def leaves(tree):
    """The leaf data sets of a multiblock reader's output."""
    it = tree.NewTreeIterator()
    it.VisitOnlyLeavesOn()
    it.InitTraversal()
    grids = []
    while not it.IsDoneWithTraversal():
        grids.append(it.GetCurrentDataObject())
        it.GoToNextItem()
    return grids


def cgns(path):
    """The zone's cells: every leaf block (boundary patches are not loaded)."""
    r = vtkCGNSReader()
    r.SetFileName(path)
    r.UpdateInformation()
    r.EnableAllBases()
    r.Update()
    return leaves(r.GetOutput())


def exodus(path):
    """Every element block (side sets off)."""
    r = vtkExodusIIReader()
    r.SetFileName(path)
    r.UpdateInformation()
    for k in range(r.GetNumberOfObjects(vtkExodusIIReader.ELEM_BLOCK)):
        r.SetObjectStatus(vtkExodusIIReader.ELEM_BLOCK, k, 1)
    r.Update()
    return leaves(r.GetOutput())


def su2(path):
    """NELEM lines "TYPE ids... index" as VTK cells, NPOIN lines "x y z index" as points."""
    lines = open(path).read().split("\n")
    grid, points = vtkUnstructuredGrid(), vtkPoints()
    points.SetDataTypeToDouble()
    cells, k = [], 0
    while k < len(lines):
        if lines[k].startswith("NELEM="):
            cells = [[int(x) for x in lines[k + 1 + e].split()] for e in range(int(lines[k].split("=")[1]))]
            k += len(cells)
        elif lines[k].startswith("NPOIN="):
            for i in range(int(lines[k].split("=")[1].split()[0])):
                points.InsertNextPoint(*[float(x) for x in lines[k + 1 + i].split()[:3]])
            break
        k += 1
    grid.SetPoints(points)
    for c in cells:
        grid.InsertNextCell(c[0], len(c) - 2, c[1:-1])
    return [grid]


grids = {"vtu": vtu, "cgns": cgns, "exodus": exodus, "su2": su2}[sys.argv[1]](sys.argv[2])
NAMES = {10: "tet", 13: "wedge", 14: "pyramid"}
out = {"tets": 0, "wedges": 0, "pyramids": 0, "other": 0, "tet_volume": 0.0, "wedge_volume": 0.0, "pyramid_volume": 0.0}
bounds = {t: [float("inf"), -float("inf")] for t in NAMES}
for g in grids:
    size = vtkCellSizeFilter()
    size.SetInputData(g)
    size.Update()
    v = size.GetOutput().GetCellData().GetArray("Volume")
    for c in range(g.GetNumberOfCells()):
        t, x = g.GetCellType(c), v.GetValue(c)
        out[NAMES[t] + "s" if t in NAMES else "other"] += 1
        if t in bounds:
            out[NAMES[t] + "_volume"] += x
            bounds[t] = [min(bounds[t][0], x), max(bounds[t][1], x)]
for t, name in NAMES.items():
    out[name + "_min_max"] = bounds[t]
print(json.dumps(out))
