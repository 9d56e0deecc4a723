#pragma once
// A DEM raster read through GDAL (GeoTIFF, SRTM .hgt, ESRI ASCII grid, USGS DEM,
// anything GDAL opens): its georeference, and windowed, subsampled reads that
// never load more of the file than the requested posts need.

#include "geodesy/geo_transform.h"

#include <cstddef>
#include <memory>
#include <string>

namespace terralux
{
/// A rectangle of raster pixels: first column and row, width and height.
struct PixelWindow
{
  int col0 = 0;
  int row0 = 0;
  int width = 0;
  int height = 0;

  bool isEmpty() const { return this->width <= 0 || this->height <= 0; }
  /// Number of posts along an extent when every stride-th post is kept.
  static int postCount(int extent, int stride) { return extent <= 0 ? 0 : (extent - 1) / stride + 1; }
};

struct RasterInfo
{
  std::string driver;
  int width = 0;
  int height = 0;
  int bandCount = 0;
  int band = 1;
  bool hasGeoTransform = false;
  GeoTransform geoTransform;
  std::string crsWkt; ///< empty when the raster has no CRS
  bool hasNoData = false;
  double noData = 0.0;
  /// True when float32 cannot hold every value exactly (Float64, 32-bit integers).
  bool needsDoublePrecision = false;
};

class DemRaster
{
public:
  /// Opens band `band` (1-based) of a raster. Throws Error naming the problem when the
  /// file is missing, not a raster GDAL reads, or has no such band.
  DemRaster(const std::string& fileName, int band);
  ~DemRaster();
  DemRaster(const DemRaster&) = delete;
  DemRaster& operator=(const DemRaster&) = delete;

  const RasterInfo& info() const { return this->Info; }

  /// The whole raster as a window.
  PixelWindow fullWindow() const { return { 0, 0, this->Info.width, this->Info.height }; }
  /// The smallest window of whole pixels covering map bounds (xmin, ymin, xmax, ymax),
  /// clipped to the raster; empty when they do not overlap.
  PixelWindow windowCovering(double xmin, double ymin, double xmax, double ymax) const;

  /// Reads the posts (col0 + i*stride, row0 + j*stride) of the window into `heights`,
  /// row-major in raster order (row 0 first), postCount(width) x postCount(height)
  /// values. No-data posts (the band's no-data value, NaN, infinities) become NaN.
  /// Returns the number of valid posts. Throws Error on read failure or a window
  /// outside the raster.
  std::size_t read(const PixelWindow& window, int stride, float* heights);
  std::size_t read(const PixelWindow& window, int stride, double* heights);

private:
  template <typename T>
  std::size_t readPosts(const PixelWindow& window, int stride, T* heights);

  struct Impl;
  std::unique_ptr<Impl> State;
  RasterInfo Info;
};
} // namespace terralux
