# VolGrid's .vtu/.vtp files against the expat that Debian 12 ships now (2.5.0-1+deb12u5 and later defer
# re-parsing, CVE-2023-52425), which breaks VTK 9.2's reading of raw appended data:
# 1. every XML file the CLI writes (prep, mesh --boundary, delaunay --out) is read back by plain
#    VTK readers (ParaView's own VTK, nothing of VolGrid's), with the counts the CLI reported; the legacy
#    .vtk of the same mesh holds what its .vtu holds;
# 2. raw appended files written by plain VTK (the default of VTK's and ParaView's writers) go through
#    VolGrid's reading path: check, mesh and quality give what they give on VolGrid's own files.
import ctypes
import ctypes.util
import json
import os
import subprocess
import sys
import tempfile

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkCommonDataModel import VTK_TETRA
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader, vtkXMLPolyDataWriter, vtkXMLUnstructuredGridReader,
                                 vtkXMLUnstructuredGridWriter)

CLI = os.environ["VOLGRID_CLI"]
WING = os.path.join(os.environ["VOLGRID_TEST_DATA_DIR"], "straight_wing.stl")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(*args):
    r = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=300)
    return r.returncode, r.stdout, r.stderr


def json_of(*args):
    code, out, err = run(*args)
    check(code == 0, f"volgrid {' '.join(args)} exits 0 (got {code}: {err.strip()})")
    try:
        return json.loads(out.strip().splitlines()[-1])
    except (ValueError, IndexError):
        check(False, f"volgrid {' '.join(args)} prints a JSON line (got {out!r})")
        return {}


def plain_read(path):
    reader = vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def plain_write_raw(data, path):
    writer = vtkXMLUnstructuredGridWriter() if path.endswith(".vtu") else vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    check(writer.Write() == 1, f"plain VTK writes {path}")
    with open(path, "rb") as f:
        check(b'encoding="raw"' in f.read(), f"{path} has raw appended data")


def expat_defers():
    name = ctypes.util.find_library("expat")
    return bool(name) and hasattr(ctypes.CDLL(name), "XML_SetReparseDeferralEnabled")


print("expat with reparse deferral:", expat_defers())
tmp = tempfile.mkdtemp(prefix="volgrid-xml-")
domain = os.path.join(tmp, "domain.vtp")
mesh = os.path.join(tmp, "mesh.vtu")
boundary = os.path.join(tmp, "boundary.vtp")
points = os.path.join(tmp, "points.vtu")

# 1. What VolGrid writes, plain VTK reads.
prep = json_of("prep", WING, domain, "--enclosure", "sphere", "--enclosure-scale", "5", "--json")
meshed = json_of("mesh", domain, mesh, "--boundary", boundary, "--json")
delaunay = json_of("delaunay", "--random", "2000", "--seed", "3", "--out", points, "--json")
for path, cells in ((domain, prep.get("triangles")), (mesh, meshed.get("tets")), (points, delaunay.get("tets"))):
    with open(path, "rb") as f:
        check(b"<AppendedData" not in f.read(), f"{os.path.basename(path)} has no appended data block")
    data = plain_read(path)
    check(data.GetNumberOfCells() == cells and cells,
          f"plain VTK reads {os.path.basename(path)}: {data.GetNumberOfCells()} cells, the CLI said {cells}")
check(plain_read(boundary).GetNumberOfCells() == prep.get("triangles"),
      "plain VTK reads the boundary .vtp with one cell per input triangle")

# 1b. The legacy .vtk of the same run (VolGrid writes its cells itself, not through VTK's copy to 64-bit
# ids): plain VTK's legacy reader gives the .vtu's points, cells, cell arrays and names.
legacy = os.path.join(tmp, "mesh.vtk")
json_of("mesh", domain, legacy, "--json")
reader = vtkUnstructuredGridReader()
reader.SetFileName(legacy)
reader.ReadAllScalarsOn()
reader.ReadAllFieldsOn()
reader.Update()
old_grid, new_grid = plain_read(mesh), reader.GetOutput()
check(new_grid.GetNumberOfCells() == meshed.get("tets"),
      f"plain VTK reads the legacy .vtk: {new_grid.GetNumberOfCells()} cells, the CLI said {meshed.get('tets')}")
same = lambda a, b: a is not None and b is not None and numpy.array_equal(vtk_to_numpy(a), vtk_to_numpy(b))
check(same(old_grid.GetPoints().GetData(), new_grid.GetPoints().GetData()), "the .vtk's points are the .vtu's")
check(same(old_grid.GetCells().GetConnectivityArray(), new_grid.GetCells().GetConnectivityArray()) and
      same(old_grid.GetCells().GetOffsetsArray(), new_grid.GetCells().GetOffsetsArray()),
      "the .vtk's cells are the .vtu's")
check(set(vtk_to_numpy(new_grid.GetCellTypesArray()).tolist()) == {VTK_TETRA}, "the .vtk's cells are tets")
for name in ("Region", "Forced", "BoundaryFacePatch"):
    check(same(old_grid.GetCellData().GetArray(name), new_grid.GetCellData().GetArray(name)),
          f"the .vtk's cell array {name} is the .vtu's")
for name in ("PatchNames", "RegionNames"):
    a, b = old_grid.GetFieldData().GetAbstractArray(name), new_grid.GetFieldData().GetAbstractArray(name)
    check(a is not None and b is not None and
          [a.GetValue(i) for i in range(a.GetNumberOfValues())] == [b.GetValue(i) for i in range(b.GetNumberOfValues())],
          f"the .vtk's field data {name} is the .vtu's")

# 2. Raw appended files from other tools, through VolGrid's readers.
raw_domain = os.path.join(tmp, "raw_domain.vtp")
raw_mesh = os.path.join(tmp, "raw_mesh.vtu")
plain_write_raw(plain_read(domain), raw_domain)
plain_write_raw(plain_read(mesh), raw_mesh)
vtkObject.GlobalWarningDisplayOff()  # plain VTK's parse errors on a deferring expat are expected here
print("plain VTK reads raw appended data:", plain_read(raw_mesh).GetNumberOfCells() == meshed.get("tets"))
vtkObject.GlobalWarningDisplayOn()
code, out, err = run("check", raw_domain)
check(code == 0, f"volgrid check reads a raw appended .vtp and finds it clean (exit {code}: {err.strip()})")
again = json_of("mesh", raw_domain, os.path.join(tmp, "again.vtu"), "--json")
check(again.get("tets") == meshed.get("tets") and again.get("boundary_preserved") is True,
      f"meshing the raw appended .vtp gives the same {meshed.get('tets')} tets (got {again.get('tets')})")
quality = json_of("quality", raw_mesh, "--json")
check(quality.get("cells") == meshed.get("tets"),
      f"volgrid quality reads the raw appended .vtu: {quality.get('cells')} cells, expected {meshed.get('tets')}")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all XML file checks passed")
