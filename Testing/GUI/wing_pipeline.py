"""ParaView GUI test script (run by `paraview --test-script=wing_pipeline.py --test-baseline=... --exit`):
loads the VolGrid plugin, builds the wing pipeline with the filters' default settings (Surface Prep with a
sphere enclosure, Tetrahedralize, Quality), crinkle-clips and slices the mesh, colours the clip by the
minimum dihedral angle and leaves the view for the test utility to compare with the baseline image.
Environment: VOLGRID_PLUGIN, VOLGRID_WING, VOLGRID_SCREENSHOT (optional: also save the view there).
"""
import os

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["VOLGRID_PLUGIN"], remote=False, ns=globals())
wing = STLReader(registrationName="wing", FileNames=[os.environ["VOLGRID_WING"]])
prep = VolGridSurfacePrep(registrationName="prep", Input=[wing])
prep.Enclosure = "Sphere"
prep.EnclosureScale = 3.0
mesh = VolGridTetrahedralize(registrationName="mesh", Input=prep)
quality = VolGridQuality(registrationName="quality", Input=mesh)
wing.UpdatePipeline()
b = wing.GetDataInformation().GetBounds()
centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
extent = [b[1] - b[0], b[3] - b[2], b[5] - b[4]]
span = extent.index(max(extent))
normal = [1.0 if a == span else 0.0 for a in range(3)]
clip = Clip(registrationName="clip", Input=quality, ClipType="Plane", Crinkleclip=1)
clip.ClipType.Origin = centre
clip.ClipType.Normal = normal
slice_ = Slice(registrationName="slice", Input=quality, SliceType="Plane")
slice_.SliceType.Origin = centre
slice_.SliceType.Normal = normal

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
for proxy in (wing, prep, mesh, quality):
    Hide(proxy, view)
shown = Show(clip, view)
ColorBy(shown, ("CELLS", "MinDihedralAngle"))
lut = GetColorTransferFunction("MinDihedralAngle")
lut.RescaleTransferFunction(0.0, 70.0)
shown.SetScalarBarVisibility(view, True)
shown.SetRepresentationType("Surface With Edges")
Hide3DWidgets(proxy=clip.ClipType)
Hide3DWidgets(proxy=slice_.SliceType)
Hide(slice_, view)
Render(view)
# From the removed side of the crinkle clip, looking at its cut face around the wing section.
chord = sorted(extent)[1]
camera = GetActiveCamera()
camera.SetFocalPoint(centre)
camera.SetPosition([centre[a] + (4.0 * chord if a == span else 0.3 * chord) for a in range(3)])
camera.SetViewUp([0.0, 0.0, 1.0] if span != 2 else [0.0, 1.0, 0.0])
Render(view)
if os.environ.get("VOLGRID_SCREENSHOT"):
    SaveScreenshot(os.environ["VOLGRID_SCREENSHOT"], view, ImageResolution=[800, 600])
