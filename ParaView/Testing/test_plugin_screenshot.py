"""pvbatch (under xvfb-run): the Olinda terrain coloured by Irradiance with a scalar bar,
saved as a screenshot, which must show the terrain in many colours and the bar.

Environment: TERRALUX_PLUGIN, TERRALUX_DEM, TERRALUX_OUTPUT_DIR (irradiance.png goes there).
"""
import os
import sys

import numpy as np
from paraview import simple as pv
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

from pipeline_parameters import paraview_pipeline

pv.LoadPlugin(os.environ["TERRALUX_PLUGIN"], remote=False)
path = os.path.join(os.environ["TERRALUX_OUTPUT_DIR"], "irradiance.png")
if os.path.exists(path):
    os.remove(path)

terrain, sun, sky, solver = paraview_pipeline(pv, os.environ["TERRALUX_DEM"])

view = pv.CreateView("RenderView")
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
display = pv.Show(solver, view)
pv.ColorBy(display, ("POINTS", "Irradiance"))
display.RescaleTransferFunctionToDataRange(True, False)
lut = pv.GetColorTransferFunction("Irradiance")
bar = pv.GetScalarBar(lut, view)
bar.Title = "Irradiance (W/m^2)"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.WindowLocation = "Any Location"
bar.Orientation = "Horizontal"
bar.Position = [0.2, 0.03]
bar.ScalarBarLength = 0.6
bar.RangeLabelFormat = "%.0f"
view.CameraPosition = [0, -12000, 14000]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
pv.ResetCamera(view)


def screenshot(file_name):
    pv.SaveScreenshot(file_name, view, ImageResolution=[900, 600])
    reader = vtkPNGReader()
    reader.SetFileName(file_name)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].reshape(height, width, 3).astype(int)


display.SetScalarBarVisibility(view, False)
without_bar = screenshot(path.replace(".png", "_without_bar.png"))
display.SetScalarBarVisibility(view, True)
rgb = screenshot(path)
height, width, _ = rgb.shape
background = np.all(rgb == rgb[0, 0], axis=2)  # the corner's colour
coverage = 1.0 - background.mean()
colours = len(np.unique(rgb.reshape(-1, 3), axis=0))
# The scalar bar: what showing it changes, in the bottom fifth of the image (rows of a
# PNG read by VTK start at the bottom).
bottom = slice(0, int(0.2 * height))
bar_pixels = np.any(rgb[bottom] != without_bar[bottom], axis=2)
bar_colours = len(np.unique(rgb[bottom][bar_pixels], axis=0))
print("screenshot %s: %dx%d, %.0f %% not background, %d colours; the scalar bar changes %d pixels (%d colours)"
      % (path, width, height, 100 * coverage, colours, bar_pixels.sum(), bar_colours))
failures = []
if coverage < 0.2:
    failures.append("the terrain covers only %.1f %% of the image" % (100 * coverage))
if colours < 200:
    failures.append("only %d colours: not coloured by Irradiance" % colours)
if bar_pixels.sum() < 0.01 * width * height or bar_colours < 50:
    failures.append("no scalar bar (%d pixels, %d colours change with it)" % (bar_pixels.sum(), bar_colours))
if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("OK")
