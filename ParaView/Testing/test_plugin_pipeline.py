"""pvpython: the TerraLux plugin's pipeline against the same pipeline in plain VTK.

Environment: TERRALUX_PLUGIN (TerraLux.so), TERRALUX_DEM (the Olinda DEM),
TERRALUX_REFERENCE_DIR (what plain_vtk_reference.py wrote), TERRALUX_OUTPUT_DIR.
"""
import json
import os
import unittest

import numpy as np
from paraview import servermanager
from paraview import simple as pv
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLStructuredGridReader

from pipeline_parameters import IRRADIATION_INSTANT, IRRADIATION_RANGE, RELATIVE_TOLERANCE, paraview_pipeline

PLUGIN = os.environ["TERRALUX_PLUGIN"]
DEM = os.environ["TERRALUX_DEM"]
REFERENCE_DIR = os.environ["TERRALUX_REFERENCE_DIR"]
OUTPUT_DIR = os.environ["TERRALUX_OUTPUT_DIR"]

pv.LoadPlugin(PLUGIN, remote=False)  # adds the proxies to paraview.simple


def reference(name):
    reader = vtkXMLStructuredGridReader()
    reader.SetFileName(os.path.join(REFERENCE_DIR, name))
    reader.Update()
    return reader.GetOutput()


def point_arrays(data):
    pd = data.GetPointData()
    return {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)).astype(float)
            for k in range(pd.GetNumberOfArrays())}


class PluginPipeline(unittest.TestCase):
    def setUp(self):
        for proxy in list(pv.GetSources().values()):
            pv.Delete(proxy)
        self.terrain, self.sun, self.sky, self.solver = paraview_pipeline(pv, DEM)

    def assertSameArrays(self, proxy, reference_name, port=0):
        expected = point_arrays(reference(reference_name))
        actual = point_arrays(servermanager.Fetch(proxy, None, port) if port else servermanager.Fetch(proxy))
        self.assertEqual(sorted(actual), sorted(expected))
        for name, values in expected.items():
            got = actual[name]
            self.assertEqual(got.shape, values.shape, name)
            finite = np.isfinite(values)
            np.testing.assert_array_equal(np.isfinite(got), finite, err_msg=name)
            scale = max(np.abs(values[finite]).max(), 1e-30)
            error = np.abs(got[finite] - values[finite]).max() / scale
            self.assertLessEqual(error, RELATIVE_TOLERANCE, "%s: relative difference %g" % (name, error))

    def test_radiosity_equals_plain_vtk(self):
        self.assertSameArrays(self.solver, "radiosity.vts")
        info = self.solver.GetDataInformation()
        self.assertEqual(info.GetDataSetTypeAsString(), "vtkStructuredGrid")

    def test_property_change_re_executes(self):
        first = point_arrays(servermanager.Fetch(self.solver))["ReflectedIrradiance"]
        self.solver.DefaultReflectance = 0.5
        second = point_arrays(servermanager.Fetch(self.solver))["ReflectedIrradiance"]
        self.assertGreater(second.mean(), 2.0 * first.mean())
        self.assertSameArrays(self.solver, "radiosity_rho05.vts")

    def test_reflectance_array_from_the_array_list(self):
        # A cell array of 0.5 chosen as the reflectance gives DefaultReflectance 0.5's
        # values; the list's None gives the default's again.
        albedo = pv.Calculator(Input=self.terrain, AttributeType="Cell Data", ResultArrayName="albedo",
                               Function="0.5")
        self.solver.Input = albedo
        self.assertEqual(self.solver.ReflectanceArray[1], "None")
        self.solver.ReflectanceArray = ["CELLS", "albedo"]
        self.assertSameArrays(self.solver, "radiosity_rho05.vts")
        self.solver.ReflectanceArray = ["POINTS", "None"]
        self.assertSameArrays(self.solver, "radiosity.vts")

    def test_lights_reset_and_set_again(self):
        self.solver.UpdatePipeline()
        self.solver.Lights = [self.sun]
        self.assertSameArrays(self.solver, "radiosity_sun_only.vts")
        self.solver.Lights = []
        self.solver.UpdatePipeline()
        self.assertEqual(self.solver.GetDataInformation().GetNumberOfPoints(), 0)  # no light: refused, empty
        self.solver.Lights = [self.sun, self.sky]
        self.assertSameArrays(self.solver, "radiosity.vts")

    def test_geometry_reset_keeps_lights(self):
        self.solver.UpdatePipeline()
        self.solver.Input = [self.terrain]  # re-sets port 0 only
        self.assertSameArrays(self.solver, "radiosity.vts")

    def test_writer_equals_plain_vtk(self):
        path = os.path.join(OUTPUT_DIR, "radiosity.tif")
        if os.path.exists(path):
            os.remove(path)
        pv.SaveData(path, proxy=self.solver, ArrayNames=["Irradiance", "SkyViewFactor"])
        writer = servermanager.writers.TerrainRasterWriter(Input=self.solver)
        self.assertEqual(list(writer.GetProperty("ArrayNames")), [])  # default: the irradiance arrays

        def bands(file_name):
            reader = pv.GDALRasterReader(FileName=file_name)
            data = servermanager.Fetch(reader)
            return {name: values for name, values in point_arrays(data).items()} or \
                {data.GetCellData().GetArrayName(k): vtk_to_numpy(data.GetCellData().GetArray(k)).astype(float)
                 for k in range(data.GetCellData().GetNumberOfArrays())}

        ours, plain = bands(path), bands(os.path.join(REFERENCE_DIR, "radiosity.tif"))
        self.assertEqual(sorted(ours), sorted(plain))
        self.assertGreaterEqual(len(ours), 1)
        for name in plain:
            scale = np.nanmax(np.abs(plain[name]))
            self.assertLessEqual(np.nanmax(np.abs(ours[name] - plain[name])) / scale, RELATIVE_TOLERANCE, name)

    def test_solar_irradiation_sums_and_time_steps(self):
        start, end, step = IRRADIATION_RANGE
        summed = pv.SolarIrradiation(Input=self.terrain, StartTime=start, EndTime=end, TimeStep=step)
        self.assertSameArrays(summed, "irradiation.vts")
        with open(os.path.join(REFERENCE_DIR, "irradiation_times.json")) as f:
            times = json.load(f)
        np.testing.assert_allclose(list(summed.TimestepValues), times, rtol=0, atol=1e-9)
        summed.IntegrateOverTime = 0
        summed.UpdatePipeline(IRRADIATION_INSTANT)
        data = servermanager.Fetch(summed)  # Fetch updates at the time last asked for
        self.assertIn("Irradiance", point_arrays(data))
        self.assertSameArrays(summed, "irradiation_instant.vts")

    def test_terrain_from_height_field(self):
        wavelet = pv.Wavelet(WholeExtent=[0, 20, 0, 10, 0, 0])
        terrain = pv.TerrainFromHeightField(Input=wavelet)
        data = servermanager.Fetch(terrain)
        self.assertEqual(data.GetClassName(), "vtkStructuredGrid")
        self.assertEqual(data.GetNumberOfPoints(), 21 * 11)
        heights = vtk_to_numpy(data.GetPoints().GetData())[:, 2]
        scalars = vtk_to_numpy(servermanager.Fetch(wavelet).GetPointData().GetScalars())
        np.testing.assert_allclose(heights, scalars, rtol=1e-6)


