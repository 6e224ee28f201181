#!/usr/bin/env python3
"""Malformed inputs through every command that reads a surface or a mesh: truncated and lying binary STL,
garbage ASCII STL, NaN/Inf/garbage numbers in every format, bad OBJ/OFF/PLY indices, PLY with huge counts,
corrupt, truncated and oversized (bomb) gzip, a directory, an empty file. Every run must end in a clean
refusal: an exit code in 1..127 other than 3 (no signal, no "internal error"), a message on stderr that
names the file, and no output file written.

usage: test_cli_fuzz_inputs.py VOLGRID_CLI [-v]
"""
import gzip
import os
import shutil
import struct
import sys
import tempfile
import zlib

from cli_test_support import refused_cleanly, run, write

TRI = "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n"
TET_POINTS = ["0 0 0", "1 0 0", "0 1 0", "0 0 1"]


def off(points, faces=TRI, header="OFF\n"):
    return header + "%d 4 0\n" % len(points) + "\n".join(points) + "\n" + faces


def obj(points, faces="f 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n"):
    return "".join("v %s\n" % p for p in points) + faces


def ascii_stl(vertex="1 0 0"):
    return ("solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex %s\nvertex 0 1 0\nendloop\nendfacet\n"
            "endsolid t\n" % vertex)


def binary_stl(announced, actual):
    tri = struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0)
    return b"\0" * 80 + struct.pack("<I", announced) + tri * actual


def ply_ascii(vertex_count="4", face_count="4", points=TET_POINTS, faces=None):
    faces = faces or ["3 0 1 2", "3 0 3 1", "3 1 3 2", "3 2 3 0"]
    return ("ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %s\nproperty list uchar int vertex_indices\nend_header\n" % (vertex_count, face_count) +
            "\n".join(points + faces) + "\n")


def ply_binary_huge():
    return (b"ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
            b"property float z\nelement face 2000000000\nproperty list uchar int vertex_indices\nend_header\n" +
            b"\0" * 64)


def medit(points):
    return ("MeshVersionFormatted 2\nDimension 3\nVertices\n4\n" + "".join("%s 0\n" % p for p in points) +
            "Triangles\n4\n1 2 3 0\n1 4 2 0\n2 4 3 0\n3 4 1 0\nEnd\n")


def gzip_bomb(path, megabytes=160):
    """Zeros compress about 1000:1: ~160 KiB on disk, 160 MiB inflated."""
    c = zlib.compressobj(9, zlib.DEFLATED, 16 + zlib.MAX_WBITS)
    with open(path, "wb") as f:
        block = b"\0" * (1 << 20)
        for _ in range(megabytes):
            f.write(c.compress(block))
        f.write(c.flush())
    return path


