// ISO 8601 instants (date_time.h): parsing, UTC offsets, Julian days.
#include "sun/clear_sky.h"
#include "base/angles.h"
#include "sun/date_time.h"
#include "base/error.h"
#include "sun/solar_position.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace terralux;

TEST(DateTime, ParsesOffsetsAndUtc)
{
  const DateTime local = DateTime::parse("2003-10-17T12:30:30-07:00");
  EXPECT_EQ(local.utcOffsetMinutes, -420);
  EXPECT_NEAR(local.julianDay(), 2452930.312847, 1e-6); // SPA paper, table A4.1
  EXPECT_DOUBLE_EQ(DateTime::parse("2003-10-17T19:30:30Z").julianDay(), local.julianDay());
  EXPECT_DOUBLE_EQ(DateTime::parse("2003-10-18T05:00:30+0930").julianDay(), local.julianDay());
  EXPECT_DOUBLE_EQ(DateTime::parse("2003-10-17 21:30:30+02").julianDay(), local.julianDay());
  EXPECT_EQ(local.toUtcString(), "2003-10-17T19:30:30.000Z");
  // Crossing midnight and a year boundary through the offset.
  EXPECT_EQ(DateTime::parse("2024-01-01T02:00:00+05:00").toUtcString(), "2023-12-31T21:00:00.000Z");
  EXPECT_NEAR(DateTime::parse("2000-01-01T12:00:00Z").julianDay(), 2451545.0, 1e-9);
  EXPECT_NEAR(DateTime::parse("1582-10-04T00:00:00Z").julianDay() + 1.0,
    DateTime::parse("1582-10-15T00:00:00Z").julianDay(), 1e-9); // Julian -> Gregorian
}

TEST(DateTime, RejectsAmbiguousOrImpossibleTimes)
{
  EXPECT_THROW(DateTime::parse("2003-10-17T12:30:30"), Error); // no offset
  EXPECT_THROW(DateTime::parse("2003-02-30T12:00:00Z"), Error);
  EXPECT_THROW(DateTime::parse("2003-13-01T12:00:00Z"), Error);
  EXPECT_THROW(DateTime::parse("2003-10-17T25:00:00Z"), Error);
  EXPECT_THROW(DateTime::parse("noon"), Error);
  EXPECT_THROW(DateTime::parse("7000-01-01T00:00:00Z"), Error);
  EXPECT_NO_THROW(DateTime::parse("2024-02-29T00:00:00Z"));
  EXPECT_THROW(DateTime::parse("2023-02-29T00:00:00Z"), Error);
  try
  {
    DateTime::parse("2003-10-17T12:30:30");
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("UTC offset"), std::string::npos);
  }
}
