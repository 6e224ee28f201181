#!/usr/bin/env python3
"""`volgrid mesh --threads N` is deterministic and does not depend on N (README, "Threads").

What a user relies on: the same input, options and thread count give a byte-identical mesh, also with
more threads than cores (--threads 8 on a 2-core machine), and the thread count does not change the mesh.
The bundled wing is meshed inside a sphere far field (the demo's domain) twice with --threads 8 and once
with --threads 1; the three .vtu files (tets and boundary) must be byte-identical and pass --check.

usage: test_cli_threads.py VOLGRID_CLI WING_STL
"""
import filecmp
import os
import subprocess
import sys
import tempfile


def run(cmd):
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s%s" % (" ".join(cmd), done.stdout, done.stderr))


def main():
    cli, wing = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        domain = os.path.join(tmp, "domain.off")
        run([cli, "prep", wing, domain, "--enclosure", "sphere", "--enclosure-scale", "5"])
        outputs = []
        for tag, threads in (("a", 8), ("b", 8), ("c", 1)):
            mesh = os.path.join(tmp, "mesh_%s.vtu" % tag)
            boundary = os.path.join(tmp, "boundary_%s.vtp" % tag)
            run([cli, "mesh", domain, mesh, "--boundary", boundary, "--check", "--threads", str(threads)])
            outputs.append((mesh, boundary))
        for other in outputs[1:]:
            for first, second in zip(outputs[0], other):
                if not filecmp.cmp(first, second, shallow=False):
                    sys.exit("not byte-identical: %s and %s" % (first, second))
    print("byte-identical with --threads 8 (twice) and --threads 1")


if __name__ == "__main__":
    main()
