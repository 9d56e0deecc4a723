// The horizons of every post found at once (horizon_map.h), against closed forms and
// against Embree's rays, which know nothing of the sweep: just above a post's horizon a
// ray escapes, just below it a ray is blocked.

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


} // namespace

TEST(HorizonMap, AzimuthsAreEvenlySpreadAndWallsSeenAtTheirTangent)
{
  // Flat ground, and a 50 m wall whose top edge runs along x = 700 m.
  const auto grid = makeGrid(101, 101, 10.0, [](double x, double) { return x >= 699.0 ? 50.0 : 0.0; });
  const HorizonMap map(*grid);
  const std::vector<double>& azimuths = map.azimuths();
  ASSERT_EQ(azimuths.size(), static_cast<std::size_t>(map.azimuthCount()));
  for (std::size_t a = 0; a < azimuths.size(); ++a)
  {
    const double next = a + 1 < azimuths.size() ? azimuths[a + 1] : azimuths[0] + 2.0 * pi;
    EXPECT_GT(next - azimuths[a], 10.0 * degree);
    EXPECT_LT(next - azimuths[a], 12.0 * degree);
  }
  // From post (20, 50), 500 m west of the edge: toward an azimuth phi within 45 deg of
  // east the edge is 500 / cos(phi) away; farther round the line leaves the grid
  // first, and away from the wall nothing rises.
  const HorizonMap::Post post = map.find(grid->post(20, 50));
  ASSERT_TRUE(post);
  for (int a = 0; a < map.azimuthCount(); ++a)
  {
    const double c = std::cos(azimuths[a]);
    const double expected = c >= std::sqrt(0.5) - 1e-9 ? std::atan(0.1 * c) : 0.0;
    EXPECT_NEAR(map.elevation(post, a), expected, 1e-4) << azimuths[a] / degree;
  }
  // Points that are not posts are not found: between posts, above one, off the grid.
  EXPECT_FALSE(map.find(grid->post(20, 50) + Vec3(3.0, 0.0, 0.0)));
  EXPECT_FALSE(map.find(grid->post(20, 50) + Vec3(0.0, 0.0, 2.0)));
  EXPECT_FALSE(map.find(Vec3(-500.0, 0.0, 0.0)));
}

class HorizonMapDensity : public ::testing::TestWithParam<bool>
{
};

TEST_P(HorizonMapDensity, AgreesWithRaysOnRoughTerrain)
{
  const auto grid = makeGrid(129, 129, 10.0, rough);
  ASSERT_TRUE(grid->facesUp());
  const HorizonMap map(*grid, GetParam());
  EXPECT_EQ(map.azimuthCount(), GetParam() ? 64 : 32);
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


// For `height` on a grid of 129^2 posts `spacing` apart, the proofs at every 4th post.
Proven checkProvenOpen(const std::function<double(double, double)>& height, double spacing, bool dense)
{
  const auto grid = makeGrid(129, 129, spacing, height);
  EXPECT_TRUE(grid->facesUp());
  const HorizonMap map(*grid, dense);
  const Visibility rays(sceneOf({ grid.get() }));
  return checkProofs(map, rays, *grid, 0, 128, 0, 128, 4);
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
    [](double x, double y) { return 200.0 * std::sin(x / 900.0) * std::cos(y / 1300.0) + 60.0 * std::sin((x + 2.0 * y) / 500.0); },
    30.0, GetParam());
  EXPECT_GT(share.open, 0.5) << "share " << share.open;
  EXPECT_GT(share.shadowed, 0.3) << "share " << share.shadowed;
}

INSTANTIATE_TEST_SUITE_P(StandardAndDense, HorizonMapDensity, ::testing::Values(false, true));

TEST(HorizonMap, DenseAzimuthsLieBetweenTheStandardOnes)
{
  const auto grid = makeGrid(9, 9, 10.0, [](double, double) { return 0.0; });
  const HorizonMap standard(*grid), dense(*grid, true);
  ASSERT_EQ(dense.azimuthCount(), 64);
  const std::vector<double>& a = dense.azimuths();
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    const double next = k + 1 < a.size() ? a[k + 1] : a[0] + 2.0 * pi;
    EXPECT_GT(next - a[k], 3.0 * degree);
    EXPECT_LT(next - a[k], 8.2 * degree);
  }
  for (const double azimuth : standard.azimuths())
    EXPECT_NE(std::find_if(a.begin(), a.end(), [&](double b) { return std::abs(b - azimuth) < 1e-12; }), a.end());
}

TEST(HorizonMap, BearingsWrapAround)
{
  const auto grid = makeGrid(9, 9, 10.0, [](double, double) { return 0.0; });
  const HorizonMap map(*grid);
  const std::vector<double>& a = map.azimuths();
  const HorizonMap::Bearing last = map.bearing(a.back() + 0.01);
  EXPECT_EQ(last.k, map.azimuthCount() - 1);
  EXPECT_NEAR(last.fromBelow, 0.01, 1e-12);
  EXPECT_NEAR(last.toAbove, a.front() + twoPi - a.back() - 0.01, 1e-12);
  const HorizonMap::Bearing negative = map.bearing(a[3] + 0.02 - twoPi);
  EXPECT_EQ(negative.k, 3);
  EXPECT_NEAR(negative.fromBelow, 0.02, 1e-9);
  // A flat plane: every direction above the horizontal is open, and proven so.
  const HorizonMap::Post post = map.find(grid->post(4, 4));
  HorizonMap::View view(map, post);
  EXPECT_TRUE(view.clearlyAbove(map.sight(1.0, 0.01)));
  EXPECT_FALSE(view.clearlyAbove(map.sight(1.0, 0.0)));
}

TEST(HorizonMap, PostsNearAnEdgeSeeOutOfTheGridWithoutRays)
{
  // A 100 m hill in the middle of flat ground; a post 2 cells from the west edge. Out
  // of the grid (west) both mapped azimuths' lines end within 20 m, and so does every
  // bearing between them (no corner lies within): the terrain beyond them is no
  // terrain, so low suns that way are proven open, although the hill rises 79 deg above
  // 20 m away. Toward the hill (east) the same elevation is not.
  const auto grid = makeGrid(129, 129, 10.0, [](double x, double y) {
    return 100.0 * std::exp(-(std::pow(x - 640.0, 2) + std::pow(y - 640.0, 2)) / (2.0 * 150.0 * 150.0));
  });
  const HorizonMap map(*grid);
  const Visibility rays(sceneOf({ grid.get() }));
  const Vec3 point = grid->post(2, 64);
  const HorizonMap::Post post = map.find(point);
  ASSERT_TRUE(post);
  HorizonMap::View view(map, post);
  int proven = 0, tried = 0;
  for (double azimuth = 135.0 * degree; azimuth <= 225.0 * degree; azimuth += 2.5 * degree)
  {
    const HorizonMap::Sight sight = map.sight(azimuth, 5.0 * degree);
    ++tried;
    if (view.clearlyAbove(sight))
    {
      ++proven;
      EXPECT_FALSE(rays.occludedToward(point, Vec3(0, 0, 1), directionOf(azimuth, 5.0 * degree)));
    }
  }
  EXPECT_EQ(proven, tried);
  // Toward the hill: its top rises about 8 deg.
  EXPECT_FALSE(view.clearlyAbove(map.sight(0.0, 5.0 * degree)));
  EXPECT_TRUE(rays.occludedToward(point, Vec3(0, 0, 1), directionOf(0.0, 5.0 * degree)));
}
