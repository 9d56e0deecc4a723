// The directions in which a post sees terrain (terrain_directions.h) and the sky its
// neighbours receive (post_sky.h), against closed forms and against brute-force
// cosine-weighted rays over the whole hemisphere, which know nothing of horizons.

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

namespace
{


// The pieces and horizons a post's terrain directions share with the sky it hides
// (the sky's radiance plays no part in the directions).
struct MappedHorizons
{
  explicit MappedHorizons(const TerrainGrid& grid)
    : scene(sceneOf(grid))
    , rays(scene)
    , map(grid)
    , horizons(rays, open, &map)
  {
  }
  RadiosityScene scene;
  Visibility rays;
  SkyHierarchy sky{ UniformSky(), 100.0, 6 };
  OpenSky open{ sky };
  HorizonMap map;
  HorizonSky horizons;
};

struct Estimate
{
  double mean = 0.0, standardError = 0.0;
};

// The terrain's view factor from a post, (1 / pi) x the integral of the cosine over the
// directions whose ray meets terrain: from rays drawn below the horizon...
Estimate viewFactorBelowHorizon(
  const TerrainDirections& directions, const Visibility& rays, const Vec3& from, const Vec3& n, int count)
{
  SampleGenerator random(11);
  double sum = 0.0, squares = 0.0;
  for (int k = 0; k < count; ++k)
  {
    double s, t;
    stratifiedPoint(k, count, random, s, t);
    const TerrainDirections::Sample sample = directions.sample(s, t);
    const double value = sample.weight > 0.0 && rays.occludedToward(from, n, sample.direction) ? sample.weight : 0.0;
    sum += value;
    squares += value * value;
  }
  const double mean = sum / count;
  return { mean, std::sqrt(std::max(0.0, squares / count - mean * mean) / count) };
}

// ... and from cosine-weighted rays over the whole hemisphere (the fraction blocked).
Estimate viewFactorOverHemisphere(const Visibility& rays, const Vec3& from, const Vec3& n, int count)
{
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 u = glm::normalize(glm::cross(a, n)), v = glm::cross(n, u);
  SampleGenerator random(5);
  int blocked = 0;
  for (int k = 0; k < count; ++k)
  {
    double s, t;
    stratifiedPoint(k, count, random, s, t);
    const double r = std::sqrt(s), phi = 2.0 * pi * t;
    const Vec3 d = glm::normalize(r * std::cos(phi) * u + r * std::sin(phi) * v + std::sqrt(1.0 - s) * n);
    blocked += rays.occludedToward(from, n, d);
  }
  const double p = static_cast<double>(blocked) / count;
  return { p, std::sqrt(p * (1.0 - p) / count) };
}
} // namespace

TEST(TerrainDirections, FlatOpenPostsHaveNoneAndNeedNoRay)
{
  const auto grid = makeGrid(33, 33, 10.0, [](double, double) { return 0.0; });
  const MappedHorizons mapped(*grid);
  const HorizonMap::Post post = mapped.map.find(grid->post(16, 16));
  ASSERT_TRUE(post);
  EXPECT_TRUE(TerrainDirections(mapped.horizons, post, Vec3(0, 0, 1)).empty());
}

TEST(TerrainDirections, ValleyBottomSeesOneMinusCosOfTheSlopeInTerrain)
{
  // A valley 4 km long whose sides rise at `slope` to 50 m: its bottom sees terrain over
  // 1 - cos(slope) of its view (in 2-D; the ends 2 km away add under 0.1 %). Every ray
  // drawn below the horizon meets the walls: few are needed.
  for (double slope : { 20.0, 40.0 })
  {
    const double half = 160.0;
    const auto grid = makeGrid(
      201, 161, 2.0, [&](double, double y) { return std::min(50.0, std::abs(y - half) * std::tan(slope * degree)); },
      [](int, int) { return true; }, [](int i) { return -2000.0 + 20.0 * i; });
    const MappedHorizons mapped(*grid);
    const Visibility& rays = mapped.rays;
    const Vec3 p(0, half, 0), n(0, 0, 1);
    const HorizonMap::Post post = mapped.map.find(p);
    ASSERT_TRUE(post);
    const TerrainDirections directions(mapped.horizons, post, n);
    const Estimate below = viewFactorBelowHorizon(directions, rays, p + 2.0 * rays.offset() * n, n, 4096);
    EXPECT_NEAR(below.mean, 1.0 - std::cos(slope * degree), 0.01) << slope;
    // Hit or miss over the hemisphere: sqrt(p (1 - p) / 4096), 0.0066 at 40 deg.
    EXPECT_LT(below.standardError, 0.6 * std::sqrt(below.mean * (1.0 - below.mean) / 4096.0)) << slope;
  }
}

