// GDAL geotransforms (geo_transform.h): pixels to map and back, windows, pieces.
#include "base/error.h"
#include "base/angles.h"
#include "geodesy/geo_transform.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_projection.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

using namespace terralux;

TEST(GeoTransform, PixelMapRoundTripWithRotation)
{
  GeoTransform gt;
  gt.coefficients = { 500000.0, 25.0, 5.0, 4000000.0, 3.0, -30.0 };
  double x, y, col, row;
  gt.pixelToMap(12.5, 7.25, x, y);
  gt.mapToPixel(x, y, col, row);
  EXPECT_NEAR(col, 12.5, 1e-9);
  EXPECT_NEAR(row, 7.25, 1e-9);
}

TEST(GeoTransform, WindowKeepsPostCentres)
{
  GeoTransform gt;
  gt.coefficients = { 1000.0, 10.0, 2.0, 2000.0, 1.0, -10.0 };
  for (int stride : { 1, 2, 3, 7 })
  {
    const GeoTransform w = gt.window(4, 9, stride);
    for (int i : { 0, 1, 5 })
    {
      for (int j : { 0, 2 })
      {
        double xw, yw, xo, yo;
        w.pixelToMap(i + 0.5, j + 0.5, xw, yw);
        gt.pixelToMap(4 + i * stride + 0.5, 9 + j * stride + 0.5, xo, yo);
        EXPECT_NEAR(xw, xo, 1e-9);
        EXPECT_NEAR(yw, yo, 1e-9);
      }
    }
  }
}

TEST(GeoTransform, PieceOfAGridAndTheWholeBack)
{
  // North-up (rows reversed in the grid) and south-up (kept), each with a rotation.
  for (const auto& coefficients : { std::array<double, 6>{ 1000.0, 30.0, 2.0, 9000.0, 1.0, -30.0 },
         std::array<double, 6>{ 1000.0, 30.0, 2.0, 2000.0, 1.0, 30.0 } })
  {
    GeoTransform whole;
    whole.coefficients = coefficients;
    const int rows = 50, i0 = 7, j0 = 12, j1 = 30;
    const int row0 = whole.firstRasterRow(j0, j1, rows);
    EXPECT_EQ(row0, whole.gridRow(0, rows) != 0 ? rows - 1 - j1 : j0);
    const GeoTransform piece = whole.pieceOf(i0, j0, j1, rows);
    // The piece's pixel (i, r) is the whole's (i0 + i, row0 + r), and back again.
    for (int i : { 0, 3 })
      for (int r : { 0, 5, j1 - j0 })
      {
        double xp, yp, xw, yw;
        piece.pixelToMap(i + 0.5, r + 0.5, xp, yp);
        whole.pixelToMap(i0 + i + 0.5, row0 + r + 0.5, xw, yw);
        EXPECT_NEAR(xp, xw, 1e-9);
        EXPECT_NEAR(yp, yw, 1e-9);
      }
    const GeoTransform back = piece.window(-i0, -row0, 1);
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(back.coefficients[k], whole.coefficients[k], 1e-9);
  }
}

TEST(GeoTransform, SingularIsRejected)
{
  GeoTransform gt;
  gt.coefficients = { 0, 0, 0, 0, 0, 0 };
  EXPECT_FALSE(gt.isValid());
  double col, row;
  EXPECT_THROW(gt.mapToPixel(1, 1, col, row), Error);
}
