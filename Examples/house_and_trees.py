#!/usr/bin/env python3
"""The paper's Figs. 5 to 7: a house and two trees on a small hill, lit by a CIE clear
sky alone (soft shadows toward the bright part of the sky), then by the sky and the sun
(sharp shadows, trees shadowing the walls), and seen toward the sun with the sky dome.

    xvfb-run -a /usr/bin/python3 Examples/house_and_trees.py [--output-dir DIR] [--quick]

Writes into DIR: sky_only.vtm and sky_and_sun.vtm (the scene with its irradiance arrays),
fig5_sky_only.png, fig6_sky_and_sun.png, fig7_toward_the_sun.png.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from example_scenes import HOUSE, clear_sky, house_and_trees, sun_at  # noqa: E402
from example_support import (caption, coloured_actor, field_value, legend, oblique_view,  # noqa: E402
                             parse_arguments, render, solve, write)

from terralux import vtkHierarchicalRadiosity  # noqa: E402

SUN_ALTITUDE, SUN_AZIMUTH = 35.0, 160.0  # degrees; the sun stands south-south-east


def light(scene, lights, quick):
    """Lights the scene; returns the filter and its wall time."""
    radiosity = vtkHierarchicalRadiosity()
    radiosity.SetInputData(scene)
    for port in lights:
        radiosity.AddLightConnection(port)
    return radiosity, solve(radiosity, 0.3, quick)


def picture(leaves, png, title, value_range, view):
    """The adaptive leaf mesh (output 1: every surface, values continuous across
    T-vertices) coloured by irradiance with Gouraud shading."""
    actor, mapper = coloured_actor(leaves, "Irradiance", value_range)
    render([actor], png, size=(1100, 800), view=view, overlays=[caption(title)],
           key=legend(mapper, "Irradiance\n(W/m^2)"))


def main():
    args = parse_arguments(__doc__.splitlines()[0])
    out = args.output_dir
    scene = house_and_trees(args.quick)
    sky = clear_sky(SUN_ALTITUDE, SUN_AZIMUTH, diffuse=100.0, levels=5 if args.quick else 7, dome_radius=60.0)
    sun = sun_at(SUN_ALTITUDE, SUN_AZIMUTH, 800.0)

    sky_only, seconds_sky = light(scene, [sky.GetOutputPort(0)], args.quick)
    with_sun, seconds_sun = light(scene, [sky.GetOutputPort(0), sun.GetOutputPort()], args.quick)

    for name, radiosity, seconds in (("sky_only", sky_only, seconds_sky), ("sky_and_sun", with_sun, seconds_sun)):
        lit = radiosity.GetOutput()
        write(lit, os.path.join(out, name + ".vtm"))
        print("%s: %d elements, %d links, %d leaves, %.2f s" % (
            name, field_value(lit, "Elements"), field_value(lit, "Links"),
            radiosity.GetOutputDataObject(1).GetNumberOfCells(), seconds))

    # Figs. 5 and 6: from the south-west, above the house's roof.
    view = oblique_view((0.0, 0.0, 2.0), 215.0, 35.0, 75.0, zoom=1.1)
    ground = sky_only.GetOutput().GetBlock(0).GetPointData().GetArray("Irradiance").GetRange()
    picture(sky_only.GetOutputDataObject(1), os.path.join(out, "fig5_sky_only.png"),
            "Sky only (CIE clear sky, 100 W/m^2): soft shadows toward the bright sky", ground, view)
    lit = with_sun.GetOutput().GetBlock(0).GetPointData().GetArray("Irradiance").GetRange()
    picture(with_sun.GetOutputDataObject(1), os.path.join(out, "fig6_sky_and_sun.png"),
            "Sky and sun (%g deg up, azimuth %g deg): sharp shadows" % (SUN_ALTITUDE, SUN_AZIMUTH), lit, view)

    # Fig. 7: toward the sun, the sky dome behind the scene, coloured by its radiance.
    dome = sky.GetDomeOutput()
    dome_actor, dome_mapper = coloured_actor(dome, "Radiance", dome.GetCellData().GetArray("Radiance").GetRange(),
                                             association="cell", gouraud=False)
    scene_actor, _ = coloured_actor(with_sun.GetOutputDataObject(1), "Irradiance", lit)
    actors = [dome_actor, scene_actor]
    toward = oblique_view((0.0, 0.0, 16.0), SUN_AZIMUTH + 180.0, 5.0, 45.0, zoom=0.8)
    render(actors, os.path.join(out, "fig7_toward_the_sun.png"), size=(1100, 800), view=toward,
           overlays=[caption("Toward the sun: the sky dome's radiance behind the lit scene")],
           key=legend(dome_mapper, "Sky radiance\n(W/m^2/sr)"))

    # Shadows where the geometry puts them: the ground north-north-west of the house lies
    # in its shadow, the ground south-south-east of it in the sun.
    terrain = with_sun.GetOutput().GetBlock(0)
    behind = terrain.FindPoint(-1.5, HOUSE[3] + 3.0, 0.0)
    front = terrain.FindPoint(1.5, HOUSE[2] - 3.0, 0.0)
    sun_values = terrain.GetPointData().GetArray("SunIrradiance")
    print("ground behind the house: %.1f W/m^2 of sun, in front: %.1f W/m^2" % (
        sun_values.GetValue(behind), sun_values.GetValue(front)))


if __name__ == "__main__":
    main()
