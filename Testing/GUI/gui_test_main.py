"""Run inside the ParaView GUI (`paraview --script=gui_test_main.py`) by test_gui.py: builds the wing pipeline
of wing_pipeline.py through the GUI's own server manager (panels, domains, representations), saves the view
and compares it with the baseline image (vtkImageDifference, ParaView's regression threshold 10), then exits
the GUI with status 0 (pass), 1 (image differs) or 2 (the script failed).
Environment: VOLGRID_GUI_DIR (this folder), VOLGRID_PLUGIN, VOLGRID_WING, VOLGRID_BASELINE, VOLGRID_SCREENSHOT (the image to write).
"""
import json
import os
import traceback

status, detail = 2, ""
try:
    exec(open(os.path.join(os.environ["VOLGRID_GUI_DIR"], "wing_pipeline.py")).read())
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference

    images = []
    for path in (os.environ["VOLGRID_SCREENSHOT"], os.environ["VOLGRID_BASELINE"]):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        images.append(reader.GetOutput())
    diff = vtkImageDifference()
    diff.SetInputData(images[0])
    diff.SetImageData(images[1])
    diff.Update()
    error = diff.GetThresholdedError()
    status = 0 if error <= 10.0 else 1
    detail = "image difference %g (threshold 10)" % error
except Exception:
    detail = traceback.format_exc()
with open(os.environ["VOLGRID_SCREENSHOT"] + ".json", "w") as f:
    json.dump({"status": status, "detail": detail}, f)
os._exit(status)
