// The suns each post proves seen or hidden (post_sunlight.h), read at points inside
// the cells between them, against Embree's shadow rays from those points, which know
// nothing of the horizons.

#include "base/angles.h"
#include "horizons/horizon_map.h"
#include "base/error.h"
#include "horizons/post_sunlight.h"
#include "visibility/sampling.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace terralux;
using namespace terralux_test;

namespace
{
double hills(double x, double y)
{
  return Hills{ 60.0, 90.0, 120.0, 25.0, 70.0 }(x, y) + (x > 900.0 ? 80.0 : 0.0); // and a cliff: long shadows
}

Vec3 towardSun(double azimuth, double elevation)
{
  return { std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation) };
}

struct Agreement
{
  int points = 0, proven = 0, wrong = 0, edgeCellsProven = 0, edgeCells = 0;
};

// Points spread over every cell, each judged by a shadow ray from just above it (as a
// gather's hit is) for each sun; a cell whose points the rays split between lit and
// dark holds a shadow's edge.
Agreement checkAgainstRays(const TerrainGrid& grid, const PostSunlight& sunlight, const std::vector<Vec3>& suns)
{
  const Visibility rays(sceneOf(grid));
  SampleGenerator random(7);
  Agreement result;
  for (int j = 0; j + 1 < grid.postsY(); ++j)
    for (int i = 0; i + 1 < grid.postsX(); ++i)
    {
      if (!grid.cellValid(i, j))
        continue;
      std::vector<int> litCount(suns.size(), 0);
      constexpr int samples = 6;
      std::vector<SunsProven> proofs;
      for (int k = 0; k < samples; ++k)
      {
        // A hit as a gather's ray makes it: on the cell's triangles, found by a ray
        // from high above a point of the cell, with its grid parameters.
        const double fu = random.uniform(), fv = random.uniform();
        const Vec3 above = (1 - fu) * (1 - fv) * grid.post(i, j) + fu * (1 - fv) * grid.post(i + 1, j) +
          (1 - fu) * fv * grid.post(i, j + 1) + fu * fv * grid.post(i + 1, j + 1) + Vec3(0, 0, 5000);
        SurfaceHit hit;
        EXPECT_TRUE(rays.firstHit(above, Vec3(0, 0, 1), Vec3(0, 0, -1), hit));
        EXPECT_EQ(static_cast<int>(std::floor(hit.u)), i);
        EXPECT_EQ(static_cast<int>(std::floor(hit.v)), j);
        const Vec3 front = hit.normal.z < 0.0 ? -hit.normal : hit.normal;
        const SunsProven proven = sunlight.between(hit.u, hit.v);
        proofs.push_back(proven);
        for (std::size_t s = 0; s < suns.size(); ++s)
        {
          const bool lit = !rays.occludedToward(hit.point, front, suns[s]);
          litCount[s] += lit;
          ++result.points;
          const unsigned bit = 1u << s;
          if (proven.seen & bit || proven.hidden & bit)
            ++result.proven;
          if ((proven.seen & bit && !lit) || (proven.hidden & bit && lit))
            ++result.wrong;
          EXPECT_FALSE(proven.seen & proven.hidden & bit);
        }
      }
      // Every point of a cell reads the same proof.
      for (const SunsProven& proven : proofs)
        EXPECT_TRUE(proven.seen == proofs[0].seen && proven.hidden == proofs[0].hidden) << i << " " << j;
      for (std::size_t s = 0; s < suns.size(); ++s)
        if (litCount[s] > 0 && litCount[s] < samples)
        {
          ++result.edgeCells;
          result.edgeCellsProven += ((proofs[0].seen | proofs[0].hidden) >> s) & 1u;
        }
    }
  return result;
}
} // namespace

