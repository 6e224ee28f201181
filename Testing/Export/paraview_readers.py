"""ParaView's own readers of CGNS (vtkCGNSReader) and Exodus II (vtkExodusIIReader) on a solver file, run
under pvpython: prints one JSON line {"points", "tets", "patches": {name: faces}} as the reader saw them.
Usage: pvpython paraview_readers.py cgns|exodus FILE"""
import json
import sys

from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
from vtkmodules.vtkIOCGNSReader import vtkCGNSReader
from vtkmodules.vtkIOExodus import vtkExodusIIReader


def leaves(data):
    it = data.NewTreeIterator()
    it.VisitOnlyLeavesOn()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        yield it.GetCurrentMetaData().Get(vtkCompositeDataSet.NAME()), it.GetCurrentDataObject()
        it.GoToNextItem()


def cgns(path):
    """The zone's cells (block "Internal") and one block per boundary condition (LoadBndPatch)."""
    r = vtkCGNSReader()
    r.SetFileName(path)
    r.UpdateInformation()
    r.EnableAllBases()
    r.SetLoadBndPatch(1)
    r.Update()
    points, tets, patches = 0, 0, {}
    for name, block in leaves(r.GetOutput()):
        if name == "Internal":
            points, tets = block.GetNumberOfPoints(), block.GetNumberOfCells()
        else:
            patches[name] = block.GetNumberOfCells()
    return points, tets, patches


def exodus(path):
    """Every element block and side set switched on; side sets come back as blocks of faces."""
    r = vtkExodusIIReader()
    r.SetFileName(path)
    r.UpdateInformation()
    kinds = (vtkExodusIIReader.ELEM_BLOCK, vtkExodusIIReader.SIDE_SET)
    names = {}
    for kind in kinds:
        for k in range(r.GetNumberOfObjects(kind)):
            r.SetObjectStatus(kind, k, 1)
            names[r.GetObjectName(kind, k)] = kind
    r.Update()
    tets, patches = 0, {}
    for name, block in leaves(r.GetOutput()):
        if names.get(name) == vtkExodusIIReader.ELEM_BLOCK:
            tets += block.GetNumberOfCells()
        else:
            patches[name] = block.GetNumberOfCells()
    return r.GetNumberOfNodes(), tets, patches


if __name__ == "__main__":
    points, tets, patches = {"cgns": cgns, "exodus": exodus}[sys.argv[1]](sys.argv[2])
    print(json.dumps({"points": points, "tets": tets, "patches": patches}))