TEST(TerrainDirections, AgreeWithHemisphereRaysOnRoughTerrain)
{
  // Ridges, bowls and pits, posts on slopes facing every way: the same view factor from
  // rays below the horizon as from the whole hemisphere, within their noise, and with
  // a fraction of the spread. Terrain that rises above the horizon interpolated
  // between the map's azimuths must still be drawn (the margin), or the estimate would
  // fall short.
  const auto grid = makeGrid(65, 65, 10.0, [](double x, double y) {
    return 60.0 * std::sin(x / 40.0) * std::cos(y / 55.0) + 25.0 * std::sin((x + 2.0 * y) / 23.0) +
      8.0 * std::sin(x / 7.0 + 1.3) * std::sin(y / 9.0);
  });
  ASSERT_TRUE(grid->facesUp());
  const MappedHorizons mapped(*grid);
  const Visibility& rays = mapped.rays;
  double sumBelow = 0.0, sumHemisphere = 0.0, sumVariance = 0.0, spreadBelow = 0.0, spreadHemisphere = 0.0;
  int posts = 0;
  for (int j = 8; j < 60; j += 6)
    for (int i = 8; i < 60; i += 6)
    {
      const Vec3 n = grid->postNormal(i, j), from = grid->post(i, j) + 2.0 * rays.offset() * n;
      const HorizonMap::Post post = mapped.map.find(grid->post(i, j));
      ASSERT_TRUE(post);
      const TerrainDirections directions(mapped.horizons, post, n);
      const Estimate below = viewFactorBelowHorizon(directions, rays, from, n, 1024);
      const Estimate hemisphere = viewFactorOverHemisphere(rays, from, n, 16384);
      const double se = std::hypot(below.standardError, hemisphere.standardError);
      EXPECT_NEAR(below.mean, hemisphere.mean, 4.0 * se + 1e-3) << i << " " << j;
      sumBelow += below.mean;
      sumHemisphere += hemisphere.mean;
      sumVariance += se * se;
      spreadBelow += below.standardError * std::sqrt(1024.0);
      spreadHemisphere += hemisphere.standardError * std::sqrt(16384.0);
      ++posts;
    }
  // Over all posts: no bias beyond the noise of the sum.
  EXPECT_NEAR(sumBelow, sumHemisphere, 3.0 * std::sqrt(sumVariance) + 1e-3);
  // Per ray, rays below the horizon spread less than hit-or-miss over the hemisphere,
  // here where terrain fills half the view (on open slopes, far less).
  EXPECT_LT(spreadBelow, 0.75 * spreadHemisphere);
  std::printf("terrain view factor of %d posts: below the horizon %.4f, hemisphere %.4f; spread per ray %.3f "
              "against %.3f\n",
    posts, sumBelow / posts, sumHemisphere / posts, spreadBelow / posts, spreadHemisphere / posts);
}

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

// Two passes: every second lattice post first; the others only in the coarse cells
// whose corners disagree (relative to what each receives) or lack data, and at the far
// edges; a post reads between the corners of the finest cell gathered around it.
TEST(PostLattice, RefinesOnlyTheCellsWhoseCornersDisagree)
{
  // 21 x 17 posts, every 4th: lattice posts 0..5 x 0..4, coarse cells of 8 x 8 posts:
  // (0, 0), (1, 0) complete; the column at i = 16..20 lacks its far corners.
  PostLattice lattice(21, 17, 4);
  EXPECT_TRUE(lattice.gatheredInPass(8, 8, true));
  EXPECT_FALSE(lattice.gatheredInPass(4, 0, true));
  EXPECT_FALSE(lattice.gatheredInPass(8, 8, false));
  auto gathered = [](double reflected, double received) {
    PostLattice::Gathered g;
    g.reflected = uniformSpectrum(reflected);
    g.variance = 1.0;
    g.terrainSeen = 0.5;
    g.received = received;
    return g;
  };
  // Cell (0, 0): its corners find 10 and 10.2 W/m^2 per half of terrain seen, a spread
  // of 0.2 per 1 terrain seen, 0.1 at theirs: within 0.001 x their 200 W/m^2. Cell
  // (1, 0): 10 and 14.
  for (int j : { 0, 8, 16 })
    for (int i : { 0, 8, 16 })
      lattice.set(i, j, gathered(i == 16 ? 14.0 : (j == 8 ? 10.1 : 10.0), 200.0));
  lattice.refine(0.001);
  EXPECT_FALSE(lattice.gatheredInPass(4, 0, false));  // inside cell (0, 0) alone
  EXPECT_TRUE(lattice.gatheredInPass(12, 0, false));  // inside cell (1, 0)
  EXPECT_TRUE(lattice.gatheredInPass(8, 4, false));   // on their common side
  EXPECT_TRUE(lattice.gatheredInPass(20, 12, false)); // the edge column: always
  EXPECT_FALSE(lattice.gatheredInPass(4, 12, false)); // cell (0, 1) agrees too
  // Cell (0, 0) reads between its coarse corners: at (4, 4), the mean of 20, 20, 20.2,
  // 20.2 per terrain seen.
  PostLattice::PerTerrainSeen per;
  ASSERT_TRUE(lattice.perTerrainSeenAt(4.0, 4.0, per));
  EXPECT_DOUBLE_EQ(per.reflected[0], 0.5 * (20.0 + 20.2));
  EXPECT_DOUBLE_EQ(lattice.around(5, 5).largestPerTerrainSeen, 20.2);
  EXPECT_DOUBLE_EQ(lattice.around(5, 5).leastPerTerrainSeen, 20.0);
  // Cell (1, 0) reads between its lattice posts once the second pass has them.
  lattice.set(12, 0, gathered(12.0, 200.0));
  lattice.set(12, 4, gathered(12.0, 200.0));
  lattice.set(8, 4, gathered(10.0, 200.0));
  lattice.set(16, 4, gathered(14.0, 200.0));
  EXPECT_DOUBLE_EQ(lattice.around(13, 1).largestPerTerrainSeen, 28.0); // (16, 0), (16, 4)
  EXPECT_DOUBLE_EQ(lattice.around(13, 1).leastPerTerrainSeen, 24.0);  // (12, 0), (12, 4)
  Spectrum read;
  ASSERT_TRUE(lattice.reflectedAt(12.0, 2.0, read));
  EXPECT_DOUBLE_EQ(read[0], 12.0);
  // Refined too where a corner has no data.
  PostLattice holes(17, 17, 4);
  for (int j : { 0, 8, 16 })
    for (int i : { 0, 8, 16 })
      if (!(i == 16 && j == 16))
        holes.set(i, j, gathered(10.0, 200.0));
  holes.refine(0.001);
  EXPECT_FALSE(holes.gatheredInPass(4, 4, false));
  EXPECT_TRUE(holes.gatheredInPass(12, 12, false));
}

