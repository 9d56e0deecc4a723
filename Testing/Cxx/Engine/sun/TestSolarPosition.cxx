// The NREL SPA solar position (solar_position.h) against its published test case,
// sunrise and sunset.
#include "sun/clear_sky.h"
#include "base/angles.h"
#include "sun/date_time.h"
#include "base/error.h"
#include "sun/solar_position.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace terralux;

namespace
{
SolarPosition sunAt(const std::string& when, double lat, double lon, double height = 0.0,
  bool refraction = true)
{
  SolarPositionInput in;
  in.julianDayUT = DateTime::parse(when).julianDay();
  in.latitudeDeg = lat;
  in.longitudeDeg = lon;
  in.heightM = height;
  in.refraction = refraction;
  return computeSolarPosition(in);
}

double angleDifference(double a, double b)
{
  double d = std::fmod(a - b + 540.0, 360.0) - 180.0;
  return std::abs(d);
}

// The Julian day where f changes sign in [a, b] (bisection to ~0.01 s).
double crossing(double a, double b, const std::function<double(double)>& f)
{
  double fa = f(a);
  for (int k = 0; k < 60; ++k)
  {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm < 0) == (fa < 0))
    {
      a = m;
      fa = fm;
    }
    else
    {
      b = m;
    }
  }
  return 0.5 * (a + b);
}
} // namespace

// The published SPA test case (Reda & Andreas 2004, table A5.1).
TEST(SolarPosition, NrelSpaReferenceCase)
{
  SolarPositionInput in;
  in.julianDayUT = DateTime::parse("2003-10-17T12:30:30-07:00").julianDay();
  in.deltaT = 67.0;
  in.latitudeDeg = 39.742476;
  in.longitudeDeg = -105.1786;
  in.heightM = 1830.14;
  in.pressureHPa = 820.0;
  in.temperatureC = 11.0;
  const SolarPosition p = computeSolarPosition(in);
  EXPECT_NEAR(p.zenithDeg, 50.111622, 0.0003);
  EXPECT_NEAR(p.azimuthDeg, 194.340241, 0.0003);
  EXPECT_NEAR(p.earthSunDistanceAU, 0.9965422974, 1e-6);
  EXPECT_NEAR(p.equationOfTimeMinutes, 14.641503, 1e-3);
  EXPECT_NEAR(p.declinationDeg, -9.316179, 1e-4); // topocentric declination
}

TEST(SolarPosition, RefractionNearTheHorizon)
{
  // London, 2024-06-21: sunrise at 03:43 UTC (04:43 BST) per almanacs, to the minute.
  // Sunrise is when the geometric centre of the sun is 0.8333 deg below the horizon
  // (refraction 0.5667 deg plus the sun's radius, as SPA defines it).
  const double midnight = DateTime::parse("2024-06-21T00:00:00Z").julianDay();
  auto geometricAltitude = [](double jd, double offset) {
    SolarPositionInput in;
    in.julianDayUT = jd;
    in.latitudeDeg = 51.5074;
    in.longitudeDeg = -0.1278;
    in.refraction = false;
    return 90.0 - computeSolarPosition(in).zenithDeg + offset;
  };
  const double sunrise = crossing(midnight + 2.0 / 24, midnight + 5.0 / 24,
    [&](double jd) { return geometricAltitude(jd, 0.8333); });
  EXPECT_NEAR((sunrise - midnight) * 24 * 60, 3 * 60 + 43, 1.5);

  // With the geometric centre on the horizon, SPA's refraction lifts the sun by
  // 1.02 / (60 tan(10.3 / 5.11 deg)) = 0.483 deg at 1010 hPa and 10 degC.
  const double horizon = crossing(midnight + 2.0 / 24, midnight + 6.0 / 24,
    [&](double jd) { return geometricAltitude(jd, 0.0); });
  SolarPositionInput in;
  in.julianDayUT = horizon;
  in.latitudeDeg = 51.5074;
  in.longitudeDeg = -0.1278;
  in.pressureHPa = 1010.0;
  in.temperatureC = 10.0;
  const SolarPosition refracted = computeSolarPosition(in);
  EXPECT_NEAR(refracted.geometricZenithDeg, 90.0, 1e-6);
  EXPECT_NEAR(refracted.geometricZenithDeg - refracted.zenithDeg, 0.4830, 5e-4);
  in.refraction = false;
  EXPECT_DOUBLE_EQ(computeSolarPosition(in).zenithDeg, refracted.geometricZenithDeg);
  // No refraction once the sun is more than its radius plus refraction below the horizon.
  in.refraction = true;
  in.julianDayUT = sunrise - 1.0 / 24;
  const SolarPosition night = computeSolarPosition(in);
  EXPECT_GT(night.geometricZenithDeg, 91.0);
  EXPECT_DOUBLE_EQ(night.zenithDeg, night.geometricZenithDeg);
}

