// The hierarchical sky (sky_hierarchy.h, paper section 5.1) against closed forms and
// an independent brute-force integration.
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

TEST(SkyHierarchy, SolidAnglesOfEveryLevelSumToTwoPi)
{
  for (int level = 0; level <= 9; ++level)
  {
    // Neumaier summation, so the test measures the solid angles, not rounding.
    const int n = SkyHierarchy::cellsPerSide(level);
    double sum = 0.0, compensation = 0.0;
    for (int iu = 0; iu < n; ++iu)
      for (int iv = 0; iv < n; ++iv)
      {
        const double omega = SkyPatch{ level, iu, iv }.solidAngle();
        const double t = sum + omega;
        compensation += std::abs(sum) >= omega ? (sum - t) + omega : (omega - t) + sum;
        sum = t;
      }
    EXPECT_NEAR(sum + compensation, 2.0 * pi, 1e-12) << level;
  }
}

TEST(SkyHierarchy, ParametersMapToCompassDirections)
{
  const Direction south = directionFromSkyParameters(0.0, 0.0);
  const Direction west = directionFromSkyParameters(0.0, 0.5 * pi);
  EXPECT_NEAR(south[1], -1.0, 1e-12);
  EXPECT_NEAR(west[0], -1.0, 1e-12);
  EXPECT_NEAR(directionFromSkyParameters(0.5 * pi, 1.0)[2], 1.0, 1e-12);
}

TEST(SkyHierarchy, UniformSkyClosedForms)
{
  const double radiance = 30.0;
  const SkyHierarchy sky(UniformSky(), pi * radiance, 7);
  EXPECT_NEAR(sky.radianceScale(), radiance, 1e-9); // E = pi L
  EXPECT_NEAR(sky.horizontalIrradiance(0), pi * radiance, 1e-9);
  for (int level : { 0, 3, 7, 9 })
  {
    EXPECT_NEAR(sky.radiance(SkyPatch{ level, 0, 0 }, 0), radiance, 1e-9);
  }
  // Tilted plane: pi L (1 + cos beta) / 2, summing R S Omega L over patches.
  for (double tilt : { 0.0, 30.0, 60.0, 90.0 })
  {
    const Direction normal{ 0.0, std::sin(tilt * degree), std::cos(tilt * degree) };
    const double expected = pi * radiance * (1.0 + std::cos(tilt * degree)) / 2.0;
    EXPECT_NEAR(sky.planeIrradiance(normal, 9, 0) / expected, 1.0, 2e-3) << tilt;
  }
  EXPECT_DOUBLE_EQ(skyIrradianceContribution(0.5, 0.25, 2.0, 10.0), 2.5);
}

TEST(SkyHierarchy, TraditionalOvercastClosedForm)
{
  // E = 7 pi Lz / 9 for L = Lz (1 + 2 cos Z) / 3.
  const SkyHierarchy sky(CieOvercastSky(), 100.0, 6);
  EXPECT_NEAR(sky.radianceScale() * 7.0 * pi / 9.0, 100.0, 1e-9);
  EXPECT_NEAR(mapHorizontalIrradiance(sky), 100.0, 0.05);
}

TEST(SkyHierarchy, EveryCieTypeIntegratesBackToItsDiffuseIrradiance)
{
  const Direction sun = directionFromZenithAzimuth(50.0 * degree, 200.0 * degree);
  for (int type = 1; type <= 15; ++type)
  {
    const CieGeneralSky model(type, sun);
    const SkyHierarchy sky(model, 120.0, 7);
    // The map's own integral and an independent brute-force integral of the scaled model.
    EXPECT_NEAR(mapHorizontalIrradiance(sky) / 120.0, 1.0, 1e-3) << type;
    EXPECT_NEAR(sky.radianceScale() * horizontalIntegral(model) / 120.0, 1.0, 1e-3) << type;
    // Every level of the pyramid carries the same power.
    double total7 = 0.0, total2 = 0.0;
    for (int level : { 2, 7 })
    {
      const int n = SkyHierarchy::cellsPerSide(level);
      double& total = level == 2 ? total2 : total7;
      for (int iu = 0; iu < n; ++iu)
        for (int iv = 0; iv < n; ++iv)
          total += sky.radiance(SkyPatch{ level, iu, iv }, 0) * SkyPatch{ level, iu, iv }.solidAngle();
    }
    EXPECT_NEAR(total2 / total7, 1.0, 1e-12);

    const SkyPatch brightest = brightestFinestPatch(sky);
    if (type >= 11)
    {
      EXPECT_LT(angleBetween(brightest.direction(), sun), 5.0 * degree) << type;
    }
    if (type == 1 || type == 3)
    {
      EXPECT_GT(brightest.u0(), 85.0 * degree) << type; // overcast: brightest at the zenith
    }
    if (type <= 4)
    {
      // Steep gradation: the zenith outshines the horizon even away from the sun.
      const SkyPatch zenith{ 7, 127, 0 };
      const SkyPatch horizonAwayFromSun{ 7, 0, 64 + 16 };
      EXPECT_GT(sky.radiance(zenith, 0), 1.2 * sky.radiance(horizonAwayFromSun, 0)) << type;
    }
    if (type == 5) // sky of uniform luminance
    {
      EXPECT_NEAR(sky.radiance(SkyPatch{ 7, 127, 0 }, 0), sky.radiance(SkyPatch{ 7, 0, 9 }, 0), 1e-9);
    }
  }
}

