"""pvbatch (one process or `mpiexec -np N pvbatch --mpi`): the wing pipeline of a ParaView user, with the
figures a user compares, printed as one JSON line by rank 0.

  surface reader -> [RedistributeDataSet] -> VolGrid Surface Prep [sphere] -> VolGrid Tetrahedralize
                 -> VolGrid Quality, Slice, Clip, a .pvtu save read back

usage: pvbatch [--mpi] mpi_pipeline.py SURFACE OUTDIR [--enclosure Sphere|None] [--spread] [--empty]
"""
import json
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

args = sys.argv[1:]
surface_file, outdir = args[0], args[1]
enclosure = args[args.index("--enclosure") + 1] if "--enclosure" in args else "Sphere"
LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()

reader = OpenDataFile(surface_file)
source = reader
if "--empty" in args:  # a connected input without a single cell, on every rank
    source = Clip(Input=reader, ClipType="Plane", Crinkleclip=1)
    source.ClipType.Origin = [1e30, 0, 0]
    source.Invert = 0
if "--spread" in args:  # the surface spread over the ranks before meshing
    # D3, not RedistributeDataSet: the latter exchanges data as raw appended XML, which Debian 12's ParaView
    # 5.11 cannot read back (see README), and loses pieces.
    source = D3(Input=source, BoundaryMode="Assign cells uniquely")
prep = VolGridSurfacePrep(Input=[source], Enclosure=enclosure, EnclosureScale=5.0)
mesh = VolGridTetrahedralize(Input=prep)
quality = VolGridQuality(Input=mesh)
quality.UpdatePipeline()


def cells(proxy, port=0):
    proxy.UpdatePipeline()
    return proxy.GetDataInformation(port).GetNumberOfCells()


figures = {"ranks": ranks, "prep_triangles": cells(prep), "tets": cells(mesh),
           "boundary_faces": cells(mesh, 1)}
volume = IntegrateVariables(Input=mesh)
volume.DivideCellDataByVolume = 0
v = servermanager.Fetch(volume)
volume_array = v.GetCellData().GetArray("Volume")
figures["volume"] = volume_array.GetValue(0) if volume_array and v.GetNumberOfCells() else 0.0
table = servermanager.Fetch(quality, idx=1)
figures["quality_table"] = {
    table.GetColumnName(c): [table.GetValue(r, c).ToDouble() for r in range(table.GetNumberOfRows())]
    for c in range(table.GetNumberOfColumns())}
boundary_quality = VolGridQuality(Input=OutputPort(mesh, 1))  # the Boundary lives on rank 0 only
boundary_quality.UpdatePipeline()
figures["boundary_quality_rows"] = servermanager.Fetch(boundary_quality, idx=1).GetNumberOfRows()
stats = table.GetFieldData().GetArray("MinDihedralAngleStatistics")
figures["min_dihedral_statistics"] = list(stats.GetTuple(0)) if stats else None
if figures["tets"]:
    bounds = mesh.GetDataInformation().GetBounds()
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    slice_ = Slice(Input=quality, SliceType="Plane")
    slice_.SliceType.Origin = centre
    slice_.SliceType.Normal = [0, 0, 1]
    clip = Clip(Input=quality, ClipType="Plane", Crinkleclip=1)
    clip.ClipType.Origin = centre
    clip.ClipType.Normal = [0, 1, 0]
    figures["slice_cells"] = cells(slice_)
    figures["crinkle_clip_cells"] = cells(clip)
    pvtu = os.path.join(outdir, "mesh.pvtu")
    # Data Mode Binary: Debian 12's ParaView 5.11 (with its updated expat) cannot read back the raw appended
    # data that Save Data writes by default (see README).
    SaveData(pvtu, proxy=quality, DataMode="Binary")
    back = XMLPartitionedUnstructuredGridReader(FileName=[pvtu])
    figures["pvtu_cells"] = cells(back)
    pieces = [f for f in os.listdir(os.path.join(outdir, "mesh")) if f.endswith(".vtu")] \
        if os.path.isdir(os.path.join(outdir, "mesh")) else []
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    piece_cells = []
    for name in sorted(pieces):
        r = vtkXMLUnstructuredGridReader()
        r.SetFileName(os.path.join(outdir, "mesh", name))
        r.Update()
        piece_cells.append(r.GetOutput().GetNumberOfCells())
    figures["pvtu_piece_cells"] = piece_cells
print("VOLGRID_FIGURES " + json.dumps(figures))
