#!/usr/bin/env python3
"""Objects from files: a building written as STL, read back with VTK's STL reader and
placed on the real Olinda DEM at a geographic position (vtkGeodeticFrame), then lit by
the sun and the sky with the terrain.

    xvfb-run -a /usr/bin/python3 Examples/building_on_dem.py [--latitude DEG --longitude DEG]
        [--output-dir DIR] [--quick]

Any mesh a VTK reader gives (vtkOBJReader, vtkSTLReader, vtkPLYReader, ...) enters the
same way: in metres, z up, placed by translating it to the local east-north-up point of
its geographic position. Writes into DIR: building.stl, lit_scene.vtm,
building_on_dem.png.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from example_support import (OLINDA, caption, coloured_actor, fail, legend, oblique_view,  # noqa: E402
                             parse_arguments, render, solve, write)
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMultiBlockDataSet, vtkPolyData  # noqa: E402
from vtkmodules.vtkCommonTransforms import vtkTransform  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter  # noqa: E402
from vtkmodules.vtkIOGeometry import vtkSTLReader, vtkSTLWriter  # noqa: E402

from terralux import (vtkGeodeticFrame, vtkHierarchicalRadiosity, vtkSkySource, vtkSunSource,  # noqa: E402
                      vtkTerrainSource)

WHEN = "2024-08-15T07:00:00-03:00"  # a low morning sun: long shadows
# A hall 160 x 70 m and 30 m high (a few DEM posts wide) with a gable roof 12 m higher.
LENGTH, WIDTH, EAVES, RIDGE = 160.0, 70.0, 30.0, 42.0


def arguments(parser):
    # Default: a point on the flat coastal plain south of the hills.
    parser.add_argument("--latitude", type=float, default=-8.0240)
    parser.add_argument("--longitude", type=float, default=-34.8690)


def hall():
    """A closed, outward-facing gabled hall centred on the origin, its floor at z = 0."""
    x, y = 0.5 * LENGTH, 0.5 * WIDTH
    corners = [(-x, -y, 0), (x, -y, 0), (x, y, 0), (-x, y, 0),              # floor
               (-x, -y, EAVES), (x, -y, EAVES), (x, y, EAVES), (-x, y, EAVES),  # eaves
               (-x, 0, RIDGE), (x, 0, RIDGE)]                               # ridge
    faces = [(0, 3, 2, 1),                                   # floor, facing down
             (0, 1, 5, 4), (2, 3, 7, 6),                     # long walls
             (1, 2, 6, 9, 5), (3, 0, 4, 8, 7),               # gable walls
             (4, 5, 9, 8), (6, 7, 8, 9)]                     # roof
    points = vtkPoints()
    for p in corners:
        points.InsertNextPoint(*p)
    polys = vtkCellArray()
    for face in faces:
        polys.InsertNextCell(len(face))
        for k in face:
            polys.InsertCellPoint(k)
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def main():
    args = parse_arguments(__doc__.splitlines()[0], arguments)
    out = args.output_dir
    stl = os.path.join(out, "building.stl")
    writer = vtkSTLWriter()  # STL holds triangles: TerraLux reads them as they are
    writer.SetInputData(hall())
    writer.SetFileName(stl)
    writer.Write()
    print("wrote", stl)

    terrain = vtkTerrainSource()
    terrain.SetFileName(OLINDA)
    terrain.Update()
    ground = terrain.GetOutput()
    if ground.GetNumberOfPoints() == 0:
        fail("could not read %s" % OLINDA)
    frame = vtkGeodeticFrame()
    frame.SetOriginFromFieldData(ground)
    east, north, _ = frame.GeodeticToLocal(args.latitude, args.longitude, 0.0)
    bounds = ground.GetBounds()
    if not (bounds[0] < east < bounds[1] and bounds[2] < north < bounds[3]):
        fail("%.4f, %.4f is not on the DEM" % (args.latitude, args.longitude))
    # The floor one metre into the ground at the nearest post, so no light leaks under it.
    base = ground.GetPoint(ground.FindPoint(east, north, 0.0))[2] - 1.0
    print("building at %.4f, %.4f: %.0f m east, %.0f m north of the DEM's origin, floor %.1f m" % (
        args.latitude, args.longitude, east, north, base))

    reader = vtkSTLReader()
    reader.SetFileName(stl)
    place = vtkTransform()
    place.Translate(east, north, base)
    placed = vtkTransformPolyDataFilter()
    placed.SetTransform(place)
    placed.SetInputConnection(reader.GetOutputPort())
    placed.Update()

    scene = vtkMultiBlockDataSet()
    scene.SetBlock(0, ground)
    scene.SetBlock(1, placed.GetOutput())
    sun = vtkSunSource()
    sun.SetInputData(ground)
    sun.SetDateTime(WHEN)
    sky = vtkSkySource()
    sky.SetSunConnection(sun.GetOutputPort())
    radiosity = vtkHierarchicalRadiosity()
    radiosity.SetInputData(scene)
    radiosity.AddLightConnection(sun.GetOutputPort())
    radiosity.AddLightConnection(sky.GetOutputPort(0))
    solve(radiosity, 0.25, args.quick)
    lit = radiosity.GetOutput()
    write(lit, os.path.join(out, "lit_scene.vtm"))
    building = lit.GetBlock(1)
    values = building.GetPointData().GetArray("SunIrradiance").GetRange()
    print("sun on the building: %.0f to %.0f W/m^2" % values)

    leaves = radiosity.GetOutputDataObject(1)
    actor, mapper = coloured_actor(leaves, "Irradiance", leaves.GetPointData().GetArray("Irradiance").GetRange())
    render([actor], os.path.join(out, "building_on_dem.png"), size=(1100, 800),
           view=oblique_view((east - 80.0, north, base + 10.0), 200.0, 35.0, 900.0),
           overlays=[caption("A hall from STL at %.4f, %.4f on Olinda, %s" % (args.latitude, args.longitude, WHEN))],
           key=legend(mapper, "Irradiance\n(W/m^2)"))


if __name__ == "__main__":
    main()
