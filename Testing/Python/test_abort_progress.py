"""pvpython: VolGrid Tetrahedralize's progress and abort, as ParaView shows and uses them.

What a user relies on: one progress bar per run that never moves back and reaches 100% only at the end
(Core's stages each report 0..1; the filter weights them into one bar); an abort (AbortExecute, what a stop
button or Python sets) ends the run quickly with an empty output, and the next run meshes normally instead of
failing at once with "cancelled".
"""
import os
import sys
import time

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
WING = os.path.join(os.environ["VOLGRID_TEST_DATA_DIR"], "straight_wing.stl")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


wing = STLReader(FileNames=[WING])
prep = VolGridSurfacePrep(Input=[wing], Enclosure="Sphere", EnclosureScale=5.0)
prep.UpdatePipeline()
mesh = VolGridTetrahedralize(Input=prep)
algorithm = mesh.GetClientSideObject()

values = []
tag = algorithm.AddObserver("ProgressEvent", lambda o, e: values.append(o.GetProgress()))
mesh.UpdatePipeline()
algorithm.RemoveObserver(tag)
cells = mesh.GetDataInformation().GetNumberOfCells()
check(cells > 0, "the wing is meshed (%d tets)" % cells)
backwards = [(a, b) for a, b in zip(values, values[1:]) if b < a]
check(not backwards, "the bar never moves back (first backward step %s)" % (backwards[:1],))
check(values and values[-1] == 1.0, "the bar ends at 100%")
check(len([v for v in values if v >= 0.99]) <= 3, "no stage sits at 100%% before the end (%d reports >= 99%%)"
      % len([v for v in values if v >= 0.99]))
check(len(set(round(v, 2) for v in values)) > 10, "the bar moves in steps (%d distinct values)" % len(set(values)))

# Abort at 30%: the run ends soon with an empty output, and the flag does not outlive the run.
abort_time = []


def abort(o, e):
    if o.GetProgress() > 0.3 and not abort_time:
        abort_time.append(time.time())
        o.SetAbortExecute(1)


tag = algorithm.AddObserver("ProgressEvent", abort)
mesh.MaxEdgeLength = 0.5  # a long run
mesh.UpdatePipeline()
stopped = time.time()
algorithm.RemoveObserver(tag)
check(abort_time and stopped - abort_time[0] < 5.0, "the aborted run ended %.2f s after the abort"
      % ((stopped - abort_time[0]) if abort_time else -1))
check(mesh.GetDataInformation().GetNumberOfCells() == 0, "an aborted run leaves an empty output")
check(algorithm.GetAbortExecute() == 0, "the abort flag is cleared after the aborted run")
mesh.MaxEdgeLength = 0.0
mesh.UpdatePipeline()
check(mesh.GetDataInformation().GetNumberOfCells() == cells,
      "the next run meshes normally (%d tets, not %d)" % (mesh.GetDataInformation().GetNumberOfCells(), cells))

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("OK")
