#pragma once
// Measured weather for irradiation sums: the hourly direct normal and diffuse
// horizontal irradiance of an EnergyPlus EPW or a TMY3 CSV file, in the file's own
// local standard time, turned into steps for the Perez all-weather sky.

#include "solar_steps.h"

#include <string>
#include <vector>

namespace terralux
{
/// One hour of a weather file: the hour that ends at `hour` (1..24) local standard time.
struct WeatherRecord
{
  int month = 1;
  int day = 1;
  int hour = 1;
  double directNormalWh = 0.0;       ///< Wh/m^2 over the hour (its mean W/m^2)
  double diffuseHorizontalWh = 0.0;  ///< Wh/m^2 over the hour
};

struct WeatherFile
{
  std::string format; ///< "EPW" or "TMY3"
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0;
  double elevationM = 0.0;
  double utcOffsetHours = 0.0; ///< the file's standard time minus UTC
  std::vector<WeatherRecord> records;
};

/// Reads an EPW (LOCATION line, eight header lines, 8760 or 8784 hourly rows) or a TMY3
/// CSV (site line, column names, 8760 rows), told apart by their first line. Throws
/// Error naming the file, the line and the field for anything missing or garbled: too
/// few fields, values that are no numbers, missing irradiance (EPW's 9999), negative
/// irradiance, dates or hours out of range, the wrong number of rows.
WeatherFile readWeatherFile(const std::string& path);

/// What the steps of a weather file left out.
struct WeatherSummary
{
  int hours = 0;                ///< records whose hour overlaps the range
  double unlitDirectWh = 0.0;   ///< direct normal Wh/m^2 in hours the sun never rises (SPA)
};

/// Steps of the records whose hours overlap [startJulianDay, endJulianDay] (the file's
/// month, day and hour put in each year the range spans; 29 February skipped in other
/// years): each hour's lit part, clipped to the range, evaluated at its middle, with the
/// record's mean irradiance over its lit part (so the hour's energy is kept). Throws
/// Error for an end not after the start or a range over ten years.
std::vector<SolarStep> weatherSteps(const WeatherFile& weather, double startJulianDay, double endJulianDay,
  const SolarSite& site, WeatherSummary* summary = nullptr);

/// Great-circle distance in km between two places (spherical Earth, for a plausibility check).
double distanceKm(double latitudeA, double longitudeA, double latitudeB, double longitudeB);
} // namespace terralux
