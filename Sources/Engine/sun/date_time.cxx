#include "sun/date_time.h"

#include "base/error.h"

#include <cmath>
#include <cstdio>
#include <regex>

namespace terralux
{
namespace
{
bool isLeapYear(int year)
{
  if (year < 1583) // Julian calendar
  {
    return year % 4 == 0;
  }
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

double julianDayOf(int year, int month, double dayWithFraction)
{
  if (month < 3)
  {
    year -= 1;
    month += 12;
  }
  double jd = std::floor(365.25 * (year + 4716.0)) + std::floor(30.6001 * (month + 1)) +
    dayWithFraction - 1524.5;
  if (jd > 2299160.0) // Gregorian reform
  {
    const double a = std::floor(year / 100.0);
    jd += 2.0 - a + std::floor(a / 4.0);
  }
  return jd;
}
} // namespace

int daysInMonth(int year, int month)
{
  static const int days[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
  return month == 2 && isLeapYear(year) ? 29 : days[month - 1];
}

DateTime DateTime::parse(const std::string& text)
{
  static const std::regex pattern(
    R"(^\s*(-?\d{4})-(\d{2})-(\d{2})[T ](\d{2}):(\d{2})(?::(\d{2}(?:\.\d+)?))?\s*(Z|[+-]\d{2}(?::?\d{2})?)?\s*$)");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
  {
    throw Error("date-time '" + text +
      "' is not ISO 8601: write it as YYYY-MM-DDTHH:MM:SS with Z or a UTC offset, e.g. "
      "2003-10-17T12:30:30-07:00");
  }
  if (!match[7].matched)
  {
    throw Error("date-time '" + text +
      "' has no UTC offset: local times are ambiguous, append Z (UTC) or an offset such as -07:00");
  }
  DateTime result;
  result.year = std::stoi(match[1]);
  result.month = std::stoi(match[2]);
  result.day = std::stoi(match[3]);
  result.hour = std::stoi(match[4]);
  result.minute = std::stoi(match[5]);
  result.second = match[6].matched ? std::stod(match[6]) : 0.0;
  const std::string zone = match[7];
  if (zone != "Z")
  {
    const int sign = zone[0] == '-' ? -1 : 1;
    const int hours = std::stoi(zone.substr(1, 2));
    const std::string rest = zone.size() > 3 ? zone.substr(zone.size() - 2) : "00";
    const int minutes = std::stoi(rest);
    if (hours > 14 || minutes > 59)
    {
      throw Error("date-time '" + text + "' has an impossible UTC offset " + zone);
    }
    result.utcOffsetMinutes = sign * (hours * 60 + minutes);
  }
  if (result.year < -2000 || result.year > 6000)
  {
    throw Error("date-time '" + text + "' is outside the years -2000..6000 where SPA is valid");
  }
  if (result.month < 1 || result.month > 12 || result.day < 1 ||
    result.day > daysInMonth(result.year, result.month) || result.hour > 24 || result.minute > 59 ||
    result.second >= 61.0 || (result.hour == 24 && (result.minute > 0 || result.second > 0.0)))
  {
    throw Error("date-time '" + text + "' names no real date and time (check month, day, hour, minute, second)");
  }
  return result;
}

double DateTime::julianDay() const
{
  const double utcHours =
    this->hour + this->minute / 60.0 + this->second / 3600.0 - this->utcOffsetMinutes / 60.0;
  // The Julian day is linear in the fractional day, so offsets that cross midnight
  // need no calendar arithmetic.
  return julianDayOf(this->year, this->month, this->day + utcHours / 24.0);
}

DateTime DateTime::fromJulianDay(double julianDay)
{
  // Meeus, Astronomical Algorithms, ch. 7.
  const double jd = julianDay + 0.5;
  const double z = std::floor(jd);
  const double fraction = jd - z;
  double a = z;
  if (z >= 2299161.0)
  {
    const double alpha = std::floor((z - 1867216.25) / 36524.25);
    a = z + 1.0 + alpha - std::floor(alpha / 4.0);
  }
  const double b = a + 1524.0;
  const double c = std::floor((b - 122.1) / 365.25);
  const double d = std::floor(365.25 * c);
  const double e = std::floor((b - d) / 30.6001);
  DateTime result;
  result.day = static_cast<int>(b - d - std::floor(30.6001 * e));
  result.month = static_cast<int>(e < 14 ? e - 1 : e - 13);
  result.year = static_cast<int>(result.month > 2 ? c - 4716 : c - 4715);
  double seconds = std::round(fraction * 86400.0 * 1000.0) / 1000.0;
  if (seconds >= 86400.0)
    seconds = 86399.999; // rounding reached midnight: stay on the day
  result.hour = static_cast<int>(seconds / 3600.0);
  result.minute = static_cast<int>((seconds - result.hour * 3600.0) / 60.0);
  result.second = seconds - result.hour * 3600.0 - result.minute * 60.0;
  return result;
}

std::string DateTime::toUtcString() const
{
  const DateTime utc = fromJulianDay(this->julianDay());
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%04d-%02d-%02dT%02d:%02d:%06.3fZ", utc.year, utc.month, utc.day, utc.hour,
    utc.minute, utc.second);
  return buffer;
}
} // namespace terralux
