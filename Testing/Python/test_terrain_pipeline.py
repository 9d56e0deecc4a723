"""Python pipelines around vtkTerrainSource: XML round trip, vtkDEMReader input,
geodetic conversions and bad input, all with /usr/bin/python3 and `terralux`."""
import math
import os
import shutil
import subprocess
import unittest

from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
from vtkmodules.vtkIOImage import vtkDEMReader
from vtkmodules.vtkIOXML import vtkXMLStructuredGridReader, vtkXMLStructuredGridWriter

from terralux import vtkGeodeticFrame, vtkTerrainSource
from terralux_testing import LUXEMBOURG, OLINDA, ErrorCatcher, field_values, scratch_dir



def hidden_count(grid):
    return sum(0 if grid.IsPointVisible(k) else 1 for k in range(grid.GetNumberOfPoints()))


class XmlRoundTrip(unittest.TestCase):
    def round_trip(self, path):
        source = vtkTerrainSource()
        source.SetFileName(path)
        writer = vtkXMLStructuredGridWriter()
        writer.SetInputConnection(source.GetOutputPort())
        out = os.path.join(scratch_dir(), "terrain.vts")
        writer.SetFileName(out)
        self.assertEqual(writer.Write(), 1)
        reader = vtkXMLStructuredGridReader()
        reader.SetFileName(out)
        reader.Update()
        return source.GetOutput(), reader.GetOutput()

    def assert_same(self, original, back):
        self.assertEqual(back.GetDimensions(), original.GetDimensions())
        self.assertEqual(back.GetNumberOfPoints(), original.GetNumberOfPoints())
        for k in range(0, original.GetNumberOfPoints(), 7):
            self.assertEqual(back.GetPoint(k), original.GetPoint(k))
        a = original.GetPointData().GetArray("Elevation")
        b = back.GetPointData().GetArray("Elevation")
        for k in range(a.GetNumberOfTuples()):
            va, vb = a.GetValue(k), b.GetValue(k)
            self.assertTrue(va == vb or (math.isnan(va) and math.isnan(vb)))
        for name in ("GeoOrigin", "GeoTransform", "RasterSize"):
            self.assertEqual(field_values(back, name), field_values(original, name))
        self.assertEqual(
            back.GetFieldData().GetAbstractArray("CRS").GetValue(0),
            original.GetFieldData().GetAbstractArray("CRS").GetValue(0))
        self.assertEqual(hidden_count(back), hidden_count(original))

    def test_olinda(self):
        original, back = self.round_trip(OLINDA)
        self.assert_same(original, back)
        self.assertEqual(original.GetDimensions(), (111, 111, 1))
        self.assertEqual(original.GetPointData().GetArray("Elevation").GetRange(), (-1.0, 88.0))
        lat, lon, _ = field_values(original, "GeoOrigin")
        self.assertAlmostEqual(lat, -(7 + 59 / 60 + 42.66 / 3600), delta=1e-5)  # gdalinfo centre
        self.assertAlmostEqual(lon, -(34 + 52 / 60 + 15.88 / 3600), delta=1e-5)

    def test_luxembourg_keeps_blanking(self):
        original, back = self.round_trip(LUXEMBOURG)
        self.assert_same(original, back)
        self.assertGreater(hidden_count(back), 1000)
        ghosts = back.GetPointData().GetArray(vtkDataSetAttributes.GhostArrayName())
        self.assertIsNotNone(ghosts)


