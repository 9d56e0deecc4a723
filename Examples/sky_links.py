#!/usr/bin/env python3
"""The paper's Fig. 9: the links to the sky drawn over the house-and-trees scene
(vtkHierarchicalRadiosity's output 2), coloured by the level of the sky patch: large
patches are linked high in the hierarchy, small ones where the sky is seen in part.

    xvfb-run -a /usr/bin/python3 Examples/sky_links.py [--output-dir DIR] [--quick]

Writes into DIR: links.vtp (every link, cell data Level, Power, Sender, SenderLevel),
sky_links.vtp (those from sky patches) and fig9_sky_links.png.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from example_scenes import clear_sky, house_and_trees  # noqa: E402
from example_support import caption, coloured_actor, legend, oblique_view, parse_arguments, render, write  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataObject  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkThreshold  # noqa: E402
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter  # noqa: E402

from terralux import vtkHierarchicalRadiosity  # noqa: E402

SKY_PATCH = 1  # the Sender value of links from sky patches


def main():
    args = parse_arguments(__doc__.splitlines()[0])
    radiosity = vtkHierarchicalRadiosity()
    radiosity.SetInputData(house_and_trees(args.quick))
    sky = clear_sky(35.0, 160.0, levels=5 if args.quick else 7)
    radiosity.AddLightConnection(sky.GetOutputPort(0))
    radiosity.SetDefaultReflectance(0.3)
    radiosity.SetErrorTolerance(3e-3)  # coarse enough to see single links
    radiosity.Update()
    links = radiosity.GetOutputDataObject(2)
    write(links, os.path.join(args.output_dir, "links.vtp"))

    # The links from sky patches, as a ParaView user would pick them: Threshold on Sender.
    threshold = vtkThreshold()
    threshold.SetInputData(links)
    threshold.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, "Sender")
    threshold.SetLowerThreshold(SKY_PATCH)
    threshold.SetUpperThreshold(SKY_PATCH)
    lines = vtkGeometryFilter()
    lines.SetInputConnection(threshold.GetOutputPort())
    lines.Update()
    sky_links = lines.GetOutput()
    write(sky_links, os.path.join(args.output_dir, "sky_links.vtp"))
    levels = sky_links.GetCellData().GetArray("SenderLevel").GetRange()
    print("%d links, %d from sky patches of levels %d to %d" % (
        links.GetNumberOfCells(), sky_links.GetNumberOfCells(), levels[0], levels[1]))

    scene_actor, _ = coloured_actor(radiosity.GetOutputDataObject(1), "Irradiance",
                                    radiosity.GetOutputDataObject(1).GetPointData().GetArray("Irradiance").GetRange())
    scene_actor.GetProperty().SetOpacity(0.85)
    link_actor, mapper = coloured_actor(sky_links, "SenderLevel", levels, association="cell", gouraud=False)
    link_actor.GetProperty().SetLineWidth(1.0)
    link_actor.GetProperty().SetOpacity(0.6)
    render([scene_actor, link_actor], os.path.join(args.output_dir, "fig9_sky_links.png"), size=(1100, 900),
           view=oblique_view((0.0, 0.0, 20.0), 215.0, 30.0, 220.0),
           overlays=[caption("Links to the sky over the scene, coloured by the sky patch's level")],
           key=legend(mapper, "Sky patch\nlevel", labels=int(levels[1] - levels[0]) + 1))


if __name__ == "__main__":
    main()
