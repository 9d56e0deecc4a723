#!/usr/bin/env python3
"""Solar radiation over a DEM, as a terrain analyst maps it: a DEM, a place and a date
in; beam, diffuse (sky), reflected and global irradiance and the sky view factor out,
as GeoTIFFs on the DEM's own grid, a map with a colour legend, a scale bar and a north
arrow, and plots of a profile and a histogram.

    xvfb-run -a /usr/bin/python3 Examples/terrain_analyst.py [DEM] [--when ISO-8601]
        [--reflectance 0.2] [--linke 3.0] [--output-dir DIR] [--quick]

Default DEM: the SRTM Olinda tile (UTM 25S); default time: the paper's Fig. 4 morning,
2024-08-15T08:30:00-03:00. The place is the DEM's own (its GeoOrigin); the sun comes
from NREL SPA with the ESRA clear sky (Linke turbidity, as GRASS r.sun), the sky is the
matching CIE clear sky (type 12). Writes into DIR: irradiance.tif (bands Irradiance,
SunIrradiance, SkyIrradiance, ReflectedIrradiance, SkyViewFactor), irradiance.vts,
irradiance_map.png, profile_histogram.png.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from example_support import (OLINDA, caption, coloured_actor, fail, legend, lit_dem,  # noqa: E402
                             map_decorations, parse_arguments, render, write)
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

from terralux import vtkTerrainRasterWriter  # noqa: E402

BANDS = ("Irradiance", "SunIrradiance", "SkyIrradiance", "ReflectedIrradiance", "SkyViewFactor")


def arguments(parser):
    parser.add_argument("dem", nargs="?", default=OLINDA, help="a DEM GDAL reads (default: Olinda)")
    parser.add_argument("--when", default="2024-08-15T08:30:00-03:00",
                        help="date and time, ISO 8601 with a UTC offset")
    parser.add_argument("--reflectance", type=float, default=0.2, help="ground reflectance (albedo)")
    parser.add_argument("--linke", type=float, default=3.0, help="Linke turbidity of the clear sky")


def light(dem, when, reflectance, linke, quick):
    """DEM -> terrain, sun and sky at its place and time -> irradiance at every post."""
    sun, radiosity, seconds = lit_dem(dem, when, reflectance, linke, quick, horn_normals=True)
    output = radiosity.GetOutput()
    if output.GetNumberOfPoints() == 0:
        fail("could not light %s (see the error above)" % dem)
    return sun, output, seconds


def write_rasters(lit, path):
    writer = vtkTerrainRasterWriter()
    writer.SetInputData(lit)
    writer.SetFileName(path)
    for name in BANDS:
        writer.AddArrayName(name)
    if not writer.Write():
        fail("could not write " + path)
    print("wrote", path)


def draw_map(lit, png, title):
    """Global irradiance as a map: north up, legend in W/m^2, scale bar, north arrow."""
    surface = vtkDataSetSurfaceFilter()  # blanked no-data posts drop out
    surface.SetInputData(lit)
    surface.Update()
    data = surface.GetOutput()
    low, high = data.GetPointData().GetArray("Irradiance").GetRange()
    actor, mapper = coloured_actor(data, "Irradiance", (low, high))
    bounds = data.GetBounds()
    render([actor], png, size=(1100, 900),
           overlays=[caption(title), lambda renderer: map_decorations(renderer, bounds)],
           key=legend(mapper, "Global\nirradiance\n(W/m^2)"))


def plot_profile_and_histogram(lit, png, title):
    """A west-east profile through the middle row and the histogram of global irradiance."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    nx, ny, _ = lit.GetDimensions()
    points = vtk_to_numpy(lit.GetPoints().GetData())
    values = {name: vtk_to_numpy(lit.GetPointData().GetArray(name)) for name in BANDS[:4]}
    row = slice((ny // 2) * nx, (ny // 2 + 1) * nx)
    distance = (points[row, 0] - points[row, 0].min()) / 1000.0
    figure, (profile, histogram) = plt.subplots(1, 2, figsize=(12, 4.5))
    for name, label in zip(BANDS[:4], ("global", "beam (sun)", "diffuse (sky)", "reflected")):
        profile.plot(distance, values[name][row], label=label)
    heights = vtk_to_numpy(lit.GetPointData().GetArray("Elevation"))[row]
    elevation = profile.twinx()
    elevation.fill_between(distance, heights, np.nanmin(heights), color="0.85", zorder=0)
    elevation.set_ylabel("elevation (m)")
    profile.set_zorder(elevation.get_zorder() + 1)
    profile.patch.set_visible(False)
    profile.set_xlabel("west-east distance (km)")
    profile.set_ylabel("irradiance (W/m$^2$)")
    profile.set_title("profile along the middle row")
    profile.legend(loc="best", fontsize=8)
    finite = values["Irradiance"][np.isfinite(values["Irradiance"])]
    histogram.hist(finite, bins=40, color="#3b528b")
    histogram.set_xlabel("global irradiance (W/m$^2$)")
    histogram.set_ylabel("posts")
    histogram.set_title("distribution over %d posts" % finite.size)
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(png, dpi=100)
    plt.close(figure)
    print("wrote", png)


def main():
    args = parse_arguments(__doc__.splitlines()[0], arguments)
    if not os.path.exists(args.dem):
        fail("no such DEM: %s" % args.dem)
    sun, lit, seconds = light(args.dem, args.when, args.reflectance, args.linke, args.quick)
    nx, ny, _ = lit.GetDimensions()
    print("%s: %d x %d posts, sun %.1f deg up at azimuth %.1f deg, solved in %.2f s" % (
        os.path.basename(args.dem), nx, ny, sun.GetOutput().GetFieldData().GetArray("SunAltitude").GetValue(0),
        sun.GetOutput().GetFieldData().GetArray("SunAzimuth").GetValue(0), seconds))
    for name in BANDS:
        array = vtk_to_numpy(lit.GetPointData().GetArray(name))
        print("  mean %-20s %8.2f %s" % (name, float(array[array == array].mean()),
                                           "" if name == "SkyViewFactor" else "W/m^2"))
    out = args.output_dir
    write_rasters(lit, os.path.join(out, "irradiance.tif"))
    write(lit, os.path.join(out, "irradiance.vts"))
    title = "%s, %s" % (os.path.basename(args.dem), args.when)
    draw_map(lit, os.path.join(out, "irradiance_map.png"), title)
    plot_profile_and_histogram(lit, os.path.join(out, "profile_histogram.png"), title)
    print("outputs in", os.path.abspath(out))


if __name__ == "__main__":
    main()
