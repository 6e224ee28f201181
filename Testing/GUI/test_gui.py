"""ctest driver: the ParaView GUI under Xvfb builds the wing pipeline with the VolGrid plugin (gui_test_main.py),
and the test passes when the view matches the baseline image and the GUI printed no error or warning (ParaView
echoes its Output Messages to stderr: creating or applying a filter with its default settings must not raise
any, e.g. the "Index out of range" of an array-list domain on an unconnected optional input).

Why --script and not --test-script: Debian 12's ParaView 5.11 GUI plays QtTesting XML recordings but not
Python test scripts (its QtTesting is built without Python: `--test-script=x.py` prints "Playing" and does
nothing), so the script runs through --script and compares the image itself, as --test-baseline would.

usage: python3 test_gui.py BASELINE.png WING.stl
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    baseline, wing = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    out = tempfile.mkdtemp(prefix="volgrid-gui-")
    shot = os.path.join(out, "wing_clip.png")
    env = dict(os.environ, VOLGRID_GUI_DIR=HERE, VOLGRID_WING=wing, VOLGRID_BASELINE=baseline, VOLGRID_SCREENSHOT=shot)
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "paraview", "--dr",
               "--script=" + os.path.join(HERE, "gui_test_main.py")]
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=900)
    messages = [l for l in done.stderr.splitlines() if "ERR|" in l or "WARN|" in l or "Warning" in l]
    result = {"status": 2, "detail": "no result file"}
    if os.path.exists(shot + ".json"):
        result = json.load(open(shot + ".json"))
    print("paraview exited with", done.returncode, "-", result["detail"])
    print("image written to", shot)
    failures = []
    if done.returncode != 0 or result["status"] != 0:
        failures.append("view differs from the baseline or the script failed: " + result["detail"])
    if messages:
        failures.append("the GUI printed %d error/warning message(s):\n  " % len(messages) + "\n  ".join(messages))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
