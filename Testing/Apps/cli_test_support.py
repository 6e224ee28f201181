"""Shared by the CLI tests of Testing/Apps: small input files written on the fly, and running volgrid with a
verdict on how it ended (exit code, signal, messages)."""
import os
import subprocess
import time

# A closed, outward-oriented octahedron (OFF) and the unit cube as 6 tets (VTK XML, ASCII).
OCTAHEDRON_OFF = """OFF
6 8 0
1 0 0
-1 0 0
0 1 0
0 -1 0
0 0 1
0 0 -1
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
"""


def cube_vtu(target_size):
    """The unit cube split into 6 tets around the diagonal 0-6, with the point array TargetSize."""
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    tets = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
    points = " ".join("%g %g %g" % p for p in pts)
    conn = " ".join("%d %d %d %d" % t for t in tets)
    offsets = " ".join(str(4 * (i + 1)) for i in range(len(tets)))
    sizes = " ".join(repr(target_size) for _ in pts)
    return f"""<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid><Piece NumberOfPoints="8" NumberOfCells="6">
<PointData><DataArray type="Float64" Name="TargetSize" format="ascii">{sizes}</DataArray></PointData>
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">{points}</DataArray></Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">{conn}</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">{offsets}</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">{" ".join(["10"] * len(tets))}</DataArray>
</Cells></Piece></UnstructuredGrid></VTKFile>
"""


def write(path, content):
    with open(path, "wb") as f:
        f.write(content.encode() if isinstance(content, str) else content)
    return path


class Run:
    def __init__(self, args, returncode, stdout, stderr, seconds):
        self.args, self.returncode, self.stdout, self.stderr, self.seconds = args, returncode, stdout, stderr, seconds

    def describe(self):
        return "%s -> exit %s in %.2f s\n  stderr: %s" % (" ".join(self.args), self.returncode, self.seconds,
                                                      self.stderr.strip()[:600])


def run(args, timeout=120, shell_prefix=None, cwd=None):
    """Runs args (a list); with shell_prefix (e.g. 'ulimit -f 16') through bash with that prefix first."""
    started = time.monotonic()
    if shell_prefix:
        quoted = " ".join("'" + a.replace("'", "'\\''") + "'" for a in args)
        command = ["bash", "-c", shell_prefix + "; exec " + quoted]
    else:
        command = args
    try:
        p = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=timeout, cwd=cwd)
        code, out, err = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired as e:
        code, out, err = "timeout", "", (e.stderr or b"").decode(errors="replace") if isinstance(e.stderr, bytes) else str(e.stderr or "")
    return Run(args, code, out, err, time.monotonic() - started)


def refused_cleanly(r):
    """A refusal: a positive exit code other than 3 (internal error), no signal, no timeout, a message."""
    return isinstance(r.returncode, int) and 0 < r.returncode != 3 and r.returncode < 128 and r.stderr.strip() != ""


def leftover_temporaries(directory):
    return [n for n in os.listdir(directory) if ".volgrid-" in n]
