// The time axis of irradiation sums (TimeIntegration/Engine): daylight steps with
// sunrise and sunset inside a step, judged against the astronomical day length; the
// cumulative sky against the sum of its skies.
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

namespace
{
using namespace terralux;

SolarSite siteAt(double latitude, double longitude)
{
  SolarSite site;
  site.position.latitudeDeg = latitude;
  site.position.longitudeDeg = longitude;
  return site;
}

double dayOf(const char* text)
{
  return DateTime::parse(text).julianDay();
}

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

TEST(CumulativeSky, IsTheHourWeightedSumOfItsSkies)
{
  CumulativeSky sum(6);
  EXPECT_EQ(sum.hierarchy(), nullptr);
  const Direction low = directionFromZenithAzimuth(70 * degree, 90 * degree);
  const Direction high = directionFromZenithAzimuth(30 * degree, 180 * degree);
  sum.add(CieGeneralSky(12, low), low, 80.0, 0.5);
  sum.add(CieGeneralSky(12, high), high, 120.0, 2.0);
  const auto total = sum.hierarchy();
  ASSERT_NE(total, nullptr);
  EXPECT_EQ(sum.steps(), 2);
  // Each sky is scaled to its diffuse irradiance with its own quadrature; the sum's
  // horizontal irradiance comes from its cell averages: equal to the cells' resolution.
  EXPECT_NEAR(total->horizontalIrradiance(0), 0.5 * 80.0 + 2.0 * 120.0, 1e-3 * 280.0);
  // Cell by cell, as SkyHierarchy's full 3 x 3 quadrature of each sky, within 0.5 %
  // (the centre rule away from the sun) and on average within 0.05 %.
  const SkyHierarchy morning(CieGeneralSky(12, low), 80.0, 6), noon(CieGeneralSky(12, high), 120.0, 6);
  double worst = 0.0, sumOurs = 0.0, sumTheirs = 0.0;
  for (int iu = 0; iu < 64; ++iu)
    for (int iv = 0; iv < 64; ++iv)
    {
      const SkyPatch patch{ 6, iu, iv };
      const double expected = 0.5 * morning.radiance(patch, 0) + 2.0 * noon.radiance(patch, 0);
      const double ours = total->radiance(patch, 0);
      worst = std::max(worst, std::abs(ours / expected - 1.0));
      sumOurs += ours * patch.solidAngle();
      sumTheirs += expected * patch.solidAngle();
    }
  EXPECT_LT(worst, 5e-3);
  EXPECT_NEAR(sumOurs / sumTheirs, 1.0, 5e-4);
  EXPECT_THROW(sum.add(CieGeneralSky(12, high), high, -1.0, 1.0), Error);
  EXPECT_THROW(sum.add(CieGeneralSky(12, high), high, 10.0, NAN), Error);
}

namespace
{
// A year of EPW rows at one place (constant irradiance by day), with one row damaged.
std::string writeEpw(const std::string& name, int rows, int damagedRow = -1, int field = 0, const char* text = "")
{
  const std::string path = ::testing::TempDir() + name;
  std::ofstream epw(path);
  epw << "LOCATION,Test,,XX,synthetic,000000,46.8,8.0,1.0,500.0\n";
  for (int k = 0; k < 7; ++k)
    epw << "HEADER " << k << "\n";
  int written = 0;
  for (int month = 1; month <= 12 && written < rows; ++month)
    for (int day = 1; day <= daysInMonth(2023, month) && written < rows; ++day)
      for (int hour = 1; hour <= 24 && written < rows; ++hour, ++written)
      {
        std::vector<std::string> fields = { "2023", std::to_string(month), std::to_string(day), std::to_string(hour),
          "60", "A7", "10", "5", "70", "95000", "0", "0", "300", "500", hour >= 10 && hour <= 15 ? "600" : "0",
          hour >= 8 && hour <= 17 ? "100" : "0" };
        fields.resize(35, "0");
        if (written == damagedRow)
          fields[field] = text;
        for (std::size_t f = 0; f < fields.size(); ++f)
          epw << (f ? "," : "") << fields[f];
        epw << "\n";
      }
  return path;
}
} // namespace

TEST(WeatherFile, ReadsAnEpwYearAndKeepsEachHoursEnergy)
{
  const WeatherFile weather = readWeatherFile(writeEpw("year.epw", 8760));
  EXPECT_EQ(weather.format, "EPW");
  EXPECT_EQ(weather.records.size(), 8760u);
  EXPECT_DOUBLE_EQ(weather.latitudeDeg, 46.8);
  EXPECT_DOUBLE_EQ(weather.utcOffsetHours, 1.0);
  const SolarSite site = siteAt(46.8, 8.0);
  const double start = dayOf("2024-06-21T00:00:00+01:00");
  WeatherSummary summary;
  const std::vector<SolarStep> steps = weatherSteps(weather, start, start + 1.0, site, &summary);
  EXPECT_EQ(summary.hours, 24);
  // Diffuse energy: 10 hours of 100 Wh/m^2, all of them in daylight in June.
  double diffuse = 0.0, direct = 0.0;
  for (const SolarStep& step : steps)
  {
    diffuse += step.irradiance.diffuseHorizontalWm2 * step.hours;
    direct += step.irradiance.directNormalWm2 * step.hours;
  }
  EXPECT_NEAR(diffuse, 1000.0, 1e-6);
  EXPECT_NEAR(direct, 3600.0, 1e-6);
  EXPECT_DOUBLE_EQ(summary.unlitDirectWh, 0.0);
  // In December the sun is down at 08:00-09:00: that hour's diffuse light is kept over
  // the minutes the sun is up, and no direct light falls in unlit hours here.
  const double winter = dayOf("2024-12-21T00:00:00+01:00");
  double winterDiffuse = 0.0;
  for (const SolarStep& step : weatherSteps(weather, winter, winter + 1.0, site))
    winterDiffuse += step.irradiance.diffuseHorizontalWm2 * step.hours;
  EXPECT_LT(winterDiffuse, 1000.0);
  EXPECT_GT(winterDiffuse, 800.0);
}

TEST(WeatherFile, DamagedFilesAreRefusedWithTheirLine)
{
  const struct
  {
    const char* name;
    int rows, row, field;
    const char* text;
    const char* expected;
  } cases[] = {
    { "short.epw", 8759, -1, 0, "", "8759 hourly rows" },
    { "text.epw", 8760, 10, 14, "abc", "line 19: direct normal radiation 'abc' is not a number" },
    { "gap.epw", 8760, 20, 15, "9999", "missing (9999)" },
    { "negative.epw", 8760, 30, 14, "-1", "negative" },
    { "huge.epw", 8760, 40, 1, "1e30", "month '1e30' is out of range" },
    { "fraction.epw", 8760, 50, 3, "2.5", "hour '2.5' is out of range" },
    { "cut.epw", 8760, 60, 14, "", "is not a number" },
  };
  for (const auto& c : cases)
  {
    try
    {
      readWeatherFile(writeEpw(c.name, c.rows, c.row, c.field, c.text));
      ADD_FAILURE() << c.name << " was accepted";
    }
    catch (const Error& error)
    {
      EXPECT_NE(std::string(error.what()).find(c.expected), std::string::npos) << c.name << ": " << error.what();
    }
  }
  EXPECT_THROW(readWeatherFile(::testing::TempDir() + "no-such-file.epw"), Error);
}
