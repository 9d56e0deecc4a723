#!/usr/bin/python3
"""GRASS r.sun's error against the accuracy report's reference, beside TerraLux's knob.

For one terrain scene of the accuracy report (one sun and its CIE clear sky), r.sun's
instant is run on the scene's DEM with its inputs matched as far as r.sun allows:
- the sun: a latitude, declination and local solar time that put r.sun's sun at the
  scene's altitude and azimuth (checked on a horizontal and a tilted plane);
- the light: real-sky coefficients that make r.sun's beam normal irradiance and its
  diffuse horizontal irradiance on open flat ground the scene's (800 and 100 W/m^2);
  r.sun's diffuse sky model (Muneer's) stays its own, not CIE's;
- the albedo: the scene's reflectance.
It runs plain (no terrain taken off the diffuse sky) and with r.horizon's horizons at
TerraLux's 32 azimuths, in one GRASS session with the DEM's ingest, its slopes,
r.horizon where used, and r.sun (nprocs=2).

Prints one JSON line per run in the accuracy report's format (method "rsun" or
"rsun-horizons"; seconds: r.horizon and r.sun alone, as the report times TerraLux's
solve; session_seconds: the whole GRASS session): append them to the report's runs and accuracy_report.py plots them as
points beside TerraLux's curves. Errors are taken as the report takes TerraLux's: global
over the posts where r.sun and the reference agree on shadow.

Usage: /usr/bin/python3 rsun_accuracy.py BUILD_DIR REFERENCE_DIR SCENE
  (the scene's reference must be in REFERENCE_DIR; needs grass-core and python3-gdal)
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

# Where the posts are placed: UTM zone 32N (EPSG), about its false origin.
UTM_EPSG = 32632
UTM_ORIGIN = (500000.0, 5000000.0)
# TerraLux's horizons: 32 azimuths.
HORIZON_STEP_DEG = 11.25
# r.horizon at those azimuths. GRASS 8.2 (Debian bookworm's) writes negative horizons
# where the terrain falls away, which r.sun misreads as shadow (OSGeo/grass#2935); GRASS
# 8.3 went back to horizons of at least 0 (OSGeo/grass#2955): so do they here.
HORIZONS = """$TIMED r.horizon elevation=dem step=%g output=horizon --overwrite --quiet
for map in $(g.list type=raster pattern='horizon_*'); do
  r.mapcalc "$map = max($map, 0)" --overwrite --quiet
done
"""
# r.sun's day (its extraterrestrial irradiance; the coefficients take out its effect).
DAY = 356
# A winter declination (deg): the scenes' low suns at a latitude found for them.
DECLINATION_DEG = -23.44


def sun_position(latitude, declination, hour_angle):
    """Altitude and compass azimuth (deg) of the sun at a latitude, declination and hour
    angle (deg, negative before noon)."""
    phi, delta, omega = (math.radians(v) for v in (latitude, declination, hour_angle))
    s = math.sin(phi) * math.sin(delta) + math.cos(phi) * math.cos(delta) * math.cos(omega)
    altitude = math.asin(max(-1.0, min(1.0, s)))
    east = -math.cos(delta) * math.sin(omega)
    north = math.sin(delta) * math.cos(phi) - math.cos(delta) * math.sin(phi) * math.cos(omega)
    return math.degrees(altitude), math.degrees(math.atan2(east, north)) % 360.0


def matching_sun(altitude, azimuth):
    """A latitude and hour angle (deg) that put the sun at `altitude` toward compass
    `azimuth` on the winter declination: a coarse search, then a finer one around it."""
    best = None
    span_lat, span_hour, centre = 80.0, 90.0, (0.0, 0.0)
    for _ in range(6):
        for lat in np.linspace(centre[0] - span_lat, centre[0] + span_lat, 81):
            if not -85.0 < lat < 85.0:
                continue
            for hour in np.linspace(centre[1] - span_hour, centre[1] + span_hour, 81):
                a, z = sun_position(lat, DECLINATION_DEG, hour)
                miss = (a - altitude) ** 2 + (((z - azimuth + 180.0) % 360.0) - 180.0) ** 2
                if best is None or miss < best[0]:
                    best = (miss, lat, hour)
        centre = best[1:]
        span_lat, span_hour = span_lat / 10.0, span_hour / 10.0
    if best[0] > 1e-4:
        raise RuntimeError("no latitude and time put the sun at %g deg toward %g deg" % (altitude, azimuth))
    return best[1], best[2]


def grass(location, script, work):
    """Runs a bash script in a GRASS session on `location`; returns (seconds, peak MiB)."""
    path = os.path.join(work, "session.sh")
    with open(path, "w") as f:
        f.write("set -e\n" + script)
    timing = os.path.join(work, "session.time")
    started = time.time()
    session = subprocess.run(["/usr/bin/time", "-f", "elapsed %e peak %M", "-o", timing,
                    "grass", os.path.join(location, "PERMANENT"), "--exec", "bash", path],
                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if session.returncode != 0:
        raise RuntimeError("GRASS failed:\n%s\n%s" % (script, session.stderr[-2000:]))
    match = re.search(r"elapsed ([0-9.]+) peak ([0-9]+)", open(timing).read())
    return (float(match.group(1)) if match else time.time() - started), (int(match.group(2)) / 1024.0 if match else 0.0)


def export(maps, work):
    """The GRASS commands that write raster maps to WORK/<map>.tif."""
    return "".join("r.out.gdal input=%s output=%s/%s.tif --overwrite --quiet\n" % (m, work, m) for m in maps)


def read_raster(work, name):
    """WORK/<name>.tif's first band."""
    from osgeo import gdal
    data = gdal.Open(os.path.join(work, name + ".tif"))  # kept while its band is read (GDAL frees bands with it)
    return data.GetRasterBand(1).ReadAsArray().astype(np.float64)


