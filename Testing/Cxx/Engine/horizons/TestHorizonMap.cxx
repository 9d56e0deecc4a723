// The horizons of every post found at once (horizon_map.h), against closed forms and
// against Embree's rays, which know nothing of the sweep.

#include "horizons/horizon_map.h"
#include "base/angles.h"
#include "hierarchy/radiosity_types.h"
#include "horizon_checks.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include "base/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace terralux;
using namespace terralux_test;

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

TEST(HorizonMap, TerrainFallingAwayKeepsItsHorizonBelowTheHorizontal)
{
  // A plane falling at 0.2 toward +x: from a post inside, toward azimuth phi the
  // terrain ahead lies at atan(-0.2 cos phi), below the horizontal where cos phi > 0;
  // from a post on the grid's +x edge nothing lies ahead there (the nadir).
  const auto grid = makeGrid(101, 101, 10.0, [](double x, double) { return -0.2 * x; });
  for (const HorizonMap::Density density : HorizonMap::densities)
  {
    const HorizonMap map(*grid, density);
    const HorizonMap::Post inside = map.find(grid->post(50, 50)), edge = map.find(grid->post(100, 50));
    ASSERT_TRUE(inside && edge);
    for (int a = 0; a < map.azimuthCount(); ++a)
    {
      const double c = std::cos(map.azimuths()[a]);
      const double expected = std::atan(-0.2 * c);
      EXPECT_NEAR(map.trueElevation(inside, a), expected, 5e-5) << map.azimuths()[a] / degree;
      EXPECT_NEAR(map.elevation(inside, a), std::max(0.0, expected), 5e-5) << map.azimuths()[a] / degree;
      if (c > 1e-9)
        EXPECT_EQ(map.trueElevation(edge, a), -0.5 * pi) << map.azimuths()[a] / degree;
      else
        EXPECT_GE(map.trueElevation(edge, a), -2.5e-5) << map.azimuths()[a] / degree;
      EXPECT_GE(map.elevation(edge, a), 0.0);
    }
  }
}

TEST(HorizonMap, CoarseAndDenseAzimuthsKeepTheStandardOnesOrder)
{
  // Dense azimuths lie between the standard ones, coarse ones are every other standard
  // one, evenly apart either way.
  const auto grid = makeGrid(9, 9, 10.0, [](double, double) { return 0.0; });
  const HorizonMap standard(*grid), dense(*grid, HorizonMap::Density::Dense),
    coarse(*grid, HorizonMap::Density::Coarse);
  ASSERT_EQ(dense.azimuthCount(), 64);
  ASSERT_EQ(coarse.azimuthCount(), 16);
  auto checkGaps = [](const std::vector<double>& a, double least, double most) {
    for (std::size_t k = 0; k < a.size(); ++k)
    {
      const double next = k + 1 < a.size() ? a[k + 1] : a[0] + 2.0 * pi;
      EXPECT_GT(next - a[k], least * degree);
      EXPECT_LT(next - a[k], most * degree);
    }
  };
  checkGaps(dense.azimuths(), 3.0, 8.2);
  checkGaps(coarse.azimuths(), 21.7, 23.3);
  auto contains = [](const std::vector<double>& a, double azimuth) {
    return std::find_if(a.begin(), a.end(), [&](double b) { return std::abs(b - azimuth) < 1e-12; }) != a.end();
  };
  for (const double azimuth : standard.azimuths())
    EXPECT_TRUE(contains(dense.azimuths(), azimuth));
  for (const double azimuth : coarse.azimuths())
    EXPECT_TRUE(contains(standard.azimuths(), azimuth));
}

TEST(HorizonMap, AFinerMapCopiesACoarserOnesSweepsBitForBit)
{
  // Rough hills, with a hole of missing cells (the sweep's checked crossings).
  auto grid = makeGrid(61, 53, 10.0, [](double x, double y) {
    return rollingHills(4.0 * x, 4.0 * y) + 20.0 * std::sin(0.09 * x) * std::cos(0.13 * y);
  });
  for (int j = 20; j < 26; ++j)
    for (int i = 30; i < 41; ++i)
      grid->setCellValid(i, j, false);
  const HorizonMap coarse(*grid, HorizonMap::Density::Coarse), standard(*grid),
    dense(*grid, HorizonMap::Density::Dense);
  const HorizonMap standardFromCoarse(*grid, HorizonMap::Density::Standard, nullptr, &coarse),
    denseFromStandard(*grid, HorizonMap::Density::Dense, nullptr, &standard);
  int differences = 0;
  for (std::size_t index = 0; index < static_cast<std::size_t>(grid->postsX()) * grid->postsY(); ++index)
  {
    const HorizonMap::Post post{ true, index };
    for (int a = 0; a < standard.azimuthCount(); ++a)
      differences += standardFromCoarse.elevation(post, a) != standard.elevation(post, a);
    for (int a = 0; a < dense.azimuthCount(); ++a)
      differences += denseFromStandard.elevation(post, a) != dense.elevation(post, a);
  }
  EXPECT_EQ(differences, 0);
  // Only a map of the same posts lends its sweeps.
  const auto other = makeGrid(61, 53, 10.0, [](double, double) { return 0.0; });
  EXPECT_THROW(HorizonMap(*other, HorizonMap::Density::Standard, nullptr, &coarse), Error);
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