class PluginProxies(unittest.TestCase):
    """Every proxy's defaults are its class's own, and every parameter is offered."""

    PROXIES = {"TerrainSource": "vtkTerrainReader", "SunSource": "vtkSunSource",
               "SkySource": "vtkSkySource", "HierarchicalRadiosity": "vtkHierarchicalRadiosity",
               "SolarIrradiation": "vtkSolarIrradiation"}
    # The arrays to process (SetInputArrayToProcess, index first, name last) and the
    # class's named setters for them; the array list's "None" is the class's none.
    ARRAYS_TO_PROCESS = {"0": "ReflectanceArrayName", "1": "EmissionArrayName"}

    def setUp(self):
        with open(os.path.join(REFERENCE_DIR, "defaults.json")) as f:
            self.defaults = json.load(f)

    def check(self, proxy, class_name):
        expected = self.defaults[class_name]
        offered = set()
        for name in proxy.ListProperties():
            prop = proxy.GetProperty(name).SMProperty
            command = prop.GetCommand()
            if not command or not command.startswith("Set") or prop.GetInformationOnly():
                continue
            key = command[3:]
            if command == "SetInputArrayToProcess":
                key = self.ARRAYS_TO_PROCESS[prop.GetElement(0)]
                offered.add(key)
                self.assertEqual(prop.GetElement(4), expected[key] or "None", "%s.%s" % (class_name, key))
                continue
            offered.add(key)
            if key not in expected or key == "FileName":
                continue
            value = [prop.GetElement(k) for k in range(prop.GetNumberOfElements())]
            value = value[0] if len(value) == 1 else value  # raw values, not enumeration texts
            want = expected[key] if expected[key] is not None else ""
            if isinstance(want, list):
                np.testing.assert_allclose(value, want, err_msg="%s.%s" % (class_name, key))
            elif isinstance(want, float):
                self.assertAlmostEqual(float(value), want, msg="%s.%s" % (class_name, key))
            else:
                self.assertEqual(value, want, "%s.%s" % (class_name, key))
        missing = set(expected) - offered
        self.assertFalse(missing, "%s parameters without a property: %s" % (class_name, sorted(missing)))

    def test_sources_and_filters(self):
        terrain = pv.TerrainSource()
        for proxy_name, class_name in self.PROXIES.items():
            proxy = terrain if proxy_name == "TerrainSource" else getattr(pv, proxy_name)(Input=terrain)
            self.assertEqual(proxy.GetXMLName(), proxy_name)
            self.check(proxy, class_name)

    def test_writer(self):
        terrain = pv.TerrainSource(FileName=DEM)
        self.check(servermanager.writers.TerrainRasterWriter(Input=terrain), "vtkTerrainRasterWriter")

    def test_reader_for_dem_extensions(self):
        factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
        types = factory.GetSupportedFileTypes(servermanager.ActiveConnection.Session)
        offer = [entry for entry in types.split(";;") if entry.startswith("TerraLux terrain (DEM)")]
        self.assertEqual(len(offer), 1, types)
        for extension in ("tif", "tiff", "hgt", "asc", "dem", "dt0", "dt1", "dt2"):
            self.assertIn("*." + extension, offer[0].split("(")[-1].rstrip(")").split())

if __name__ == "__main__":
    unittest.main(verbosity=2)
