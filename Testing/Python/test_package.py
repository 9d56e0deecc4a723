"""The `terralux` package imports with /usr/bin/python3 and exposes its classes."""
import unittest


class Package(unittest.TestCase):
    def test_classes_are_exported(self):
        import terralux
        from terralux import vtkGeodeticFrame, vtkSkySource, vtkSunSource, vtkTerrainSource

        self.assertTrue(terralux.__version__)
        for cls in (vtkTerrainSource, vtkGeodeticFrame, vtkSunSource, vtkSkySource):
            self.assertEqual(cls().GetClassName(), cls.__name__)

    def test_vtk_conventions(self):
        from terralux import vtkTerrainSource

        source = vtkTerrainSource()
        self.assertEqual(source.GetBand(), 1)
        self.assertEqual(source.GetStride(), 1)
        source.SetStride(0)  # clamped by vtkSetClampMacro
        self.assertEqual(source.GetStride(), 1)
        self.assertEqual(source.GetOutputPointsPrecision(), vtkTerrainSource.SINGLE_PRECISION)
        self.assertFalse(source.GetUseGeoOrigin())
        source.SetGeoOrigin(1.0, 2.0, 3.0)
        self.assertTrue(source.GetUseGeoOrigin())
        source.SetGeoOriginToGridCenter()
        self.assertFalse(source.GetUseGeoOrigin())
        self.assertIn("Stride: 1", str(source))


if __name__ == "__main__":
    unittest.main(verbosity=2)
