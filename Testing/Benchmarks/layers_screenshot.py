#!/usr/bin/env python3
"""ParaView screenshot of the boundary layers at the ONERA M6 trailing edge.

Run by itself: it meshes the wing with `volgrid mesh --layers 15 --first-height 1e-4 --growth 1.2`, then runs
the ParaView GUI under xvfb (pvpython's offscreen rendering crashes on this machine) with this same file as
the --script: a slice at a spanwise station, coloured by LayerIndex, zoomed on the trailing edge.
Usage: layers_screenshot.py VOLGRID_BINARY OUT.png [SPAN_Y]
"""
import os
import subprocess
import sys
import tempfile

if "VOLGRID_SHOT_VTU" in os.environ:  # inside ParaView
    from paraview.simple import *  # noqa: F401,F403

    vtu, png, y, xte = (os.environ["VOLGRID_SHOT_VTU"], os.environ["VOLGRID_SHOT_PNG"],
                        float(os.environ["VOLGRID_SHOT_Y"]), float(os.environ["VOLGRID_SHOT_XTE"]))
    reader = XMLUnstructuredGridReader(FileName=[vtu])
    cut = Slice(Input=reader)
    cut.SliceType = "Plane"
    cut.SliceType.Origin = [xte, y, 0.0]
    cut.SliceType.Normal = [0.0, 1.0, 0.0]
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [960, 720]
    view.OrientationAxesVisibility = 0
    shown = Show(cut, view)
    ColorBy(shown, ("CELLS", "LayerIndex"))
    lut = GetColorTransferFunction("LayerIndex")
    lut.ApplyPreset("Turbo", True)
    lut.RescaleTransferFunction(-1.0, 14.0)
    shown.SetScalarBarVisibility(view, True)
    shown.SetRepresentationType("Surface With Edges")
    shown.EdgeColor = [0.1, 0.1, 0.1]
    Hide3DWidgets(proxy=cut.SliceType)
    Render(view)  # the GUI resets the camera on the first render: place it afterwards
    view.CameraPosition = [xte - 0.007, y - 1.0, 0.0]
    view.CameraFocalPoint = [xte - 0.007, y, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.012
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[960, 720], CompressionLevel="9")
    os._exit(0)


def trailing_edge_x(mesh, y, patches):
    """Largest x where the wing's triangle edges cross the plane at span station y: the trailing edge there."""
    f = open(mesh).read().split()
    i = f.index("Vertices")
    n = int(f[i + 1])
    pts = [tuple(map(float, f[i + 2 + 4 * k:i + 5 + 4 * k])) for k in range(n)]
    i = f.index("Triangles")
    best = None
    for k in range(int(f[i + 1])):
        if int(f[i + 5 + 4 * k]) not in patches:
            continue
        tri = [pts[int(v) - 1] for v in f[i + 2 + 4 * k:i + 5 + 4 * k]]
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            if (a[1] - y) * (b[1] - y) <= 0 and a[1] != b[1]:
                x = a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1])
                best = x if best is None else max(best, x)
    return best


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    volgrid, png = sys.argv[1], os.path.abspath(sys.argv[2])
    y = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
    here = os.path.dirname(os.path.abspath(__file__))
    mesh = os.path.join(here, "..", "..", "..", "shared", "data", "real", "derived-onera-m6",
                        "onera_m6_halfsphere_domain.mesh")
    if not os.path.exists(mesh):
        print("skipped: %s is absent" % mesh)
        return 0
    patches = list(range(3, 13))
    work = tempfile.mkdtemp(prefix="volgrid-layers-shot-")
    vtu = os.path.join(work, "m6.vtu")
    subprocess.run([volgrid, "mesh", mesh, vtu, "--layers", "15", "--first-height", "1e-4", "--growth", "1.2",
                    "--layer-patches", ",".join(map(str, patches))], check=True)
    env = dict(os.environ, VOLGRID_SHOT_VTU=vtu, VOLGRID_SHOT_PNG=png, VOLGRID_SHOT_Y=str(y),
               VOLGRID_SHOT_XTE=repr(trailing_edge_x(mesh, y, set(patches))))
    done = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "paraview", "--dr",
                           "--script=" + os.path.abspath(__file__)], env=env, timeout=900)
    print("paraview exited with", done.returncode, "; image:", png, os.path.exists(png))
    return 0 if os.path.exists(png) else 1


if __name__ == "__main__":
    sys.exit(main())
