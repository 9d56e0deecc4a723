// The reference path tracer against closed forms, before it judges anything: planes
// under uniform and CIE skies, a tilted plane, the furnace, the pit, a long V-valley.
// Each estimate must lie within a few standard errors (and within a fixed bound) of the
// exact value.
#include "path_tracer.h"

#include "base/angles.h"
#include "sky/cie_sky.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "sky/sky_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace terralux_reference;
using terralux::RadiosityScene;
using terralux_test::addPolygon;

namespace
{
using terralux::degree;

terralux::SkyHierarchy uniformSky(double diffuse)
{
  return terralux::SkyHierarchy(terralux::UniformSky(), diffuse, 7);
}

// The estimate agrees with `exact` within 4 standard errors plus `tolerance` (relative).
void expectAgrees(const Estimate& e, double exact, double tolerance)
{
  if (std::getenv("TERRALUX_REFERENCE_PRINT"))
    std::printf("estimate %.4f +- %.4f, exact %.4f\n", e.mean, e.standardError, exact);
  EXPECT_NEAR(e.mean, exact, 4.0 * e.standardError + tolerance * std::abs(exact))
    << "standard error " << e.standardError;
}
} // namespace

TEST(Reference, PlaneUnderUniformAndCieSkies)
{
  RadiosityScene scene;
  addPolygon(scene, { { -50, -50, 0 }, { 50, -50, 0 }, { 50, 50, 0 }, { -50, 50, 0 } }, 0.0);
  const ReferenceScene reference(scene);
  const auto uniform = uniformSky(100.0);
  const PathTracer tracer(reference, &uniform, {});
  const ReferenceIrradiance e = tracer.irradianceAt(Vec3(3, 4, 0), Vec3(0, 0, 1), 4096, 7);
  expectAgrees(e.sky, 100.0, 0.002);
  EXPECT_EQ(e.reflected.mean, 0.0);
  for (int type : { 1, 8, 12, 15 })
  {
    const terralux::Direction sun = terralux::directionFromZenithAzimuth(60 * degree, 135 * degree);
    const terralux::SkyHierarchy cie(terralux::CieGeneralSky(type, sun), 100.0, 7);
    const PathTracer cieTracer(reference, &cie, {});
    expectAgrees(cieTracer.irradianceAt(Vec3(0, 0, 0), Vec3(0, 0, 1), 16384, 3).sky, cie.horizontalIrradiance(0), 0.003);
  }
}

TEST(Reference, SunIsOneShadowRay)
{
  RadiosityScene scene;
  addPolygon(scene, { { -50, -50, 0 }, { 50, -50, 0 }, { 50, 50, 0 }, { -50, 50, 0 } }, 0.0);
  addPolygon(scene, { { -1, 0, 5 }, { 1, 0, 5 }, { 1, 2, 5 }, { -1, 2, 5 } }, 0.0, 0.0, 1); // a roof facing up
  const ReferenceScene reference(scene);
  const Vec3 sun = glm::normalize(Vec3(0.3, 0.0, 1.0));
  const PathTracer tracer(reference, nullptr, { { sun, 800.0 } });
  EXPECT_NEAR(tracer.directSun(Vec3(20, 20, 0), Vec3(0, 0, 1)), 800.0 * sun.z, 1e-9);
  EXPECT_EQ(tracer.directSun(Vec3(-1.5 + 0.0, 1.0, 0), Vec3(0, 0, 1)), 0.0); // under the roof's shadow
}

TEST(Reference, TiltedPlaneSeesPiL1PlusCosOver2)
{
  const auto sky = uniformSky(100.0);
  for (double slope : { 20.0, 45.0, 70.0 })
  {
    RadiosityScene scene;
    const double c = std::cos(slope * degree), s = std::sin(slope * degree);
    // A plane through the origin with normal (-s, 0, c), 200 m each way.
    addPolygon(scene, { { -100 * c, -100, -100 * s }, { 100 * c, -100, 100 * s }, { 100 * c, 100, 100 * s },
      { -100 * c, 100, -100 * s } }, 0.0);
    const ReferenceScene reference(scene);
    const PathTracer tracer(reference, &sky, {});
    expectAgrees(tracer.irradianceAt(Vec3(0, 0, 0), Vec3(-s, 0, c), 4096, 11).sky, 100.0 * (1 + c) / 2, 0.003);
  }
}

TEST(Reference, FurnaceGivesEmissionOverOneMinusReflectance)
{
  for (double rho : { 0.3, 0.5, 0.8 })
  {
    RadiosityScene scene;
    terralux_test::addInwardCube(scene, 2.0, rho, 100.0);
    const ReferenceScene reference(scene);
    const PathTracer tracer(reference, nullptr, {});
    // Inside, every direction sees radiosity B = 100 / (1 - rho): irradiance is B.
    const ReferenceIrradiance e = tracer.irradianceAt(Vec3(0.7, 1.1, 0.0), Vec3(0, 0, 1), 4096, 5);
    expectAgrees(e.reflected, 100.0 / (1.0 - rho), 0.01);
  }
}

TEST(Reference, PitBottomSeesSinSquaredOfItsOpening)
{
  const auto sky = uniformSky(100.0);
  for (double depth : { 1.0, 3.0 })
  {
    RadiosityScene scene;
    terralux_test::addPit(scene, 2.0, depth, 96, 0.0);
    const ReferenceScene reference(scene);
    const PathTracer tracer(reference, &sky, {});
    const double opening = std::atan(2.0 / depth);
    const double exact = 100.0 * std::sin(opening) * std::sin(opening);
    // A 96-gon is a little smaller than the circle: within 0.2 %.
    expectAgrees(tracer.irradianceAt(Vec3(0, 0, -depth), Vec3(0, 0, 1), 16384, 13).sky, exact, 0.004);
  }
}

TEST(Reference, VValleyBottomSeesCosOfItsSlope)
{
  const auto sky = uniformSky(100.0);
  for (double slope : { 20.0, 40.0 })
  {
    // Sides rising at `slope` to 50 m on both sides of the x axis, 4 km long.
    const double run = 50.0 / std::tan(slope * degree), l = 2000.0;
    RadiosityScene scene;
    addPolygon(scene, { { -l, 0, 0 }, { l, 0, 0 }, { l, run, 50 }, { -l, run, 50 } }, 0.0);   // north side, faces south-up
    addPolygon(scene, { { -l, -run, 50 }, { l, -run, 50 }, { l, 0, 0 }, { -l, 0, 0 } }, 0.0); // south side
    const ReferenceScene reference(scene);
    const PathTracer tracer(reference, &sky, {});
    // A horizontal receiver on the valley line sees the sky between the two horizons at
    // elevation `slope` (in 2-D, cos slope); the finite ends add a little.
    const ReferenceIrradiance e = tracer.irradianceAt(Vec3(0, 0, 0), Vec3(0, 0, 1), 16384, 17);
    expectAgrees(e.sky, 100.0 * std::cos(slope * degree), 0.004);
  }
}
