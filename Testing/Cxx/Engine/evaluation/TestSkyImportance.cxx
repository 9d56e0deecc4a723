// Sky rays drawn by radiance (sky_importance.h) integrate the open sky.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "evaluation/final_gather.h"
#include "evaluation/open_sky.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "visibility/sampling.h"
#include "sky/sky_hierarchy.h"
#include "evaluation/sky_importance.h"
#include "solver/solver.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

TEST(SkyImportance, RaysDrawnByRadianceIntegrateTheOpenSky)
{
  // Each direction carries radiance / density: over an open plane their mean, weighted
  // by the cosine, is the plane's irradiance, for any normal.
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(70.0 * degree, 1.0)), 100.0, 6);
  const OpenSky open(sky);
  const SkyImportance samples(open);
  for (const Vec3& n : { Vec3(0, 0, 1), glm::normalize(Vec3(0.5, -0.3, 0.8)) })
  {
    constexpr int side = 128;
    double sum = 0.0;
    SampleGenerator random(5);
    for (int k = 0; k < side * side; ++k)
    {
      double s, t;
      stratifiedPoint(k, side * side, random, s, t);
      SkyImportance::Sample sample;
      ASSERT_TRUE(samples.sample(s, t, sample));
      EXPECT_NEAR(glm::length(sample.direction), 1.0, 1e-12);
      ASSERT_GE(sample.direction.z, 0.0);
      sum += sample.weight[0] * std::max(0.0, glm::dot(n, sample.direction));
    }
    Spectrum e;
    double omega = 0.0;
    open.irradiance(n, e, omega);
    EXPECT_NEAR(sum / (side * side) / e[0], 1.0, 0.005) << n.x;
  }
}
