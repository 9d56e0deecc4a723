"""vtkSolarIrradiation and `python3 -m terralux.irradiation`: daily sums judged against
closed forms on open ground (a one-minute sum of vtkSunSource's beam and diffuse
irradiance, the almanac's day length), against the sum of vtkHierarchicalRadiosity solves
at each step, against GRASS r.sun's daily mode where GRASS is installed; instants against
an independent solve at that instant; bad input and polar night."""
import datetime
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersSources import vtkPlaneSource

from terralux import vtkHierarchicalRadiosity, vtkSkySource, vtkSolarIrradiation, vtkSunSource, vtkTerrainSource
from terralux_testing import OLINDA, ErrorCatcher, field_values, scratch_dir

SUMS = ("GlobalIrradiation", "BeamIrradiation", "SkyIrradiation", "ReflectedIrradiation")
DAY = ("2024-06-21T00:00:00+01:00", "2024-06-22T00:00:00+01:00")
OLINDA_DAY = ("2024-06-21T00:00:00-02:00", "2024-06-22T00:00:00-02:00")


def values(data, name):
    return vtk_to_numpy(data.GetPointData().GetArray(name)).astype(float)



def open_plane():
    plane = vtkPlaneSource()
    plane.SetOrigin(-50.0, -50.0, 0.0)
    plane.SetPoint1(50.0, -50.0, 0.0)
    plane.SetPoint2(-50.0, 50.0, 0.0)
    plane.SetResolution(2, 2)
    return plane


def irradiation(source, start, end, step=30.0, **settings):
    f = vtkSolarIrradiation()
    f.SetInputConnection(source.GetOutputPort())
    f.SetStartTime(start)
    f.SetEndTime(end)
    f.SetTimeStep(step)
    for name, value in settings.items():
        getattr(f, "Set" + name)(value)
    return f


class OpenGround(unittest.TestCase):
    """A flat plane at 46.8 N, 8 E on 21 June: no shadow, the whole sky, no reflection."""

    @classmethod
    def setUpClass(cls):
        cls.filter = irradiation(open_plane(), *DAY, Latitude=46.8, Longitude=8.0)
        cls.filter.Update()
        cls.out = cls.filter.GetOutput()
        # The same day by vtkSunSource minute by minute (a Riemann sum of its own code path).
        sun = vtkSunSource()
        sun.SetLatitude(46.8)
        sun.SetLongitude(8.0)
        cls.beam = cls.diffuse = cls.day_hours = 0.0
        start = datetime.datetime(2024, 6, 20, 23, 0, 30)  # the middle of each minute, UTC
        for minute in range(24 * 60):
            sun.SetDateTime((start + datetime.timedelta(minutes=minute)).isoformat() + "Z")
            sun.Update()
            if sun.GetZenith() < 90.0:
                cls.day_hours += 1.0 / 60.0
                cls.beam += sun.GetNormalIrradiance() * math.cos(math.radians(sun.GetZenith())) / 60.0
                cls.diffuse += sun.GetDiffuseHorizontalIrradiance() / 60.0

    def test_beam_and_sky_are_the_days_irradiance(self):
        beam, sky = values(self.out, "BeamIrradiation"), values(self.out, "SkyIrradiation")
        self.assertGreater(self.beam, 5000.0)
        numpy.testing.assert_allclose(beam, self.beam, rtol=3e-3)
        numpy.testing.assert_allclose(sky, self.diffuse, rtol=5e-3)
        numpy.testing.assert_allclose(values(self.out, "ReflectedIrradiation"), 0.0, atol=1e-9)
        total = beam + sky + values(self.out, "ReflectedIrradiation")
        numpy.testing.assert_allclose(values(self.out, "GlobalIrradiation"), total, rtol=1e-12)
        numpy.testing.assert_allclose(values(self.out, "OutgoingIrradiation"), 0.2 * total, rtol=1e-9)

    def test_sunshine_is_the_day_length(self):
        numpy.testing.assert_allclose(values(self.out, "SunshineDuration"), self.day_hours, atol=2.0 / 60.0)
        self.assertAlmostEqual(sum(field_values(self.out, "StepHours")), self.day_hours, delta=2.0 / 60.0)

    def test_field_data_describes_the_steps(self):
        steps = int(field_values(self.out, "Steps")[0])
        self.assertGreater(steps, 30)
        for name in ("StepHours", "SunZenith", "SunAzimuth", "SunNormalIrradiance", "DiffuseHorizontalIrradiance"):
            self.assertEqual(len(field_values(self.out, name)), steps, name)
        times = self.out.GetFieldData().GetAbstractArray("StepTime")
        self.assertEqual(times.GetNumberOfValues(), steps)
        self.assertTrue(times.GetValue(0).startswith("2024-06-21T03:"), times.GetValue(0))  # sunrise, UTC
        self.assertEqual(self.out.GetPointData().GetArray("GlobalIrradiation").GetInformation().Get(
            self.out.GetPointData().GetArray("GlobalIrradiation").UNITS_LABEL()), "Wh/m^2")

    def test_time_steps_are_advertised(self):
        info = self.filter.GetOutputInformation(0)
        steps = info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
        self.assertEqual(len(steps), 49)
        self.assertAlmostEqual(steps[0], 0.0)
        self.assertAlmostEqual(steps[-1], 24.0, places=6)


