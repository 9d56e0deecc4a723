// The local east-north-up frame (local_frame.h) against GeographicLib's closed forms.
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

TEST(LocalFrame, OriginMapsToZero)
{
  const LocalFrame frame({ 45.0, 7.0, 1234.5 });
  const LocalPoint p = frame.toLocal({ 45.0, 7.0, 1234.5 });
  EXPECT_NEAR(p[0], 0.0, 1e-9);
  EXPECT_NEAR(p[1], 0.0, 1e-9);
  EXPECT_NEAR(p[2], 0.0, 1e-9);
}

TEST(LocalFrame, AxesPointEastNorthUp)
{
  const LocalFrame frame({ -8.0, -35.0, 0.0 });
  const LocalPoint north = frame.toLocal({ -7.99, -35.0, 0.0 });
  const LocalPoint east = frame.toLocal({ -8.0, -34.99, 0.0 });
  EXPECT_GT(north[1], 1100.0); // 0.01 deg of latitude ~ 1.1 km
  EXPECT_NEAR(north[0], 0.0, 1e-6);
  EXPECT_GT(east[0], 1000.0);
  // The parallel curves toward the pole: north offset x^2 tan(lat) / (2 N).
  EXPECT_NEAR(east[1], east[0] * east[0] * std::tan(-8.0 * pi / 180) / (2 * 6378137.0), 1e-3);
  const LocalPoint up = frame.toLocal({ -8.0, -35.0, 100.0 });
  EXPECT_NEAR(up[2], 100.0, 1e-9);
}

// Curvature: ground at constant ellipsoidal height 50 km north of the origin lies
// d^2 / (2 M) below the tangent plane (M: meridional radius of curvature), ~196 m.
TEST(LocalFrame, CurvatureDropAtFiftyKilometres)
{
  const double latitude = 45.0;
  const LocalFrame frame({ latitude, 10.0, 0.0 });
  // Walk 50 km of tangent-plane distance north, then drop to the ellipsoid.
  const GeodeticPoint above = frame.toGeodetic({ 0.0, 50000.0, 0.0 });
  const LocalPoint ground = frame.toLocal({ above.latitudeDeg, above.longitudeDeg, 0.0 });
  const double a = GeographicLib::Constants::WGS84_a();
  const double f = GeographicLib::Constants::WGS84_f();
  const double e2 = f * (2 - f);
  const double s = std::sin(latitude * pi / 180.0);
  const double meridionalRadius = a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5);
  const double expectedDrop = 50000.0 * 50000.0 / (2 * meridionalRadius);
  EXPECT_NEAR(-ground[2], expectedDrop, 0.5);
  EXPECT_NEAR(-ground[2], 196.0, 1.0);
}

TEST(LocalFrame, RoundTripFarFromOrigin)
{
  const LocalFrame frame({ 49.8, 6.1, 300.0 });
  for (double d : { 1.0, 1e3, 1e5, 1e6 })
  {
    const LocalPoint local{ d, -0.5 * d, 0.01 * d };
    const LocalPoint back = frame.toLocal(frame.toGeodetic(local));
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(back[k], local[k], 1e-6 * std::max(1.0, d / 1e3));
    }
  }
}

TEST(LocalFrame, MatchesEcefDifferenceRotatedToEnu)
{
  // Independent construction: ECEF difference rotated by the ENU basis at the origin.
  const double lat0 = 35.0, lon0 = 139.0, h0 = 40.0;
  const LocalFrame frame({ lat0, lon0, h0 });
  const auto& earth = GeographicLib::Geocentric::WGS84();
  double x0, y0, z0, x1, y1, z1;
  earth.Forward(lat0, lon0, h0, x0, y0, z0);
  earth.Forward(35.2, 139.3, 900.0, x1, y1, z1);
  const double phi = lat0 * pi / 180, lambda = lon0 * pi / 180;
  const double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
  const double east = -std::sin(lambda) * dx + std::cos(lambda) * dy;
  const double north = -std::sin(phi) * std::cos(lambda) * dx - std::sin(phi) * std::sin(lambda) * dy +
    std::cos(phi) * dz;
  const double up = std::cos(phi) * std::cos(lambda) * dx + std::cos(phi) * std::sin(lambda) * dy +
    std::sin(phi) * dz;
  const LocalPoint p = frame.toLocal({ 35.2, 139.3, 900.0 });
  EXPECT_NEAR(p[0], east, 1e-6);
  EXPECT_NEAR(p[1], north, 1e-6);
  EXPECT_NEAR(p[2], up, 1e-6);
}

TEST(LocalFrame, RejectsInvalidOrigins)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(LocalFrame({ nan, 0.0, 0.0 }), Error);
  EXPECT_THROW(LocalFrame({ 0.0, nan, 0.0 }), Error);
  EXPECT_THROW(LocalFrame({ 0.0, 0.0, std::numeric_limits<double>::infinity() }), Error);
  EXPECT_THROW(LocalFrame({ 91.0, 0.0, 0.0 }), Error);
  EXPECT_NO_THROW(LocalFrame({ 90.0, 0.0, 0.0 }));
}
