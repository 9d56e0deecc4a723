#pragma once
// What the time integration tests share.

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

namespace terralux_test
{

using namespace terralux;

inline SolarSite siteAt(double latitude, double longitude)
{
  SolarSite site;
  site.position.latitudeDeg = latitude;
  site.position.longitudeDeg = longitude;
  return site;
}

inline double dayOf(const char* text)
{
  return DateTime::parse(text).julianDay();
}
} // namespace terralux_test
