#pragma once
// Instants in time for the solar position: ISO 8601 parsing with a UTC offset,
// and Julian days (UT) as the NREL SPA uses them.

#include <string>

namespace terralux
{
/// A civil date and time with its offset from UTC, as written in ISO 8601.
struct DateTime
{
  int year = 2000;
  int month = 1;
  int day = 1;
  int hour = 0;
  int minute = 0;
  double second = 0.0;
  int utcOffsetMinutes = 0; ///< local time minus UTC, e.g. -420 for -07:00

  /// Parses "YYYY-MM-DDTHH:MM[:SS[.fff]](Z|+HH:MM|-HH:MM|+HHMM|+HH)"; a space may stand
  /// for the T. Throws Error naming what is wrong; the UTC offset is required.
  static DateTime parse(const std::string& text);

  /// Julian day (UT) of this instant; Gregorian calendar from 1582-10-15 on, Julian before,
  /// as in SPA (Reda & Andreas 2004, eq. 4).
  double julianDay() const;

  /// The instant of a Julian day (UT), in UTC (to the millisecond).
  static DateTime fromJulianDay(double julianDay);

  /// The same instant written in UTC, "YYYY-MM-DDTHH:MM:SS.sssZ".
  std::string toUtcString() const;
};

/// Days in a month of the proleptic calendar SPA uses.
int daysInMonth(int year, int month);
} // namespace terralux
