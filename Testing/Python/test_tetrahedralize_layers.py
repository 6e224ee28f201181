"""pvpython: boundary layers through VolGrid Tetrahedralize's "Boundary layers" properties.

What a viscous-CFD user relies on: a body inside a far-field sphere (made by `volgrid prep`) gets
NumberOfLayers prism layers on the body and none on the far field; output 0 holds VTK_WEDGE cells (LayerIndex
0 at the wall) and VTK_TETRA cells (LayerIndex -1), none with a non-positive volume, and the same cells as
`volgrid mesh --layers` on the same surface; SplitPrisms gives three tets per prism; output 1 holds the input
triangles with PatchId; a missing first height is refused with an error and an empty output.
"""
import json
import os
import subprocess
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
CLI = os.environ["VOLGRID_CLI"]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


work = tempfile.mkdtemp(prefix="volgrid-pv-layers-")
body, domain = os.path.join(work, "body.off"), os.path.join(work, "domain.vtp")
for args in (["--enclosure", "sphere", "--center", "0,0,0", "--dimensions", "1", "--edge-length", "0.2", body],
             [body, domain, "--enclosure", "sphere", "--enclosure-scale", "10"]):
    subprocess.run([CLI, "prep"] + args, check=True, capture_output=True)
LAYERS, FIRST, GROWTH = 5, 0.01, 1.2
cli = subprocess.run([CLI, "mesh", domain, os.path.join(work, "cli.vtu"), "--json", "--layers", str(LAYERS),
                      "--first-height", str(FIRST), "--growth", str(GROWTH)], capture_output=True, text=True)
check(cli.returncode == 0, "volgrid mesh --layers failed: " + cli.stderr)
expected = json.loads(cli.stdout) if cli.returncode == 0 else {}

reader = XMLPolyDataReader(FileName=[domain])
surface = servermanager.Fetch(reader)
mesher = VolGridTetrahedralize(Input=reader)
mesher.NumberOfLayers = LAYERS
mesher.FirstLayerHeight = FIRST
mesher.LayerGrowthRatio = GROWTH
mesher.UpdatePipeline()
volume = servermanager.Fetch(mesher, idx=0)
boundary = servermanager.Fetch(mesher, idx=1)

types = [volume.GetCellType(c) for c in range(volume.GetNumberOfCells())]
wedges, tets = types.count(13), types.count(10)
check(wedges + tets == len(types), "cells other than wedges and tets")
check(wedges == expected.get("wedges") and tets == expected.get("tets"),
      f"filter {wedges} wedges + {tets} tets, CLI {expected.get('wedges')} + {expected.get('tets')}")
check(wedges == LAYERS * expected.get("layered_faces", -1), "not every body face has every layer")
body_faces = expected.get("layered_faces", 0)
check(0 < body_faces < surface.GetNumberOfCells(), f"{body_faces} layered faces of {surface.GetNumberOfCells()}: "
      "the far field must get none")
layer = volume.GetCellData().GetArray("LayerIndex")
check(layer is not None, "no LayerIndex array")
if layer is not None:
    per_layer = [0] * LAYERS
    for c, t in enumerate(types):
        k = int(layer.GetValue(c))
        if t == 13 and 0 <= k < LAYERS:
            per_layer[k] += 1
        elif t == 10:
            check(k == -1, f"tet {c} has LayerIndex {k}")
    check(per_layer == [body_faces] * LAYERS, f"wedges per layer {per_layer}")

sizes = CellSize(Input=mesher)
sizes.ComputeVolume = 1
sizes.ComputeArea = sizes.ComputeLength = sizes.ComputeVertexCount = 0
sized = servermanager.Fetch(sizes)
vol = sized.GetCellData().GetArray("Volume")
non_positive = sum(vol.GetValue(c) <= 0 for c in range(vol.GetNumberOfTuples()))
check(non_positive == 0, f"{non_positive} cells with a non-positive volume")
first_layer = [vol.GetValue(c) for c, t in enumerate(types) if t == 13 and int(layer.GetValue(c)) == 0]
second_layer = [vol.GetValue(c) for c, t in enumerate(types) if t == 13 and int(layer.GetValue(c)) == 1]
check(first_layer and second_layer and 1.1 < sum(second_layer) / sum(first_layer) < 1.3,
      "the second layer is not about GROWTH times the first")

check(boundary.GetNumberOfCells() == surface.GetNumberOfCells(), "the boundary is not the input triangles")
check(boundary.GetCellData().GetArray("PatchId") is not None, "no PatchId on the boundary")

