# pvpython test of the "VolGrid Quality" filter: arrays on a tet mesh and a surface, the statistics table,
# histogram counts summing to the cell count, the metric selector and the bin-count clamp.
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def fetch(proxy, port):
    return servermanager.Fetch(proxy, idx=port)


# A tet mesh: ParaView's Delaunay3D of 2000 random points in a ball of radius 0.5 (about 13000 tets).
points = PointSource(NumberOfPoints=2000, Radius=0.5)
mesh = Delaunay3D(Input=points)
quality = VolGridQuality(Input=mesh)
quality.BinCount = 12
quality.UpdatePipeline()

grid = fetch(quality, 0)
table = fetch(quality, 1)
cells = grid.GetNumberOfCells()
check(cells > 100, "the Delaunay3D mesh has tets (%d)" % cells)
for name in ["AspectRatio", "MinDihedralAngle", "MaxDihedralAngle", "MinSolidAngle", "Volume",
             "VolumeGradient", "RadiusEdgeRatio", "RadiusRatio", "Quality"]:
    array = grid.GetCellData().GetArray(name)
    check(array is not None and array.GetNumberOfTuples() == cells, "cell array %s" % name)

check(table.GetNumberOfRows() == 12, "one table row per bin (%d)" % table.GetNumberOfRows())
for name in ["AspectRatio", "MinDihedralAngle", "Volume", "VolumeGradient"]:
    counts = table.GetColumnByName(name + "_Count")
    check(counts is not None, "table column %s_Count" % name)
    if counts is not None:
        total = sum(counts.GetValue(i) for i in range(counts.GetNumberOfTuples()))
        check(total == cells, "%s histogram sums to the cell count (%d vs %d)" % (name, total, cells))
    stats = grid.GetFieldData().GetArray(name + "Statistics")
    check(stats is not None and stats.GetNumberOfComponents() == 6, "field data %sStatistics" % name)
    check(table.GetFieldData().GetArray(name + "Statistics") is not None, "table field data %sStatistics" % name)

# Delaunay3D orients its tets positively: all volumes positive.
stats = grid.GetFieldData().GetArray("VolumeStatistics")
check(stats.GetComponent(0, 1) > 0.0, "no inverted tet (min volume %g)" % stats.GetComponent(0, 1))
total_volume = grid.GetFieldData().GetArray("TotalVolume").GetValue(0)
check(0.3 < total_volume < 4.0 / 3.0 * math.pi * 0.125, "total volume of the hull (%g)" % total_volume)

# The metric selector: Quality follows the chosen metric.
quality.Metric = "Aspect Ratio"
quality.UpdatePipeline()
grid = fetch(quality, 0)
q = grid.GetCellData().GetArray("Quality")
a = grid.GetCellData().GetArray("AspectRatio")
check(all(q.GetValue(i) == a.GetValue(i) for i in range(0, cells, 7)), "Quality is AspectRatio")

# Values set from Python are clamped in C++.
quality.BinCount = 0
quality.UpdatePipeline()
check(fetch(quality, 1).GetNumberOfRows() == 1, "BinCount 0 is clamped to 1")

# A closed surface: triangle metrics and the surface-wide figures.
surface = VolGridQuality(Input=Sphere(ThetaResolution=32, PhiResolution=32, Radius=1.0))
surface.UpdatePipeline()
out = fetch(surface, 0)
fd = out.GetFieldData()
for name in ["AspectRatio", "Area", "MinAngle", "MaxAngle", "Quality"]:
    check(out.GetCellData().GetArray(name) is not None, "surface cell array %s" % name)
check(fd.GetArray("Shells").GetValue(0) == 1, "one shell")
check(fd.GetArray("BoundaryLoops").GetValue(0) == 0, "no boundary loop")
volume = fd.GetArray("EnclosedVolume").GetValue(0)
check(abs(volume - 4.0 / 3.0 * math.pi) < 0.05, "enclosed volume of the unit sphere (%g)" % volume)

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("test_quality: all checks passed")
