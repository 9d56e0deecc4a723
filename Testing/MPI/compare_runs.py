"""Compares what mpi_pipeline.py wrote under different numbers of ranks with the run
of the first folder (1 rank): every point array of the .pvts pieces put together, and
every band and the georeference of the GeoTIFFs assembled on rank 0 and of the VRTs
over the ranks' own GeoTIFFs, within 1e-6 relative. With --rasters, two GeoTIFFs (e.g. pvbatch's under mpirun and plain VTK's).

  /usr/bin/python3 compare_runs.py ONE_RANK_DIR OTHER_DIR...
  /usr/bin/python3 compare_runs.py --rasters ONE_RANK.tif OTHER.tif
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPStructuredGridReader

import terralux

RELATIVE_TOLERANCE = 1e-6
OUTPUTS = ("instant", "near", "series", "window", "window_series")
# A detail distance changes what far gather hits send: the irradiance a little (at
# most this, relative to the largest), never nothing (the test would then hold no halo).
NEAR_AGAINST_INSTANT = 0.02


def pieces(path):
    reader = vtkXMLPStructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    arrays = {}
    pd = data.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        if pd.GetArrayName(k) != "vtkGhostType":
            arrays[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k)).astype(float)
    return data.GetExtent(), arrays


def bands(path):
    """Each band of a GeoTIFF (vtkTerrainSource reads any band as Elevation)."""
    result, band = [], 1
    while True:
        reader = terralux.vtkTerrainSource()
        reader.SetFileName(path)
        reader.SetBand(band)
        reader.GlobalWarningDisplayOff()
        reader.Update()
        data = reader.GetOutput()
        if data.GetNumberOfPoints() == 0:
            return result
        transform = data.GetFieldData().GetArray("GeoTransform")
        result.append((tuple(transform.GetValue(k) for k in range(6)),
                       vtk_to_numpy(data.GetPointData().GetArray("Elevation")).astype(float)))
        band += 1


def relative_difference(a, b):
    finite = np.isfinite(b)
    if not np.array_equal(np.isfinite(a), finite):
        return float("inf")
    scale = max(np.abs(b[finite]).max(), 1e-30) if finite.any() else 1.0
    return float(np.abs(a[finite] - b[finite]).max() / scale) if finite.any() else 0.0


def compare_bands(expected_path, got_path, failures):
    """The largest relative difference of the bands, and their georeference checked."""
    expected, got = bands(expected_path), bands(got_path)
    if not expected or len(got) != len(expected):
        failures.append("%s: %d bands, not %d" % (got_path, len(got), len(expected)))
        return float("inf")
    worst = 0.0
    for (transform, values), (want_transform, want_values) in zip(got, expected):
        if not np.allclose(transform, want_transform, rtol=1e-12, atol=1e-9):
            failures.append("%s: GeoTransform %s, not %s" % (got_path, transform, want_transform))
        worst = max(worst, relative_difference(values, want_values))
    return worst


def main(reference_dir, other_dirs):
    failures = []
    for name in OUTPUTS:
        extent, expected = pieces(os.path.join(reference_dir, name + ".pvts"))
        expected_bands = bands(os.path.join(reference_dir, name + ".tif"))
        if not expected or not expected_bands:
            failures.append("%s: the one-rank run wrote nothing" % name)
            continue
        for other in other_dirs:
            got_extent, got = pieces(os.path.join(other, name + ".pvts"))
            if got_extent != extent or sorted(got) != sorted(expected):
                failures.append("%s in %s: extent %s, arrays %s (one rank: %s, %s)"
                                % (name, other, got_extent, sorted(got), extent, sorted(expected)))
                continue
            worst = max(relative_difference(got[a], expected[a]) for a in expected)
            for written in (name + ".tif", name + "_pieces.vrt"):  # assembled; per rank + VRT
                worst = max(worst, compare_bands(os.path.join(reference_dir, name + ".tif"),
                                                 os.path.join(other, written), failures))
            print("%s, %s: %d arrays, %d bands, largest relative difference %.1e"
                  % (name, other, len(expected), len(expected_bands), worst))
            if worst > RELATIVE_TOLERANCE:
                failures.append("%s in %s differs by %.2e relative" % (name, other, worst))
    near, instant = (pieces(os.path.join(reference_dir, n + ".pvts"))[1] for n in ("near", "instant"))
    change = relative_difference(near["Irradiance"], instant["Irradiance"]) if "Irradiance" in instant else 0.0
    print("near against instant (one rank): irradiance differs by at most %.1e relative" % change)
    if not 0.0 < change <= NEAR_AGAINST_INSTANT:
        failures.append("DetailDistance changed the irradiance by %.2e relative (expected (0, %g])"
                        % (change, NEAR_AGAINST_INSTANT))
    # The far terrain changes what rays see beyond 500 m a little, never nothing.
    window = pieces(os.path.join(reference_dir, "window.pvts"))[1]
    change = relative_difference(window["Irradiance"], instant["Irradiance"]) if "Irradiance" in instant else 0.0
    print("window against instant (one rank): irradiance differs by at most %.1e relative" % change)
    if not 0.0 < change <= NEAR_AGAINST_INSTANT:
        failures.append("the far terrain changed the irradiance by %.2e relative (expected (0, %g])"
                        % (change, NEAR_AGAINST_INSTANT))
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK")


def main_rasters(expected_path, got_path):
    failures = []
    worst = compare_bands(expected_path, got_path, failures)
    print("%s against %s: largest relative difference %.1e" % (got_path, expected_path, worst))
    if failures or worst > RELATIVE_TOLERANCE:
        sys.exit("FAIL: " + "; ".join(failures or ["differs by %.2e relative" % worst]))
    print("OK")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--rasters":
        main_rasters(sys.argv[2], sys.argv[3])
    elif len(sys.argv) >= 3 and not sys.argv[1].startswith("--"):
        main(sys.argv[1], sys.argv[2:])
    else:
        sys.exit(__doc__)
