// Clear-sky irradiance (clear_sky.h): ESRA and Ineichen-Perez against published values.
#include "sun/clear_sky.h"
#include "base/angles.h"
#include "sun/date_time.h"
#include "base/error.h"
#include "sun/solar_position.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace terralux;

TEST(ClearSky, ModelsAgreeAndBehave)
{
  const double i0 = solarConstantWm2;
  for (double zenith : { 10.0, 30.0, 60.0 })
  {
    const ClearSkyIrradiance esra = esraClearSky(90.0 - zenith, 0.0, 3.0, i0);
    const ClearSkyIrradiance ineichen = ineichenPerezClearSky(zenith, 0.0, 3.0, i0);
    // Same turbidity, two independent fits of clear-sky data: within ~8 %.
    EXPECT_NEAR(esra.directNormalWm2 / ineichen.directNormalWm2, 1.0, 0.08) << zenith;
    EXPECT_NEAR(esra.globalHorizontalWm2 / ineichen.globalHorizontalWm2, 1.0, 0.08) << zenith;
    EXPECT_GT(esra.diffuseHorizontalWm2, 0.05 * esra.globalHorizontalWm2);
    EXPECT_LT(esra.diffuseHorizontalWm2, 0.35 * esra.globalHorizontalWm2);
    EXPECT_NEAR(esra.globalHorizontalWm2,
      esra.directNormalWm2 * std::cos(zenith * pi / 180) + esra.diffuseHorizontalWm2, 1e-9);
  }
  // A clear sky at sea level with the sun at 30 deg zenith: global 800..1000 W/m^2.
  const ClearSkyIrradiance noon = esraClearSky(60.0, 0.0, 3.0, i0);
  EXPECT_GT(noon.globalHorizontalWm2, 800.0);
  EXPECT_LT(noon.globalHorizontalWm2, 1000.0);
  // More turbidity: less beam; higher site: more beam.
  EXPECT_LT(esraClearSky(60.0, 0.0, 5.0, i0).directNormalWm2, noon.directNormalWm2);
  EXPECT_GT(esraClearSky(60.0, 3000.0, 3.0, i0).directNormalWm2, noon.directNormalWm2);
  EXPECT_GT(ineichenPerezClearSky(30.0, 3000.0, 3.0, i0).directNormalWm2,
    ineichenPerezClearSky(30.0, 0.0, 3.0, i0).directNormalWm2);
  // Below the horizon: nothing.
  EXPECT_EQ(esraClearSky(-1.0, 0.0, 3.0, i0).globalHorizontalWm2, 0.0);
  EXPECT_EQ(ineichenPerezClearSky(91.0, 0.0, 3.0, i0).directNormalWm2, 0.0);
  // Just above it: small, finite.
  const ClearSkyIrradiance low = esraClearSky(0.05, 0.0, 3.0, i0);
  EXPECT_TRUE(std::isfinite(low.directNormalWm2));
  EXPECT_GT(low.directNormalWm2, 0.0);
  EXPECT_LT(low.directNormalWm2, 200.0); // air mass ~ 30
  EXPECT_NEAR(kastenYoungAirMass(0.0), 1.0, 1e-3);
  EXPECT_NEAR(kastenYoungAirMass(60.0), 1.995, 0.01);
  EXPECT_NEAR(kastenYoungAirMass(90.0), 37.92, 0.01); // Kasten & Young 1989
}

TEST(ClearSky, GivenIrradianceMakesItsGlobalAndNothingBelowTheHorizon)
{
  const ClearSkyIrradiance day = givenIrradiance(60.0, 700.0, 120.0);
  EXPECT_DOUBLE_EQ(day.directNormalWm2, 700.0);
  EXPECT_DOUBLE_EQ(day.diffuseHorizontalWm2, 120.0);
  EXPECT_NEAR(day.globalHorizontalWm2, 700.0 * 0.5 + 120.0, 1e-9);
  const ClearSkyIrradiance night = givenIrradiance(90.5, 700.0, 120.0);
  EXPECT_EQ(night.directNormalWm2, 0.0);
  EXPECT_EQ(night.diffuseHorizontalWm2, 0.0);
  EXPECT_EQ(night.globalHorizontalWm2, 0.0);
}
