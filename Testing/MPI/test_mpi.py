"""ctest driver: the pvbatch pipeline of mpi_pipeline.py in one process and under `mpiexec -np N`, compared.

What a ParaView user relies on under MPI: the same mesh as in one process (tet count, volume, boundary
faces, Quality's statistics table and histogram, slice and crinkle clip), no overlapping meshes, the tets
spread over all ranks, a .pvtu that reads back whole; the surface spread over the ranks first
(D3) gives that same mesh; an empty input is an error on every rank count, never a mesh.

usage: python3 test_mpi.py NRANKS SURFACE [--enclosure Sphere|None] [--no-variants]
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PVBATCH = os.environ.get("VOLGRID_PVBATCH", "pvbatch")
MPIEXEC = os.environ.get("VOLGRID_MPIEXEC", "mpiexec")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(ranks, surface, extra):
    outdir = tempfile.mkdtemp(prefix="volgrid-mpi-")
    script = [os.path.join(HERE, "mpi_pipeline.py"), surface, outdir] + extra
    if ranks == 1:
        command = [PVBATCH] + script
    else:
        command = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), PVBATCH, "--mpi"] + script
    print("running:", " ".join(command), flush=True)
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    shutil.rmtree(outdir, ignore_errors=True)
    lines = [l for l in done.stdout.splitlines() if l.startswith("VOLGRID_FIGURES ")]
    if done.returncode != 0 or len(lines) != 1:
        print(done.stdout[-3000:], done.stderr[-3000:])
        check(False, "%s exited with %d and %d figure line(s)" % (command, done.returncode, len(lines)))
        return {}, done.stderr
    figures = json.loads(lines[0][len("VOLGRID_FIGURES "):])
    print({k: v for k, v in figures.items() if k != "quality_table"})
    return figures, done.stderr


def same_mesh(one, many, label):
    for key in ("prep_triangles", "tets", "boundary_faces", "boundary_quality_rows", "slice_cells", "crinkle_clip_cells", "pvtu_cells",
                "min_dihedral_statistics", "quality_table"):
        check(one.get(key) == many.get(key), "%s: %s differs: %s vs %s" % (
            label, key, str(one.get(key))[:200], str(many.get(key))[:200]))
    check(abs(one.get("volume", 0) - many.get("volume", -1)) <= 1e-9 * abs(one.get("volume", 1)),
          "%s: volume %s vs %s (overlapping or missing tets)" % (label, one.get("volume"), many.get("volume")))
    check(many.get("pvtu_cells") == one.get("tets"), "%s: the .pvtu read back has %s cells, not %s" % (
        label, many.get("pvtu_cells"), one.get("tets")))


def main():
    ranks, surface = int(sys.argv[1]), sys.argv[2]
    extra = sys.argv[3:]
    variants = "--no-variants" not in extra
    extra = [a for a in extra if a != "--no-variants"]
    one, _ = run(1, surface, extra)
    check(one.get("tets", 0) > 0, "one process made no mesh")
    many, _ = run(ranks, surface, extra)
    check(many.get("ranks") == ranks, "pvbatch ran with %s ranks, not %d" % (many.get("ranks"), ranks))
    same_mesh(one, many, "%d ranks" % ranks)
    pieces = many.get("pvtu_piece_cells", [])
    check(len(pieces) == ranks and all(n > 0 for n in pieces),
          "the tets are not spread over the %d ranks: cells per piece %s" % (ranks, pieces))
    if variants:
        spread, _ = run(ranks, surface, extra + ["--spread"])
        same_mesh(one, spread, "%d ranks, surface redistributed first" % ranks)
        for n in (1, ranks):
            empty, err = run(n, surface, extra + ["--empty"])
            check(empty.get("tets") == 0, "empty input on %d rank(s) gave %s tets" % (n, empty.get("tets")))
            check("no surface triangles" in err, "empty input on %d rank(s): no clear error in %r" % (n, err[-500:]))
    if failures:
        print("%d failure(s)" % len(failures))
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
