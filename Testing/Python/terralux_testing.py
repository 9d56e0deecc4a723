"""Helpers shared by the Python tests: paths, field data and error capture."""
import os
import tempfile

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING

EXTERNAL_DATA_DIR = os.environ.get("TERRALUX_EXTERNAL_DATA_DIR", "")
OLINDA = os.path.join(EXTERNAL_DATA_DIR, "olinda_dem_utm25s.tif")
LUXEMBOURG = os.path.join(EXTERNAL_DATA_DIR, "elev.tif")


def terrain_sun_sky(dem, when, sky_levels=6):
    """The usual pipeline head: terrain from a DEM, the sun over it at `when` (ISO 8601),
    and a sky lit by that sun. Returns (terrain, sun, sky), not yet updated."""
    from terralux import vtkSkySource, vtkSunSource, vtkTerrainSource

    terrain = vtkTerrainSource()
    terrain.SetFileName(dem)
    sun = vtkSunSource()
    sun.SetInputConnection(terrain.GetOutputPort())
    sun.SetDateTime(when)
    sky = vtkSkySource()
    sky.SetSunConnection(sun.GetOutputPort())
    sky.SetLevels(sky_levels)
    return terrain, sun, sky


def field_values(data, name):
    """Every value of field array `name` of `data` (tuples of one value, or one tuple of
    several: GeoOrigin and SunDirection are one tuple of three)."""
    array = data.GetFieldData().GetArray(name)
    return [array.GetValue(k) for k in range(array.GetNumberOfValues())]


def field(data, name, k=0):
    """Value k of field array `name` of `data`."""
    return field_values(data, name)[k]


def scratch_dir():
    """A fresh folder for files a test writes."""
    return tempfile.mkdtemp(prefix="terralux-py-")


class ErrorCatcher:
    """Collects vtkErrorMacro messages of an algorithm (and its executive)."""

    def __init__(self, vtk_object):
        self.messages = []
        vtk_object.AddObserver("ErrorEvent", self._record)
        if hasattr(vtk_object, "GetExecutive"):
            vtk_object.GetExecutive().AddObserver("ErrorEvent", self._record)

    # VTK passes the message only to observers that ask for it as call data.
    @calldata_type(VTK_STRING)
    def _record(self, caller, event, message=None):
        self.messages.append(str(message))

    def text(self):
        return "\n".join(self.messages)
