"""pvbatch (under xvfb-run): Examples/paraview_state.py, the GUI's state script, builds
its pipeline and shows the terrain coloured by Irradiance.

Environment: TERRALUX_PLUGIN, TERRALUX_DEM, TERRALUX_STATE_SCRIPT.
"""
import os
import sys

from paraview import simple as pv

with open(os.environ["TERRALUX_STATE_SCRIPT"]) as f:
    exec(compile(f.read(), os.environ["TERRALUX_STATE_SCRIPT"], "exec"), {"__name__": "__main__"})

failures = []
names = sorted(name for name, _ in pv.GetSources())
for wanted in ("Olinda DEM", "SunSource1", "SkySource1", "HierarchicalRadiosity1", "SolarIrradiation1"):
    if wanted not in names:
        failures.append("no %s in the pipeline (%s)" % (wanted, names))
solver = pv.FindSource("HierarchicalRadiosity1")
view = pv.GetActiveView()
display = pv.GetDisplayProperties(solver, view)
if list(display.ColorArrayName) != ["POINTS", "Irradiance"]:
    failures.append("the terrain is coloured by %s" % list(display.ColorArrayName))
points = solver.GetDataInformation().GetNumberOfPoints()
if points != 111 * 111:
    failures.append("the solve has %d points" % points)
low, high = solver.PointData["Irradiance"].GetRange()
if not 300 < low < high < 1100:
    failures.append("Irradiance range %g .. %g W/m^2" % (low, high))
times = pv.FindSource("SolarIrradiation1").TimestepValues
if len(times) != 49:
    failures.append("the day offers %d time steps, not 49" % len(times))
if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("OK: %s; Irradiance %.1f .. %.1f W/m^2; %d time steps" % (names, low, high, len(times)))
