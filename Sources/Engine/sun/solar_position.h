#pragma once
// Topocentric solar position by the NREL Solar Position Algorithm (Reda &
// Andreas, Solar Energy 76, 2004): uncertainty +-0.0003 deg for years -2000..6000.

namespace terralux
{
struct SolarPositionInput
{
  double julianDayUT = 2451545.0; ///< Julian day of the instant, UT (see DateTime)
  double deltaT = 69.0;           ///< TT - UT in seconds
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0; ///< east positive
  double heightM = 0.0;      ///< above the ellipsoid (SPA: above sea level)
  double pressureHPa = 1013.25;
  double temperatureC = 12.0;
  bool refraction = true; ///< apply atmospheric refraction (SPA's formula)
};

struct SolarPosition
{
  double zenithDeg = 0.0;           ///< topocentric, refracted when asked
  double azimuthDeg = 0.0;          ///< compass bearing, clockwise from north
  double geometricZenithDeg = 0.0;  ///< topocentric, without refraction
  double earthSunDistanceAU = 1.0;  ///< radius vector R
  double declinationDeg = 0.0;      ///< topocentric
  double hourAngleDeg = 0.0;        ///< topocentric local hour angle
  double equationOfTimeMinutes = 0.0;

  double altitudeDeg() const { return 90.0 - this->zenithDeg; }
};

/// Throws Error when the latitude or any input is not finite or out of range.
SolarPosition computeSolarPosition(const SolarPositionInput& input);
} // namespace terralux
