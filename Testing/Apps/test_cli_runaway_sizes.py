#!/usr/bin/env python3
"""Absurd size options are refused before any work, within seconds, with the estimate and the option named:
mesh --max-edge 1e-9 / --max-volume 1e-30 / --size-scale 1e-300, refine to a 1e-9 target size, delaunay
--random 200000000 (over the kernel's limit) and --random 67108864 (its limit, more than the memory holds),
and --max-tets N as an explicit limit. Reasonable runs under the same options still succeed.

usage: test_cli_runaway_sizes.py VOLGRID_CLI DATA_DIR
"""
import os
import shutil
import sys
import tempfile

from cli_test_support import OCTAHEDRON_OFF, cube_vtu, refused_cleanly, run, write

# The issue asks for under a second; a loaded CI machine gets some slack for process start-up.
LIMIT_SECONDS = 3.0
failures = []


def expect_fast_refusal(label, args, names, shell_prefix=None, absent=None):
    r = run(args, timeout=60, shell_prefix=shell_prefix)
    problems = []
    if not refused_cleanly(r):
        problems.append("not a clean refusal")
    if r.seconds > LIMIT_SECONDS:
        problems.append("took %.1f s" % r.seconds)
    for word in names + ["tets"]:
        if word not in r.stderr:
            problems.append("the message does not say '%s'" % word)
    if absent and os.path.exists(absent):
        problems.append("'%s' was written" % absent)
    print("%-48s %s (%.2f s)" % (label, "ok" if not problems else "FAILED: " + "; ".join(problems), r.seconds))
    if problems or "-v" in sys.argv:
        print("  " + r.describe())
    if problems:
        failures.append(label)


def main():
    volgrid, data_dir = sys.argv[1], sys.argv[2]
    tmp = tempfile.mkdtemp(prefix="volgrid-size-")
    try:
        octa = write(os.path.join(tmp, "octa.off"), OCTAHEDRON_OFF)
        wing = os.path.join(data_dir, "straight_wing.stl")
        out = os.path.join(tmp, "out.vtu")
        expect_fast_refusal("mesh --max-edge 1e-9", [volgrid, "mesh", octa, out, "--max-edge", "1e-9"],
                            ["--max-edge 1e-9"], absent=out)
        expect_fast_refusal("mesh --max-volume 1e-30", [volgrid, "mesh", octa, out, "--max-volume", "1e-30"],
                            ["--max-volume 1e-30"], absent=out)
        expect_fast_refusal("mesh --size-scale 1e-300", [volgrid, "mesh", wing, out, "--size-scale", "1e-300"],
                            ["--size-scale 1e-300"], absent=out)
        expect_fast_refusal("mesh --max-edge 1e-3 under a 2 GB address limit",
                            [volgrid, "mesh", octa, out, "--max-edge", "1e-3"], ["--max-edge 1e-3", "memory"],
                            shell_prefix="ulimit -v 2000000", absent=out)
        expect_fast_refusal("mesh --max-tets 1000 --max-edge 0.05",
                            [volgrid, "mesh", octa, out, "--max-edge", "0.05", "--max-tets", "1000"],
                            ["--max-edge 0.05", "--max-tets 1000"], absent=out)
        cube = write(os.path.join(tmp, "cube.vtu"), cube_vtu(1e-9))
        expect_fast_refusal("refine to a 1e-9 target size", [volgrid, "refine", cube, out, "--size-array", "TargetSize"],
                            ["TargetSize", "1e-09"], absent=out)
        expect_fast_refusal("delaunay --random 200000000", [volgrid, "delaunay", "--random", "200000000"],
                            ["200000000", "at most 67108864"])
        expect_fast_refusal("delaunay --random 67108864 (2 GB address limit)",
                            [volgrid, "delaunay", "--random", "67108864"], ["--random 67108864", "memory"],
                            shell_prefix="ulimit -v 2000000")
        expect_fast_refusal("delaunay --random 1000000 --max-tets 100000",
                            [volgrid, "delaunay", "--random", "1000000", "--max-tets", "100000"],
                            ["--random 1000000", "--max-tets 100000"])

        # Reasonable sizes still run (the estimate must not refuse ordinary work).
        for label, args in [("mesh --max-edge 0.1", [volgrid, "mesh", octa, out, "--max-edge", "0.1"]),
                            ("mesh of the wing (defaults)", [volgrid, "mesh", wing, out]),
                            ("refine to 0.25", [volgrid, "refine", write(os.path.join(tmp, "c2.vtu"), cube_vtu(0.25)),
                                                out, "--size-array", "TargetSize"]),
                            ("delaunay --random 100000", [volgrid, "delaunay", "--random", "100000"])]:
            r = run(args, timeout=300)
            ok = r.returncode == 0
            print("%-48s %s" % (label + " runs", "ok" if ok else "FAILED"))
            if not ok:
                print("  " + r.describe())
                failures.append(label)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d case(s) failed: %s" % (len(failures), ", ".join(failures)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
