#pragma once
// Test support: GeoTIFFs written with GDAL directly (not through TerraLux), so
// the tests read files whose georeference is known independently.

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>

namespace terralux_test
{
struct RasterSpec
{
  int width = 0;
  int height = 0;
  std::array<double, 6> geoTransform{ 0, 1, 0, 0, 0, -1 };
  std::string crs; ///< anything OSR's SetFromUserInput takes; empty: no CRS
  std::optional<double> noData;
  bool float64 = false;
  /// Height of pixel (col, row); return NaN to write the no-data value there.
  std::function<double(int col, int row)> elevation = [](int, int) { return 0.0; };
  /// When set: a per-dataset mask band, invalid (0) where this returns true.
  std::function<bool(int col, int row)> masked;
};

/// Writes the raster as a GeoTIFF (or with the named GDAL driver) and returns the path.
std::string writeRaster(const std::string& name, const RasterSpec& spec, const char* driver = "GTiff");

/// A folder for the files of this test process, created on first use.
std::string scratchDir();

/// Folder with the real DEMs extracted by cmake/install-dependencies.sh.
std::string externalDataDir();
} // namespace terralux_test
