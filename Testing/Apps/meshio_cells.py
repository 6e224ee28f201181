"""A mesh file read by meshio (not VolGrid's reader), run under the system python3 that has python3-meshio.
Prints one JSON line: cells by meshio type, and per volume type the sum and the min/max of each cell's
signed volume, computed from its outward faces by the divergence theorem (a quad split around its mean
point, so both cells beside it agree). The faces are VTK's (meshio keeps each file's point order), after the
format's own wedge order is mapped to VTK's: Medit's prisms are SolverMesh's (the base's normal towards the
top), VTK's the reverse; SU2's are VTK's. A cell in the wrong order gets a negative volume.
Usage: python3 meshio_cells.py su2|medit FILE"""
import json
import sys

import meshio
import numpy as np

FACES = {  # VTK's outward faces
    "tetra": [(0, 2, 1), (0, 1, 3), (1, 2, 3), (2, 0, 3)],
    "wedge": [(0, 1, 2), (3, 5, 4), (0, 3, 4, 1), (1, 4, 5, 2), (2, 5, 3, 0)],
    "pyramid": [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
}
TO_VTK = {("medit", "wedge"): [0, 2, 1, 3, 5, 4]}


def volumes(points, cells, faces):
    """Signed volumes of all cells of one type at once: sum over triangles of a . (b x c) / 6."""
    v = np.zeros(len(cells))
    for f in faces:
        loop = [points[cells[:, k]] for k in f]
        if len(loop) == 3:
            tris = [loop]
        else:
            m = sum(loop) / 4.0
            tris = [[m, loop[k], loop[(k + 1) % 4]] for k in range(4)]
        for a, b, c in tris:
            v += np.einsum("ij,ij->i", a, np.cross(b, c)) / 6.0
    return v


kind, path = sys.argv[1], sys.argv[2]
mesh = meshio.read(path, file_format=kind)
out = {"cells": {}, "volume": {}, "min": {}, "max": {}, "total_volume": 0.0}
for block in mesh.cells:
    out["cells"][block.type] = out["cells"].get(block.type, 0) + len(block.data)
    if block.type not in FACES:
        continue
    data = block.data[:, TO_VTK[(kind, block.type)]] if (kind, block.type) in TO_VTK else block.data
    v = volumes(mesh.points.astype(float), data, FACES[block.type])
    out["volume"][block.type] = out["volume"].get(block.type, 0.0) + float(v.sum())
    out["min"][block.type] = min(out["min"].get(block.type, float("inf")), float(v.min()))
    out["max"][block.type] = max(out["max"].get(block.type, -float("inf")), float(v.max()))
    out["total_volume"] += float(v.sum())
print(json.dumps(out))