def mean_of(work, name):
    return float(np.nanmean(read_raster(work, name)))


def errors(value, reference, reference_error, include):
    """The report's error figures of one component (accuracy_report.cxx errorJson)."""
    d = (value - reference)[include]
    mean = float(reference[include].mean()) if include.any() else 0.0
    relative = (lambda x: float(x) / mean) if mean > 0 else (lambda x: 0.0)
    absolute = np.sort(np.abs(d))
    p95 = absolute[int(0.95 * (len(absolute) - 1))] if len(absolute) else 0.0
    return {"mean": mean, "rms": relative(math.sqrt(float((d ** 2).mean())) if len(d) else 0.0),
            "p95": relative(p95), "max": relative(absolute[-1] if len(absolute) else 0.0),
            "bias": relative(d.mean() if len(d) else 0.0),
            "reference_error": relative(reference_error[include].mean() if include.any() else 0.0)}


def main():
    build_dir, reference_dir, scene = sys.argv[1:4]
    report = os.path.join(build_dir, "bin", "accuracy_report")
    scene_info = json.loads(subprocess.run([report, scene, reference_dir, "describe"], check=True,
                                           capture_output=True, text=True).stdout)
    if not scene_info["terrain"] or not scene_info["sun_normal_irradiance"] > 0:
        sys.exit("%s: r.sun needs a terrain scene under one sun and its clear sky" % scene)
    work = tempfile.mkdtemp(prefix="rsun-accuracy-")
    try:
        # The scene's posts and the reference's values at them, from a TerraLux solve.
        points = os.path.join(work, "points.csv")
        subprocess.run([report, scene, reference_dir, "solve", "points", "1e-2"], check=True,
                       stdout=subprocess.DEVNULL, env=dict(os.environ, TERRALUX_REPORT_POINTS=points))
        with open(points) as f:
            records = list(csv.DictReader(f))
        column = {k: np.array([float(r[k]) for r in records]) for k in records[0]}
        xs, ys = np.unique(column["x"]), np.unique(column["y"])
        spacing = float(xs[1] - xs[0])
        cols = np.rint((column["x"] - xs[0]) / spacing).astype(int)
        rows = np.rint((ys[-1] - column["y"]) / spacing).astype(int)
        heights = np.full((len(ys), len(xs)), np.nan)
        heights[rows, cols] = column["z"]
        if np.isnan(heights).any() or len(records) != heights.size:
            sys.exit("%s: the posts are not one full grid" % scene)
        from osgeo import gdal, osr
        dem = os.path.join(work, "dem.tif")
        out = gdal.GetDriverByName("GTiff").Create(dem, len(xs), len(ys), 1, gdal.GDT_Float64)
        # r.sun wants a projected location: the posts placed in UTM zone 32N (r.sun's sun
        # comes from the latitude given, not from there).
        out.SetGeoTransform((UTM_ORIGIN[0] + xs[0] - spacing / 2, spacing, 0.0,
                             UTM_ORIGIN[1] + ys[-1] + spacing / 2, 0.0, -spacing))
        utm = osr.SpatialReference()
        utm.ImportFromEPSG(UTM_EPSG)
        out.SetProjection(utm.ExportToWkt())
        out.GetRasterBand(1).WriteArray(heights)
        out = None

        altitude, azimuth = scene_info["sun_altitude_deg"], scene_info["sun_azimuth_deg"]
        latitude, hour_angle = matching_sun(altitude, azimuth)
        solar_time = 12.0 + hour_angle / 15.0
        location = os.path.join(work, "location")
        subprocess.run(["grass", "-e", "-c", "EPSG:%d" % UTM_EPSG, location], check=True, capture_output=True)
        # The DEM, its slopes, and the latitude (the longitude only completes the pair
        # r.sun asks for: with local solar time it plays no part).
        setup = ("r.in.gdal input=%s output=dem --overwrite --quiet\ng.region raster=dem\n"
                 "r.slope.aspect elevation=dem slope=slope aspect=aspect --overwrite --quiet\n"
                 "r.mapcalc 'lat = %.9f' --overwrite --quiet\nr.mapcalc 'long = 9' --overwrite --quiet\n"
                 % (dem, latitude))
        sun = "lat=lat long=long day=%d time=%.6f declination=%.9f" % (DAY, solar_time, math.radians(DECLINATION_DEG))

        # r.sun's sun, checked on open planes (no shadows): a horizontal one (incidence =
        # altitude) and one tilted 30 deg toward the compass azimuth 90 deg off the sun's,
        # its slope and aspect from r.slope.aspect as the DEM's are (incidence from the
        # sun's direction; r.sun's single aspect_value follows another convention).
        facing = math.radians(azimuth + 90.0)
        centre = (UTM_ORIGIN[0] + xs.mean(), UTM_ORIGIN[1] + ys.mean())
        s_alt = math.sin(math.radians(altitude))
        expected_tilted = math.degrees(math.asin(s_alt * math.cos(math.radians(30.0))))
        planes = ("r.mapcalc 'tilted = -0.5773503 * ((x() - %.3f) * %.9f + (y() - %.3f) * %.9f)' --overwrite --quiet\n"
                  "r.slope.aspect elevation=tilted slope=tilted_slope aspect=tilted_aspect --overwrite --quiet\n"
                  % (centre[0], math.sin(facing), centre[1], math.cos(facing)))
        grass(location, setup +
              "r.sun -p elevation=dem slope_value=0 aspect_value=270 %s linke_value=3.0 albedo_value=0 "
              "beam_rad=b0 diff_rad=d0 incidout=i0 --overwrite --quiet\n" % sun + planes +
              "r.sun -p elevation=tilted slope=tilted_slope aspect=tilted_aspect %s incidout=i1 --overwrite --quiet\n"
              % sun + export(("b0", "d0", "i0", "i1"), work), work)
        if abs(mean_of(work, "i0") - altitude) > 0.3:
            sys.exit("%s: r.sun's sun did not come to %g deg up (%.2f)" % (scene, altitude, mean_of(work, "i0")))
        tilted = mean_of(work, "i1")
        if abs(tilted - expected_tilted) > 0.5:
            sys.exit("%s: r.sun's sun is not toward %g deg (a tilted plane sees it at %.2f deg, not %.2f)"
                     % (scene, azimuth, tilted, expected_tilted))
        # Real-sky coefficients: the scene's beam normal and diffuse horizontal irradiance.
        coeff_bh = scene_info["sun_normal_irradiance"] / (mean_of(work, "b0") / s_alt)
        coeff_dh = scene_info["diffuse_horizontal"] / mean_of(work, "d0")

        lines = []
        for method, horizons in (("rsun", False), ("rsun-horizons", True)):
            call = ("r.sun elevation=dem slope=slope aspect=aspect %s linke_value=3.0 albedo_value=%g "
                    "coeff_bh=coeff_bh coeff_dh=coeff_dh beam_rad=beam diff_rad=diff refl_rad=refl glob_rad=glob "
                    "nprocs=2 --overwrite --quiet" % (sun, scene_info["reflectance"]))
            if horizons:
                call += " horizon_basename=horizon horizon_step=%g" % HORIZON_STEP_DEG
            # r.horizon and r.sun are timed alone too ($TIMED), as the report times TerraLux's solve.
            timed = os.path.join(work, "steps.time")
            script = ("TIMED='/usr/bin/time -f %%e -a -o %s'\n" % timed + setup +
                      "r.mapcalc 'coeff_bh = %.9f' --overwrite --quiet\n" % coeff_bh +
                      "r.mapcalc 'coeff_dh = %.9f' --overwrite --quiet\n" % coeff_dh +
                      (HORIZONS % HORIZON_STEP_DEG if horizons else "") + "$TIMED " + call + "\n")
            if os.path.exists(timed):
                os.remove(timed)
            session_seconds, peak = grass(location, script, work)
            seconds = sum(float(line) for line in open(timed) if re.match(r"^[0-9.]+$", line.strip()))
            outputs = ("beam", "diff", "refl", "glob")
            grass(location, export(outputs, work), work)
            value = {m: read_raster(work, m)[rows, cols] for m in outputs}
            used = (column["used"] != 0) & np.isfinite(value["glob"])
            rsun_lit, ref_lit = value["beam"] > 0, column["ref_sun"] > 0
            agree = used & (rsun_lit == ref_lit)
            sun_facing = used & (column["sun_facing"] != 0)
            zero = np.zeros(len(records))
            run = {"scene": scene, "method": method, "tolerance": 0, "seconds": seconds,
                   "session_seconds": session_seconds, "peak_mib": peak,
                   "elements": 0, "links": 0, "rays": 0, "iterations": 0, "floor_seconds": 0,
                   "shadow_disagreement": float((sun_facing & (rsun_lit != ref_lit)).sum() / max(1, sun_facing.sum())),
                   "sun": errors(value["beam"], column["ref_sun"], zero, used),
                   "sky": errors(value["diff"], column["ref_sky"], zero, used),
                   "reflected": errors(value["refl"], column["ref_reflected"], zero, used),
                   "global": errors(value["glob"], column["ref_global"], column["ref_error"], agree),
                   "matched": {"latitude_deg": latitude, "solar_time_h": solar_time, "coeff_bh": coeff_bh,
                               "coeff_dh": coeff_dh, "albedo": scene_info["reflectance"]}}
            lines.append(json.dumps(run))
        print("\n".join(lines))
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
