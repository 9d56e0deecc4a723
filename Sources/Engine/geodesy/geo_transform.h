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

  /// Grid index j of raster row `row` in a grid of `rows` rows whose cells face up in a
  /// right-handed map CRS (x east, y north): rows reversed when the transform is
  /// orientation-reversing, as a north-up raster's is (columns east, rows south), kept
  /// in order when it is not (negative pixel width, south-up rasters), so that any
  /// valid transform, rotated ones included, gives an upward-facing terrain.
  int gridRow(int row, int rows) const
  {
    const auto& c = this->coefficients;
    return c[1] * c[5] - c[2] * c[4] < 0.0 ? rows - 1 - row : row;
  }

  /// Geotransform of a subsampled window: its pixel (i, j) is centred where this
  /// transform's pixel (col0 + i*stride, row0 + j*stride) is centred, with pixels
  /// stride times larger, so a raster written with it lands on the same posts.
  GeoTransform window(int col0, int row0, int stride) const;

  /// First raster row of the grid rows [j0, j1] of a grid of `rows` rows (gridRow's
  /// inverse for a block of rows).
  int firstRasterRow(int j0, int j1, int rows) const { return gridRow(0, rows) != 0 ? rows - 1 - j1 : j0; }
  /// Geotransform of the piece [i0, ...] x [j0, j1] (grid indices) of a grid of `rows`
  /// rows that this transform georeferences. The piece's transform gives the whole
  /// grid's back as window(-i0, -firstRasterRow(j0, j1, rows), 1).
  GeoTransform pieceOf(int i0, int j0, int j1, int rows) const { return window(i0, firstRasterRow(j0, j1, rows), 1); }
};
} // namespace terralux
