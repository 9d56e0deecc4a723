"""What the TerraLux examples share: their command line, off-screen rendering with a
colour legend, map decorations (scale bar, north arrow), captions, and writers.

Rendering needs an X display: run the examples under `xvfb-run -a` on a headless machine.
"""
import argparse
import math
import os
import sys
import time

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLPolyDataWriter, vtkXMLStructuredGridWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkActor2D, vtkColorTransferFunction, vtkCoordinate,
                                         vtkPolyDataMapper, vtkPolyDataMapper2D, vtkRenderer,
                                         vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401,E402  (the OpenGL back end)

HERE = os.path.dirname(os.path.abspath(__file__))
OLINDA = os.path.join(HERE, "..", "Testing", "Data", "External", "olinda_dem_utm25s.tif")


def parse_arguments(description, extra=None):
    """--output-dir and --quick for every example; `extra(parser)` adds its own."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--output-dir", default="terralux-examples", help="where results go")
    parser.add_argument("--quick", action="store_true",
                        help="coarser settings, for tests (seconds instead of minutes)")
    if extra:
        extra(parser)
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    return args


def lit_dem(dem, when, reflectance=0.2, linke=3.0, quick=False, horn_normals=False):
    """The usual pipeline: a DEM (vtkTerrainSource), the sun over it at `when` (NREL SPA,
    ESRA clear sky with that Linke turbidity), the matching CIE clear sky, and the
    radiosity filter lighting the terrain. Returns (sun, radiosity, seconds of the solve)."""
    from terralux import vtkHierarchicalRadiosity, vtkSkySource, vtkSunSource, vtkTerrainSource

    terrain = vtkTerrainSource()
    terrain.SetFileName(dem)
    sun = vtkSunSource()
    sun.SetInputConnection(terrain.GetOutputPort())  # place: the DEM's GeoOrigin
    sun.SetDateTime(when)
    sun.SetLinkeTurbidity(linke)
    sky = vtkSkySource()
    sky.SetSunConnection(sun.GetOutputPort())
    sky.SetSkyType(12)  # CIE clear sky
    radiosity = vtkHierarchicalRadiosity()
    radiosity.SetInputConnection(terrain.GetOutputPort())
    radiosity.AddLightConnection(sun.GetOutputPort())
    radiosity.AddLightConnection(sky.GetOutputPort(0))
    if horn_normals:
        radiosity.SetPostNormals(vtkHierarchicalRadiosity.HORN_NORMALS)  # as r.slope.aspect
    return sun, radiosity, solve(radiosity, reflectance, quick)


def solve(radiosity, reflectance, quick):
    """Runs the radiosity filter (coarser with --quick); returns its wall time."""
    radiosity.SetDefaultReflectance(reflectance)
    if quick:
        radiosity.SetErrorTolerance(1e-2)
        radiosity.SetMaximumGatherRays(256)
    start = time.perf_counter()
    radiosity.Update()
    return time.perf_counter() - start


def fail(message):
    """One line on stderr and a non-zero exit, as a command-line tool should."""
    sys.exit("%s: %s" % (os.path.basename(sys.argv[0]), message))


def irradiance_colours(low, high):
    """A perceptually ordered ramp (dark blue to yellow), like viridis."""
    ramp = vtkColorTransferFunction()
    stops = ((0.0, (0.267, 0.005, 0.329)), (0.25, (0.229, 0.322, 0.546)), (0.5, (0.128, 0.567, 0.551)),
             (0.75, (0.369, 0.789, 0.383)), (1.0, (0.993, 0.906, 0.144)))
    for fraction, rgb in stops:
        ramp.AddRGBPoint(low + fraction * (high - low), *rgb)
    return ramp


def coloured_actor(data, array, value_range, association="point", gouraud=True):
    """An actor showing `data` coloured by one component-0 array, in the given range."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(data)
    if association == "point":
        mapper.SetScalarModeToUsePointFieldData()
    else:
        mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray(array)
    mapper.SetLookupTable(irradiance_colours(*value_range))
    mapper.UseLookupTableScalarRangeOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    if gouraud:
        actor.GetProperty().SetInterpolationToGouraud()
    # Lit only by ambient light: the colours are the physics, not a second shading.
    actor.GetProperty().SetAmbient(1.0)
    actor.GetProperty().SetDiffuse(0.0)
    return actor, mapper


