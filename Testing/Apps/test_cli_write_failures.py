#!/usr/bin/env python3
"""Write failures never lose data: every command that writes (mesh, mesh --boundary, refine, delaunay --out,
prep) to an unwritable directory, a missing directory, /dev/full, past a file size limit (ulimit -f in a
subshell), onto its own input, or with an extension no writer handles, exits non-zero with a message naming
the path, leaves the earlier file byte-identical and leaves no temporary file behind.

usage: test_cli_write_failures.py VOLGRID_CLI DATA_DIR
"""
import os
import shutil
import stat
import sys
import tempfile

from cli_test_support import OCTAHEDRON_OFF, cube_vtu, leftover_temporaries, refused_cleanly, run, write

failures = []


def expect_refusal(label, args, protected=None, names=None, shell_prefix=None, absent=None):
    """The run must fail cleanly, name `names` in its message, keep `protected` (a path or a list) byte-identical
    and not create `absent`."""
    protected = [protected] if isinstance(protected, str) else (protected or [])
    before = [open(p, "rb").read() for p in protected]
    r = run(args, shell_prefix=shell_prefix)
    problems = []
    if not refused_cleanly(r):
        problems.append("not a clean refusal")
    if names and names not in r.stderr:
        problems.append("the message does not name '%s'" % names)
    for p, content in zip(protected, before):
        if open(p, "rb").read() != content:
            problems.append("'%s' changed" % p)
    if absent and os.path.lexists(absent):
        problems.append("'%s' was created" % absent)
    for d in {os.path.dirname(p) for p in protected + [absent] if p}:
        if os.path.isdir(d) and leftover_temporaries(d):
            problems.append("temporary files left in %s: %s" % (d, leftover_temporaries(d)))
    print("%-44s %s" % (label, "ok" if not problems else "FAILED: " + "; ".join(problems)))
    if problems:
        print("  " + r.describe())
        failures.append(label)