# TotalLayerThickness with a first height: the growth ratio is solved for (1.5 here, not LayerGrowthRatio's 1.2).
mesher.TotalLayerThickness = FIRST * (1.5 ** LAYERS - 1) / 0.5
mesher.UpdatePipeline()
thick = servermanager.Fetch(CellSize(Input=mesher, ComputeArea=0, ComputeLength=0, ComputeVertexCount=0))
thick_types = [thick.GetCellType(c) for c in range(thick.GetNumberOfCells())]
thick_layer = thick.GetCellData().GetArray("LayerIndex")
thick_vol = thick.GetCellData().GetArray("Volume")
per_layer = [sum(thick_vol.GetValue(c) for c, t in enumerate(thick_types) if t == 13 and int(thick_layer.GetValue(c)) == k)
             for k in range(2)]
check(per_layer[0] > 0 and 1.4 < per_layer[1] / per_layer[0] < 1.6,
      f"TotalLayerThickness: layer volumes {per_layer}, not a ratio of about 1.5")
mesher.TotalLayerThickness = 0

mesher.SplitPrisms = 1
mesher.UpdatePipeline()
split = servermanager.Fetch(mesher, idx=0)
split_types = [split.GetCellType(c) for c in range(split.GetNumberOfCells())]
check(split_types.count(13) == 0 and split_types.count(10) == 3 * wedges + tets,
      f"SplitPrisms: {split_types.count(10)} tets, expected {3 * wedges + tets}")

mesher.SplitPrisms = 0
mesher.FirstLayerHeight = -1.0  # clamped to 0: no first height, refused
mesher.UpdatePipeline()
check(servermanager.Fetch(mesher, idx=0).GetNumberOfCells() == 0, "layers without a first height were meshed")



def fanned_box_off(path):
    """A box whose top is a fan from one corner (its long triangles meet the side fans at wall edges that
    checkMesh would find skewed, as a wing's root fan meets its leading edge), outward, as OFF."""
    pts, tris = [], []
    add = lambda x, y, z: pts.append((x, y, z)) or len(pts) - 1
    x1 = [add(1, k / 8, 1) for k in range(17)]
    y2 = [add(k / 8, 2, 1) for k in range(7, -1, -1)]
    o, x, xy, y, top = add(0, 0, 0), add(1, 0, 0), add(1, 2, 0), add(0, 2, 0), add(0, 0, 1)
    fan = lambda hub, rim: tris.extend((hub, rim[k], rim[k + 1]) for k in range(len(rim) - 1))
    fan(top, x1 + y2)
    fan(x, x1 + [xy])
    fan(y, [xy, x1[-1]] + y2)
    fan(o, [x, xy, y])
    fan(o, [x, x1[0], top])
    fan(o, [top, y2[-1], y])
    out = []
    for a, b, c in tris:
        u = [pts[b][k] - pts[a][k] for k in range(3)]
        w = [pts[c][k] - pts[a][k] for k in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        d = (pts[a][0] - 0.5, pts[a][1] - 1.0, pts[a][2] - 0.5)
        out.append((a, b, c) if sum(n[k] * d[k] for k in range(3)) > 0 else (a, c, b))
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(out)))
        f.writelines("%r %r %r\n" % p for p in pts)
        f.writelines("3 %d %d %d\n" % t for t in out)
    return len(out)


# KeepWallTriangles: by default the wall triangles beside skewed edges are split first (as the CLI does);
# kept, the wall is the input's.
box, box_domain = os.path.join(work, "box.off"), os.path.join(work, "box_domain.vtp")
box_triangles = fanned_box_off(box)
subprocess.run([CLI, "prep", box, box_domain, "--enclosure", "sphere", "--enclosure-scale", "10"], check=True,
               capture_output=True)
box_cli = subprocess.run([CLI, "mesh", box_domain, os.path.join(work, "box.vtu"), "--json", "--layers", "3",
                          "--first-height", "1e-3"], capture_output=True, text=True)
box_json = json.loads(box_cli.stdout) if box_cli.returncode == 0 else {}
check(box_json.get("wall_split_edges", 0) > 0 and box_json.get("wall_skew_edges") == 0,
      f"the fanned box's skewed wall edges are not split by the CLI: {box_json} {box_cli.stderr}")
box_mesher = VolGridTetrahedralize(Input=XMLPolyDataReader(FileName=[box_domain]), NumberOfLayers=3,
                                   FirstLayerHeight=1e-3)
wedge_counts = []
for keep in (0, 1):
    box_mesher.KeepWallTriangles = keep
    box_mesher.UpdatePipeline()
    out = servermanager.Fetch(box_mesher, idx=0)
    wedge_counts.append(sum(out.GetCellType(c) == 13 for c in range(out.GetNumberOfCells())))
check(wedge_counts[0] == box_json.get("wedges") and wedge_counts[1] == 3 * box_triangles,
      f"KeepWallTriangles 0 and 1: {wedge_counts} wedges, expected the CLI's {box_json.get('wedges')} and "
      f"3 * {box_triangles}")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("layers: all checks passed")
