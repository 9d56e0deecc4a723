#!/usr/bin/env python3
"""TerraLux demo: ingest a real DEM, render shaded relief, light it with sun and sky.

    xvfb-run -a /usr/bin/python3 Examples/terrain_demo.py [DEM] [--output-dir DIR]

Default DEM: the SRTM Olinda tile (UTM 25S) extracted by cmake/install-dependencies.sh.
Writes DIR/terrain.vtp (surface with normals and Elevation), DIR/shaded_relief.png,
DIR/irradiance.vts (the DEM grid with Irradiance, SunIrradiance, SkyIrradiance,
ReflectedIrradiance, Radiosity in W/m^2 and SkyViewFactor for a December morning under
a clear sky), DIR/leaves.vtp (the adaptive mesh of terrain patches the solution used,
with its Level) and DIR/irradiance.png (global irradiance in colour).
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLStructuredGridWriter

from terralux import vtkHierarchicalRadiosity, vtkSkySource, vtkSunSource, vtkTerrainSource

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DEM = os.path.join(HERE, "..", "Testing", "Data", "External", "olinda_dem_utm25s.tif")


def build_surface(dem, exaggeration):
    """DEM -> ENU structured grid -> polygonal surface (no-data cells dropped) with normals."""
    terrain = vtkTerrainSource()
    terrain.SetFileName(dem)
    surface = vtkDataSetSurfaceFilter()  # honours the blanking of no-data posts
    surface.SetInputConnection(terrain.GetOutputPort())
    transform = vtkTransform()
    transform.Scale(1.0, 1.0, exaggeration)
    exaggerate = vtkTransformFilter()
    exaggerate.SetTransform(transform)
    exaggerate.SetInputConnection(surface.GetOutputPort())
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(exaggerate.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    if terrain.GetOutput().GetNumberOfPoints() == 0:
        sys.exit("terrain_demo: could not read %s (see the error above)" % dem)
    return terrain, normals


def light_terrain(terrain, when):
    """Sun (NREL SPA + ESRA clear sky) and CIE clear sky over the terrain, then radiosity."""
    sun = vtkSunSource()
    sun.SetInputConnection(terrain.GetOutputPort())  # place: the DEM's GeoOrigin
    sun.SetDateTime(when)
    sky = vtkSkySource()
    sky.SetSunConnection(sun.GetOutputPort())
    radiosity = vtkHierarchicalRadiosity()
    radiosity.SetInputConnection(terrain.GetOutputPort())
    radiosity.AddLightConnection(sun.GetOutputPort())
    radiosity.AddLightConnection(sky.GetOutputPort(0))
    radiosity.SetDefaultReflectance(0.2)
    radiosity.Update()
    return sun, radiosity


def write_xml(writer, data, path):
    """Writes a data set with a VTK XML writer and says so."""
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()
    print("wrote", path)


def render_shaded_relief(surface, png, size=(1000, 1000), array="Elevation", tint=None):
    """Hillshade as GIS tools draw it: sun from the north-west, 45 deg up, hypsometric tint."""
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkLight,
                                             vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                             vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL back end)

    data = surface.GetOutput()
    low, high = data.GetPointData().GetArray(array).GetRange()
    colours = tint or ((0.0, (0.20, 0.45, 0.25)), (0.35, (0.55, 0.70, 0.35)),
                       (0.7, (0.80, 0.70, 0.45)), (1.0, (0.95, 0.93, 0.90)))
    tint = vtkColorTransferFunction()
    for fraction, rgb in colours:
        tint.AddRGBPoint(low + fraction * (high - low), *rgb)

    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    mapper.SetLookupTable(tint)
    mapper.UseLookupTableScalarRangeOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetInterpolationToGouraud()
    actor.GetProperty().SetAmbient(0.15)
    actor.GetProperty().SetDiffuse(0.85)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AutomaticLightCreationOff()
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPositional(False)
    sun.SetPosition(-1.0, 1.0, 1.41421356)  # azimuth 315 deg, altitude 45 deg
    sun.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(sun)

    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()  # map view, north up
    center = data.GetCenter()
    camera.SetFocalPoint(center)
    camera.SetPosition(center[0], center[1], center[2] + 1e5)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCamera()
    camera.Zoom(1.4)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dem", nargs="?", default=DEFAULT_DEM)
    parser.add_argument("--output-dir", default="terralux-demo")
    parser.add_argument("--exaggeration", type=float, default=5.0,
                        help="vertical exaggeration of the rendering (default 5)")
    parser.add_argument("--date-time", default="2024-12-21T09:00:00-03:00",
                        help="instant of the lighting, ISO 8601 with UTC offset")
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)

    terrain, surface = build_surface(args.dem, args.exaggeration)
    grid = terrain.GetOutput()
    lat, lon, height = (grid.GetFieldData().GetArray("GeoOrigin").GetValue(i) for i in range(3))
    print("DEM %s: %d x %d posts, origin %.6f, %.6f at %.1f m, elevation %g..%g m"
          % (os.path.basename(args.dem), *grid.GetDimensions()[:2], lat, lon, height,
             *grid.GetPointData().GetArray("Elevation").GetRange()))

    surface.Update()
    write_xml(vtkXMLPolyDataWriter(), surface.GetOutput(), os.path.join(args.output_dir, "terrain.vtp"))

    if not os.environ.get("DISPLAY"):
        # Debian's VTK renders only through X; without one the render window aborts.
        sys.exit("terrain_demo: no X display for the rendering; run under xvfb-run -a")
    png = os.path.join(args.output_dir, "shaded_relief.png")
    render_shaded_relief(surface, png)
    print("wrote", png)

    # Light it: 21 December, 09:00 local time (UTC-3), clear sky, reflectance 0.2.
    sun, radiosity = light_terrain(terrain, args.date_time)
    lit = radiosity.GetOutput()
    irradiance = lit.GetPointData().GetArray("Irradiance")
    fields = lit.GetFieldData()
    print("sun at zenith %.1f deg, azimuth %.1f deg, beam %.0f W/m^2; global irradiance "
          "%.0f..%.0f W/m^2 (%d elements, %d links, %.2f s solve)"
          % (sun.GetZenith(), sun.GetAzimuth(), sun.GetNormalIrradiance(), *irradiance.GetRange(),
             fields.GetArray("Elements").GetValue(0), fields.GetArray("Links").GetValue(0),
             sum(fields.GetArray(n).GetValue(0) for n in
                 ("SecondsVisibilityBuild", "SecondsRefine", "SecondsGather", "SecondsPushPull"))))
    write_xml(vtkXMLStructuredGridWriter(), lit, os.path.join(args.output_dir, "irradiance.vts"))
    write_xml(vtkXMLPolyDataWriter(), radiosity.GetLeafMeshOutput(), os.path.join(args.output_dir, "leaves.vtp"))
    lit_surface = vtkDataSetSurfaceFilter()
    lit_surface.SetInputData(lit)
    lit_normals = vtkPolyDataNormals()
    lit_normals.SetInputConnection(lit_surface.GetOutputPort())
    lit_normals.SplittingOff()
    lit_normals.Update()
    png = os.path.join(args.output_dir, "irradiance.png")
    render_shaded_relief(lit_normals, png, array="Irradiance",
                         tint=((0.0, (0.10, 0.10, 0.45)), (0.5, (0.85, 0.35, 0.20)),
                               (1.0, (1.0, 0.95, 0.60))))
    print("wrote", png)


if __name__ == "__main__":
    main()