def main():
    volgrid, data_dir = sys.argv[1], sys.argv[2]
    wing = os.path.join(data_dir, "straight_wing.stl")
    tmp = tempfile.mkdtemp(prefix="volgrid-write-")
    try:
        octa = write(os.path.join(tmp, "octa.off"), OCTAHEDRON_OFF)
        old = write(os.path.join(tmp, "old.vtu"), "the earlier result, which must survive\n")
        old_vtp = write(os.path.join(tmp, "old.vtp"), "the earlier boundary\n")
        old_off = write(os.path.join(tmp, "old.off"), "the earlier prep output\n")
        cube = write(os.path.join(tmp, "cube.vtu"), cube_vtu(0.5))
        nodes = write(os.path.join(tmp, "pts.node"), "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n")
        full = os.path.join(tmp, "full.vtu")
        os.symlink("/dev/full", full)

        # Sanity: the commands do write when nothing is wrong (so the refusals below are not blanket failures).
        good = run([volgrid, "mesh", octa, os.path.join(tmp, "good.vtu"), "--boundary", os.path.join(tmp, "good.vtp")])
        if good.returncode != 0 or not os.path.exists(os.path.join(tmp, "good.vtu")):
            print("mesh of the octahedron failed:\n  " + good.describe())
            failures.append("sanity")

        missing = os.path.join(tmp, "no-such-dir", "out.vtu")
        expect_refusal("mesh into a missing directory", [volgrid, "mesh", octa, missing], names=missing)
        expect_refusal("mesh into /proc", [volgrid, "mesh", octa, "/proc/volgrid-test.vtu"], names="/proc/volgrid-test.vtu")
        expect_refusal("mesh into a path below a file", [volgrid, "mesh", octa, os.path.join(octa, "x.vtu")], names=octa)
        expect_refusal("mesh to /dev/full (a symlink .vtu)", [volgrid, "mesh", octa, full], names=full)
        if not stat.S_ISCHR(os.stat("/dev/full").st_mode):
            failures.append("/dev/full replaced")
        expect_refusal("mesh --boundary into a missing directory",
                       [volgrid, "mesh", octa, old, "--boundary", os.path.join(tmp, "nope", "b.vtp")],
                       protected=old, names="nope")
        expect_refusal("mesh --boundary to /dev/full", [volgrid, "mesh", octa, old, "--boundary", "/dev/full"],
                       protected=old, names="/dev/full")
        expect_refusal("mesh a.off a.off (output is the input)", [volgrid, "mesh", octa, octa], protected=octa,
                       names=octa)
        expect_refusal("mesh with an unknown output extension", [volgrid, "mesh", octa, os.path.join(tmp, "o.xyz")],
                       names="o.xyz", absent=os.path.join(tmp, "o.xyz"))
        expect_refusal("mesh --boundary equal to OUT", [volgrid, "mesh", octa, old, "--boundary", old], protected=old)
        expect_refusal("prep onto its own input", [volgrid, "prep", octa, octa], protected=octa, names=octa)
        link = os.path.join(tmp, "same.off")
        os.symlink(octa, link)
        expect_refusal("prep onto its input under another name", [volgrid, "prep", octa, link], protected=octa)
        expect_refusal("refine onto its own input", [volgrid, "refine", cube, cube, "--size-array", "TargetSize"],
                       protected=cube, names=cube)
        expect_refusal("delaunay --out into a missing directory",
                       [volgrid, "delaunay", nodes, "--out", os.path.join(tmp, "none", "d.vtu")], names="none")
        expect_refusal("delaunay --out /dev/full", [volgrid, "delaunay", nodes, "--out", full], names=full)

        if os.geteuid() != 0:
            ro = os.path.join(tmp, "readonly")
            os.mkdir(ro)
            ro_old = write(os.path.join(ro, "old.vtu"), "earlier\n")
            os.chmod(ro, 0o555)
            expect_refusal("mesh into a read-only directory", [volgrid, "mesh", octa, ro_old], protected=ro_old,
                           names=ro_old)
            expect_refusal("prep into a read-only directory", [volgrid, "prep", octa, os.path.join(ro, "p.off")],
                           names=ro)
            os.chmod(ro, 0o755)
        else:
            print("%-44s skipped (root ignores directory permissions; /proc and missing directories cover it)"
                  % "read-only directory")

        # A file size limit: the writes fail part-way (EFBIG); the earlier files stay as they were.
        limit = "ulimit -f 8"  # 8 KiB
        expect_refusal("mesh --boundary past ulimit -f", [volgrid, "mesh", wing, old, "--boundary", old_vtp],
                       protected=[old, old_vtp], names=old, shell_prefix=limit)
        old_vtk = write(os.path.join(tmp, "old.vtk"), "the earlier legacy result, which must survive\n")
        expect_refusal("mesh to legacy .vtk past ulimit -f", [volgrid, "mesh", wing, old_vtk], protected=old_vtk,
                       names=old_vtk, shell_prefix=limit)
        expect_refusal("prep past ulimit -f", [volgrid, "prep", wing, old_off], protected=old_off, names=old_off,
                       shell_prefix=limit)
        expect_refusal("refine past ulimit -f", [volgrid, "refine", cube, old, "--size-array", "TargetSize"],
                       protected=old, shell_prefix="ulimit -f 1")
        expect_refusal("delaunay --out past ulimit -f", [volgrid, "delaunay", "--random", "20000", "--out", old],
                       protected=old, names=old, shell_prefix=limit)
    finally:
        for root, dirs, _ in os.walk(tmp):
            for d in dirs:
                os.chmod(os.path.join(root, d), 0o755)
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d case(s) failed: %s" % (len(failures), ", ".join(failures)))
        return 1
    print("all write-failure cases refused cleanly with the earlier files intact")
    return 0


if __name__ == "__main__":
    sys.exit(main())
