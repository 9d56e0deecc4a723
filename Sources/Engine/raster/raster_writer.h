#pragma once
// Writes grid values as a multi-band GeoTIFF on a given georeference (GDAL), so
// results land on exactly the grid, CRS and geotransform of the DEM they came from.

#include "geodesy/geo_transform.h"

#include <memory>
#include <string>
#include <vector>

namespace terralux
{
struct RasterBand
{
  std::string description; ///< e.g. the array name
  std::string unit;        ///< e.g. "W/m^2"
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

/// A Float32 GeoTIFF (deflate-compressed, bands one after another, tiled when large,
/// BigTIFF where it might pass 4 GiB) written a window at a time: the whole grid, or
/// the pieces of a grid as MPI ranks send them, so that the writer holds a window, not
/// the grid. Posts no window covers read as no data (set grid.hasNoData where some may
/// stay uncovered). Throws Error where GDAL cannot create or write the file.
class GeoTiffWriter
{
public:
  /// Creates the file, a band per element of `bands` (its description and unit).
  GeoTiffWriter(const std::string& fileName, const RasterGrid& grid, const std::vector<RasterBand>& bands);
  ~GeoTiffWriter();
  GeoTiffWriter(const GeoTiffWriter&) = delete;
  GeoTiffWriter& operator=(const GeoTiffWriter&) = delete;
  /// Writes `values` (width x height, raster order) into band `band` (from 0) at raster
  /// column `column`, row `row`.
  void writeWindow(int band, int column, int row, int width, int height, const float* values);
  /// For a raster of more than 64 MiB of values: writes out the blocks GDAL caches
  /// (compressed), so that they do not pile up in its cache (5 % of the memory by
  /// default) while windows keep coming; call it after each window or piece. A block
  /// written again later (one two windows share) is stored again, at the end of the
  /// file. Smaller rasters stay in the cache until close(), each block written once.
  void flush();
  /// Marks grid.noData as the bands' no-data value (some written value is no data).
  void setNoData(double noData);
  /// Writes what GDAL still caches and closes the file; throws Error where that fails.
  void close();

private:
  /// Throws that writing the file failed, with GDAL's last message.
  [[noreturn]] void failed() const;

  struct Dataset;
  std::unique_ptr<Dataset> File;
  std::string FileName;
  int Width, Height;
  bool Large; // more than 64 MiB of values
};

/// Writes a GDAL VRT at `fileName` that mosaics `tiles` (GeoTIFFs of the same CRS and
/// bands, pieces of one grid, overlapping or not) into one raster, with the first
/// tile's band descriptions and units. Throws Error when GDAL cannot build it.
void writeVrtMosaic(const std::string& fileName, const std::vector<std::string>& tiles);
} // namespace terralux
