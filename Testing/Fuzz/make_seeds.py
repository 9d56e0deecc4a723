#!/usr/bin/python3
"""Writes the seed corpora of the fuzz targets (Testing/Fuzz/corpus/<target>/seed-*).

Run with Debian's /usr/bin/python3 (GDAL's Python bindings, numpy). The seeds are small
valid inputs of each target's byte layout (see ByteReader in fuzz_support.h); libFuzzer
mutates them. Inputs of past findings live beside them as finding-* files.
"""
import os
import random
import struct
import tempfile

import numpy as np
from osgeo import gdal, osr

here = os.path.dirname(os.path.abspath(__file__))


def corpus(target):
    path = os.path.join(here, "corpus", target)
    os.makedirs(path, exist_ok=True)
    return path


def raster_bytes(width, height, transform, epsg, data_type=gdal.GDT_Float32, nodata=None, driver="GTiff"):
    memory = gdal.GetDriverByName("MEM").Create("", width, height, 1, data_type)
    memory.SetGeoTransform(transform)
    if epsg:
        crs = osr.SpatialReference()
        crs.ImportFromEPSG(epsg)
        memory.SetProjection(crs.ExportToWkt())
    values = (np.arange(width * height).reshape(height, width) % 17 * 3.0 + 100).astype(np.float64)
    if nodata is not None:
        memory.GetRasterBand(1).SetNoDataValue(nodata)
        values[1, 1] = nodata
    memory.GetRasterBand(1).WriteArray(values)
    with tempfile.TemporaryDirectory() as folder:
        name = os.path.join(folder, "seed" + (".asc" if driver == "AAIGrid" else ".tif"))
        gdal.GetDriverByName(driver).CreateCopy(name, memory)
        with open(name, "rb") as f:
            return f.read()


def dem_seeds():
    out = corpus("fuzz_dem_raster")
    rasters = {
        "utm": raster_bytes(8, 6, (380000, 30, 0, 5080000, 0, -30), 32632),
        "geographic-int16": raster_bytes(6, 6, (6.0, 0.01, 0, 49.8, 0, -0.01), 4326, gdal.GDT_Int16, -32768),
        "ascii-grid": raster_bytes(5, 4, (1000, 10, 0, 2000, 0, -10), 0, driver="AAIGrid"),
        "south-up-float64": raster_bytes(7, 5, (380000, -30, 0, 5080000, 0, 30), 32632, gdal.GDT_Float64),
    }
    # Request header: mode, stride, window (col0, row0, width, height) as uint16 each.
    for mode, (name, data) in enumerate(rasters.items()):
        header = struct.pack("<6H", mode, 0, 2, 2, 5, 4)
        with open(os.path.join(out, "seed-" + name), "wb") as f:
            f.write(header + data)


def number(value, scale):
    """The int16 branch of ByteReader::number."""
    return struct.pack("<Bh", 0, int(value / scale * 32767))


def scene(flags, points, cells, emission=()):
    data = struct.pack("<HH", flags, len(points))
    for x, y, z in points:
        data += number(x, 20) + number(y, 20) + number(z, 5)
    if flags & 1:
        return data + struct.pack("<3H", 3, 3, 1)
    data += struct.pack("<H", len(cells))
    for cell in cells:
        # ids are read as between(-2, n + 2): stored value v gives v - 2.
        data += struct.pack("<H", len(cell)) + b"".join(struct.pack("<H", i + 2) for i in cell)
    for e in emission:
        data += number(e, 500)
    return data


def scene_seeds():
    out = corpus("fuzz_radiosity_scene")
    quad = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0)]
    box = [(2, 2, 0), (4, 2, 0), (4, 4, 0), (2, 4, 0), (2, 2, 2), (4, 2, 2), (4, 4, 2), (2, 4, 2)]
    u_shape = [(0, 0, 1), (3, 0, 1), (3, 3, 1), (2, 3, 1), (2, 1, 1), (1, 1, 1), (1, 3, 1), (0, 3, 1)]
    seeds = {
        "plane": scene(32, quad, [[0, 1, 2, 3]]),
        "plane-box": scene(32 | 128, quad + box, [[0, 1, 2, 3], [4, 5, 6, 7], [8, 9, 10, 11], [4, 5, 9, 8],
                                                  [5, 6, 10, 9], [6, 7, 11, 10], [7, 4, 8, 11]]),
        "concave-emitter": scene(4, u_shape + quad, [[7, 6, 5, 4, 3, 2, 1, 0], [8, 9, 10, 11]], (400, 0)),
        "grid": scene(1, [(x * 2, y * 2, (x * y) % 3) for y in range(3) for x in range(3)], []),
    }
    for name, data in seeds.items():
        with open(os.path.join(out, "seed-" + name), "wb") as f:
            f.write(data)


def parameter_seeds():
    out = corpus("fuzz_source_parameters")
    generator = random.Random(7)
    for k in range(4):
        with open(os.path.join(out, "seed-random-%d" % k), "wb") as f:
            f.write(bytes(generator.randrange(256) for _ in range(160)))
    with open(os.path.join(out, "seed-zeros"), "wb") as f:
        f.write(bytes(160))


if __name__ == "__main__":
    dem_seeds()
    scene_seeds()
    parameter_seeds()
