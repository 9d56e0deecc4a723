// Weather files (weather_file.h): EPW and TMY3 read, damaged rows refused.
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
