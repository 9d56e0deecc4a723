# ParaView Python state: the Olinda DEM lit by the paper's August morning, in the
# ParaView GUI through the TerraLux plugin.
#
#   build-paraview/prefix/usr/bin/paraview --script=Examples/paraview_state.py
#   (or File > Load State... and this file, or View > Python Shell > Run Script)
#
# The pipeline browser then holds TerrainSource -> SunSource -> SkySource ->
# HierarchicalRadiosity (the terrain coloured by Irradiance, W/m^2, with its scalar
# bar; the sky's dome output coloured by Radiance, hidden), and SolarIrradiation over that
# day at 30-minute steps with IntegrateOverTime off, hidden: show it and drag the time
# slider to scrub through the day. The plugin and the DEM are found beside this file
# (build-paraview/ and Testing/Data/External/ of the repository) unless
# TERRALUX_PLUGIN and TERRALUX_DEM name them.
import os

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, Hide, LoadPlugin,
                             OutputPort, RenameSource, Render, ResetCamera, SetActiveSource,
                             SetActiveView, Show)

try:
    repository = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
except NameError:  # File > Load State runs the script without __file__
    repository = os.getcwd()
plugin = os.environ.get("TERRALUX_PLUGIN", os.path.join(
    repository, "build-paraview", "lib", "paraview-5.11", "plugins", "TerraLux", "TerraLux.so"))
dem = os.environ.get("TERRALUX_DEM", os.path.join(
    repository, "Testing", "Data", "External", "olinda_dem_utm25s.tif"))
LoadPlugin(plugin, remote=False, ns=globals())

terrain = TerrainSource(FileName=dem)  # noqa: F821 (the plugin's proxies)
RenameSource("Olinda DEM", terrain)
sun = SunSource(Input=terrain, DateTime="2024-08-15T08:30:00-03:00",  # noqa: F821
                IrradianceModel="ESRA", LinkeTurbidity=3.0)
sky = SkySource(Input=sun, SkyModel="CIE General", SkyType=12)  # noqa: F821
solver = HierarchicalRadiosity(Input=terrain, Lights=[sun, sky],  # noqa: F821
                               DefaultReflectance=0.2)
day = SolarIrradiation(Input=terrain, StartTime="2024-08-15T00:00:00-03:00",  # noqa: F821
                       EndTime="2024-08-16T00:00:00-03:00", TimeStep=30.0,
                       IntegrateOverTime=0)

view = GetActiveViewOrCreate("RenderView")
SetActiveView(view)
display = Show(solver, view)
ColorBy(display, ("POINTS", "Irradiance"))
display.RescaleTransferFunctionToDataRange(True, False)
bar = GetScalarBar(GetColorTransferFunction("Irradiance"), view)
bar.Title = "Irradiance (W/m^2)"
bar.ComponentTitle = ""
display.SetScalarBarVisibility(view, True)

# The sky dome (10 km around the terrain), coloured by radiance: click its eye to see it.
dome = Show(OutputPort(sky, 1), view)
ColorBy(dome, ("CELLS", "Radiance"))
Hide(OutputPort(sky, 1), view)
Hide(day, view)
GetAnimationScene().UpdateAnimationUsingDataTimeSteps()

view.CameraPosition = [0.0, -15000.0, 12000.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
SetActiveSource(solver)
Render(view)
