// The directions in which a post sees terrain (terrain_directions.h), against view
// factors over the hemisphere.

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