class OlindaDay(unittest.TestCase):
    """The real Olinda DEM on 21 June: sums against the sum of instant solves."""

    @classmethod
    def setUpClass(cls):
        cls.terrain = vtkTerrainSource()
        cls.terrain.SetFileName(OLINDA)
        cls.filter = irradiation(cls.terrain, *OLINDA_DAY)
        cls.filter.Update()
        cls.out = cls.filter.GetOutput()

    def instant(self, when):
        sun = vtkSunSource()
        sun.SetInputConnection(self.terrain.GetOutputPort())
        sun.SetDateTime(when)
        sky = vtkSkySource()
        sky.SetSunConnection(sun.GetOutputPort())
        solve = vtkHierarchicalRadiosity()
        solve.SetInputConnection(self.terrain.GetOutputPort())
        solve.AddLightConnection(sun.GetOutputPort())
        solve.AddLightConnection(sky.GetOutputPort(0))
        solve.Update()
        return solve.GetOutput()

    def test_sums_are_the_sum_of_instant_solves(self):
        times = self.out.GetFieldData().GetAbstractArray("StepTime")
        hours = field_values(self.out, "StepHours")
        total = {name: 0.0 for name in ("SunIrradiance", "SkyIrradiance", "ReflectedIrradiance")}
        for k, weight in enumerate(hours):
            lit = self.instant(times.GetValue(k))
            for name in total:
                total[name] = total[name] + weight * values(lit, name)
        beam, sky = values(self.out, "BeamIrradiation"), values(self.out, "SkyIrradiation")
        # The same shadow rays: equal to rounding.
        numpy.testing.assert_allclose(beam, total["SunIrradiance"], rtol=1e-6, atol=1e-6)
        # Sky and reflected light by other rays (one gather under the cumulative sky
        # against one per step): equal within the gather's noise, which it holds to
        # 0.3 % of each point's irradiance (sun and sky), several times that of the sky's.
        self.assertAlmostEqual(sky.mean() / total["SkyIrradiance"].mean(), 1.0, delta=2e-3)
        self.assertLess(numpy.sqrt(numpy.mean((sky / total["SkyIrradiance"] - 1.0) ** 2)), 0.02)
        glob = sum(total.values())
        self.assertLess(numpy.sqrt(numpy.mean((values(self.out, "GlobalIrradiation") / glob - 1.0) ** 2)), 0.005)
        reflected = values(self.out, "ReflectedIrradiation")
        self.assertAlmostEqual(reflected.mean() / total["ReflectedIrradiance"].mean(), 1.0, delta=0.05)

    def test_an_instant_is_the_solve_at_that_instant(self):
        f = irradiation(self.terrain, *OLINDA_DAY, IntegrateOverTime=False)
        for hours in (9.25, 12.0, 16.5):  # hours since the start: 09:15, 12:00, 16:30 at -02:00
            f.UpdateTimeStep(hours)
            out = f.GetOutput()
            when = "2024-06-21T%02d:%02d:00-02:00" % (int(hours), round(60 * (hours % 1)))
            reference = self.instant(when)
            for name in ("Irradiance", "SunIrradiance", "SkyIrradiance", "ReflectedIrradiance"):
                ours, theirs = values(out, name), values(reference, name)
                self.assertLess(abs(ours.mean() / theirs.mean() - 1.0), 1e-3 if name != "ReflectedIrradiance" else 0.02,
                                (hours, name))
            numpy.testing.assert_allclose(values(out, "SunIrradiance"), values(reference, "SunIrradiance"),
                                          rtol=1e-6, atol=1e-6)
            self.assertIsNone(out.GetPointData().GetArray("SunshineDuration"))

    def test_shadows_shorten_sunshine(self):
        sunshine = values(self.out, "SunshineDuration")
        day = sum(field_values(self.out, "StepHours"))
        self.assertLessEqual(sunshine.max(), day + 1e-9)
        self.assertLess(sunshine.min(), day - 1.0)  # steep slopes lose hours

    def test_a_long_range_is_the_sum_of_its_parts(self):
        # 12 days at hourly steps: about 150 suns, which the hierarchy merges within 2
        # degrees of the sky; in parts of 3 days (about 40 suns) nothing is merged.
        def run(start, end):
            f = irradiation(self.terrain, start, end, 60.0)
            f.Update()
            return f.GetOutput()
        whole = run("2024-03-01T00:00:00-03:00", "2024-03-13T00:00:00-03:00")
        parts = [run("2024-03-%02dT00:00:00-03:00" % d, "2024-03-%02dT00:00:00-03:00" % (d + 3)) for d in (1, 4, 7, 10)]
        self.assertGreater(field_values(whole, "Steps")[0], 64)
        for name, tolerance in (("BeamIrradiation", 1e-9), ("SunshineDuration", 1e-9), ("SkyIrradiation", 3e-3)):
            total = sum(values(part, name) for part in parts)
            if tolerance < 1e-6:  # the same suns, ray for ray
                numpy.testing.assert_allclose(values(whole, name), total, rtol=tolerance, atol=1e-6, err_msg=name)
            else:
                self.assertAlmostEqual(values(whole, name).mean() / total.mean(), 1.0, delta=tolerance, msg=name)
        # Light from surfaces is 0.06 % of Olinda's global, read between a few hundred
        # lattice posts whose hits each draw one of the many suns: its mean is a few
        # percent noisy, so it is held against the global, within 0.01 % of it.
        reflected = values(whole, "ReflectedIrradiation").mean()
        self.assertGreater(reflected, 0.0)
        self.assertAlmostEqual(reflected, sum(values(part, "ReflectedIrradiation") for part in parts).mean(),
                               delta=1e-4 * values(whole, "GlobalIrradiation").mean())

    def test_input_is_not_modified(self):
        grid = self.terrain.GetOutput()
        for name in SUMS + ("SunshineDuration",):
            self.assertIsNone(grid.GetPointData().GetArray(name), name)

    @unittest.skipUnless(shutil.which("grass"), "GRASS GIS (grass-core) is not installed")
    def test_beam_agrees_with_grass_r_sun_daily(self):
        work = tempfile.mkdtemp(prefix="terralux-rsun-")
        subprocess.run(["grass", "-c", OLINDA, os.path.join(work, "loc"), "-e"], check=True, capture_output=True)
        script = os.path.join(work, "job.sh")
        with open(script, "w") as job:
            job.write("set -e\nr.in.gdal -o input=%s output=dem --quiet\ng.region raster=dem\n"
                      "r.slope.aspect elevation=dem slope=slope aspect=aspect --quiet\n"
                      "r.sun elevation=dem slope=slope aspect=aspect day=173 step=0.5 linke_value=3.0 "
                      "albedo_value=0.2 beam_rad=beam --quiet\n"
                      "r.out.gdal -c input=beam output=%s/beam.tif --quiet\n" % (OLINDA, work))
        subprocess.run(["grass", os.path.join(work, "loc", "PERMANENT"), "--exec", "bash", script],
                       check=True, capture_output=True)
        from osgeo import gdal
        dataset = gdal.Open(os.path.join(work, "beam.tif"))  # held: its bands die with it
        peer = dataset.GetRasterBand(1).ReadAsArray().astype(float)
        shutil.rmtree(work, ignore_errors=True)
        f = irradiation(self.terrain, *OLINDA_DAY)
        f.SetPostNormalsToHorn()  # r.slope.aspect's
        f.Update()
        ours = values(f.GetOutput(), "BeamIrradiation").reshape(111, 111)[::-1, :]  # grid rows run south to north
        inner = (slice(1, -1), slice(1, -1))  # r.slope.aspect has no slope on the border
        relative = ours[inner] / peer[inner] - 1.0
        self.assertLess(abs(ours[inner].mean() / peer[inner].mean() - 1.0), 0.005)
        self.assertLess(numpy.sqrt(numpy.mean(relative ** 2)), 0.01)