TEST(PostLattice, ReadsBetweenItsPostsAndTellsTheLargestSpreadAround)
{
  // 10 x 7 posts, every 4th: lattice posts at i = 0, 4, 8 and j = 0, 4.
  PostLattice lattice(10, 7, 4);
  EXPECT_TRUE(lattice.onLattice(8, 4));
  EXPECT_FALSE(lattice.onLattice(2, 4));
  EXPECT_EQ(lattice.varianceAround(5, 1), -1.0); // nothing gathered yet
  Spectrum read;
  EXPECT_FALSE(lattice.reflectedAt(5.0, 1.0, read));
  auto gathered = [](double reflected, double variance, double terrainSeen, double skyCorrection = 0.0) {
    PostLattice::Gathered g;
    g.reflected = uniformSpectrum(reflected);
    g.skyCorrection = uniformSpectrum(skyCorrection);
    g.skyViewCorrection = skyCorrection / 100.0;
    g.variance = variance;
    g.terrainSeen = terrainSeen;
    return g;
  };
  lattice.set(4, 0, gathered(10.0, 2.0, 0.1));
  lattice.set(8, 0, gathered(20.0, 5.0, 0.1, -1.0));
  lattice.set(4, 4, gathered(30.0, 1.0, 0.2));
  // (8, 4) has no data: the others share its weight.
  EXPECT_EQ(lattice.varianceAround(5, 1), 5.0);
  EXPECT_EQ(lattice.varianceAround(9, 6), 5.0); // beyond the last lattice post: its cell
  ASSERT_TRUE(lattice.reflectedAt(4.0, 0.0, read));
  EXPECT_DOUBLE_EQ(read[0], 10.0);
  ASSERT_TRUE(lattice.reflectedAt(6.0, 0.0, read));
  EXPECT_DOUBLE_EQ(read[0], 15.0);
  ASSERT_TRUE(lattice.reflectedAt(4.0, 2.0, read));
  EXPECT_DOUBLE_EQ(read[0], 20.0);
  // Near the post without data: from the others alone; at it, nothing.
  ASSERT_TRUE(lattice.reflectedAt(7.0, 3.0, read));
  EXPECT_GT(read[0], 10.0);
  EXPECT_LT(read[0], 30.0);
  EXPECT_FALSE(lattice.reflectedAt(8.0, 4.0, read));

  // Per terrain seen: (4, 0) found 10 / 0.1 = 100, (8, 0) (20 - 1) / 0.1 = 190, (4, 4)
  // 30 / 0.2 = 150: the spread around is 100 to 190.
  const PostLattice::Around around = lattice.around(5, 1);
  EXPECT_DOUBLE_EQ(around.largestPerTerrainSeen, 190.0);
  EXPECT_DOUBLE_EQ(around.leastPerTerrainSeen, 100.0);
  PostLattice::PerTerrainSeen per;
  ASSERT_TRUE(lattice.perTerrainSeenAt(6.0, 0.0, per));
  EXPECT_DOUBLE_EQ(per.reflected[0], 0.5 * (100.0 + 200.0));
  EXPECT_DOUBLE_EQ(per.skyCorrection[0], 0.5 * (0.0 - 10.0));
  EXPECT_DOUBLE_EQ(per.skyViewCorrection, 0.5 * (0.0 - 0.1));
  EXPECT_FALSE(lattice.perTerrainSeenAt(8.0, 4.0, per));
}