TEST(SkyHierarchy, TextureModulatesRadiance)
{
  SkyTexture half;
  half.width = 4;
  half.height = 3;
  half.components = 1;
  half.values.assign(12, 0.5);
  const SkyHierarchy dimmed(UniformSky(), 100.0, 6, &half);
  EXPECT_NEAR(dimmed.horizontalIrradiance(0), 50.0, 1e-9);

  // RGB texture: red 1, green 0.5, blue 0 everywhere; and a west-only cloud check.
  SkyTexture colour;
  colour.width = 2;
  colour.height = 2;
  colour.components = 3;
  colour.values = { 1, 0.5, 0, 1, 0.5, 0, 1, 0.5, 0, 1, 0.5, 0 };
  const SkyHierarchy tinted(CieOvercastSky(), 100.0, 6, &colour);
  EXPECT_EQ(tinted.bands(), 3);
  EXPECT_NEAR(tinted.horizontalIrradiance(0), 100.0, 1e-9);
  EXPECT_NEAR(tinted.horizontalIrradiance(1), 50.0, 1e-9);
  EXPECT_NEAR(tinted.horizontalIrradiance(2), 0.0, 1e-12);

  // Azimuth samples: 0 deg (north) bright, 180 deg (south) dark.
  SkyTexture northern;
  northern.width = 3; // azimuth 0, 180, 360
  northern.height = 2;
  northern.components = 1;
  northern.values = { 1, 0, 1, 1, 0, 1 };
  const SkyHierarchy north(UniformSky(), 100.0, 6, &northern);
  const SkyPatch southPatch{ 6, 5, 0 }; // v near 0: south
  const SkyPatch northPatch{ 6, 5, 32 }; // v near pi: north
  EXPECT_LT(north.radiance(southPatch, 0), 0.1 * north.radiance(northPatch, 0));
}

TEST(SkyHierarchy, SubsamplingBelowTheFinestLevel)
{
  const Direction sun = directionFromZenithAzimuth(30.0 * degree, 180.0 * degree);
  const SkyHierarchy sky(CieGeneralSky(12, sun), 100.0, 5);
  // A level-8 patch inside a level-5 cell: interpolated, close to its parent cell.
  const SkyPatch fine{ 8, 8 * 10 + 3, 8 * 7 + 4 };
  const SkyPatch parent{ 5, 10, 7 };
  EXPECT_NEAR(sky.radiance(fine, 0) / sky.radiance(parent, 0), 1.0, 0.15);
  // Children of a patch tile it.
  SkyPatch kids[4];
  parent.children(kids);
  double omega = 0.0;
  for (const SkyPatch& kid : kids)
    omega += kid.solidAngle();
  EXPECT_NEAR(omega, parent.solidAngle(), 1e-15);
}

TEST(SkyHierarchy, TheSkyMapRunsClockwiseFromNorthAndUpFromTheHorizon)
{
  const int level = 4, n = 1 << level;
  auto near = [](const Direction& d, double x, double y, double z) {
    return std::abs(d[0] - x) < 1e-12 && std::abs(d[1] - y) < 1e-12 && std::abs(d[2] - z) < 1e-12;
  };
  EXPECT_TRUE(near(skyMapCorner(level, 0, 0), 0.0, 1.0, 0.0));     // north, on the horizon
  EXPECT_TRUE(near(skyMapCorner(level, n / 4, 0), 1.0, 0.0, 0.0)); // east
  EXPECT_TRUE(near(skyMapCorner(level, n / 2, 0), 0.0, -1.0, 0.0)); // south
  EXPECT_NEAR(skyMapCorner(level, 3, n)[2], 1.0, 1e-12);            // the zenith
  // Each map cell's pyramid patch lies between its corners' azimuths and altitudes.
  for (int j = 0; j < n; j += 3)
    for (int i = 0; i < n; i += 5)
    {
      const Direction d = skyMapCell(level, i, j).direction();
      double compass = std::atan2(d[0], d[1]) / degree;
      compass += compass < 0.0 ? 360.0 : 0.0;
      EXPECT_GT(compass, 360.0 * i / n);
      EXPECT_LT(compass, 360.0 * (i + 1) / n);
      const double altitude = std::asin(d[2]) / degree;
      EXPECT_GT(altitude, 90.0 * j / n);
      EXPECT_LT(altitude, 90.0 * (j + 1) / n);
    }
}
