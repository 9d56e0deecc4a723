// CIE and Perez sky models (cie_sky.h, perez_sky.h) against published values and
// closed forms.
#include "sky_checks.h"
#include "sky/cie_sky.h"
#include "base/angles.h"
#include "base/error.h"
#include "sky/perez_sky.h"
#include "sky/sky_hierarchy.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

TEST(SkyModels, CieType12IsRadianceGenskyClearSky)
{
  // Radiance's gensky +s (CIE clear sky), written from its documented formula:
  //   L / Lz = (0.91 + 10 exp(-3 g) + 0.45 cos^2 g)(1 - exp(-0.32 / cos Z))
  //          / ((0.91 + 10 exp(-3 Zs) + 0.45 cos^2 Zs)(1 - exp(-0.32)))
  const double zs = 35.0 * degree;
  const Direction sun = directionFromZenithAzimuth(zs, 120.0 * degree);
  const CieGeneralSky cie(12, sun);
  auto gensky = [&](const Direction& d) {
    const double g = angleBetween(d, sun);
    const double z = std::acos(d[2]);
    auto f = [](double x) { return 0.91 + 10.0 * std::exp(-3.0 * x) + 0.45 * std::cos(x) * std::cos(x); };
    return f(g) * (1.0 - std::exp(-0.32 / std::cos(z))) / (f(zs) * (1.0 - std::exp(-0.32)));
  };
  for (double z = 0.0; z < 89.0; z += 7.0)
    for (double a = 0.0; a < 360.0; a += 30.0)
    {
      const Direction d = directionFromZenithAzimuth(z * degree, a * degree);
      // gensky rounds 1 - 10 exp(-3 pi / 2) = 0.9102 to 0.91: agreement to 0.05 %.
      EXPECT_NEAR(cie.relativeRadiance(d) / gensky(d), 1.0, 5e-4) << z << " " << a;
    }
}

TEST(SkyModels, StableAtTheEdges)
{
  const Direction zenithSun{ 0.0, 0.0, 1.0 };
  const Direction horizonSun{ 0.0, -1.0, 0.0 };
  const Direction belowSun = directionFromZenithAzimuth(90.5 * degree, 180.0 * degree);
  const Direction horizon{ 1.0, 0.0, 0.0 };
  for (int type = 1; type <= 15; ++type)
    for (const Direction& sun : { zenithSun, horizonSun, belowSun })
    {
      const CieGeneralSky model(type, sun);
      for (const Direction& d : { horizon, zenithSun, horizonSun, sun })
      {
        const double value = model.relativeRadiance(d);
        EXPECT_TRUE(std::isfinite(value) && value >= 0.0) << type;
      }
      const SkyHierarchy sky(model, 50.0, 5);
      EXPECT_TRUE(std::isfinite(sky.radianceScale()));
      EXPECT_NEAR(sky.horizontalIrradiance(0), 50.0, 1e-9);
    }
  for (const Direction& sun : { zenithSun, horizonSun, belowSun })
  {
    const PerezSky perez(sun, 600.0, 120.0, 1367.0);
    for (const Direction& d : { horizon, zenithSun, horizonSun })
    {
      EXPECT_TRUE(std::isfinite(perez.relativeRadiance(d)));
    }
    const SkyHierarchy sky(perez, 120.0, 5);
    EXPECT_NEAR(mapHorizontalIrradiance(sky), 120.0, 0.12);
  }
  EXPECT_THROW(CieGeneralSky(16, zenithSun), Error);
  EXPECT_THROW(CieGeneralSky(0, zenithSun), Error);
  EXPECT_THROW(SkyHierarchy(UniformSky(), NAN, 5), Error);
  EXPECT_THROW(SkyHierarchy(UniformSky(), 10.0, 11), Error);
  EXPECT_THROW(PerezSky(zenithSun, -1.0, 100.0, 1367.0), Error);
}

TEST(SkyModels, PerezClearAndOvercast)
{
  const Direction sun = directionFromZenithAzimuth(40.0 * degree, 150.0 * degree);
  const PerezSky clear(sun, 850.0, 90.0, 1367.0);
  EXPECT_GT(clear.clearness(), 6.2); // the clearest bin
  const SkyHierarchy clearSky(clear, 90.0, 7);
  EXPECT_LT(angleBetween(brightestFinestPatch(clearSky).direction(), sun), 5.0 * degree);
  EXPECT_NEAR(mapHorizontalIrradiance(clearSky) / 90.0, 1.0, 1e-3);
  EXPECT_NEAR(clearSky.radianceScale() * horizontalIntegral(clear) / 90.0, 1.0, 1e-3);

  const PerezSky overcast(sun, 0.0, 150.0, 1367.0);
  EXPECT_DOUBLE_EQ(overcast.clearness(), 1.0);
  const SkyHierarchy overcastSky(overcast, 150.0, 7);
  EXPECT_GT(brightestFinestPatch(overcastSky).u0(), 60.0 * degree); // high in the sky
  EXPECT_NEAR(mapHorizontalIrradiance(overcastSky) / 150.0, 1.0, 1e-3);
}
