#!/usr/bin/python3
"""What a post's terrain seen holds, and what reads between lattice posts make of it
(diagnostic of the faint bands of reflected light; docs/tuning.md, "What a read cannot
tell"). Not run by ctest.

From a terrain scene's points as the accuracy report dumps them (TERRALUX_REPORT_POINTS,
in grid order) and the reference's bands file, per band of reflected light:
- the map's terrain seen (1 - SkyViewFactor) against a march over the grid's triangles
  from each post: the terrain it meets (each visible sample at the reference's radiosity
  there, reflectance x its global) and the void below the horizontal (directions above
  the post's plane that leave the DEM without meeting terrain);
- reads of every post from the reference's own light at lattice posts `step` apart (the
  engine's read: the corners' light over their terrain seen, bilinear, times the post's),
  by the map's terrain seen and by the map's less the void.

Usage: faint_reads.py POINTS_CSV REFERENCE_BANDS REFLECTANCE [AZIMUTHS] [STEP]
  e.g. TERRALUX_REPORT_POINTS=/tmp/p.csv build/bin/accuracy_report steep-noon docs/validation solve points 0.01 0.008
       Testing/Benchmarks/faint_reads.py /tmp/p.csv docs/validation/steep-noon.reference.bands 0.5
"""
import csv
import sys

import numpy as np

BANDS = [(0.0, 1.0), (1.0, 10.0), (10.0, 50.0), (50.0, np.inf)]


def load(path):
    rows = list(csv.DictReader(open(path)))
    return {key: np.array([float(row[key]) for row in rows]) for key in rows[0]}


def on_triangles(grid, u, v):
    """Values on the grid's triangles (cells split from (i+1, j) to (i, j+1), as
    TerrainGrid::cellTriangles), at grid parameters u, v."""
    ny, nx = grid.shape
    u = np.clip(u, 0, nx - 1 - 1e-9)
    v = np.clip(v, 0, ny - 1 - 1e-9)
    i = np.minimum(np.floor(u).astype(int), nx - 2)
    j = np.minimum(np.floor(v).astype(int), ny - 2)
    s, t = u - i, v - j
    lower = grid[j, i] + s * (grid[j, i + 1] - grid[j, i]) + t * (grid[j + 1, i] - grid[j, i])
    upper = (grid[j + 1, i + 1] + (1 - s) * (grid[j + 1, i] - grid[j + 1, i + 1]) +
             (1 - t) * (grid[j, i + 1] - grid[j + 1, i + 1]))
    return np.where(s + t <= 1, lower, upper)


def march(points, spacing, heights, radiosity, azimuths):
    """Per post: the terrain seen, the light it sends and the void below the horizontal,
    as shares of the hemisphere's projected solid angle (the light in W/m^2)."""
    ny, nx = heights.shape
    normal = np.stack([points["nx"], points["ny"], points["nz"]], 1)
    i, j, z = points["i"], points["j"], points["z"]
    steps = np.arange(1, 2 * max(nx, ny)) * 0.5
    seen, light, void = (np.zeros(len(z)) for _ in range(3))
    for a in range(azimuths):
        phi = 2 * np.pi * (a + 0.5) / azimuths
        dx, dy = np.cos(phi), np.sin(phi)
        u, v = i[:, None] + steps * dx, j[:, None] + steps * dy
        inside = (u >= 0) & (u <= nx - 1) & (v >= 0) & (v <= ny - 1)
        elevation = np.where(inside, np.arctan2(on_triangles(heights, u, v) - z[:, None], steps * spacing),
                             -np.pi)
        nearer = np.concatenate([np.full((len(z), 1), -np.pi), np.maximum.accumulate(elevation, 1)[:, :-1]], 1)
        # The post's plane in this azimuth, and the projected solid angle of an elevation
        # band above it: the integral of (n . w) cos e de over the azimuth's slice.
        along = normal[:, 0] * dx + normal[:, 1] * dy
        plane = np.arctan(-along / normal[:, 2])

        def projected(low, high):
            f = lambda e: along[:, None] * (e / 2 + np.sin(2 * e) / 4) + normal[:, 2][:, None] * np.sin(e) ** 2 / 2
            return np.where(high > low, f(high) - f(low), 0.0) * (2 * np.pi / azimuths) / np.pi

        low = np.maximum(nearer, plane[:, None])
        weight = projected(low, np.where((elevation > nearer) & inside, elevation, low))
        seen += weight.sum(1)
        light += (weight * np.nan_to_num(on_triangles(radiosity, u, v))).sum(1)
        horizon = elevation.max(1)
        void += projected(np.maximum(plane, horizon)[:, None], np.zeros((len(z), 1)))[:, 0]
    return seen, light, void