TEST(SolarPosition, SouthernHemisphereSummerNoon)
{
  // Cape Town at the December solstice: at solar noon the sun stands north of the
  // zenith by |latitude - declination| ~ 33.9 - 23.44 = 10.5 deg.
  const double day = DateTime::parse("2023-12-22T00:00:00Z").julianDay();
  auto zenithSlope = [&](double jd) {
    SolarPositionInput in;
    in.julianDayUT = jd;
    in.latitudeDeg = -33.9249;
    in.longitudeDeg = 18.4241;
    in.refraction = false;
    const double z0 = computeSolarPosition(in).zenithDeg;
    in.julianDayUT = jd + 1e-4;
    return computeSolarPosition(in).zenithDeg - z0;
  };
  const double noon = crossing(day + 8.0 / 24, day + 13.0 / 24, zenithSlope);
  SolarPositionInput in;
  in.julianDayUT = noon;
  in.latitudeDeg = -33.9249;
  in.longitudeDeg = 18.4241;
  in.refraction = false;
  const SolarPosition p = computeSolarPosition(in);
  EXPECT_NEAR(p.declinationDeg, -23.43, 0.02);
  EXPECT_NEAR(p.zenithDeg, std::abs(-33.9249 - p.declinationDeg), 0.01);
  EXPECT_LT(angleDifference(p.azimuthDeg, 0.0), 0.5); // due north
  // Solar noon at longitude 18.42 E: 12:00 - 18.42 * 4 min - equation of time.
  EXPECT_NEAR((noon - day) * 24 * 60, 12 * 60 - 18.4241 * 4 - p.equationOfTimeMinutes, 0.5);
}

TEST(SolarPosition, PolarDayAndNight)
{
  // Latitude 89 N: the sun circles within 1 deg of its declination (+-23.44 deg at the
  // solstices), plus a few hundredths of refraction.
  for (int hour = 0; hour < 24; hour += 3)
  {
    char june[64], december[64];
    std::snprintf(june, sizeof(june), "2024-06-21T%02d:00:00Z", hour);
    std::snprintf(december, sizeof(december), "2024-12-21T%02d:00:00Z", hour);
    const SolarPosition day = sunAt(june, 89.0, 10.0);
    const SolarPosition night = sunAt(december, 89.0, 10.0);
    EXPECT_NEAR(day.altitudeDeg(), 23.44, 1.1);
    EXPECT_NEAR(night.altitudeDeg(), -23.44, 1.05);
    EXPECT_TRUE(std::isfinite(night.azimuthDeg));
  }
}

TEST(SolarPosition, LongitudesAcrossTheDateLine)
{
  const std::string when = "2024-03-01T23:30:00Z";
  // 0.002 deg of longitude apart (220 m) across the date line: nearly the same sun.
  const SolarPosition west = sunAt(when, -17.7, 179.999);
  const SolarPosition east = sunAt(when, -17.7, -179.999);
  EXPECT_LT(std::abs(west.zenithDeg - east.zenithDeg), 0.003);
  EXPECT_LT(angleDifference(west.azimuthDeg, east.azimuthDeg), 0.01);
  const SolarPosition a = sunAt(when, -17.7, 180.0);
  const SolarPosition b = sunAt(when, -17.7, -180.0);
  EXPECT_NEAR(a.zenithDeg, b.zenithDeg, 1e-9);
  EXPECT_NEAR(angleDifference(a.azimuthDeg, b.azimuthDeg), 0.0, 1e-9);
  // The same instant written with the local offset of Fiji (+12:00).
  const SolarPosition fiji = sunAt("2024-03-02T11:30:00+12:00", -17.7, 179.999);
  EXPECT_DOUBLE_EQ(fiji.zenithDeg, west.zenithDeg);
}

TEST(SolarPosition, BadInputThrows)
{
  SolarPositionInput in;
  in.latitudeDeg = 95.0;
  EXPECT_THROW(computeSolarPosition(in), Error);
  in.latitudeDeg = NAN;
  EXPECT_THROW(computeSolarPosition(in), Error);
}
