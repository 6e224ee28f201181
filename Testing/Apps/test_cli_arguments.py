#!/usr/bin/env python3
"""The argument messages and exit codes of the volgrid sub-commands, word for word: a missing value, a
malformed or out-of-range number (the option table's ranges for its rows), an unknown flag and a missing
value (one wording for every command: flag, command and a pointer to --help), a bad choice, a wrong count
of file arguments, and --help (exit 0, usage on stdout). Each case names the first line of
stderr, whether the usage text follows it, and the exit code; these are what a user or a script sees.

usage: test_cli_arguments.py VOLGRID_CLI DATA_DIR
"""
import os
import subprocess
import sys

volgrid, data = sys.argv[1], sys.argv[2]
wing = os.path.join(data, "straight_wing.stl")
failures = []

U = True  # the usage text follows the message
# (command, arguments, exit code, first line of stderr, usage follows)
CASES = [
    ("mesh", ["--alpha"], 2, "volgrid mesh: --alpha needs a value (see volgrid mesh --help)", False),
    ("mesh", ["--alpha", "x"], 2, "volgrid mesh: --alpha expects a finite number, got 'x'", False),
    ("mesh", ["--alpha", "0"], 2, "volgrid mesh: --alpha is out of range: 0 (in (0, inf); see --help)", False),
    ("mesh", ["--passes", "2.5"], 2, "volgrid mesh: --passes is out of range: 2.5 (an integer in [0, 1000]; see --help)",
     False),
    ("mesh", ["--target-angle", "61"], 2, "volgrid mesh: --target-angle is out of range: 61 (in (0, 60]; see --help)",
     False),
    ("mesh", ["--threads", "x"], 2, "volgrid mesh: --threads expects an integer, got 'x'", False),
    ("mesh", ["--threads", "1025"], 2, "volgrid mesh: --threads is out of range: 1025 (see --help)", False),
    ("mesh", ["--max-tets", "0"], 2, "volgrid mesh: --max-tets must be a positive number of tets, got '0'", False),
    ("mesh", ["--cluster-size", "0"], 2, "volgrid mesh: --cluster-size is out of range: 0 (see --help)", False),
    ("mesh", ["--regions", "foo"], 2, "volgrid mesh: --regions is even-odd, orientation or keep-all, not 'foo'",
     False),
    ("mesh", ["--boundary"], 2, "volgrid mesh: --boundary needs a value (see volgrid mesh --help)", False),
    ("mesh", ["--bogus"], 2, "volgrid mesh: unknown option '--bogus' (see volgrid mesh --help)", False),
    ("mesh", ["-"], 2, "volgrid mesh: unknown option '-' (see volgrid mesh --help)", False),
    ("mesh", [wing], 2, "volgrid mesh: expected SURFACE and OUT.vtu", U),
    ("mesh", ["--layers"], 2, "volgrid mesh: --layers needs a value (see volgrid mesh --help)", False),
    ("mesh", ["--patch"], 2, "volgrid mesh: --patch needs a value (see volgrid mesh --help)", False),
    ("mesh", ["--first-height", "1e-3"], 2, "volgrid mesh: --first-height, --y-plus, --layer-thickness, "
     "--layer-patches, --split-prisms and --keep-wall-triangles need --layers N", False),
    ("mesh", ["--keep-wall-triangles"], 2, "volgrid mesh: --first-height, --y-plus, --layer-thickness, "
     "--layer-patches, --split-prisms and --keep-wall-triangles need --layers N", False),
    ("refine", ["--alpha"], 2, "volgrid refine: --alpha needs a value (see volgrid refine --help)", False),
    ("refine", ["--alpha", "0"], 2, "volgrid refine: --alpha is out of range: 0 (in (0, inf); see --help)", False),
    ("refine", ["--size-scale", "2"], 2, "volgrid refine: unknown option '--size-scale' (see volgrid refine --help)", False),
    ("refine", ["--gradation", "x"], 2, "volgrid refine: --gradation expects a finite number, got 'x'", False),
    ("refine", ["--gradation", "0.5"], 2, "volgrid refine: --gradation is out of range: 0.5", False),
    ("refine", ["--max-tets"], 2, "volgrid refine: --max-tets needs a value (see volgrid refine --help)", False),
    ("refine", ["--max-tets", "x"], 2, "volgrid refine: --max-tets expects an integer, got 'x'", False),
    ("refine", ["a", "b"], 2, "volgrid refine: expected MESH OUT --size-array NAME", U),
    ("prep", ["--enclosure"], 2, "volgrid prep: --enclosure needs a value (see volgrid prep --help)", False),
    ("prep", ["--axis", "w"], 2, "volgrid prep: --axis expects x, y or z", U),
    ("prep", ["--center", "1,2,3,4"], 2, "volgrid prep: --center expects one to three numbers X[,Y[,Z]]", U),
    ("prep", ["--dimensions", "1,-1"], 2, "volgrid prep: --dimensions must be positive", U),
    ("prep", ["--enclosure-scale"], 2, "volgrid prep: --enclosure-scale needs a value (see volgrid prep --help)", False),
    ("prep", ["--enclosure-scale", "x"], 2, "volgrid prep: --enclosure-scale expects a finite number, got 'x'", False),
    ("prep", ["--enclosure-scale", "0.5"], 2, "volgrid prep: --enclosure-scale must be in [1, 1e6]", U),
    ("prep", ["--merge-tolerance", "0.1"], 2, "volgrid prep: --merge-tolerance must be in [0, 0.01]", U),
    ("prep", ["--fill-holes", "1.5"], 2, "volgrid prep: --fill-holes expects an integer, got '1.5'", False),
    ("prep", ["--fill-holes", "-1"], 2, "volgrid prep: --fill-holes must be in [0, 1000000]", U),
    ("prep", ["--bogus"], 2, "volgrid prep: unknown option '--bogus' (see volgrid prep --help)", False),
    ("prep", [], 2, "volgrid prep: missing OUT", U),
    ("prep", ["--center", "0,0,0", "out.vtp"], 2, "volgrid prep: --center and --dimensions go together", U),
    ("quality", [], 2, "volgrid quality: no input file", U),
    ("quality", ["--bins"], 2, "volgrid quality: --bins needs a value (see volgrid quality --help)", False),
    ("quality", ["--bins", "0"], 2, "volgrid quality: --bins needs an integer in 1..10000", U),
    ("quality", ["--bins", "x"], 2, "volgrid quality: --bins expects an integer, got 'x'", False),
    ("quality", ["--threads", "-1"], 2, "volgrid quality: --threads needs an integer >= 0", U),
    ("quality", ["--metric"], 2, "volgrid quality: --metric needs a value (see volgrid quality --help)", False),
    ("quality", ["--metric", "Foo"], 2, "volgrid quality: unknown metric 'Foo'", U),
    ("quality", ["--bogus"], 2, "volgrid quality: unknown option '--bogus' (see volgrid quality --help)", False),
    ("quality", ["a", "b"], 2, "volgrid quality: more than one input file", U),
    ("delaunay", [], 2, "volgrid delaunay: give either an input .node file or --random N", U),
    ("delaunay", ["--random"], 2, "volgrid delaunay: --random needs a value (see volgrid delaunay --help)", False),
    ("delaunay", ["--random", "-1"], 2, "volgrid delaunay: --random needs a non-negative count", False),
    ("delaunay", ["--seed", "x"], 2, "volgrid delaunay: --seed expects an integer, got 'x'", False),
    ("delaunay", ["--threads", "1025"], 2, "volgrid delaunay: --threads is 0 (all cores) or 1..1024, not 1025", False),
    ("delaunay", ["--location", "foo"], 2, "volgrid delaunay: --location is walk or grid, not 'foo'", False),
    ("delaunay", ["a", "b"], 2, "volgrid delaunay: more than one input ('b')", False),
    ("delaunay", ["--bogus"], 2, "volgrid delaunay: unknown option '--bogus' (see volgrid delaunay --help)", False),
    ("convert", ["a"], 2, "volgrid convert: expected IN and OUT", U),
    ("convert", ["--bogus"], 2, "volgrid convert: unknown option '--bogus' (see volgrid convert --help)", False),
    ("convert", ["--format"], 2, "volgrid convert: --format needs a value (see volgrid convert --help)", False),
    ("check", [], 2, "volgrid check: missing SURFACE", U),
    ("check", ["--bogus"], 2, "volgrid check: unknown option '--bogus' (see volgrid check --help)", False),
    ("check", ["a", "b"], 2, "volgrid check: only one surface file", U),
]