def read(light, seen, step):
    """Every post read from the lattice posts `step` apart around it, as the engine reads."""
    ny, nx = light.shape
    result = np.zeros_like(light)
    for j in range(ny):
        for i in range(nx):
            i0, j0 = min(i // step * step, nx - 1 - step), min(j // step * step, ny - 1 - step)
            s, t = (i - i0) / step, (j - j0) / step
            corners = [(i0, j0, (1 - s) * (1 - t)), (i0 + step, j0, s * (1 - t)), (i0, j0 + step, (1 - s) * t),
                       (i0 + step, j0 + step, s * t)]
            sent = sum(w * light[cj, ci] for ci, cj, w in corners)
            terrain = sum(w * seen[cj, ci] for ci, cj, w in corners)
            result[j, i] = seen[j, i] * sent / terrain if terrain > 1e-9 else 0.0
    return result


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    points = load(sys.argv[1])
    bands = np.fromfile(sys.argv[2], dtype="<f8")
    reflectance = float(sys.argv[3])
    azimuths = int(sys.argv[4]) if len(sys.argv) > 4 else 64
    step = int(sys.argv[5]) if len(sys.argv) > 5 else 4
    xs, ys = np.unique(points["x"]), np.unique(points["y"])
    if len(xs) * len(ys) != len(points["x"]):
        sys.exit("faint_reads.py: the points are not an axis-aligned grid of posts (a terrain scene's, "
                 "e.g. steep-noon, steep-morning or fractal)")
    spacing = float(np.median(np.diff(xs)))
    points["i"] = np.round((points["x"] - xs[0]) / spacing).astype(int)
    points["j"] = np.round((points["y"] - ys[0]) / spacing).astype(int)

    def grid(values):
        g = np.full((len(ys), len(xs)), np.nan)
        g[points["j"], points["i"]] = values
        return g

    heights = grid(points["z"])
    seen, light, void = march(points, spacing, heights, grid(reflectance * points["ref_global"]), azimuths)
    mapped = 1.0 - points["sky_view"]
    truth = points["ref_reflected"]
    used = points["used"] > 0
    by_map = read(grid(truth), grid(mapped), step)[points["j"], points["i"]]
    less_void = np.maximum(mapped - void, 0.0)
    by_less_void = read(grid(truth), grid(less_void), step)[points["j"], points["i"]]
    print("band W/m^2 | points | map's terrain seen | march: terrain, void | reflected: reference, march | "
          "reads by the map's, by the map's less the void")
    for low, high in BANDS:
        m = used & (bands >= low) & (bands < high)
        if m.sum() < 30:
            continue
        bias = lambda r: 100 * (r[m].mean() / truth[m].mean() - 1)
        print("%g-%g | %d | %.4f | %.4f, %.4f | %.3f, %.3f | %+.1f %%, %+.1f %%" % (
            low, high, m.sum(), mapped[m].mean(), seen[m].mean(), void[m].mean(), truth[m].mean(), light[m].mean(),
            bias(by_map), bias(by_less_void)))


if __name__ == "__main__":
    main()
