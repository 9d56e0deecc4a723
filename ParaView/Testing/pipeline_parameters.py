"""The parameters both sides of the plugin tests use (plain VTK and pvpython), and the
plugin's pipeline the pvpython and pvbatch tests build."""
# The paper's August morning on the Olinda DEM.
DATE_TIME = "2024-08-15T08:30:00-03:00"
# Three morning hours at 60-minute steps: start, end, step in minutes.
IRRADIATION_RANGE = ("2024-08-15T06:00:00-03:00", "2024-08-15T09:00:00-03:00", 60.0)
# The instant of the time-step test, hours after the start.
IRRADIATION_INSTANT = 1.5
# Relative agreement the plugin's arrays must reach with plain VTK's.
RELATIVE_TOLERANCE = 1e-6


def paraview_pipeline(simple, dem):
    """TerrainSource -> SunSource -> SkySource -> HierarchicalRadiosity with the plugin's
    proxies (`simple`: paraview.simple, the plugin loaded). Returns the four proxies."""
    terrain = simple.TerrainSource(FileName=dem)
    sun = simple.SunSource(Input=terrain, DateTime=DATE_TIME)
    sky = simple.SkySource(Input=sun)
    solver = simple.HierarchicalRadiosity(Input=terrain, Lights=[sun, sky])
    return terrain, sun, sky, solver
