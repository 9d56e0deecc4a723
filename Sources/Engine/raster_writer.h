#pragma once
// Writes grid values as a multi-band GeoTIFF on a given georeference (GDAL), so
// results land on exactly the grid, CRS and geotransform of the DEM they came from.

#include "geo_transform.h"

#include <string>
#include <vector>

namespace terralux
{
struct RasterBand
{
  std::string description; ///< e.g. the array name
  std::string unit;        ///< e.g. "W/m^2"
  std::vector<float> values; ///< width x height, raster order (row 0 first)
};

struct RasterGrid
{
  int width = 0;
  int height = 0;
  GeoTransform geoTransform;
  std::string crsWkt; ///< empty: no CRS
  bool hasNoData = false;
  double noData = -9999.0;
};

/// Writes a Float32 GeoTIFF (deflate-compressed, tiled when large). Throws Error when
/// the sizes disagree or GDAL cannot create the file.
void writeGeoTiff(const std::string& fileName, const RasterGrid& grid, const std::vector<RasterBand>& bands);

/// Writes a GDAL VRT at `fileName` that mosaics `tiles` (GeoTIFFs of the same CRS and
/// bands, pieces of one grid, overlapping or not) into one raster, with the first
/// tile's band descriptions and units. Throws Error when GDAL cannot build it.
void writeVrtMosaic(const std::string& fileName, const std::vector<std::string>& tiles);
} // namespace terralux
