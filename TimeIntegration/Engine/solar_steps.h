#pragma once
// The time axis of an irradiation sum: a range of instants cut into steps, each step
// the sun's position and the clear-sky irradiance at one instant, weighted by the
// hours it stands for. Steps through sunrise or sunset stand for the lit part of their
// interval only and are evaluated at its middle, so the day's length is not rounded to
// whole steps.

#include "sun/clear_sky.h"
#include "sun/solar_position.h"

#include <array>
#include <vector>

namespace terralux
{
/// Whatever the sun's position and the clear sky need besides the instant.
struct SolarSite
{
  SolarPositionInput position; ///< julianDayUT is ignored: each step sets its own
  ClearSkyModel model = ClearSkyModel::Esra;
  /// Linke turbidity by month (January first), taken for the month of each step's
  /// mean solar time at the site.
  std::array<double, 12> linkeByMonth{ 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0 };
  double solarConstantWm2 = terralux::solarConstantWm2;
};

struct SolarStep
{
  double julianDay = 0.0; ///< the instant evaluated (UT)
  double hours = 0.0;     ///< the time it stands for
  SolarPosition position;
  double extraterrestrialWm2 = 0.0;
  /// Direct normal and diffuse horizontal irradiance: the clear sky, or a weather
  /// file's; zero while the apparent sun is below the horizon.
  ClearSkyIrradiance irradiance;
};

/// Sun and clear sky at one instant (hours 0).
SolarStep solarStepAt(double julianDay, const SolarSite& site);

/// The steps of [startJulianDay, endJulianDay] in intervals of stepMinutes (the last
/// one shorter where the range is no whole number of steps) in which the apparent sun
/// stands above the horizon. Throws Error for an end not after the start, a step not in
/// (0, 1440] minutes, a range of more than ten years or a site SPA refuses.
std::vector<SolarStep> daylightSteps(
  double startJulianDay, double endJulianDay, double stepMinutes, const SolarSite& site);

/// Shrinks [a, b] (Julian days) to the part where the apparent sun is above the
/// horizon, by bisection on its crossings; false where that part is empty.
bool shrinkToDaylight(double& a, double& b, const SolarSite& site);

/// The instants that bound the intervals of that range: start, start + step, ..., end.
std::vector<double> stepInstants(double startJulianDay, double endJulianDay, double stepMinutes);

/// The month (1..12) of the calendar date at a Julian day.
int monthOfJulianDay(double julianDay);
} // namespace terralux
