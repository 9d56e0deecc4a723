"""The accuracy report's peer comparison: the sun r.sun is given matches the scene's
(rsun_accuracy.py's solar geometry, against closed forms), and the report places r.sun's
runs beside TerraLux's knob (accuracy_report.py: tables, plots, and the verdict whether
TerraLux lies below and to the left)."""
import importlib.util
import json
import os
import shutil
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def load(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(REPO, "Testing", "Benchmarks", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


rsun_accuracy = load("rsun_accuracy")
accuracy_report = load("accuracy_report")


def errors(rms, bias=0.0, mean=100.0):
    return {"mean": mean, "rms": rms, "p95": 2 * rms, "max": 3 * rms, "bias": bias, "reference_error": 0.001}


def terralux_run(scene, target, seconds, rms):
    return {"scene": scene, "method": "points", "tolerance": 1e-2, "target_error": target, "seconds": seconds,
            "peak_mib": 50, "elements": 10, "links": 9, "rays": 1000, "iterations": 2, "floor_seconds": 0.01,
            "shadow_disagreement": 0.0, "sun": errors(0.0), "sky": errors(rms), "reflected": errors(rms, -0.01),
            "global": errors(rms), "estimate": {"coverage": 0.95, "median": 0.01}}


def peer_run(scene, method, seconds, rms):
    return {"scene": scene, "method": method, "tolerance": 0, "seconds": seconds, "session_seconds": seconds + 1,
            "peak_mib": 52, "elements": 0, "links": 0, "rays": 0, "iterations": 0, "floor_seconds": 0,
            "shadow_disagreement": 0.01, "sun": errors(0.1), "sky": errors(0.4, 0.3), "reflected": errors(0.9, -0.7),
            "global": errors(rms, 0.1)}


class SolarGeometry(unittest.TestCase):
    def test_noon_closed_form(self):
        # At noon the sun stands 90 - |latitude - declination| up, due south north of it.
        altitude, azimuth = rsun_accuracy.sun_position(44.56, -23.44, 0.0)
        self.assertAlmostEqual(altitude, 22.0, places=6)
        self.assertAlmostEqual(azimuth, 180.0, places=6)
        # Before noon the sun is east of south, after it west, symmetrically.
        morning = rsun_accuracy.sun_position(45.0, -23.44, -30.0)
        afternoon = rsun_accuracy.sun_position(45.0, -23.44, 30.0)
        self.assertAlmostEqual(morning[0], afternoon[0], places=9)
        self.assertAlmostEqual(morning[1], 360.0 - afternoon[1], places=9)
        self.assertLess(morning[1], 180.0)

    def test_equinox_sunrise_due_east(self):
        # At the equinox the sun rises due east, 6 hours before noon, at any latitude.
        altitude, azimuth = rsun_accuracy.sun_position(50.0, 0.0, -90.0)
        self.assertAlmostEqual(altitude, 0.0, places=9)
        self.assertAlmostEqual(azimuth, 90.0, places=9)

    def test_every_scene_sun_is_matched(self):
        for altitude, azimuth in ((8.0, 135.0), (22.0, 180.0), (25.0, 120.0), (10.7, 160.0), (10.0, 135.0),
                                  (20.0, 180.0), (25.0, 200.0)):
            latitude, hour_angle = rsun_accuracy.matching_sun(altitude, azimuth)
            found = rsun_accuracy.sun_position(latitude, rsun_accuracy.DECLINATION_DEG, hour_angle)
            self.assertAlmostEqual(found[0], altitude, delta=0.01)
            self.assertAlmostEqual(found[1], azimuth, delta=0.01)

    def test_unreachable_sun_is_refused(self):
        # No sun stands higher than the zenith.
        with self.assertRaises(RuntimeError):
            rsun_accuracy.matching_sun(95.0, 180.0)


class PeersInTheReport(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="terralux-accuracy-report-")

    def tearDown(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def test_verdicts(self):
        solves = [terralux_run("a", 0.064, 0.2, 0.009), terralux_run("a", 0.008, 0.8, 0.004),
                  terralux_run("b", 0.064, 1.2, 0.015), terralux_run("b", 0.008, 2.3, 0.005)]
        peers = [peer_run("a", "rsun", 0.3, 0.2), peer_run("b", "rsun", 0.2, 0.1),
                 peer_run("c", "rsun", 0.2, 0.1)]  # a scene TerraLux did not run: no row
        rows = [line for line in accuracy_report.against_peers(solves, peers) if line.startswith("| a") or
                line.startswith("| b") or line.startswith("| c")]
        self.assertEqual(len(rows), 2)
        self.assertTrue(rows[0].endswith("| yes |"))  # 0.2 s at 0.9 % against 0.3 s at 20 %
        self.assertTrue(rows[1].endswith("| no |"))   # nothing as fast as r.sun's 0.2 s
        self.assertEqual(accuracy_report.against_peers(solves, []), [])

    def test_reflected_bands(self):
        # Each band's bias, from below 1 W/m^2 up; a band of too few points, or none, is not
        # shown, nor are bands a run does not have (an older reference).
        run = terralux_run("a", 0.008, 0.8, 0.004)
        self.assertEqual(accuracy_report.reflected_bands(run), "-")
        run["reflected_bands"] = [
            {"from": 0.0, "posts": 500, "error": errors(0.01, 0.012, 0.5)},
            {"from": 1.0, "posts": 200, "error": errors(0.01, -0.0368, 3.0)},
            {"from": 10.0, "posts": accuracy_report.BAND_POINTS - 1, "error": errors(0.01, 0.2, 20.0)},
            {"from": 50.0, "posts": 0, "error": errors(0.0, 0.0, 0.0)}]
        self.assertEqual(accuracy_report.reflected_bands(run), "1.20 / -3.68 / - / -")
        rows = [line for line in accuracy_report.summary([run]) if line.startswith("| a |")]
        self.assertEqual(len(rows), 2)  # the summary's row, then the table by band's
        self.assertIn("| 1.20 / -3.68 / - / - |", rows[0])
        # The table by band: relative, in W/m^2 (bias x the band's mean), and the points.
        table = [line for line in accuracy_report.band_table([run]) if line.startswith("| a |")]
        self.assertEqual(table, ["| a | 1.20 % = 0.006 W/m^2 (500) | -3.68 % = -0.110 W/m^2 (200) | - | - |"])
        self.assertEqual(accuracy_report.band_table([terralux_run("a", 0.008, 0.8, 0.004)]), [])
        # Drawn again on other seeds: each band's bias over them all, mean and spread.
        again = json.loads(json.dumps(run))
        again["random_seed"] = 1
        again["reflected"]["bias"] = -0.002
        again["reflected_bands"][0]["error"]["bias"] = 0.008
        again["reflected_bands"][1]["error"]["bias"] = -0.0168
        self.assertTrue(accuracy_report.drawn_again(again))
        self.assertFalse(accuracy_report.drawn_again(run))
        table = [line for line in accuracy_report.band_table([run], [again]) if line.startswith("| a |")]
        self.assertEqual(len(table), 2)
        overall = 100.0 * (run["reflected"]["bias"] - 0.002) / 2
        self.assertEqual(table[1], "| a | %.2f ± %.2f | 1.00 ± 0.28 | -2.68 ± 1.41 | - | - |" % (
            overall, abs(100.0 * (run["reflected"]["bias"] + 0.002)) / 2 ** 0.5))

    def test_report_with_peers(self):
        runs = os.path.join(self.work, "runs.jsonl")
        with open(runs, "w") as f:
            f.write(json.dumps({"scene": "a", "reference_seconds": 1.0, "points": 100, "samples": 64}) + "\n")
            # The defaults, and the same drawn again on another seed.
            for run in (terralux_run("a", 0.064, 0.2, 0.009), terralux_run("a", 0.008, 0.8, 0.004),
                        dict(terralux_run("a", 0.008, 0.9, 0.004), random_seed=1)):
                f.write(json.dumps(run) + "\n")
        with open(os.path.join(self.work, "rsun.jsonl"), "w") as f:
            f.write(json.dumps(peer_run("a", "rsun", 0.3, 0.2)) + "\n")
            f.write(json.dumps(peer_run("a", "rsun-horizons", 1.3, 0.2)) + "\n")
        argv = sys.argv
        try:
            sys.argv = ["accuracy_report.py", runs, self.work]
            accuracy_report.main()
            # Again from its report.json: the peers are read once, not twice.
            sys.argv = ["accuracy_report.py", os.path.join(self.work, "report.json"), self.work]
            accuracy_report.main()
        finally:
            sys.argv = argv
        with open(os.path.join(self.work, "report.json")) as f:
            report = json.load(f)
        self.assertEqual({r["method"] for r in report["solves"]}, {"points"})
        self.assertEqual(len(report["solves"]), 3)  # the seed's solve kept with the others'
        # ... but not among the scene's rows and the summary's: those are seed 0's alone.
        with open(os.path.join(self.work, "report.md")) as f:
            self.assertEqual(f.read().count("| 0.900 |"), 0)
        with open(os.path.join(self.work, "report.md")) as f:
            text = f.read()
        self.assertIn("## Against GRASS r.sun", text)
        self.assertEqual(text.count("| a | GRASS r.sun with r.horizon |"), 1)
        self.assertEqual(text.count("| GRASS r.sun | - | - | 0.300 |"), 1)  # its row in the scene's table
        self.assertTrue(os.path.getsize(os.path.join(self.work, "a.png")) > 0)


if __name__ == "__main__":
    unittest.main()
