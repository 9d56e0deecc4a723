// The horizon map at 16, 32 and 64 azimuths (horizon_map.h): what its proofs say of
// the sun, against Embree's rays.

#include "horizons/horizon_map.h"
#include "base/angles.h"
#include "hierarchy/radiosity_types.h"
#include "horizon_checks.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace terralux;
using namespace terralux_test;

namespace
{
double rough(double x, double y)
{
  return 60.0 * std::sin(x / 40.0) * std::cos(y / 55.0) + 25.0 * std::sin((x + 2.0 * y) / 23.0) +
    8.0 * std::sin(x / 7.0 + 1.3) * std::sin(y / 9.0);
}

// For `height` on a grid of 129^2 posts `spacing` apart, the proofs at every 4th post.
Proven checkProvenOpen(const std::function<double(double, double)>& height, double spacing, HorizonMap::Density density)
{
  const auto grid = makeGrid(129, 129, spacing, height);
  EXPECT_TRUE(grid->facesUp());
  const HorizonMap map(*grid, density);
  const Visibility rays(sceneOf({ grid.get() }));
  return checkProofs(map, rays, *grid, 0, 128, 0, 128, 4);
}
} // namespace

class HorizonMapDensity : public ::testing::TestWithParam<HorizonMap::Density>
{
};

TEST_P(HorizonMapDensity, AgreesWithRaysOnRoughTerrain)
{
  const auto grid = makeGrid(129, 129, 10.0, rough);
  ASSERT_TRUE(grid->facesUp());
  const HorizonMap map(*grid, GetParam());
  EXPECT_EQ(map.azimuthCount(), static_cast<int>(GetParam()));
  const Visibility rays(sceneOf({ grid.get() }));
  // The rays start lifted by the visibility's offset (1.8 cm here): 0.1 deg seen from
  // the next post 10 m away, more from a diagonal's crossing nearer.
  const double margin = 0.3 * degree;
  int blocked = 0, checked = 0;
  for (int j = 1; j < 128; j += 7)
    for (int i = 2; i < 128; i += 9)
    {
      blocked += checkAgainstRays(map, rays, *grid, i, j, margin);
      checked += map.azimuthCount();
    }
  // Most directions of this terrain are blocked somewhere: the check is not vacuous.
  EXPECT_GT(blocked, checked / 2);
}

TEST_P(HorizonMapDensity, OblongRotatedCellsAndNoDataAgreeWithRays)
{
  // Cells 10 m x 14 m, the grid turned by 30 deg, with a hole whose posts hold garbage
  // (as the scene sets non-finite posts).
  const double turn = 30.0 * degree, c = std::cos(turn), s = std::sin(turn);
  auto inHole = [](int i, int j) { return i >= 20 && i < 30 && j >= 30 && j < 40; };
  auto place = [&](int i, int j) {
    const double x = 10.0 * i, y = 14.0 * j;
    return Vec3(c * x - s * y, s * x + c * y, rough(x, y));
  };
  TerrainGrid grid(65, 65, Vec3(0.0));
  for (int j = 0; j < 65; ++j)
    for (int i = 0; i < 65; ++i)
      grid.setPost(i, j, i > 20 && i < 30 && j > 30 && j < 40 ? grid.origin() : place(i, j));
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i)
      grid.setCellValid(i, j, !inHole(i, j));
  ASSERT_TRUE(grid.facesUp());
  const HorizonMap map(grid, GetParam());
  const Visibility rays(sceneOf({ &grid }));
  int blocked = 0;
  for (int k = 0; k < 16; ++k)
  {
    blocked += checkAgainstRays(map, rays, grid, 3 + 3 * k, 5 + 3 * k, 0.3 * degree);
    if (grid.postUsed(60 - 3 * k, 6 + 2 * k)) // (21, 32) is inside the hole
      blocked += checkAgainstRays(map, rays, grid, 60 - 3 * k, 6 + 2 * k, 0.3 * degree);
  }
  EXPECT_GT(blocked, 31 * map.azimuthCount() / 2);
  // A post only the hole's cells use has no horizon to give.
  EXPECT_FALSE(map.find(place(25, 35)));
}

TEST_P(HorizonMapDensity, WhatItProvesOpenOrHiddenRaysFindSo)
{
  // Rough hills with a ridge along one edge (the far bound's case: terrain beyond the
  // post's distance to the edge) and a single spike (a peak between two mapped
  // azimuths, which only the slope bound covers): walls this steep leave little proven.
  checkProvenOpen(
    [](double x, double y) {
      const double ridge = y > 1180.0 ? 150.0 : 0.0;
      const double spike = std::hypot(x - 700.0, y - 600.0) < 15.0 ? 120.0 : 0.0;
      return rough(x, y) + ridge + spike;
    },
    10.0, GetParam());
  checkProvenOpen(rough, 10.0, GetParam());
  // Hills as real DEMs have them (slopes up to about 25 deg), on a grid small enough
  // that many posts lie near its edge, directions skewed toward the horizon: 69 % of the
  // open ones need no ray (a day's suns over the 1025^2 fractal DEM: 87 %).
  const Proven share = checkProvenOpen(
    rollingHills,
    30.0, GetParam());
  EXPECT_GT(share.open, 0.5) << "share " << share.open;
  EXPECT_GT(share.shadowed, 0.3) << "share " << share.shadowed;
}

INSTANTIATE_TEST_SUITE_P(CoarseStandardAndDense, HorizonMapDensity,
  ::testing::ValuesIn(HorizonMap::densities));