def check(label, ok, r):
    print("%-70s %s" % (label[:70], "ok" if ok else "FAILED"))
    if not ok:
        print("  exit %d\n  stdout: %s\n  stderr: %s" % (r.returncode, r.stdout[:300], r.stderr[:600]))
        failures.append(label)


for command, args, code, first, usage in CASES:
    r = subprocess.run([volgrid, command] + args, capture_output=True, text=True, timeout=60)
    lines = r.stderr.splitlines()
    follows = len(lines) > 1 and lines[1].startswith("usage: volgrid " + command)
    ok = r.returncode == code and lines[:1] == [first] and follows == usage and (usage or len(lines) == 1)
    check("%s %s" % (command, " ".join(args)), ok, r)

# --help (anywhere before a bad flag): usage on stdout, nothing on stderr, exit 0.
for command, extra in [("mesh", ["Boundary layers", "--format"]), ("refine", ["--size-array NAME"]),
                       ("prep", ["--fill-holes N"]),
                       ("quality", ["--metric NAME"]),
                       ("delaunay", ["--location"]),
                       ("convert", ["--patch-type"]),
                       ("check", ["--keep-points"])]:
    r = subprocess.run([volgrid, command, "--help", "--bogus"], capture_output=True, text=True, timeout=60)
    ok = r.returncode == 0 and r.stderr == "" and r.stdout.startswith("usage: volgrid " + command)
    ok = ok and all(word in r.stdout for word in extra)
    check("%s --help" % command, ok, r)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
