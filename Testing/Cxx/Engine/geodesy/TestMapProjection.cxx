// Map projections (map_projection.h): CRS to WGS84 and back, geographic bounds.
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

TEST(MapProjection, UtmSouthMatchesGeographicLib)
{
  MapProjection projection("EPSG:32725");
  double x[2] = { 288776.25, 298765.591 };
  double y[2] = { 9120760.75, 9110771.409 };
  const double x0[2] = { x[0], x[1] }, y0[2] = { y[0], y[1] };
  projection.toGeographic(2, x, y);
  for (int k = 0; k < 2; ++k)
  {
    double lat, lon;
    GeographicLib::UTMUPS::Reverse(25, false, x0[k], y0[k], lat, lon);
    EXPECT_NEAR(x[k], lon, 1e-9);
    EXPECT_NEAR(y[k], lat, 1e-9);
  }
  projection.fromGeographic(2, x, y);
  EXPECT_NEAR(x[0], x0[0], 1e-6);
  EXPECT_NEAR(y[1], y0[1], 1e-6);
}

TEST(MapProjection, GeographicAxisOrderIsLongitudeFirst)
{
  MapProjection projection("EPSG:4326");
  EXPECT_TRUE(projection.isGeographic());
  double x = 6.0, y = 49.5;
  projection.toGeographic(1, &x, &y);
  EXPECT_DOUBLE_EQ(x, 6.0);
  EXPECT_DOUBLE_EQ(y, 49.5);
}

TEST(MapProjection, BadDefinitionsThrow)
{
  EXPECT_THROW(MapProjection("not a crs"), Error);
}
