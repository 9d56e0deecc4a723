#include "solar_steps.h"

#include "sun/date_time.h"
#include "base/error.h"

#include <cmath>
#include <string>

namespace terralux
{
namespace
{
constexpr double minutesPerDay = 1440.0;

void requireRange(double start, double end, double stepMinutes)
{
  if (!std::isfinite(start) || !std::isfinite(end) || !(end > start))
    throw Error("the end time must come after the start time");
  if (!(stepMinutes > 0.0) || !(stepMinutes <= minutesPerDay))
    throw Error("the time step is " + numberText(stepMinutes) +
      " minutes: give a step in (0, 1440] minutes (at most a day)");
  if (end - start > 3653.0)
    throw Error("the time range spans more than ten years: split it into shorter runs");
}

bool sunUp(double julianDay, const SolarSite& site)
{
  SolarPositionInput in = site.position;
  in.julianDayUT = julianDay;
  return computeSolarPosition(in).zenithDeg < 90.0;
}

// The instant in [a, b] where the apparent sun crosses the horizon, knowing it is up
// at exactly one end (bisection to well under a second).
double horizonCrossing(double a, double b, bool upAtA, const SolarSite& site)
{
  for (int k = 0; k < 40; ++k)
  {
    const double mid = 0.5 * (a + b);
    (sunUp(mid, site) == upAtA ? a : b) = mid;
  }
  return 0.5 * (a + b);
}
} // namespace

int monthOfJulianDay(double julianDay)
{
  return DateTime::fromJulianDay(julianDay).month;
}

SolarStep solarStepAt(double julianDay, const SolarSite& site)
{
  SolarStep step;
  step.julianDay = julianDay;
  SolarPositionInput in = site.position;
  in.julianDayUT = julianDay;
  step.position = computeSolarPosition(in);
  const double r = step.position.earthSunDistanceAU;
  step.extraterrestrialWm2 = site.solarConstantWm2 / (r * r);
  // The month of the site's mean solar time: a day's turbidity, not UTC's.
  const int month = monthOfJulianDay(julianDay + site.position.longitudeDeg / 360.0);
  step.irradiance = clearSkyIrradiance(site.model, step.position.zenithDeg, step.position.geometricZenithDeg,
    site.position.heightM, site.linkeByMonth[month - 1], step.extraterrestrialWm2);
  return step;
}

std::vector<double> stepInstants(double startJulianDay, double endJulianDay, double stepMinutes)
{
  requireRange(startJulianDay, endJulianDay, stepMinutes);
  const double step = stepMinutes / minutesPerDay;
  std::vector<double> instants;
  // Whole steps from the start; a last step shorter than a thousandth of one merges
  // into the one before (rounding of the range, not a step of its own).
  const auto whole = static_cast<long>(std::floor((endJulianDay - startJulianDay) / step + 1e-3));
  for (long k = 0; k <= whole; ++k)
    instants.push_back(startJulianDay + k * step);
  if (endJulianDay - instants.back() > 1e-3 * step)
    instants.push_back(endJulianDay);
  else
    instants.back() = endJulianDay;
  return instants;
}

bool shrinkToDaylight(double& a, double& b, const SolarSite& site)
{
  const double mid = 0.5 * (a + b);
  const bool upAtA = sunUp(a, site), upAtB = sunUp(b, site);
  if (!upAtA && !upAtB)
  {
    if (!sunUp(mid, site)) // night (or a sun that rises and sets inside the step's halves: too short to count)
      return false;
    const double rise = horizonCrossing(a, mid, false, site);
    b = horizonCrossing(mid, b, true, site);
    a = rise;
  }
  else if (!upAtA)
  {
    a = horizonCrossing(a, b, false, site); // sunrise
  }
  else if (!upAtB)
  {
    b = horizonCrossing(a, b, true, site); // sunset
  }
  return b > a;
}

std::vector<SolarStep> daylightSteps(
  double startJulianDay, double endJulianDay, double stepMinutes, const SolarSite& site)
{
  const std::vector<double> instants = stepInstants(startJulianDay, endJulianDay, stepMinutes);
  std::vector<SolarStep> steps;
  for (std::size_t k = 0; k + 1 < instants.size(); ++k)
  {
    double a = instants[k], b = instants[k + 1];
    if (!shrinkToDaylight(a, b, site))
      continue;
    SolarStep step = solarStepAt(0.5 * (a + b), site);
    step.hours = (b - a) * 24.0;
    if (step.position.zenithDeg < 90.0)
      steps.push_back(step);
  }
  return steps;
}
} // namespace terralux