def legend(mapper, title, labels=5):
    """A colour legend with its unit, for the picture's right-hand strip."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(mapper.GetLookupTable())
    bar.SetTitle(title)
    bar.SetNumberOfLabels(labels)
    bar.SetLabelFormat("%.0f")
    bar.SetPosition(0.15, 0.08)
    bar.SetWidth(0.7)
    bar.SetHeight(0.82)
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.1, 0.1, 0.1)
        text.ShadowOff()
        text.ItalicOff()
        text.BoldOff()
    bar.GetTitleTextProperty().SetFontSize(14)
    bar.UnconstrainedFontSizeOn()
    bar.GetLabelTextProperty().SetFontSize(13)
    return bar


def caption(text, position=(0.02, 0.95), size=18):
    """Text in the picture's normalised viewport coordinates."""
    actor = vtkTextActor()
    actor.SetInput(text)
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.GetPositionCoordinate().SetValue(*position)
    actor.GetTextProperty().SetFontSize(size)
    actor.GetTextProperty().SetColor(0.1, 0.1, 0.1)
    actor.GetTextProperty().SetVerticalJustificationToTop()
    return actor


def _lines_2d(points, world):
    """A 2-D polyline actor through `points`, in world or normalised viewport coordinates."""
    vertices = vtkPoints()
    for p in points:
        vertices.InsertNextPoint(p[0], p[1], p[2] if len(p) > 2 else 0.0)
    cells = vtkCellArray()
    cells.InsertNextCell(len(points))
    for k in range(len(points)):
        cells.InsertCellPoint(k)
    data = vtkPolyData()
    data.SetPoints(vertices)
    data.SetLines(cells)
    coordinate = vtkCoordinate()
    if world:
        coordinate.SetCoordinateSystemToWorld()
    else:
        coordinate.SetCoordinateSystemToNormalizedViewport()
    mapper = vtkPolyDataMapper2D()
    mapper.SetInputData(data)
    mapper.SetTransformCoordinate(coordinate)
    actor = vtkActor2D()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.05, 0.05, 0.05)
    actor.GetProperty().SetLineWidth(3)
    return actor


def map_decorations(renderer, bounds):
    """A scale bar (a round length, a fifth of the map's width) in the lower left and a
    north arrow in the upper right, for a map view with north up (+y)."""
    width = bounds[1] - bounds[0]
    length = 10 ** math.floor(math.log10(width / 5.0))
    for step in (5, 2, 1):
        if step * length <= width / 4.0:
            length *= step
            break
    x0 = bounds[0] + 0.05 * width
    y0 = bounds[2] + 0.05 * (bounds[3] - bounds[2])
    z = bounds[5]
    renderer.AddActor2D(_lines_2d([(x0, y0, z), (x0 + length, y0, z)], world=True))
    renderer.AddActor2D(_lines_2d([(x0, y0, z), (x0, y0 + 0.01 * width, z)], world=True))
    renderer.AddActor2D(_lines_2d([(x0 + length, y0, z), (x0 + length, y0 + 0.01 * width, z)], world=True))
    label = vtkTextActor()
    label.SetInput("%g km" % (length / 1000.0) if length >= 1000 else "%g m" % length)
    label.GetPositionCoordinate().SetCoordinateSystemToWorld()
    label.GetPositionCoordinate().SetValue(x0, y0 + 0.015 * width, z)
    label.GetTextProperty().SetFontSize(16)
    label.GetTextProperty().SetColor(0.05, 0.05, 0.05)
    renderer.AddActor2D(label)
    # North arrow: a shaft and a head pointing up the picture, and an N above it.
    renderer.AddActor2D(_lines_2d([(0.93, 0.80), (0.93, 0.88)], world=False))
    renderer.AddActor2D(_lines_2d([(0.918, 0.855), (0.93, 0.88), (0.942, 0.855)], world=False))
    renderer.AddActor2D(caption("N", position=(0.921, 0.925), size=18))