TEST(PostSunlight, CellsAllOfWhosePostsAgreeAgreeWithShadowRays)
{
  const auto grid = makeGrid(121, 101, 10.0, hills);
  const HorizonMap map(*grid);
  // A low sun toward the cliff's shadow side, a high one, and one between mapped azimuths.
  const std::vector<std::pair<double, double>> angles{ { 3.0, 12.0 * degree }, { 0.4, 55.0 * degree },
    { 1.234, 20.0 * degree } };
  std::vector<Vec3> suns;
  std::vector<HorizonMap::Sight> sights;
  for (const auto& [azimuth, elevation] : angles)
  {
    suns.push_back(towardSun(azimuth, elevation));
    sights.push_back(map.sight(azimuth, elevation));
  }
  const PostSunlight sunlight(*grid, map, sights);
  ASSERT_EQ(sunlight.suns(), suns.size());
  // Each post's own proofs are the map's.
  for (int j = 0; j < grid->postsY(); j += 7)
    for (int i = 0; i < grid->postsX(); i += 5)
    {
      HorizonMap::View view(map, { true, static_cast<std::size_t>(j) * grid->postsX() + i });
      const SunsProven proven = sunlight.at(i, j);
      for (std::size_t s = 0; s < sights.size(); ++s)
      {
        const bool above = view.clearlyAbove(sights[s]);
        EXPECT_EQ(static_cast<bool>(proven.seen >> s & 1u), above);
        EXPECT_EQ(static_cast<bool>(proven.hidden >> s & 1u), !above && view.clearlyBelow(sights[s]));
      }
    }
  const Agreement agreement = checkAgainstRays(*grid, sunlight, suns);
  // A third of the hits take no ray on these small, steep hills (83 % of the sun's
  // rays at hits on the 1025^2 fractal DEM), no proof is contradicted by a ray, and a
  // cell a shadow's edge crosses is left to the rays.
  EXPECT_GT(agreement.proven, agreement.points / 4) << agreement.proven << " of " << agreement.points;
  EXPECT_EQ(agreement.wrong, 0);
  EXPECT_GT(agreement.edgeCells, 50);
  EXPECT_EQ(agreement.edgeCellsProven, 0);
}

TEST(PostSunlight, MissingPostsAndOutsideParametersProveNothing)
{
  // A hole: the map proves nothing on an incomplete grid; and on a complete one, a
  // cell's proof needs its four posts.
  const auto holed = makeGrid(41, 41, 10.0, hills, [](int i, int j) { return !(i == 20 && j == 20); });
  const HorizonMap holedMap(*holed);
  const PostSunlight none(*holed, holedMap, { holedMap.sight(1.0, 40.0 * degree) });
  for (int j = 0; j + 1 < holed->postsY(); ++j)
    for (int i = 0; i + 1 < holed->postsX(); ++i)
    {
      const SunsProven proven = none.between(i + 0.5, j + 0.5);
      EXPECT_EQ(proven.seen | proven.hidden, 0u);
    }
  const auto grid = makeGrid(41, 41, 10.0, [](double, double) { return 0.0; });
  const HorizonMap map(*grid);
  const PostSunlight flat(*grid, map, { map.sight(1.0, 40.0 * degree), map.sight(2.0, -5.0 * degree) });
  // Flat open ground: the sun above proven seen, on the grid's edges too (parameters
  // there read the last cell); one below the horizon is for the surface's cosine to
  // turn away, not the terrain's proofs.
  for (const auto& [u, v] : std::vector<std::pair<double, double>>{ { 0.0, 0.0 }, { 40.0, 40.0 }, { 17.3, 3.9 } })
  {
    const SunsProven proven = flat.between(u, v);
    EXPECT_EQ(proven.seen, 1u) << u << " " << v;
    EXPECT_EQ(proven.hidden, 0u) << u << " " << v;
  }
  const SunsProven nan = flat.between(std::nan(""), 3.0);
  EXPECT_EQ(nan.seen | nan.hidden, 0u);
  EXPECT_THROW(PostSunlight(*grid, map, std::vector<HorizonMap::Sight>(5, map.sight(1.0, 0.5))), Error);
}
