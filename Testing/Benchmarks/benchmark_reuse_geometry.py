"""Time of a second vtkHierarchicalRadiosity update over the same terrain (ReuseGeometry:
the Embree scene, the posts' horizons and the hierarchy kept) against a fresh filter at the same
instant, and whether their values agree. Usage (with the build's Python package on
PYTHONPATH): /usr/bin/python3 benchmark_reuse_geometry.py DEM.tif"""
import sys, time
from terralux import vtkTerrainSource, vtkSunSource, vtkSkySource, vtkHierarchicalRadiosity
dem = sys.argv[1]
def pipeline(reuse):
    terrain = vtkTerrainSource(); terrain.SetFileName(dem)
    sun = vtkSunSource(); sun.SetInputConnection(terrain.GetOutputPort())
    sky = vtkSkySource(); sky.SetSunConnection(sun.GetOutputPort())
    r = vtkHierarchicalRadiosity(); r.SetInputConnection(terrain.GetOutputPort()); r.SetReuseGeometry(reuse)
    r.AddLightConnection(sun.GetOutputPort()); r.AddLightConnection(sky.GetOutputPort(0))
    terrain.Update()
    return sun, r
def timed(sun, r, when):
    sun.SetDateTime(when); t = time.time(); r.Update(); return time.time() - t
sun, r = pipeline(1)
first = timed(sun, r, "2024-06-21T09:00:00+00:00")
reused = timed(sun, r, "2024-06-21T12:00:00+00:00")
sun2, r2 = pipeline(0)
fresh = timed(sun2, r2, "2024-06-21T12:00:00+00:00")
a = r.GetOutput().GetPointData().GetArray("Irradiance"); b = r2.GetOutput().GetPointData().GetArray("Irradiance")
same = all(a.GetValue(k) == b.GetValue(k) for k in range(0, a.GetNumberOfTuples(), 997))
print("first update %.2f s; noon after it, geometry reused: %.2f s; noon, fresh filter: %.2f s; ratio %.2f; same values: %s" % (first, reused, fresh, reused / fresh, same))