@unittest.skipUnless(shutil.which("gdal_translate"), "gdal_translate (gdal-bin) is needed")
class DemReaderInput(unittest.TestCase):
    """vtkDEMReader's image on the optional input, and the same USGS DEM read by GDAL."""

    @classmethod
    def setUpClass(cls):
        # The real Olinda heights as a USGS DEM on an exact 90 m UTM 25S grid.
        cls.dem = os.path.join(scratch_dir(), "olinda.dem")
        subprocess.run(["gdal_translate", "-q", "-of", "USGSDEM",
                        "-a_ullr", "288765", "9120765", "298755", "9110775", OLINDA, cls.dem],
                       check=True)

    def test_image_input(self):
        reader = vtkDEMReader()
        reader.SetFileName(self.dem)
        source = vtkTerrainSource()
        source.SetInputConnection(reader.GetOutputPort())
        source.Update()
        image, grid = reader.GetOutput(), source.GetOutput()
        self.assertEqual(grid.GetDimensions(), image.GetDimensions())
        scalars = image.GetPointData().GetScalars()
        elevation = grid.GetPointData().GetArray("Elevation")
        for k in range(0, grid.GetNumberOfPoints(), 5):
            x, y, _ = image.GetPoint(k)
            self.assertEqual(grid.GetPoint(k), (x, y, scalars.GetValue(k)))
            self.assertEqual(elevation.GetValue(k), scalars.GetValue(k))
        self.assertEqual(elevation.GetRange(), (-1.0, 88.0))
        self.assertIsNone(grid.GetFieldData().GetArray("GeoOrigin"))

        # The DEM holds the Olinda posts on a re-declared grid: post for post, the
        # heights equal those vtkTerrainSource reads from the GeoTIFF itself.
        direct = vtkTerrainSource()
        direct.SetFileName(OLINDA)
        direct.Update()
        direct_heights = direct.GetOutput().GetPointData().GetArray("Elevation")
        self.assertEqual(direct_heights.GetNumberOfTuples(), elevation.GetNumberOfTuples())
        for k in range(elevation.GetNumberOfTuples()):
            self.assertEqual(elevation.GetValue(k), direct_heights.GetValue(k))
        self.assertEqual(image.GetSpacing()[:2], (90.0, 90.0))

    def test_image_input_with_offset_extent(self):
        # A height field whose extent starts at (10, 20), through a filter upstream (not
        # a trivial producer): converted whole, no pipeline errors, heights right.
        from vtkmodules.vtkImagingCore import vtkImageCast, vtkImageTranslateExtent
        reader = vtkDEMReader()
        reader.SetFileName(self.dem)
        shifted = vtkImageTranslateExtent()
        shifted.SetInputConnection(reader.GetOutputPort())
        shifted.SetTranslation(10, 20, 0)
        cast = vtkImageCast()
        cast.SetInputConnection(shifted.GetOutputPort())
        cast.SetOutputScalarTypeToFloat()
        source = vtkTerrainSource()
        source.SetInputConnection(cast.GetOutputPort())
        errors = [ErrorCatcher(algorithm) for algorithm in (source, cast, shifted)]
        source.Update()
        self.assertEqual("".join(e.text() for e in errors), "")
        cast.Update()
        image, grid = cast.GetOutput(), source.GetOutput()
        self.assertEqual(image.GetExtent()[:4], (10, 10 + 110, 20, 20 + 110))
        self.assertEqual(grid.GetDimensions(), image.GetDimensions())
        scalars = image.GetPointData().GetScalars()
        for k in range(0, grid.GetNumberOfPoints(), 7):
            x, y, _ = image.GetPoint(k)
            self.assertEqual(grid.GetPoint(k), (x, y, scalars.GetValue(k)))
        # A piece of the terrain asked for still converts the whole height field.
        piece = vtkTerrainSource()
        piece.SetInputConnection(cast.GetOutputPort())
        piece_errors = ErrorCatcher(piece)
        piece.UpdatePiece(1, 2, 0)
        self.assertEqual(piece_errors.text(), "")
        self.assertEqual(piece.GetOutput().GetNumberOfPoints(), grid.GetNumberOfPoints())

    def test_image_input_with_geo_origin(self):
        reader = vtkDEMReader()
        reader.SetFileName(self.dem)
        source = vtkTerrainSource()
        source.SetInputConnection(reader.GetOutputPort())
        source.SetGeoOrigin(-8.0, -34.87, 20.0)
        source.Update()
        self.assertEqual(field_values(source.GetOutput(), "GeoOrigin"), [-8.0, -34.87, 20.0])
        # One tuple of three components, as a point: GetTuple3 reads it.
        self.assertEqual(source.GetOutput().GetFieldData().GetArray("GeoOrigin").GetTuple3(0), (-8.0, -34.87, 20.0))


class GeodeticConversions(unittest.TestCase):
    def test_frame_from_terrain(self):
        source = vtkTerrainSource()
        source.SetFileName(OLINDA)
        source.SetOutputPointsPrecision(vtkTerrainSource.DOUBLE_PRECISION)
        source.Update()
        grid = source.GetOutput()
        frame = vtkGeodeticFrame()
        self.assertTrue(frame.SetOriginFromFieldData(grid))
        lat0, lon0, h0 = field_values(grid, "GeoOrigin")
        self.assertEqual(frame.GetOrigin(), (lat0, lon0, h0))
        origin = frame.LocalToGeodetic(0.0, 0.0, 0.0)
        for got, want in zip(origin, (lat0, lon0, h0)):
            self.assertAlmostEqual(got, want, places=6)
        # Round trip of a far point, in both API forms.
        geodetic = frame.LocalToGeodetic(12000.0, -8000.0, 350.0)
        local = [0.0, 0.0, 0.0]
        self.assertTrue(frame.GeodeticToLocal(list(geodetic), local))
        for got, want in zip(local, (12000.0, -8000.0, 350.0)):
            self.assertAlmostEqual(got, want, places=6)
        # 1 km north is 1/111 degree of latitude, near enough.
        north = frame.LocalToGeodetic(0.0, 1000.0, 0.0)
        self.assertAlmostEqual(north[0] - lat0, 1000.0 / 110_600.0, delta=2e-5)

    def test_invalid_origin(self):
        frame = vtkGeodeticFrame()
        catcher = ErrorCatcher(frame)
        frame.SetOrigin(float("nan"), 0.0, 0.0)
        out = [0.0, 0.0, 0.0]
        self.assertFalse(frame.LocalToGeodetic([1.0, 2.0, 3.0], out))
        self.assertTrue(all(math.isnan(v) for v in out))
        self.assertIn("invalid geographic origin", catcher.text())
        self.assertFalse(frame.SetOriginFromFieldData(vtkTerrainSource().GetOutput()))
        self.assertIn("GeoOrigin", catcher.text())


class BadInput(unittest.TestCase):
    def test_missing_file(self):
        source = vtkTerrainSource()
        catcher = ErrorCatcher(source)
        source.SetFileName("/no/such/dem.tif")
        source.Update()
        self.assertIn("does not exist", catcher.text())
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)

    def test_error_then_recovery(self):
        source = vtkTerrainSource()
        catcher = ErrorCatcher(source)
        source.SetFileName(OLINDA)
        source.SetBand(3)
        source.Update()
        self.assertIn("band 3 is out of range", catcher.text())
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)
        source.SetBand(1)
        source.SetStride(10)
        source.Update()
        self.assertEqual(source.GetOutput().GetDimensions(), (12, 12, 1))


if __name__ == "__main__":
    unittest.main(verbosity=2)
