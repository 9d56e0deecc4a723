#include "weather_file.h"

#include "base/angles.h"
#include "sun/clear_sky.h"
#include "sun/date_time.h"
#include "base/error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace terralux
{
namespace
{
std::vector<std::string> splitFields(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, ','))
    fields.push_back(field);
  if (!line.empty() && line.back() == ',')
    fields.emplace_back();
  return fields;
}

class FileReader
{
public:
  explicit FileReader(const std::string& path)
    : Path(path)
    , Stream(path)
  {
    if (!this->Stream)
      throw Error("cannot open the weather file " + path);
  }
  bool next(std::string& line)
  {
    if (!std::getline(this->Stream, line))
      return false;
    ++this->Line;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    return true;
  }
  [[noreturn]] void fail(const std::string& what) const
  {
    throw Error("weather file " + this->Path + ", line " + std::to_string(this->Line) + ": " + what);
  }
  double number(const std::vector<std::string>& fields, std::size_t index, const char* name) const
  {
    if (index >= fields.size())
      this->fail(std::string("no ") + name + " field (column " + std::to_string(index + 1) + ")");
    const char* text = fields[index].c_str();
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    while (end && (*end == ' ' || *end == '"'))
      ++end;
    if (end == text || !end || *end != '\0' || !std::isfinite(value))
      this->fail(std::string(name) + " '" + fields[index] + "' is not a number");
    return value;
  }
  /// A whole number in [low, high] (checked before the conversion: a garbled 1e30 is no int).
  int integer(const std::vector<std::string>& fields, std::size_t index, const char* name, int low, int high) const
  {
    const double value = this->number(fields, index, name);
    if (!(value >= low && value <= high) || value != std::floor(value))
      this->fail(std::string(name) + " '" + fields[index] + "' is out of range (" + std::to_string(low) + ".." +
        std::to_string(high) + ")");
    return static_cast<int>(value);
  }
  double irradiance(const std::vector<std::string>& fields, std::size_t index, const char* name) const
  {
    const double value = this->number(fields, index, name);
    if (value >= 9999.0)
      this->fail(std::string(name) + " is missing (9999): fill the gap before using the file");
    if (value < 0.0)
      this->fail(std::string(name) + " " + numberText(value) + " is negative");
    return value;
  }
  void checkDate(int month, int day, int hour) const
  {
    if (month < 1 || month > 12 || day < 1 || day > daysInMonth(2024, month) || hour < 1 || hour > 24)
      this->fail("date or hour out of range (month " + std::to_string(month) + ", day " + std::to_string(day) +
        ", hour " + std::to_string(hour) + ")");
  }
  const std::string& path() const { return this->Path; }

private:
  std::string Path;
  std::ifstream Stream;
  int Line = 0;
};

void requireHours(const WeatherFile& weather, const std::string& path)
{
  const std::size_t rows = weather.records.size();
  if (rows != 8760 && rows != 8784)
    throw Error("weather file " + path + " has " + std::to_string(rows) +
      " hourly rows: a year has 8760 (8784 in a leap year)");
}

// The site's fields, in the columns its format puts them.
void readSite(const FileReader& reader, const std::vector<std::string>& fields, std::size_t latitude,
  std::size_t longitude, std::size_t timeZone, std::size_t elevation, WeatherFile& weather)
{
  weather.latitudeDeg = reader.number(fields, latitude, "latitude");
  weather.longitudeDeg = reader.number(fields, longitude, "longitude");
  weather.utcOffsetHours = reader.number(fields, timeZone, "time zone");
  weather.elevationM = reader.number(fields, elevation, "elevation");
  if (std::abs(weather.latitudeDeg) > 90.0 || std::abs(weather.longitudeDeg) > 180.0 ||
    std::abs(weather.utcOffsetHours) > 14.0)
    reader.fail("the site's latitude, longitude or time zone is out of range");
}

WeatherFile readEpw(FileReader& reader, const std::vector<std::string>& location)
{
  WeatherFile weather;
  weather.format = "EPW";
  // LOCATION,city,state,country,source,WMO,latitude,longitude,time zone,elevation
  readSite(reader, location, 6, 7, 8, 9, weather);
  std::string line;
  for (int k = 0; k < 7; ++k) // DESIGN CONDITIONS .. DATA PERIODS
    if (!reader.next(line))
      reader.fail("the file ends inside its header (EPW has eight header lines)");
  while (reader.next(line))
  {
    if (line.empty())
      continue;
    const std::vector<std::string> fields = splitFields(line);
    if (fields.size() < 16)
      reader.fail("a data row has " + std::to_string(fields.size()) + " fields; EPW rows have 35");
    WeatherRecord record;
    record.month = reader.integer(fields, 1, "month", 1, 12);
    record.day = reader.integer(fields, 2, "day", 1, 31);
    record.hour = reader.integer(fields, 3, "hour", 1, 24);
    reader.checkDate(record.month, record.day, record.hour);
    record.directNormalWh = reader.irradiance(fields, 14, "direct normal radiation");
    record.diffuseHorizontalWh = reader.irradiance(fields, 15, "diffuse horizontal radiation");
    weather.records.push_back(record);
  }
  return weather;
}

