// The cumulative sky of a time range (cumulative_sky.h): the steps' skies summed.
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
