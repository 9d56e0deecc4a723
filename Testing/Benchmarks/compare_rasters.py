#!/usr/bin/env python3
"""One band of a TerraLux GeoTIFF (by its description) against a peer's raster on the
same grid, post by post: mean difference of the means, mean and RMS of the relative
differences, over posts both have, the DEM's border aside (slope is undefined there for
r.slope.aspect). Also the same without shadow rims: posts whose 3 x 3 neighbourhood in
TerraLux's band spans more than 10 % of its mean.

    compare_rasters.py OURS.tif BAND_NAME PEER.tif
"""
import sys

import numpy as np
from osgeo import gdal


def read(path, description=None):
    dataset = gdal.Open(path)
    if dataset is None:
        sys.exit("compare_rasters: cannot open " + path)
    index = 1
    if description:
        names = [dataset.GetRasterBand(k).GetDescription() for k in range(1, dataset.RasterCount + 1)]
        if description not in names:
            sys.exit("compare_rasters: %s has no band %s (bands: %s)" % (path, description, ", ".join(names)))
        index = names.index(description) + 1
    band = dataset.GetRasterBand(index)
    values = band.ReadAsArray().astype(float)
    if band.GetNoDataValue() is not None:
        values[values == band.GetNoDataValue()] = np.nan
    return values


def main():
    ours, peer = read(sys.argv[1], sys.argv[2]), read(sys.argv[3])
    if ours.shape != peer.shape:
        sys.exit("compare_rasters: grids differ: %s against %s" % (ours.shape, peer.shape))
    both = np.isfinite(ours) & np.isfinite(peer) & (peer > 0)
    both[0, :] = both[-1, :] = both[:, 0] = both[:, -1] = False
    padded = np.pad(ours, 1, mode="edge")
    rows, columns = ours.shape
    window = np.stack([padded[1 + dy:rows + 1 + dy, 1 + dx:columns + 1 + dx]
                       for dy in (-1, 0, 1) for dx in (-1, 0, 1)])
    rim = np.nanmax(window, 0) - np.nanmin(window, 0) > 0.1 * np.nanmean(ours[both])
    relative = ours / np.where(both, peer, 1.0) - 1.0
    calm = both & ~rim
    print("means %.1f / %.1f (%+.2f %%); per post %+.2f %%, RMS %.2f %%; rims aside (%d of %d posts): %+.2f %%, RMS %.2f %%"
          % (ours[both].mean(), peer[both].mean(), 100 * (ours[both].mean() / peer[both].mean() - 1),
             100 * relative[both].mean(), 100 * np.sqrt(np.mean(relative[both] ** 2)), both.sum() - calm.sum(),
             both.sum(), 100 * relative[calm].mean(), 100 * np.sqrt(np.mean(relative[calm] ** 2))))


if __name__ == "__main__":
    main()