WeatherFile readTmy3(FileReader& reader, const std::vector<std::string>& site)
{
  WeatherFile weather;
  weather.format = "TMY3";
  // USAF,name,state,time zone,latitude,longitude,elevation
  readSite(reader, site, 4, 5, 3, 6, weather);
  std::string line;
  if (!reader.next(line))
    reader.fail("no column names (TMY3's second line)");
  const std::vector<std::string> names = splitFields(line);
  auto column = [&](const char* prefix) {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k].rfind(prefix, 0) == 0)
        return k;
    reader.fail(std::string("no column '") + prefix + "'");
  };
  const std::size_t date = column("Date"), time = column("Time"), dni = column("DNI ("), dhi = column("DHI (");
  while (reader.next(line))
  {
    if (line.empty())
      continue;
    const std::vector<std::string> fields = splitFields(line);
    if (fields.size() <= std::max({ date, time, dni, dhi }))
      reader.fail("a data row has " + std::to_string(fields.size()) + " fields, fewer than the columns named");
    WeatherRecord record;
    int year = 0, hour = 0, minute = 0;
    if (std::sscanf(fields[date].c_str(), "%d/%d/%d", &record.month, &record.day, &year) != 3 ||
      std::sscanf(fields[time].c_str(), "%d:%d", &hour, &minute) != 2)
      reader.fail("date '" + fields[date] + "' or time '" + fields[time] + "' is not MM/DD/YYYY and HH:MM");
    record.hour = hour;
    reader.checkDate(record.month, record.day, record.hour);
    record.directNormalWh = reader.irradiance(fields, dni, "DNI");
    record.diffuseHorizontalWh = reader.irradiance(fields, dhi, "DHI");
    weather.records.push_back(record);
  }
  return weather;
}

bool leapYear(int year)
{
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}
} // namespace

WeatherFile readWeatherFile(const std::string& path)
{
  FileReader reader(path);
  std::string line;
  if (!reader.next(line))
    reader.fail("the file is empty");
  const std::vector<std::string> first = splitFields(line);
  WeatherFile weather;
  if (!first.empty() && first[0] == "LOCATION")
    weather = readEpw(reader, first);
  else if (first.size() >= 7)
    weather = readTmy3(reader, first);
  else
    reader.fail("neither an EPW file (first line LOCATION,...) nor a TMY3 CSV (site line, then column names)");
  requireHours(weather, path);
  return weather;
}

std::vector<SolarStep> weatherSteps(const WeatherFile& weather, double startJulianDay, double endJulianDay,
  const SolarSite& site, WeatherSummary* summary)
{
  stepInstants(startJulianDay, endJulianDay, 60.0); // validates the range
  const int offsetMinutes = static_cast<int>(std::lround(weather.utcOffsetHours * 60.0));
  const int firstYear = DateTime::fromJulianDay(startJulianDay + weather.utcOffsetHours / 24.0).year;
  const int lastYear = DateTime::fromJulianDay(endJulianDay + weather.utcOffsetHours / 24.0).year;
  WeatherSummary counted;
  std::vector<SolarStep> steps;
  for (int year = firstYear; year <= lastYear; ++year)
    for (const WeatherRecord& record : weather.records)
    {
      if (record.month == 2 && record.day == 29 && !leapYear(year))
        continue;
      DateTime end{ year, record.month, record.day, 0, 0, 0.0, offsetMinutes };
      const double hourEnd = end.julianDay() + record.hour / 24.0, hourStart = hourEnd - 1.0 / 24.0;
      if (hourEnd <= startJulianDay || hourStart >= endJulianDay)
        continue;
      ++counted.hours;
      // The record's energy over the hour's lit part: its mean irradiance there.
      double litStart = hourStart, litEnd = hourEnd;
      if (!shrinkToDaylight(litStart, litEnd, site))
      {
        counted.unlitDirectWh += record.directNormalWh;
        continue;
      }
      const double litHours = (litEnd - litStart) * 24.0;
      double a = std::max(litStart, startJulianDay), b = std::min(litEnd, endJulianDay);
      if (!(b > a))
        continue;
      SolarStep step = solarStepAt(0.5 * (a + b), site);
      step.hours = (b - a) * 24.0;
      step.irradiance = givenIrradiance(
        step.position.zenithDeg, record.directNormalWh / litHours, record.diffuseHorizontalWh / litHours);
      if (step.position.zenithDeg < 90.0)
        steps.push_back(step);
    }
  std::sort(steps.begin(), steps.end(), [](const SolarStep& x, const SolarStep& y) { return x.julianDay < y.julianDay; });
  if (summary)
    *summary = counted;
  return steps;
}

double distanceKm(double latitudeA, double longitudeA, double latitudeB, double longitudeB)
{
  const double dLat = (latitudeB - latitudeA) * degree, dLon = (longitudeB - longitudeA) * degree;
  const double h = std::sin(dLat / 2) * std::sin(dLat / 2) +
    std::cos(latitudeA * degree) * std::cos(latitudeB * degree) * std::sin(dLon / 2) * std::sin(dLon / 2);
  return 2.0 * 6371.0 * std::asin(std::min(1.0, std::sqrt(h)));
}
} // namespace terralux
