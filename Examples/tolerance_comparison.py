#!/usr/bin/env python3
"""The paper's Fig. 8: the house-and-trees scene under sky and sun at a coarse and at a
fine ErrorTolerance side by side, each captioned with its time, links and leaf elements:
what the tolerance buys.

    xvfb-run -a /usr/bin/python3 Examples/tolerance_comparison.py [--output-dir DIR] [--quick]

Writes into DIR: coarse.vtp and fine.vtp (the leaf meshes) and fig8_tolerance.png.
"""
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from example_scenes import clear_sky, house_and_trees, sun_at  # noqa: E402
from example_support import (caption, coloured_actor, field_value, legend, oblique_view,  # noqa: E402
                             parse_arguments, render_panels, write)

from terralux import vtkHierarchicalRadiosity  # noqa: E402


def main():
    args = parse_arguments(__doc__.splitlines()[0])
    scene = house_and_trees(args.quick)
    sky = clear_sky(35.0, 160.0, levels=5 if args.quick else 7)
    sun = sun_at(35.0, 160.0, 800.0)
    tolerances = (3e-2, 1e-3) if args.quick else (3e-2, 1e-4)
    panels, value_range, mapper = [], None, None
    view = oblique_view((0.0, 0.0, 2.0), 215.0, 35.0, 75.0, zoom=1.1)
    for name, tolerance in zip(("coarse", "fine"), tolerances):
        radiosity = vtkHierarchicalRadiosity()
        radiosity.SetInputData(scene)
        radiosity.AddLightConnection(sky.GetOutputPort(0))
        radiosity.AddLightConnection(sun.GetOutputPort())
        radiosity.SetDefaultReflectance(0.3)
        radiosity.SetErrorTolerance(tolerance)
        start = time.perf_counter()
        radiosity.Update()
        seconds = time.perf_counter() - start
        leaves = radiosity.GetOutputDataObject(1)
        write(leaves, os.path.join(args.output_dir, name + ".vtp"))
        lit = radiosity.GetOutput()
        text = "ErrorTolerance %g: %.2f s, %d links, %d leaf elements" % (
            tolerance, seconds, field_value(lit, "Links"), leaves.GetNumberOfCells())
        print(text)
        if value_range is None:  # both panels on one scale
            value_range = leaves.GetPointData().GetArray("Irradiance").GetRange()
        actor, mapper = coloured_actor(leaves, "Irradiance", value_range)
        # The leaf mesh's edges show where refinement went.
        actor.GetProperty().EdgeVisibilityOn()
        actor.GetProperty().SetEdgeColor(0.2, 0.2, 0.2)
        actor.GetProperty().SetLineWidth(0.5)
        panels.append(([actor], view, [caption(text, size=15)]))
    render_panels(panels, os.path.join(args.output_dir, "fig8_tolerance.png"),
                  key=legend(mapper, "Irradiance\n(W/m^2)"))


if __name__ == "__main__":
    main()