def cases(tmp):
    """(name, file path): every malformed input."""
    nan_points = ["0 0 0", "nan 0 0", "0 1 0", "0 0 1"]
    inf_points = ["0 0 0", "1 0 0", "0 inf 0", "0 0 1"]
    abc_points = ["0 0 0", "1 0 0", "0 1 0", "0 0 abc"]
    x_points = ["0 0 0", "1x 0 0", "0 1 0", "0 0 1"]
    c = {
        "stl_truncated_binary.stl": binary_stl(320, 159),
        "stl_lying_count.stl": binary_stl(4000000000, 4),
        "stl_garbage_ascii.stl": "solid junk\nfacet normal 0 0 0\nouter loop\nvertex what is this\nendsolid\n",
        "stl_junk.stl": bytes(range(256)) * 7,
        "stl_nan.stl": ascii_stl("nan 0 0"),
        "stl_inf.stl": ascii_stl("1 inf 0"),
        "stl_1x.stl": ascii_stl("1x 0 0"),
        "obj_nan.obj": obj(nan_points),
        "obj_inf.obj": obj(inf_points),
        "obj_abc.obj": obj(abc_points),
        "obj_1x.obj": obj(x_points),
        "obj_bad_index.obj": obj(TET_POINTS, "f 1 2 3\nf 1 4 2\nf 2 4 9\nf 3 4 1\n"),
        "obj_zero_index.obj": obj(TET_POINTS, "f 1 2 3\nf 0 4 2\nf 2 4 3\nf 3 4 1\n"),
        "obj_garbage_face.obj": obj(TET_POINTS, "f 1 2 3\nf a b c\n"),
        "off_missing_header.off": off(TET_POINTS, header=""),
        "off_nan.off": off(nan_points),
        "off_abc.off": off(abc_points),
        "off_huge_counts.off": "OFF\n2000000000 2000000000 0\n0 0 0\n",
        "off_bad_index.off": off(TET_POINTS, "3 0 1 2\n3 0 3 1\n3 1 3 7\n3 2 3 0\n"),
        "ply_huge_counts.ply": ply_ascii("2000000000", "2000000000"),
        "ply_binary_huge_counts.ply": ply_binary_huge(),
        "ply_nan.ply": ply_ascii(points=nan_points),
        "ply_1x.ply": ply_ascii(points=x_points),
        "ply_bad_index.ply": ply_ascii(faces=["3 0 1 2", "3 0 3 1", "3 1 3 2", "3 2 3 99"]),
        "medit_nan.mesh": medit(nan_points),
        "medit_abc.mesh": medit(abc_points),
        "vtp_garbage.vtp": "<VTKFile type='PolyData'><garbage",
        "vtu_garbage.vtu": "<?xml version='1.0'?><VTKFile type='UnstructuredGrid'><UnstructuredGrid><Piece",
        "vtk_garbage.vtk": "# vtk DataFile Version 3.0\njunk\nASCII\nDATASET POLYDATA\nPOINTS 1000000000 float\n1 2 3\n",
        "empty.stl": "", "empty.obj": "", "empty.off": "", "empty.ply": "", "empty.vtp": "", "empty.vtu": "",
        "gz_corrupt.stl.gz": b"\x1f\x8b\x08\x00" + b"corrupt" * 20,
        "gz_truncated.obj.gz": gzip.compress(obj(TET_POINTS).encode() * 50)[:60],
        "gz_not_gzip.off.gz": off(TET_POINTS),
    }
    files = [(name, write(os.path.join(tmp, name), content)) for name, content in c.items()]
    files.append(("gz_bomb.stl.gz", gzip_bomb(os.path.join(tmp, "gz_bomb.stl.gz"))))
    directory = os.path.join(tmp, "a_directory.stl")
    os.mkdir(directory)
    files.append(("a_directory.stl", directory))
    return files


def commands(volgrid, path, out_dir):
    """(label, args, output path) for each command that reads this kind of file."""
    name = os.path.basename(path)
    runs = []
    if name.endswith(".vtu"):
        o = os.path.join(out_dir, "refined.vtu")
        runs.append(("refine", [volgrid, "refine", path, o, "--size-array", "TargetSize"], o))
    else:
        o = os.path.join(out_dir, "mesh.vtu")
        runs.append(("mesh", [volgrid, "mesh", path, o], o))
        runs.append(("check", [volgrid, "check", path], None))
        o = os.path.join(out_dir, "prep.vtp")
        runs.append(("prep", [volgrid, "prep", path, o], o))
    runs.append(("quality", [volgrid, "quality", path], None))
    return runs


def main():
    volgrid = sys.argv[1]
    verbose = "-v" in sys.argv
    tmp = tempfile.mkdtemp(prefix="volgrid-fuzz-")
    out_dir = os.path.join(tmp, "out")
    os.mkdir(out_dir)
    failures = []
    try:
        for name, path in cases(tmp):
            for label, args, out in commands(volgrid, path, out_dir):
                r = run(args, timeout=120)
                problems = []
                if not refused_cleanly(r):
                    problems.append("exit %s" % r.returncode)
                if name not in r.stderr:
                    problems.append("the message does not name the file")
                if "internal error" in r.stderr:
                    problems.append("internal error")
                if out and os.path.exists(out):
                    problems.append("wrote %s" % os.path.basename(out))
                    os.remove(out)
                if problems or verbose:
                    print("%-28s %-8s %s\n    %s" % (name, label, "; ".join(problems) or "ok",
                                                     r.stderr.strip().splitlines()[-1][:300] if r.stderr.strip() else ""))
                if problems:
                    failures.append("%s %s" % (label, name))
        # A nodes file with garbage for delaunay.
        node = write(os.path.join(tmp, "bad.node"), "4 3 0 0\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n")
        o = os.path.join(out_dir, "d.vtu")
        r = run([volgrid, "delaunay", node, "--out", o])
        if not refused_cleanly(r) or os.path.exists(o):
            print("delaunay bad.node: " + r.describe())
            failures.append("delaunay bad.node")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d run(s) did not refuse cleanly:\n  %s" % (len(failures), "\n  ".join(failures)))
        return 1
    print("every malformed input was refused cleanly by every command")
    return 0


if __name__ == "__main__":
    sys.exit(main())
