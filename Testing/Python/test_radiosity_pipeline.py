"""terrain -> sun -> sky -> vtkHierarchicalRadiosity -> writer on the real Olinda DEM."""
import math
import os
import shutil
import subprocess
import unittest

from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLStructuredGridReader, vtkXMLStructuredGridWriter

from terralux import vtkHierarchicalRadiosity, vtkTerrainRasterWriter
from terralux_testing import LUXEMBOURG, OLINDA, ErrorCatcher, field, scratch_dir, terrain_sun_sky



class OlindaRadiosity(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.terrain, cls.sun, cls.sky = terrain_sun_sky(OLINDA, "2024-12-21T09:00:00-03:00")
        cls.radiosity = vtkHierarchicalRadiosity()
        cls.radiosity.SetInputConnection(cls.terrain.GetOutputPort())
        cls.radiosity.AddLightConnection(cls.sun.GetOutputPort())
        cls.radiosity.AddLightConnection(cls.sky.GetOutputPort(0))
        cls.radiosity.SetErrorTolerance(1e-2)
        cls.out = os.path.join(scratch_dir(), "olinda-lit.vts")
        writer = vtkXMLStructuredGridWriter()
        writer.SetInputConnection(cls.radiosity.GetOutputPort(0))
        writer.SetFileName(cls.out)
        assert writer.Write() == 1

    def test_written_and_read_back(self):
        reader = vtkXMLStructuredGridReader()
        reader.SetFileName(self.out)
        reader.Update()
        grid = reader.GetOutput()
        self.assertEqual(grid.GetDimensions(), (111, 111, 1))
        data = grid.GetPointData()
        for name in ("Elevation", "Irradiance", "SunIrradiance", "SkyIrradiance",
                     "ReflectedIrradiance", "Radiosity"):
            self.assertIsNotNone(data.GetArray(name), name)
        global_, sun, sky, reflected, radiosity = (
            data.GetArray(n) for n in ("Irradiance", "SunIrradiance", "SkyIrradiance",
                                       "ReflectedIrradiance", "Radiosity"))
        dni = self.sun.GetNormalIrradiance()
        dhi = self.sun.GetDiffuseHorizontalIrradiance()
        horizontal_beam = dni * self.sun.GetDirection()[2]
        for k in range(0, grid.GetNumberOfPoints(), 37):
            total = sun.GetValue(k) + sky.GetValue(k) + reflected.GetValue(k)
            self.assertAlmostEqual(global_.GetValue(k), total, delta=1e-9 * total + 1e-12)
            self.assertAlmostEqual(radiosity.GetValue(k), 0.2 * total, delta=1e-9 * total + 1e-12)
            self.assertLessEqual(sun.GetValue(k), dni * (1 + 1e-9))  # never more than the beam
            self.assertGreaterEqual(sky.GetValue(k), 0.0)
            self.assertLessEqual(sky.GetValue(k), 1.5 * dhi)
        # The flat sea east of Olinda (elevation <= 0): unshaded beam, open sky.
        elevation = data.GetArray("Elevation")
        sea = [k for k in range(grid.GetNumberOfPoints()) if elevation.GetValue(k) <= 0.0]
        self.assertGreater(len(sea), 500)
        mean_sun = sum(sun.GetValue(k) for k in sea) / len(sea)
        mean_sky = sum(sky.GetValue(k) for k in sea) / len(sea)
        self.assertAlmostEqual(mean_sun / horizontal_beam, 1.0, delta=0.02)
        self.assertAlmostEqual(mean_sky / dhi, 1.0, delta=0.05)
        # Sky view factor: in [0, 1], ~1 over the open sea, lower in the valleys.
        svf = data.GetArray("SkyViewFactor")
        self.assertIsNotNone(svf)
        low, high = svf.GetRange()
        self.assertGreater(low, 0.5)
        self.assertLessEqual(high, 1.0 + 1e-6)
        self.assertGreater(sum(svf.GetValue(k) for k in sea) / len(sea), 0.99)

    def test_statistics_and_other_outputs(self):
        output = self.radiosity.GetOutput()
        # Terrain patches: far fewer elements than the 24,200 triangles of the grid.
        self.assertGreater(field(output, "Elements"), 10)
        self.assertLess(field(output, "Elements"), 24200)
        self.assertGreater(field(output, "Rays"), 0)
        # Rays by phase add up to all of them; the points' values take most (the gather).
        phases = [field(output, name) for name in ("RaysRefine", "RaysPushPull", "RaysPoints")]
        self.assertEqual(sum(phases), field(output, "Rays"))
        self.assertGreater(phases[2], phases[0])
        self.assertGreater(field(output, "SecondsPoints"), 0.0)
        self.assertGreaterEqual(field(output, "Iterations"), 1)
        leaves = self.radiosity.GetLeafMeshOutput()
        self.assertGreater(leaves.GetNumberOfCells(), 10)
        self.assertEqual(leaves.GetPointData().GetArray("Irradiance").GetNumberOfTuples(),
                         leaves.GetNumberOfPoints())
        links = self.radiosity.GetLinksOutput()
        self.assertEqual(links.GetNumberOfCells(), field(output, "Links"))
        writer = vtkXMLPolyDataWriter()
        writer.SetInputData(links)
        writer.SetFileName(os.path.join(scratch_dir(), "links.vtp"))
        self.assertEqual(writer.Write(), 1)

    def test_terrain_patches_agree_with_triangles(self):
        # The same DEM through the plain path: two triangles per cell in clusters.
        def run(hierarchy, at_points=True):
            r = vtkHierarchicalRadiosity()
            r.SetInputConnection(self.terrain.GetOutputPort())
            r.AddLightConnection(self.sun.GetOutputPort())
            r.AddLightConnection(self.sky.GetOutputPort(0))
            r.SetErrorTolerance(1e-3)
            r.SetUseTerrainHierarchy(hierarchy)
            r.SetEvaluateAtPoints(at_points)
            r.Update()
            return r.GetOutput()
        patches, triangles = run(True), run(False)
        self.assertLess(field(patches, "Elements"), 0.2 * field(triangles, "Elements"))
        # Olinda's benchmark: 0.13 % RMS against a converged run at this tolerance.
        a = patches.GetPointData().GetArray("Irradiance")
        b = triangles.GetPointData().GetArray("Irradiance")
        n = a.GetNumberOfTuples()
        squared = sum((a.GetValue(k) - b.GetValue(k)) ** 2 for k in range(n))
        reference = sum(b.GetValue(k) ** 2 for k in range(n))
        self.assertLess(math.sqrt(squared / reference), 0.005)
        # Interpolated from the leaf mesh, direct sun still at each post: the same beam.
        fast = run(True, False)
        sun_fast = fast.GetPointData().GetArray("SunIrradiance")
        sun_exact = patches.GetPointData().GetArray("SunIrradiance")
        for k in range(0, n, 13):
            self.assertAlmostEqual(sun_fast.GetValue(k), sun_exact.GetValue(k), delta=1e-6)
        # Sky view factors interpolated from the leaves: smoother, close to the posts' own.
        svf_fast = fast.GetPointData().GetArray("SkyViewFactor")
        svf_exact = patches.GetPointData().GetArray("SkyViewFactor")
        mean_difference = sum(abs(svf_fast.GetValue(k) - svf_exact.GetValue(k)) for k in range(n)) / n
        self.assertLess(mean_difference, 0.02)

    def test_ports_cleared_one_at_a_time(self):
        # ParaView's repeatable inputs reset one port and connect it again.
        r = vtkHierarchicalRadiosity()
        r.AddInputConnection(self.terrain.GetOutputPort())
        r.AddInputConnection(self.terrain.GetOutputPort())
        r.AddLightConnection(self.sun.GetOutputPort())
        r.AddLightConnection(self.sky.GetOutputPort(0))
        r.RemoveAllGeometryConnections()
        self.assertEqual((r.GetNumberOfInputConnections(0), r.GetNumberOfInputConnections(1)), (0, 2))
        r.AddInputConnection(self.terrain.GetOutputPort())
        r.RemoveAllLightConnections()
        self.assertEqual((r.GetNumberOfInputConnections(0), r.GetNumberOfInputConnections(1)), (1, 0))
        r.AddLightConnection(self.sun.GetOutputPort())
        r.SetErrorTolerance(1e-2)
        r.Update()
        data = r.GetOutput().GetPointData()
        self.assertIsNotNone(data.GetArray("SunIrradiance"))
        self.assertIsNone(data.GetArray("SkyViewFactor"))  # the sky is gone
        # GetOutput(port), as every VTK algorithm offers it.
        self.assertIs(r.GetOutput(0), r.GetOutput())
        self.assertIs(r.GetOutput(1), r.GetLeafMeshOutput())
        self.assertIs(r.GetOutput(2), r.GetLinksOutput())
        self.assertIs(self.sky.GetOutput(1), self.sky.GetDomeOutput())
        self.assertIs(self.sky.GetOutput(), self.sky.GetRadianceOutput())

    def test_cells_without_area_are_counted(self):
        from vtkmodules.vtkFiltersCore import vtkAppendPolyData
        from vtkmodules.vtkFiltersSources import vtkLineSource, vtkPlaneSource
        from terralux import vtkSkySource
        plane, line, scene = vtkPlaneSource(), vtkLineSource(), vtkAppendPolyData()
        plane.SetResolution(4, 4)
        line.SetPoint1(0, 0, 1)
        line.SetPoint2(0, 0, 2)
        scene.AddInputConnection(plane.GetOutputPort())
        scene.AddInputConnection(line.GetOutputPort())
        sky = vtkSkySource()
        sky.SetUseSunSource(False)
        sky.SetSkyModelToUniform()
        r = vtkHierarchicalRadiosity()
        r.SetInputConnection(scene.GetOutputPort())
        r.AddLightConnection(sky.GetOutputPort(0))
        r.Update()
        self.assertEqual(field(r.GetOutput(), "SkippedCells"), 1)  # the line
        self.assertEqual(field(r.GetOutput(), "DegeneratePolygons"), 0)

    def test_no_light_is_an_error(self):
        dark = vtkHierarchicalRadiosity()
        dark.SetInputConnection(self.terrain.GetOutputPort())
        catcher = ErrorCatcher(dark)
        dark.Update()
        self.assertIn("no light source", catcher.text())
        self.assertEqual(dark.GetLeafMeshOutput().GetNumberOfCells(), 0)


class LuxembourgWithNoData(unittest.TestCase):
    """A DEM with no-data posts, lit, then written back as a GeoTIFF on its own grid."""

    def test_lit_and_written(self):
        terrain, sun, sky = terrain_sun_sky(LUXEMBOURG, "2024-06-21T12:00:00+02:00")
        radiosity = vtkHierarchicalRadiosity()
        radiosity.SetInputConnection(terrain.GetOutputPort())
        radiosity.AddLightConnection(sun.GetOutputPort())
        radiosity.AddLightConnection(sky.GetOutputPort(0))
        radiosity.SetErrorTolerance(1e-2)
        tif = os.path.join(scratch_dir(), "luxembourg-irradiance.tif")
        writer = vtkTerrainRasterWriter()
        writer.SetInputConnection(radiosity.GetOutputPort(0))
        writer.SetFileName(tif)
        self.assertEqual(writer.Write(), 1)

        grid = radiosity.GetOutput()
        irradiance = grid.GetPointData().GetArray("Irradiance")
        for k in range(grid.GetNumberOfPoints()):
            value = irradiance.GetValue(k)
            if not grid.IsPointVisible(k):
                self.assertTrue(math.isnan(value))  # no data stays no data
            else:
                self.assertTrue(math.isnan(value) or 0.0 < value < 1400.0)
        if shutil.which("gdalinfo"):
            info = subprocess.run(["gdalinfo", tif], capture_output=True, text=True, check=True).stdout
            source = subprocess.run(["gdalinfo", LUXEMBOURG], capture_output=True, text=True,
                                    check=True).stdout
            self.assertIn("Size is 95, 90", info)
            origin = [line for line in source.splitlines() if line.startswith("Origin")]
            self.assertTrue(origin and origin[0] in info)  # the DEM's own georeference
            self.assertIn("Description = SkyViewFactor", info)
            self.assertIn("NoData Value=-32768", info)


if __name__ == "__main__":
    unittest.main(verbosity=2)
