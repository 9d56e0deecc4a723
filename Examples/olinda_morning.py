#!/usr/bin/env python3
"""The paper's Fig. 4: the Olinda terrain (SRTM, UTM 25S) lit by sky and sun on an
August morning, coloured by radiosity with Gouraud shading on the adaptive leaf mesh.

    xvfb-run -a /usr/bin/python3 Examples/olinda_morning.py [--output-dir DIR] [--quick]

Writes into DIR: olinda_lit.vts (the DEM grid with the irradiance arrays),
olinda_radiosity.tif (Radiosity and Irradiance as GeoTIFF bands), olinda_leaves.vtp
(the leaf mesh) and fig4_olinda.png.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from example_support import (OLINDA, caption, coloured_actor, fail, field_value, legend, lit_dem,  # noqa: E402
                             oblique_view, parse_arguments, render, write)
from vtkmodules.vtkCommonTransforms import vtkTransform  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter  # noqa: E402

from terralux import vtkTerrainRasterWriter  # noqa: E402

WHEN = "2024-08-15T08:30:00-03:00"
EXAGGERATION = 5.0  # the terrain's relief is 90 m over 10 km


def main():
    args = parse_arguments(__doc__.splitlines()[0])
    out = args.output_dir
    sun, radiosity, seconds = lit_dem(OLINDA, WHEN, reflectance=0.2, quick=args.quick)
    lit = radiosity.GetOutput()
    if lit.GetNumberOfPoints() == 0:
        fail("could not read or light %s (run cmake/install-dependencies.sh)" % OLINDA)
    leaves = radiosity.GetOutputDataObject(1)
    print("Olinda, %s: %d elements, %d links, %d leaves, %.2f s" % (
        WHEN, field_value(lit, "Elements"), field_value(lit, "Links"), leaves.GetNumberOfCells(), seconds))

    write(lit, os.path.join(out, "olinda_lit.vts"))
    write(leaves, os.path.join(out, "olinda_leaves.vtp"))
    raster = vtkTerrainRasterWriter()
    raster.SetInputData(lit)
    raster.SetFileName(os.path.join(out, "olinda_radiosity.tif"))
    raster.AddArrayName("Radiosity")
    raster.AddArrayName("Irradiance")
    if not raster.Write():
        fail("could not write the GeoTIFF")
    print("wrote", raster.GetFileName())

    # Radiosity on the leaf mesh, relief exaggerated, seen from the south-east.
    transform = vtkTransform()
    transform.Scale(1.0, 1.0, EXAGGERATION)
    exaggerate = vtkTransformFilter()
    exaggerate.SetTransform(transform)
    exaggerate.SetInputData(leaves)
    exaggerate.Update()
    shown = exaggerate.GetOutput()
    actor, mapper = coloured_actor(shown, "Radiosity", shown.GetPointData().GetArray("Radiosity").GetRange())
    centre = shown.GetCenter()
    render([actor], os.path.join(out, "fig4_olinda.png"), size=(1100, 800),
           view=oblique_view(centre, 200.0, 45.0, 26000.0),
           overlays=[caption("Olinda, %s: radiosity from the south-south-west (relief x %g)" % (WHEN, EXAGGERATION))],
           key=legend(mapper, "Radiosity\n(W/m^2)"))


if __name__ == "__main__":
    main()
