// Daylight steps (solar_steps.h) with sunrise and sunset inside a step, judged against
// the almanac's day length.
#include "time_checks.h"
#include "sky/cie_sky.h"
#include "base/angles.h"
#include "cumulative_sky.h"
#include "sun/date_time.h"
#include "base/error.h"
#include "solar_steps.h"
#include "weather_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace terralux;
using namespace terralux_test;

namespace
{
double totalHours(const std::vector<SolarStep>& steps)
{
  double hours = 0.0;
  for (const SolarStep& step : steps)
    hours += step.hours;
  return hours;
}

// Day length from the sunrise hour angle, cos w0 = (sin h0 - sin phi sin delta) /
// (cos phi cos delta), h0 = -0.567 deg: the sun's centre on the horizon through the
// standard refraction (almanacs' -0.833 deg adds the sun's radius: their sunrise is
// the upper limb's). Independent of SPA's per-instant refraction model.
double almanacDayLength(double latitude, double declinationDeg)
{
  const double phi = latitude * degree, delta = declinationDeg * degree;
  const double c = (std::sin(-0.567 * degree) - std::sin(phi) * std::sin(delta)) / (std::cos(phi) * std::cos(delta));
  return 2.0 * std::acos(std::max(-1.0, std::min(1.0, c))) / degree / 15.0;
}
} // namespace

TEST(SolarSteps, DaylightHoursMatchTheAlmanacDayLength)
{
  struct Case
  {
    double latitude;
    const char* day;
  };
  for (const Case& c : { Case{ 46.8, "2024-06-21T00:00:00+01:00" }, Case{ -8.0, "2024-06-21T00:00:00-02:00" },
         Case{ 0.0, "2024-03-20T00:00:00Z" }, Case{ 60.0, "2024-12-21T00:00:00+01:00" } })
  {
    const double start = dayOf(c.day);
    const SolarSite site = siteAt(c.latitude, c.latitude > 40 ? 8.0 : -35.0);
    const std::vector<SolarStep> steps = daylightSteps(start, start + 1.0, 30.0, site);
    const double declination = solarStepAt(start + 0.5, site).position.declinationDeg;
    // The sun's declination moves by up to 0.4 deg a day: a few minutes of day length.
    EXPECT_NEAR(totalHours(steps), almanacDayLength(c.latitude, declination), 4.0 / 60.0) << c.latitude;
    // The first and last steps are partial: the sunrise is not rounded to a step.
    EXPECT_LT(steps.front().hours, 0.5) << c.latitude;
    EXPECT_LT(steps.back().hours, 0.5) << c.latitude;
    for (const SolarStep& step : steps)
      EXPECT_LT(step.position.zenithDeg, 90.0);
  }
}

TEST(SolarSteps, TheDayLengthDoesNotDependOnTheStep)
{
  const SolarSite site = siteAt(46.8, 8.0);
  const double start = dayOf("2024-06-21T00:00:00+01:00");
  const double reference = totalHours(daylightSteps(start, start + 1.0, 1.0, site));
  for (double step : { 7.0, 30.0, 60.0, 180.0, 1440.0 })
    EXPECT_NEAR(totalHours(daylightSteps(start, start + 1.0, step, site)), reference, 1.0 / 60.0) << step;
}

TEST(SolarSteps, TheSunsEnergyConvergesWithTheStep)
{
  // Beam on a horizontal plane over a day: 30-minute steps within 0.3 % of 1-minute ones.
  const SolarSite site = siteAt(46.8, 8.0);
  const double start = dayOf("2024-06-21T00:00:00+01:00");
  auto beam = [&](double minutes) {
    double sum = 0.0;
    for (const SolarStep& step : daylightSteps(start, start + 1.0, minutes, site))
      sum += step.irradiance.directNormalWm2 * std::cos(step.position.zenithDeg * degree) * step.hours;
    return sum;
  };
  const double fine = beam(1.0);
  EXPECT_GT(fine, 5000.0);
  EXPECT_NEAR(beam(30.0), fine, 0.003 * fine);
}

TEST(SolarSteps, PolarNightHasNoStepsAndPolarDayAllOfThem)
{
  const SolarSite site = siteAt(80.0, 10.0);
  const double winter = dayOf("2024-12-21T00:00:00Z"), summer = dayOf("2024-06-21T00:00:00Z");
  EXPECT_TRUE(daylightSteps(winter, winter + 3.0, 30.0, site).empty());
  EXPECT_NEAR(totalHours(daylightSteps(summer, summer + 1.0, 30.0, site)), 24.0, 1e-6);
}

TEST(SolarSteps, StepInstantsCoverTheRangeWithAShorterLastStep)
{
  const double start = dayOf("2024-06-21T00:00:00Z");
  EXPECT_EQ(stepInstants(start, start + 1.0, 30.0).size(), 49u);
  const std::vector<double> odd = stepInstants(start, start + 1.0 / 24.0, 40.0);
  ASSERT_EQ(odd.size(), 3u);
  EXPECT_NEAR((odd[1] - start) * 1440.0, 40.0, 1e-6);
  EXPECT_DOUBLE_EQ(odd[2], start + 1.0 / 24.0);
}

TEST(SolarSteps, MonthlyLinkeTurbidityFollowsTheSitesMonth)
{
  SolarSite site = siteAt(46.8, 8.0);
  for (int month = 0; month < 12; ++month)
    site.linkeByMonth[month] = 2.0 + 0.25 * month;
  const SolarStep july = solarStepAt(dayOf("2024-07-15T12:00:00Z"), site);
  const ClearSkyIrradiance expected = esraClearSky(90.0 - july.position.geometricZenithDeg, 0.0, 2.0 + 0.25 * 6,
    july.extraterrestrialWm2);
  EXPECT_DOUBLE_EQ(july.irradiance.directNormalWm2, expected.directNormalWm2);
  EXPECT_EQ(monthOfJulianDay(dayOf("2024-02-29T23:59:00Z")), 2);
  EXPECT_EQ(monthOfJulianDay(dayOf("2024-03-01T00:00:00Z")), 3);
}

TEST(SolarSteps, BadRangesAreRefused)
{
  const SolarSite site = siteAt(46.8, 8.0);
  const double start = dayOf("2024-06-21T00:00:00Z");
  EXPECT_THROW(daylightSteps(start, start, 30.0, site), Error);
  EXPECT_THROW(daylightSteps(start, start - 1.0, 30.0, site), Error);
  EXPECT_THROW(daylightSteps(start, start + 1.0, 0.0, site), Error);
  EXPECT_THROW(daylightSteps(start, start + 1.0, -5.0, site), Error);
  EXPECT_THROW(daylightSteps(start, start + 1.0, 1441.0, site), Error);
  EXPECT_THROW(daylightSteps(start, start + 1.0, NAN, site), Error);
  EXPECT_THROW(daylightSteps(start, start + 3654.0, 60.0, site), Error);
  EXPECT_THROW(daylightSteps(start, start + 1.0, 30.0, siteAt(91.0, 0.0)), Error);
}