def render(actors, png, size=(1000, 800), view=None, overlays=(), key=None, background=(1.0, 1.0, 1.0)):
    """Renders off screen and writes a PNG. `view(renderer)` sets the camera (default: a
    map view from above, north up); overlays are 2-D actors or callables of the renderer;
    `key` (a legend) gets a strip of its own on the right."""
    window = vtkRenderWindow()
    renderer = vtkRenderer()
    renderer.SetBackground(*background)
    if key:
        renderer.SetViewport(0.0, 0.0, 0.84, 1.0)
        _add_key_strip(window, key, 0.84, background)
    for actor in actors:
        renderer.AddActor(actor)
    if view:
        view(renderer)
    else:
        map_view(renderer)
    for overlay in overlays:
        if callable(overlay):
            overlay(renderer)
        else:
            renderer.AddActor2D(overlay)
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    _write_png(window, png)


def render_panels(panels, png, size=(1600, 700), key=None, background=(1.0, 1.0, 1.0)):
    """Several pictures side by side in one PNG: each panel is (actors, view, overlays);
    `key` (a legend) gets a strip of its own on the right."""
    window = vtkRenderWindow()
    width = 0.88 if key else 1.0
    for k, (actors, view, overlays) in enumerate(panels):
        renderer = vtkRenderer()
        renderer.SetBackground(*background)
        renderer.SetViewport(width * k / len(panels), 0.0, width * (k + 1) / len(panels), 1.0)
        for actor in actors:
            renderer.AddActor(actor)
        view(renderer)
        for overlay in overlays:
            renderer.AddActor2D(overlay)
        window.AddRenderer(renderer)
    if key:
        _add_key_strip(window, key, width, background)
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.Render()
    _write_png(window, png)


def _add_key_strip(window, key, left, background):
    """The legend in a renderer of its own, from `left` to the window's right edge."""
    strip = vtkRenderer()
    strip.SetViewport(left, 0.0, 1.0, 1.0)
    strip.SetBackground(*background)
    strip.AddActor2D(key)
    window.AddRenderer(strip)


def _write_png(window, png):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote", png)


def map_view(renderer, zoom=1.15):
    """Parallel projection from above, north up."""
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    focal = camera.GetFocalPoint()
    camera.SetPosition(focal[0], focal[1], focal[2] + 1e5)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCamera()
    camera.Zoom(zoom)


def oblique_view(focal, azimuth_deg, elevation_deg, distance, zoom=1.0):
    """A camera looking at `focal` from a compass azimuth and an elevation angle."""
    def view(renderer):
        camera = renderer.GetActiveCamera()
        a, e = math.radians(azimuth_deg), math.radians(elevation_deg)
        camera.SetFocalPoint(*focal)
        camera.SetPosition(focal[0] + distance * math.sin(a) * math.cos(e),
                           focal[1] + distance * math.cos(a) * math.cos(e),
                           focal[2] + distance * math.sin(e))
        camera.SetViewUp(0.0, 0.0, 1.0)
        camera.Zoom(zoom)
        renderer.ResetCameraClippingRange()
    return view


def write(data, path):
    """Writes a data set with the VTK XML writer its type calls for."""
    name = data.GetClassName()
    if name == "vtkPolyData":
        writer = vtkXMLPolyDataWriter()
    elif name == "vtkStructuredGrid":
        writer = vtkXMLStructuredGridWriter()
    else:
        writer = vtkXMLMultiBlockDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    if not writer.Write():
        fail("could not write " + path)
    print("wrote", path)


def field_value(data, name):
    """Component 0 of a field-data array (the solve's statistics)."""
    array = data.GetFieldData().GetArray(name)
    return array.GetComponent(0, 0) if array else float("nan")
