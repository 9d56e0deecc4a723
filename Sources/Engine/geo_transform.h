#pragma once
// GDAL's affine geotransform: map = (c0 + col*c1 + row*c2, c3 + col*c4 + row*c5)
// for a pixel corner (col, row); pixel centres sit at col + 0.5, row + 0.5.
// Rotated (c2, c4 != 0) transforms are handled like any other.

#include <array>

namespace terralux
{
struct GeoTransform
{
  std::array<double, 6> coefficients{ 0.0, 1.0, 0.0, 0.0, 0.0, -1.0 };

  /// Map coordinates of a fractional pixel position (corner convention).
  void pixelToMap(double col, double row, double& x, double& y) const;
  /// Fractional pixel position of map coordinates. Throws Error if singular.
  void mapToPixel(double x, double y, double& col, double& row) const;
  /// True when the 2x2 linear part is invertible and every coefficient finite.
  bool isValid() const;

  /// Geotransform of a subsampled window: its pixel (i, j) is centred where this
  /// transform's pixel (col0 + i*stride, row0 + j*stride) is centred, with pixels
  /// stride times larger, so a raster written with it lands on the same posts.
  GeoTransform window(int col0, int row0, int stride) const;
};
} // namespace terralux
