# pvpython test of the solver hand-off in the ParaView proxies: the wing-in-sphere domain of Surface Prep
# names its patches (the STL as "part0", the generated sphere "farfield"), Tetrahedralize's
# PatchAssignment regroups and renames them (PatchNames field data on both outputs), and VolGrid Quality
# with the Non-orthogonality metric reports checkMesh's figures.
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())

failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def names(data):
    a = data.GetFieldData().GetAbstractArray("PatchNames")
    return [a.GetValue(i) for i in range(a.GetNumberOfValues())] if a else None


wing = STLReader(FileNames=[os.path.join(os.environ["VOLGRID_TEST_DATA_DIR"], "straight_wing.stl")])
domain = VolGridSurfacePrep(Input=[wing], Enclosure="Sphere", EnclosureScale=10.0)
domain.UpdatePipeline()
check(names(servermanager.Fetch(domain)) == ["part0", "farfield"], "Surface Prep names its patches part0, farfield")

mesh = VolGridTetrahedralize(Input=domain, PatchAssignment="wing=0,farfield=1")
mesh.UpdatePipeline()
boundary = servermanager.Fetch(mesh, idx=1)
volume = servermanager.Fetch(mesh, idx=0)
check(names(boundary)[1:] == ["wing", "farfield"], "PatchAssignment renames: %s" % names(boundary))
check(names(volume)[1:] == ["wing", "farfield"], "the tets carry the same PatchNames")
ids = boundary.GetCellData().GetArray("PatchId").GetRange()
check(ids == (1.0, 2.0), "PatchId is 1 (wing) and 2 (farfield): %s" % (ids,))

quality = VolGridQuality(Input=mesh, Metric=11)
quality.UpdatePipeline()
out = servermanager.Fetch(quality)
fd = out.GetFieldData()
check(out.GetCellData().GetArray("NonOrthogonality") is not None, "NonOrthogonality cell array")
check(0 < fd.GetArray("MaxNonOrthogonality").GetValue(0) < 90, "MaxNonOrthogonality in (0, 90)")
check(fd.GetArray("SevereNonOrthogonalFaces").GetValue(0) >= 0, "faces above 70 degrees counted")
check(out.GetCellData().GetArray("Quality").GetRange()[1] == fd.GetArray("MaxNonOrthogonality").GetValue(0),
      "the Quality array is the selected non-orthogonality")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
