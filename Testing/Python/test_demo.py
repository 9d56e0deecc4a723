"""The demo end to end: Olinda DEM -> terrain.vtp, a shaded-relief PNG, and the lit
terrain (irradiance.vts, leaves.vtp, irradiance.png).

Rendering needs an X display (Debian's VTK aborts without one): the demo runs
under xvfb-run when there is no DISPLAY, and the test is skipped when neither exists.
"""
import os
import shutil
import subprocess
import sys
import unittest

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLStructuredGridReader

from terralux_testing import OLINDA, scratch_dir

DEMO = os.path.join(os.path.dirname(__file__), "..", "..", "Examples", "terrain_demo.py")


@unittest.skipUnless(os.environ.get("DISPLAY") or shutil.which("xvfb-run"),
                     "no X display and no xvfb-run")
class Demo(unittest.TestCase):
    def test_demo_writes_surface_and_image(self):
        out = scratch_dir()
        command = [sys.executable, DEMO, OLINDA, "--output-dir", out]
        if not os.environ.get("DISPLAY"):
            command = ["xvfb-run", "-a"] + command
        result = subprocess.run(command, capture_output=True, text=True, timeout=300)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("111 x 111 posts", result.stdout)

        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(out, "terrain.vtp"))
        reader.Update()
        surface = reader.GetOutput()
        self.assertEqual(surface.GetNumberOfPoints(), 111 * 111)
        self.assertEqual(surface.GetNumberOfCells(), 110 * 110)
        self.assertIsNotNone(surface.GetPointData().GetNormals())
        self.assertEqual(surface.GetPointData().GetArray("Elevation").GetRange(), (-1.0, 88.0))

        for name in ("shaded_relief.png", "irradiance.png"):
            png = vtkPNGReader()
            png.SetFileName(os.path.join(out, name))
            png.Update()
            image = png.GetOutput()
            self.assertEqual(image.GetDimensions()[:2], (1000, 1000))
            scalars = image.GetPointData().GetScalars()
            n = scalars.GetNumberOfTuples()
            luminance = [sum(scalars.GetTuple(k)[:3]) / 3.0 for k in range(0, n, 97)]
            covered = [v for v in luminance if v < 250.0]  # not the white background
            self.assertGreater(len(covered), 0.5 * len(luminance), name)
            mean = sum(covered) / len(covered)
            spread = (sum((v - mean) ** 2 for v in covered) / len(covered)) ** 0.5
            self.assertGreater(spread, 5.0, name)  # shaded, not a flat fill

        lit = vtkXMLStructuredGridReader()
        lit.SetFileName(os.path.join(out, "irradiance.vts"))
        lit.Update()
        grid = lit.GetOutput()
        self.assertEqual(grid.GetDimensions(), (111, 111, 1))
        low, high = grid.GetPointData().GetArray("Irradiance").GetRange()
        self.assertGreater(low, 0.0)
        self.assertLess(high, 1400.0)  # below the solar constant
        self.assertIn("global irradiance", result.stdout)

        # The leaf mesh: terrain patches, far fewer than the grid's 24,200 triangles.
        leaves = vtkXMLPolyDataReader()
        leaves.SetFileName(os.path.join(out, "leaves.vtp"))
        leaves.Update()
        mesh = leaves.GetOutput()
        self.assertGreater(mesh.GetNumberOfCells(), 10)
        self.assertLess(mesh.GetNumberOfCells(), 110 * 110 * 2)
        self.assertIsNotNone(mesh.GetCellData().GetArray("Level"))


if __name__ == "__main__":
    unittest.main(verbosity=2)
