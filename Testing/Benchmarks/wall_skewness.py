#!/usr/bin/env python3
"""OpenFOAM's face skewness of the prism side faces a wall triangulation implies, before any marching.

A prism layer extruded from wall triangles has side faces whose skewness (primitiveMeshTools::faceSkewness:
distance from the face centre to where the cell-centre line crosses the face, over the face's extent in that
direction, at least 0.2 |d|) equals, in the limit of thin layers, the in-surface skewness of the wall edge
between the two triangles. So a wall edge above 4 makes checkMesh fail in every layer whatever the marching.
Usage: wall_skewness.py MESH.mesh PATCH[,PATCH...] [--top N]
"""
import math
import sys


def read_medit(path):
    f = open(path).read().split()
    i = f.index("Vertices")
    n = int(f[i + 1])
    points = [tuple(map(float, f[i + 2 + 4 * k:i + 5 + 4 * k])) for k in range(n)]
    i = f.index("Triangles")
    m = int(f[i + 1])
    triangles = [tuple(map(int, f[i + 2 + 4 * k:i + 6 + 4 * k])) for k in range(m)]
    return points, triangles


def sub(u, v):
    return [u[0] - v[0], u[1] - v[1], u[2] - v[2]]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def norm(u):
    return math.sqrt(dot(u, u))


def edge_skewness(points, walls):
    centres = [[sum(points[v][d] for v in t) / 3 for d in range(3)] for t in walls]
    edges = {}
    for t, tri in enumerate(walls):
        for a in range(3):
            edges.setdefault(tuple(sorted((tri[a], tri[(a + 1) % 3]))), []).append(t)
    out = []
    for e, ts in edges.items():
        if len(ts) != 2:
            continue
        a, b = points[e[0]], points[e[1]]
        fc = [(a[k] + b[k]) / 2 for k in range(3)]
        d = sub(centres[ts[1]], centres[ts[0]])
        cpf = sub(fc, centres[ts[0]])
        ev = sub(b, a)
        length = norm(ev)
        ev = [x / length for x in ev]
        # The side face's normal: across the edge, in the plane of the edge and the centre line.
        n = [d[k] - dot(d, ev) * ev[k] for k in range(3)]
        nn = norm(n)
        if nn == 0 or length == 0:
            continue
        n = [x / nn for x in n]
        s = dot(n, cpf) / dot(n, d)
        sv = [cpf[k] - s * d[k] for k in range(3)]
        svn = norm(sv)
        svh = [x / (svn + 1e-300) for x in sv]
        fd = max(0.2 * norm(d), abs(dot(svh, sub(a, fc))))
        out.append((svn / fd, length, fc))
    out.sort(key=lambda r: -r[0])
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    points, triangles = read_medit(sys.argv[1])
    patches = set(int(p) for p in sys.argv[2].split(","))
    top = int(sys.argv[sys.argv.index("--top") + 1]) if "--top" in sys.argv else 5
    walls = [(a - 1, b - 1, c - 1) for a, b, c, p in triangles if p in patches]
    res = edge_skewness(points, walls)
    print("%d wall triangles, %d interior edges, %d with skewness > 4" % (len(walls), len(res),
                                                                          sum(1 for r in res if r[0] > 4)))
    for s, length, fc in res[:top]:
        print("skewness %.4f  edge length %.3g  at (%.4f, %.4f, %.4f)" % (s, length, fc[0], fc[1], fc[2]))


if __name__ == "__main__":
    main()
