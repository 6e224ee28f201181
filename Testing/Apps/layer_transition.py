#!/usr/bin/env python3
"""The size step between the last prism layer and the tets, recomputed from a Medit file read by meshio
(not by VolGrid): for every tet face that is a prism's top face, the tet's height over it divided by the
prism's height (the mean distance of its base corners from the top face's plane). Prints one JSON line:
faces, median, p90, max (quantiles as index round(q (n - 1)) of the sorted ratios).

Usage: /usr/bin/python3 layer_transition.py MESH.mesh"""
import json
import sys

import meshio
import numpy as np


def heights(points, tri, apex):
    """Distances of the points `apex` (n x 3) from the planes of the triangles `tri` (n x 3 x 3)."""
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None]
    return np.abs(np.einsum("ij,ij->i", apex - tri[:, 0], n))


def main(path):
    m = meshio.read(path)
    p = m.points.astype(float)
    tets, wedges = m.get_cells_type("tetra"), m.get_cells_type("wedge")
    tops = {tuple(sorted(w[3:])): i for i, w in enumerate(wedges)}
    tet_face, layer_face = [], []
    for t in tets:
        for i in range(4):
            face = tuple(sorted(t[j] for j in range(4) if j != i))
            w = tops.get(face)
            if w is not None:
                tet_face.append((face, t[i]))
                layer_face.append(w)
    tri = np.array([[p[v] for v in f] for f, _ in tet_face])
    tet_h = heights(p, tri, np.array([p[a] for _, a in tet_face]))
    w = wedges[np.array(layer_face)]
    top = p[w[:, 3:]]
    layer_h = sum(heights(p, top, p[w[:, k]]) for k in range(3)) / 3
    ratios = np.sort(tet_h / layer_h)
    q = lambda f: float(ratios[min(len(ratios) - 1, int(f * (len(ratios) - 1) + 0.5))])
    print(json.dumps({"faces": len(ratios), "median": q(0.5), "p90": q(0.9), "max": float(ratios[-1])}))


if __name__ == "__main__":
    main(sys.argv[1])
