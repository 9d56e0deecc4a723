"""The plugin tests' reference: the same pipelines in plain VTK Python (Debian's VTK 9.1
and the terralux package of the main build), written where the pvpython tests read them.

  /usr/bin/python3 plain_vtk_reference.py DEM OUTPUT_DIR

writes into OUTPUT_DIR:
  defaults.json           every Get<X> value of a fresh object of each class whose
                          Set<X> a proxy property calls (the proxies' defaults must match)
  radiosity.vts           TerrainSource -> SunSource -> SkySource -> HierarchicalRadiosity
  radiosity_rho05.vts     the same with DefaultReflectance 0.5
  radiosity_sun_only.vts  the same with the sun as the only light
  radiosity.tif           vtkTerrainRasterWriter of radiosity.vts (Irradiance, SkyViewFactor)
  irradiation.vts         SolarIrradiation over three morning hours at 60-minute steps
  irradiation_instant.vts the same filter's instant 1.5 h after the start
  irradiation_times.json  the TIME_STEPS it advertises
"""
import json
import os
import sys

from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm, vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkIOXML import vtkXMLStructuredGridWriter

import terralux

from pipeline_parameters import DATE_TIME, IRRADIATION_INSTANT, IRRADIATION_RANGE


def defaults_of(cls):
    """Get<X>() of a fresh object for every X with a Set<X> of its own (not vtkAlgorithm's),
    where the value is plain."""
    obj = cls()
    values = {}
    for name in dir(obj):
        if not name.startswith("Get") or not hasattr(obj, "Set" + name[3:]) or hasattr(vtkAlgorithm, name):
            continue
        try:
            value = getattr(obj, name)()
        except TypeError:
            continue  # needs arguments
        if isinstance(value, (int, float, str, tuple)) or value is None:
            values[name[3:]] = list(value) if isinstance(value, tuple) else value
    return values


def write(algorithm, path, port=0):
    writer = vtkXMLStructuredGridWriter()
    writer.SetInputConnection(algorithm.GetOutputPort(port))
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    if not writer.Write():
        raise SystemExit("could not write " + path)


def radiosity(terrain, reflectance=0.2, with_sky=True):
    sun = terralux.vtkSunSource()
    sun.SetInputConnection(terrain.GetOutputPort())
    sun.SetDateTime(DATE_TIME)
    solver = terralux.vtkHierarchicalRadiosity()
    solver.AddInputConnection(terrain.GetOutputPort())
    solver.AddLightConnection(sun.GetOutputPort())
    if with_sky:
        sky = terralux.vtkSkySource()
        sky.SetSunConnection(sun.GetOutputPort())
        solver.AddLightConnection(sky.GetOutputPort(0))
    solver.SetDefaultReflectance(reflectance)
    solver.Update()
    return solver


def irradiation(terrain, integrate=True):
    solver = terralux.vtkSolarIrradiation()
    solver.SetInputConnection(terrain.GetOutputPort())
    solver.SetStartTime(IRRADIATION_RANGE[0])
    solver.SetEndTime(IRRADIATION_RANGE[1])
    solver.SetTimeStep(IRRADIATION_RANGE[2])
    solver.SetIntegrateOverTime(integrate)
    if integrate:
        solver.Update()
    else:
        solver.UpdateInformation()
        solver.GetOutputInformation(0).Set(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP(),
                                           IRRADIATION_INSTANT)
        solver.Update()
    return solver


def main(dem, out):
    os.makedirs(out, exist_ok=True)
    classes = [terralux.vtkTerrainReader, terralux.vtkSunSource, terralux.vtkSkySource,
               terralux.vtkHierarchicalRadiosity, terralux.vtkSolarIrradiation,
               terralux.vtkTerrainRasterWriter]
    with open(os.path.join(out, "defaults.json"), "w") as f:
        json.dump({cls.__name__: defaults_of(cls) for cls in classes}, f, indent=1)

    terrain = terralux.vtkTerrainSource()
    terrain.SetFileName(dem)
    terrain.Update()

    solver = radiosity(terrain)
    write(solver, os.path.join(out, "radiosity.vts"))
    raster = terralux.vtkTerrainRasterWriter()
    raster.SetInputConnection(solver.GetOutputPort(0))
    raster.SetFileName(os.path.join(out, "radiosity.tif"))
    raster.AddArrayName("Irradiance")
    raster.AddArrayName("SkyViewFactor")
    if not raster.Write():
        raise SystemExit("could not write radiosity.tif")
    write(radiosity(terrain, reflectance=0.5), os.path.join(out, "radiosity_rho05.vts"))
    write(radiosity(terrain, with_sky=False), os.path.join(out, "radiosity_sun_only.vts"))

    summed = irradiation(terrain)
    write(summed, os.path.join(out, "irradiation.vts"))
    times = summed.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    with open(os.path.join(out, "irradiation_times.json"), "w") as f:
        json.dump(list(times), f)
    write(irradiation(terrain, integrate=False), os.path.join(out, "irradiation_instant.vts"))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
