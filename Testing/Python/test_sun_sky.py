"""terrain -> sun -> sky from Python: values read back from the outputs."""
import math
import unittest

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkCommonCore import vtkFloatArray

from terralux import vtkSkySource
from terralux_testing import OLINDA, ErrorCatcher, field, terrain_sun_sky



def map_horizontal_irradiance(image, band=0):
    nx, ny, _ = (d - 1 for d in image.GetDimensions())
    radiance = image.GetCellData().GetArray("Radiance")
    total = 0.0
    for j in range(ny):
        u0, u1 = 0.5 * math.pi * j / ny, 0.5 * math.pi * (j + 1) / ny
        weight = (2 * math.pi / nx) * 0.5 * (math.sin(u1) ** 2 - math.sin(u0) ** 2)
        total += weight * sum(radiance.GetComponent(i + j * nx, band) for i in range(nx))
    return total


class TerrainSunSky(unittest.TestCase):
    def setUp(self):
        self.terrain, self.sun, self.sky = terrain_sun_sky(OLINDA, "2024-12-21T09:00:00-03:00")

    def test_sun_at_olinda(self):
        self.sky.Update()
        sun = self.sun.GetOutput()
        lat, lon, _ = (field(self.terrain.GetOutput(), "GeoOrigin", k) for k in range(3))
        self.assertEqual(field(sun, "GeoOrigin", 0), lat)
        self.assertEqual(field(sun, "GeoOrigin", 1), lon)
        # Morning in the southern summer: the sun is in the east, well up.
        self.assertGreater(self.sun.GetAzimuth(), 60.0)
        self.assertLess(self.sun.GetAzimuth(), 130.0)
        self.assertLess(self.sun.GetZenith(), 60.0)
        direction = [field(sun, "SunDirection", k) for k in range(3)]
        self.assertEqual(sun.GetFieldData().GetArray("SunDirection").GetTuple3(0), tuple(direction))
        self.assertAlmostEqual(sum(c * c for c in direction), 1.0, places=12)
        self.assertGreater(direction[0], 0.5)  # east
        self.assertAlmostEqual(field(sun, "SunNormalIrradiance"), self.sun.GetNormalIrradiance())

    def test_sky_follows_the_sun(self):
        for model in (vtkSkySource.CIE_GENERAL, vtkSkySource.PEREZ, vtkSkySource.CIE_OVERCAST,
                      vtkSkySource.UNIFORM):
            self.sky.SetSkyModel(model)
            self.sky.Update()
            image = self.sky.GetRadianceOutput()
            dhi = self.sun.GetDiffuseHorizontalIrradiance()
            self.assertGreater(dhi, 50.0)
            self.assertAlmostEqual(field(image, "DiffuseHorizontalIrradiance"), dhi)
            self.assertAlmostEqual(map_horizontal_irradiance(image) / dhi, 1.0, delta=1e-3)
            self.assertEqual(field(image, "SunAzimuth"), self.sun.GetAzimuth())
        self.assertEqual(self.sky.GetDomeOutput().GetNumberOfPolys(), 64 * 64)

    def test_rgb_texture(self):
        texture = vtkImageData()
        texture.SetDimensions(5, 3, 1)
        colours = vtkFloatArray()
        colours.SetNumberOfComponents(3)
        colours.SetNumberOfTuples(15)
        for k in range(15):
            colours.SetTuple3(k, 0.25, 0.5, 1.0)
        texture.GetPointData().SetScalars(colours)
        self.sky.SetInputDataObject(1, texture)
        self.sky.Update()
        image = self.sky.GetRadianceOutput()
        dhi = self.sun.GetDiffuseHorizontalIrradiance()
        self.assertEqual(image.GetCellData().GetArray("Radiance").GetNumberOfComponents(), 3)
        for band, factor in enumerate((0.25, 0.5, 1.0)):
            self.assertAlmostEqual(field(image, "HorizontalIrradiance", band) / dhi, factor, delta=1e-6)

    def test_bad_input(self):
        catcher = ErrorCatcher(self.sun)
        self.sun.SetDateTime("21/12/2024 09:00")
        self.sun.Update()
        self.assertIn("ISO 8601", catcher.text())
        self.assertEqual(self.sun.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
