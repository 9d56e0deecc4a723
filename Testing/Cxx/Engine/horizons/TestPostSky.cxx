// The sky each post receives (post_sky.h), found from its horizons and read between
// posts.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "horizons/horizon_map.h"
#include "horizons/horizon_sky.h"
#include "evaluation/open_sky.h"
#include "evaluation/post_lattice.h"
#include "horizons/post_sky.h"
#include "visibility/sampling.h"
#include "sky/sky_hierarchy.h"
#include "sky/sky_model.h"
#include "terrain/terrain_directions.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace terralux;
using namespace terralux_test;

TEST(PostSky, PostsHoldTheirSkyAndCellsReadItBetweenThem)
{
  // A pit in open ground under a clear sky: each post's stored sky is the sky found at
  // it; between posts it is read bilinearly, so a point on a wall of the pit gets the
  // dim sky of the pit's posts, not the open ground's.
  const auto grid = makeGrid(33, 33, 10.0, [](double x, double y) {
    const double r = std::hypot(x - 160.0, y - 160.0);
    return r < 40.0 ? -40.0 + r : 0.0;
  });
  const RadiosityScene scene = sceneOf(*grid);
  const Visibility rays(scene);
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(50.0 * degree, 1.0)), 100.0, 6);
  OpenSky open(sky);
  const HorizonMap map(*grid);
  const HorizonSky horizons(rays, open, &map);
  const PostSky skies(*grid, horizons, open);
  Spectrum open0;
  double omega = 0.0;
  open.irradiance(Vec3(0, 0, 1), open0, omega);
  auto at = [&](int i, int j) {
    const HorizonMap::Post post = map.find(grid->post(i, j));
    EXPECT_TRUE(post);
    return PostSky::at(post, grid->postNormal(i, j), horizons, open);
  };
  // Open ground far from the pit: the open sky; the pit's bottom: much less.
  EXPECT_NEAR(at(2, 2).irradiance[0], open0[0], 1e-6 * open0[0]);
  EXPECT_LT(at(16, 16).irradiance[0], 0.6 * open0[0]);
  for (const auto& [i, j] : { std::pair{ 16, 16 }, std::pair{ 14, 17 }, std::pair{ 2, 2 } })
  {
    PostSky::Value stored;
    ASSERT_TRUE(skies.found(map.find(grid->post(i, j)), grid->postNormal(i, j), stored));
    EXPECT_NEAR(stored.irradiance[0], at(i, j).irradiance[0], 1e-4 * open0[0]);
    // It also keeps the open sky of its plane (what the sky's error estimate compares
    // the sky with), as OpenSky finds it on the post's normal.
    Spectrum openHere;
    double omegaHere = 0.0;
    open.irradiance(grid->postNormal(i, j), openHere, omegaHere);
    EXPECT_NEAR(stored.openLargestBand, largestBand(openHere), 1e-6 * open0[0]);
    EXPECT_NEAR(stored.openProjectedSolidAngle, omegaHere, 1e-6);
    if (i == 16)
      EXPECT_LT(stored.irradiance[0], 0.6 * stored.openLargestBand); // the pit hides much of it
    Spectrum read;
    ASSERT_TRUE(skies.interpolate(i, j, read));
    EXPECT_NEAR(read[0], at(i, j).irradiance[0], 1e-4 * open0[0]);
  }
  // Another normal than the one stored: not found (the gather then computes it).
  PostSky::Value stored;
  EXPECT_FALSE(skies.found(map.find(grid->post(16, 16)), glm::normalize(Vec3(0.3, 0, 1)), stored));
  // Half way between two posts: their mean.
  Spectrum read;
  ASSERT_TRUE(skies.interpolate(15.5, 16.0, read));
  EXPECT_NEAR(read[0], 0.5 * (at(15, 16).irradiance[0] + at(16, 16).irradiance[0]), 1e-4 * open0[0]);
}