# A year of weather at Olinda made in code (no weather file ships with Debian): each
# hour the ESRA clear sky of vtkSunSource at the hour's middle, and every third day
# overcast (no direct light, the diffuse light a third of the clear sky's global).
OLINDA_PLACE = (-8.0, -34.85)


def synthetic_weather_rows():
    sun = vtkSunSource()
    sun.SetLatitude(OLINDA_PLACE[0])
    sun.SetLongitude(OLINDA_PLACE[1])
    rows = []
    start = datetime.datetime(2023, 1, 1)
    for hour in range(8760):
        local_end = start + datetime.timedelta(hours=hour + 1)  # the hour ending, UTC-3 standard time
        middle = local_end - datetime.timedelta(minutes=30) + datetime.timedelta(hours=3)
        sun.SetDateTime(middle.isoformat() + "Z")
        sun.Update()
        dni, dhi = sun.GetNormalIrradiance(), sun.GetDiffuseHorizontalIrradiance()
        if (hour // 24) % 3 == 2:
            glob = dni * max(0.0, math.cos(math.radians(sun.GetZenith()))) + dhi
            dni, dhi = 0.0, glob / 3.0
        end_day = local_end - datetime.timedelta(hours=1)  # hour 24 belongs to its own day
        rows.append((end_day.month, end_day.day, (hour % 24) + 1, dni, dhi))
    return rows


def write_epw(path, rows, latitude=OLINDA_PLACE[0], longitude=OLINDA_PLACE[1], drop=0, garble=None):
    with open(path, "w") as epw:
        epw.write("LOCATION,Olinda,PE,BRA,TerraLux test,000000,%.3f,%.3f,-3.0,10.0\n" % (latitude, longitude))
        for name in ("DESIGN CONDITIONS,0", "TYPICAL/EXTREME PERIODS,0", "GROUND TEMPERATURES,0",
                     "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0", "COMMENTS 1,synthetic", "COMMENTS 2,",
                     "DATA PERIODS,1,1,Data,Sunday,1/1,12/31"):
            epw.write(name + "\n")
        for k, (month, day, hour, dni, dhi) in enumerate(rows[:len(rows) - drop]):
            fields = [2023, month, day, hour, 60, "A7A7", 25.0, 20.0, 75, 101300, 0, 0, 400,
                      "%.1f" % (dni * 0 + dhi), "%.1f" % dni, "%.1f" % dhi] + [0] * 19
            if garble and k == garble[0]:
                fields[garble[1]] = garble[2]
            epw.write(",".join(str(f) for f in fields) + "\n")


def write_tmy3(path, rows):
    with open(path, "w") as tmy:
        tmy.write("000000,\"OLINDA\",PE,-3.0,%.3f,%.3f,10\n" % OLINDA_PLACE)
        tmy.write("Date (MM/DD/YYYY),Time (HH:MM),ETR (W/m^2),ETRN (W/m^2),GHI (W/m^2),GHI source,"
                  "GHI uncert (%),DNI (W/m^2),DNI source,DNI uncert (%),DHI (W/m^2),DHI source,DHI uncert (%)\n")
        for month, day, hour, dni, dhi in rows:
            tmy.write("%02d/%02d/2023,%02d:00,0,0,0,1,0,%.1f,1,0,%.1f,1,0\n" % (month, day, hour, dni, dhi))


class Weather(unittest.TestCase):
    """Sums driven by an hourly weather file (EPW, TMY3) and the Perez sky."""

    @classmethod
    def setUpClass(cls):
        cls.work = scratch_dir()
        cls.rows = synthetic_weather_rows()
        cls.epw = os.path.join(cls.work, "olinda.epw")
        write_epw(cls.epw, cls.rows)
        cls.plane = open_plane()

    def run_weather(self, path, start="2024-03-01T00:00:00-03:00", end="2024-03-04T00:00:00-03:00", **settings):
        f = irradiation(self.plane, start, end, Latitude=OLINDA_PLACE[0], Longitude=OLINDA_PLACE[1],
                        WeatherFileName=path, **settings)
        errors = ErrorCatcher(f)
        f.Update()
        return f.GetOutput(), errors

    def test_the_files_energy_reaches_open_ground(self):
        out, errors = self.run_weather(self.epw)
        self.assertEqual(errors.text(), "")
        # 1-3 March: days 59..61 of the file's year; 2 March is overcast ((day // 3) % ... as made).
        hours = [r for r in self.rows if r[0] == 3 and r[1] in (1, 2, 3)]
        sun = vtkSunSource()
        sun.SetLatitude(OLINDA_PLACE[0])
        sun.SetLongitude(OLINDA_PLACE[1])
        beam = 0.0
        for month, day, hour, dni, dhi in hours:
            sun.SetDateTime("2024-%02d-%02dT%02d:30:00-03:00" % (month, day, hour - 1))
            sun.Update()
            beam += dni * max(0.0, math.cos(math.radians(sun.GetZenith())))
        diffuse = sum(r[4] for r in hours)
        numpy.testing.assert_allclose(values(out, "BeamIrradiation"), beam, rtol=0.01)
        numpy.testing.assert_allclose(values(out, "SkyIrradiation"), diffuse, rtol=0.01)
        self.assertEqual(field_values(out, "WeatherHours"), [72.0])
        # Overcast hours bring no sunshine: two clear days' worth.
        day = sum(field_values(out, "StepHours")) / 3.0
        overcast_days = sum(1 for d in (1, 2, 3) if all(r[3] == 0.0 for r in hours if r[1] == d))
        numpy.testing.assert_allclose(values(out, "SunshineDuration"), (3 - overcast_days) * day, atol=0.1)

    def test_tmy3_gives_what_epw_gives(self):
        tmy = os.path.join(self.work, "olinda_tmy3.csv")
        write_tmy3(tmy, self.rows)
        a, _ = self.run_weather(self.epw)
        b, errors = self.run_weather(tmy)
        self.assertEqual(errors.text(), "")
        numpy.testing.assert_allclose(values(b, "GlobalIrradiation"), values(a, "GlobalIrradiation"), rtol=1e-9)

    def test_a_far_away_file_warns(self):
        far = os.path.join(self.work, "far.epw")
        write_epw(far, self.rows, latitude=-8.0, longitude=-36.0)  # about 125 km west
        f = irradiation(self.plane, "2024-03-01T00:00:00-03:00", "2024-03-02T00:00:00-03:00",
                        Latitude=OLINDA_PLACE[0], Longitude=OLINDA_PLACE[1], WeatherFileName=far)
        warnings = []
        f.AddObserver("WarningEvent", lambda caller, event: warnings.append(event))
        f.Update()
        self.assertEqual(len(warnings), 1)
        self.assertGreater(f.GetOutput().GetNumberOfPoints(), 0)

    def test_bad_files_are_refused(self):
        cases = {
            "missing.epw": ("cannot open", None),
            "short.epw": ("8760", dict(drop=1)),
            "text.epw": ("is not a number", dict(garble=(100, 14, "abc"))),
            "gap.epw": ("missing (9999)", dict(garble=(200, 15, "9999"))),
            "negative.epw": ("negative", dict(garble=(300, 14, "-5"))),
            "month.epw": ("out of range", dict(garble=(400, 1, "13"))),
        }
        for name, (expected, damage) in cases.items():
            path = os.path.join(self.work, name)
            if damage is not None:
                write_epw(path, self.rows, **damage)
            out, errors = self.run_weather(path)
            self.assertEqual(out.GetNumberOfPoints(), 0, name)
            self.assertIn(expected, errors.text(), name)
        with open(os.path.join(self.work, "cut.csv"), "w") as cut:
            cut.write("000000,OLINDA,PE,-3.0,-8.0,-34.85,10\nDate (MM/DD/YYYY),Time (HH:MM),DNI (W/m^2)\n")
        out, errors = self.run_weather(os.path.join(self.work, "cut.csv"))
        self.assertIn("no column 'DHI (", errors.text())


class PolarAndBadInput(unittest.TestCase):
    def test_polar_night_is_zero_not_an_error(self):
        f = irradiation(open_plane(), "2024-12-20T00:00:00Z", "2024-12-23T00:00:00Z", Latitude=80.0, Longitude=10.0)
        errors = ErrorCatcher(f)
        f.Update()
        self.assertEqual(errors.text(), "")
        out = f.GetOutput()
        self.assertEqual(out.GetNumberOfPoints(), 9)
        for name in SUMS + ("SunshineDuration",):
            numpy.testing.assert_array_equal(values(out, name), 0.0)
        self.assertEqual(field_values(out, "Steps"), [0.0])

    def test_polar_day_has_24_hours_of_sun(self):
        f = irradiation(open_plane(), "2024-06-21T00:00:00Z", "2024-06-22T00:00:00Z", Latitude=80.0, Longitude=10.0)
        f.Update()
        numpy.testing.assert_allclose(values(f.GetOutput(), "SunshineDuration"), 24.0, atol=1e-6)

    def test_progress_runs_through_the_steps_and_abort_stops_them(self):
        f = irradiation(open_plane(), "2024-01-01T00:00:00Z", "2024-03-01T00:00:00Z", Latitude=46.8, Longitude=8.0)
        seen = []

        def on_progress(caller, event):
            seen.append(caller.GetProgress())
            if caller.GetProgress() > 0.02:
                caller.SetAbortExecute(1)
        f.AddObserver("ProgressEvent", on_progress)
        warnings = []
        f.AddObserver("WarningEvent", lambda caller, event: warnings.append(event))
        f.Update()
        self.assertGreater(len([p for p in seen if 0.0 < p < 0.1]), 3)  # the steps report as they go
        self.assertEqual(len(warnings), 1)  # "Aborted."
        self.assertEqual(f.GetOutput().GetNumberOfPoints(), 0)
        self.assertLess(max(seen), 0.1)  # stopped between steps, before the solve

    def test_bad_ranges_are_refused(self):
        cases = [
            (("2024-06-22T00:00:00Z", "2024-06-21T00:00:00Z", 30.0), "end time must come after"),
            (("2024-06-21T00:00:00Z", "2024-06-22T00:00:00Z", 0.0), "time step"),
            (("2024-06-21T00:00:00Z", "2024-06-22T00:00:00Z", 1441.0), "time step"),
            (("2024-06-21T00:00:00Z", "2024-06-22T00:00:00Z", float("nan")), "TimeStep"),
            (("2000-01-01T00:00:00Z", "2012-01-01T00:00:00Z", 60.0), "ten years"),
            (("2024-06-21", "2024-06-22T00:00:00Z", 30.0), "ISO 8601"),
        ]
        for (start, end, step), expected in cases:
            f = irradiation(open_plane(), start, end, step)
            errors = ErrorCatcher(f)
            f.Update()
            self.assertEqual(f.GetOutput().GetNumberOfPoints(), 0, expected)
            self.assertIn(expected, errors.text())

    def test_bad_turbidity_and_place_are_refused(self):
        for settings, expected in (({"LinkeTurbidity": 40.0}, "Linke"), ({"Latitude": 95.0}, "atitude")):
            f = irradiation(open_plane(), *DAY, **settings)
            errors = ErrorCatcher(f)
            f.Update()
            self.assertEqual(f.GetOutput().GetNumberOfPoints(), 0, expected)
            self.assertIn(expected, errors.text())


class Command(unittest.TestCase):
    """python3 -m terralux.irradiation as a GIS user runs it."""

    def run_command(self, *arguments):
        return subprocess.run([sys.executable, "-m", "terralux.irradiation", *arguments],
                              capture_output=True, text=True, cwd=self.work)

    def setUp(self):
        self.work = scratch_dir()

    def test_help_writes_nothing(self):
        result = self.run_command("--help")
        self.assertEqual(result.returncode, 0)
        self.assertIn("--day-of-year", result.stdout)
        self.assertEqual(os.listdir(self.work), [])

    def test_bad_input_is_one_line(self):
        for arguments in ((OLINDA, "-o", "x.tif", "--start", "2024-06-02", "--end", "2024-06-01"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "400"),
                          (OLINDA, "-o", "x.tif", "--start", "2024-06-01", "--linke", "3,4"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "1", "--detail-distance", "-5"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "1", "--detail-distance", "nan"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "1", "--far-stride", "0"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "1", "--far-stride", "4"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "1", "--seed", "-1"),
                          (OLINDA, "-o", "x.tif", "--day-of-year", "1", "--pieces"),  # not a .vrt
                          ("missing.tif", "-o", "x.tif", "--day-of-year", "1")):
            result = self.run_command(*arguments, "--quiet")
            self.assertEqual(result.returncode, 1, arguments)
            self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
            self.assertIn("error:", result.stderr)
            self.assertFalse(os.path.exists(os.path.join(self.work, "x.tif")))

    def test_a_day_as_a_geotiff(self):
        from osgeo import gdal
        result = self.run_command(OLINDA, "-o", "day.tif", "--day-of-year", "173", "--fast")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("daylight steps", result.stdout)
        kwh = self.run_command(OLINDA, "-o", "day_kwh.tif", "--day-of-year", "173", "--fast", "--kwh", "--quiet")
        self.assertEqual(kwh.returncode, 0, kwh.stderr)
        wh, k = gdal.Open(os.path.join(self.work, "day.tif")), gdal.Open(os.path.join(self.work, "day_kwh.tif"))
        names = [wh.GetRasterBand(b).GetDescription() for b in range(1, wh.RasterCount + 1)]
        # --fast is the knob's coarse end, at points: each post has its error estimate.
        self.assertEqual(names, ["GlobalIrradiation", "BeamIrradiation", "SkyIrradiation", "ReflectedIrradiation",
                                 "SunshineDuration", "SkyViewFactor", "IrradiationError"])
        self.assertEqual((wh.RasterXSize, wh.RasterYSize), (111, 111))
        self.assertEqual(wh.GetRasterBand(1).GetUnitType(), "Wh/m^2")
        self.assertEqual(k.GetRasterBand(1).GetUnitType(), "kWh/m^2")
        self.assertEqual(wh.GetRasterBand(5).GetUnitType(), "h")
        a, b = wh.GetRasterBand(1).ReadAsArray(), k.GetRasterBand(1).ReadAsArray()
        numpy.testing.assert_allclose(b * 1000.0, a, rtol=1e-5)
        self.assertGreater(float(a.mean()), 4000.0)

    def test_at_points_each_post_has_its_error(self):
        from osgeo import gdal
        result = self.run_command(OLINDA, "-o", "points.tif", "--day-of-year", "173", "--step", "120", "--quiet")
        self.assertEqual(result.returncode, 0, result.stderr)
        tif = gdal.Open(os.path.join(self.work, "points.tif"))
        names = [tif.GetRasterBand(b).GetDescription() for b in range(1, tif.RasterCount + 1)]
        self.assertEqual(names[-1], "IrradiationError")
        error = tif.GetRasterBand(tif.RasterCount)
        self.assertEqual(error.GetUnitType(), "Wh/m^2")
        values, global_ = error.ReadAsArray().astype(float), tif.GetRasterBand(1).ReadAsArray().astype(float)
        self.assertTrue(numpy.isfinite(values).all() and (values >= 0.0).all())
        # An estimate of a small error: above 0 where light comes from surfaces, its
        # median well below the global's mean.
        self.assertGreater(float(values.max()), 0.0)
        self.assertLess(float(numpy.median(values)), 0.02 * float(global_.mean()))


if __name__ == "__main__":
    unittest.main()
