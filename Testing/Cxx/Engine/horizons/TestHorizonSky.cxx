// The sky a height field hides, from each point's horizon (horizon_sky.h), against
// closed forms and against brute-force rays.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "horizons/horizon_map.h"
#include "horizons/horizon_sky.h"
#include "horizons/post_sky.h"
#include "evaluation/open_sky.h"
#include "visibility/sampling.h"
#include "sky/sky_hierarchy.h"
#include "sky/sky_model.h"
#include "solver/solver.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace terralux;
using namespace terralux_test;

namespace
{

// Sky a plane of normal n at p does not receive because the scene is in the way, by
// brute force: stratified cosine-weighted rays, each blocked one hiding pi L(d) / N.
double hiddenByRays(const Visibility& rays, const OpenSky& sky, const Vec3& p, const Vec3& n, int side)
{
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 u = glm::normalize(glm::cross(a, n)), v = glm::cross(n, u);
  SampleGenerator random(7);
  double hidden = 0.0;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
    {
      const double s = (i + random.uniform()) / side, t = (j + random.uniform()) / side;
      const double r = std::sqrt(s), phi = 2.0 * pi * t;
      const Vec3 d = glm::normalize(r * std::cos(phi) * u + r * std::sin(phi) * v + std::sqrt(1.0 - s) * n);
      if (d.z > 0.0 && rays.occludedToward(p, n, d))
        hidden += pi * sky.radiance(d)[0];
    }
  return hidden / (side * side);
}

} // namespace

TEST(HorizonSky, OpenGroundHidesNothingForOneRayPerSector)
{
  const auto grid = makeGrid(21, 21, 10.0, [](double, double) { return 0.0; });
  const RadiosityScene scene = sceneOf(*grid);
  const Visibility rays(scene);
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(40.0 * degree, 2.0)), 100.0, 6);
  const OpenSky open(sky);
  const HorizonSky horizons(rays, open);
  const HiddenSky hidden = horizons.hiddenAt(Vec3(100, 100, 0), Vec3(0, 0, 1), 3);
  EXPECT_EQ(hidden.irradiance[0], 0.0);
  EXPECT_EQ(hidden.projectedSolidAngle, 0.0);
  EXPECT_EQ(hidden.rays, HorizonSky::sectors);
}

TEST(HorizonSky, VValleyBottomSeesCosOfItsSlope)
{
  // A valley 4 km long whose sides rise at `slope` to 50 m: a horizontal post on its
  // line sees the sky between two horizons at elevation `slope` (cos slope of a uniform
  // sky, in 2-D; the ends 2 km away add under 0.1 %).
  const SkyHierarchy sky(UniformSky(), 100.0, 6);
  const OpenSky open(sky);
  for (double slope : { 20.0, 40.0 })
  {
    const double half = 160.0;
    const auto grid = makeGrid(
      201, 161, 2.0, [&](double, double y) { return std::min(50.0, std::abs(y - half) * std::tan(slope * degree)); },
      [](int, int) { return true; }, [](int i) { return -2000.0 + 20.0 * i; });
    ASSERT_TRUE(grid->facesUp());
    const RadiosityScene scene = sceneOf(*grid);
    const Visibility rays(scene);
    const HorizonSky horizons(rays, open);
    for (std::uint64_t seed : { 1, 2, 3 })
    {
      const HiddenSky hidden = horizons.hiddenAt(Vec3(0, half, 0), Vec3(0, 0, 1), seed);
      EXPECT_NEAR(100.0 - hidden.irradiance[0], 100.0 * std::cos(slope * degree), 0.5) << slope;
      EXPECT_NEAR(1.0 - hidden.projectedSolidAngle / pi, std::cos(slope * degree), 0.005) << slope;
    }
  }
}

TEST(HorizonSky, ATiltedPlaneSeesTheVoidBelowTheHorizontalAndNoTerrain)
{
  // A post on a plane tilted by beta sees (1 + cos beta) / 2 of sky and (1 - cos beta)
  // / 2 below the horizontal, where every direction leaves the plane without meeting
  // it: void, no terrain. A V valley's bottom, level, sees none; a post on the edge of
  // a level grid none either (nothing of its view lies below the horizontal).
  const SkyHierarchy sky(UniformSky(), 100.0, 6);
  const OpenSky open(sky);
  for (double beta : { 10.0, 30.0 })
  {
    const double t = std::tan(beta * degree);
    const auto grid = makeGrid(81, 81, 10.0, [&](double x, double y) { return -t * (0.6 * x + 0.8 * y); });
    const RadiosityScene scene = sceneOf(*grid);
    const Visibility rays(scene);
    const HorizonMap map(*grid);
    const HorizonSky horizons(rays, open, &map);
    const HorizonMap::Post post = map.find(grid->post(40, 40));
    ASSERT_TRUE(post);
    const Vec3 normal = glm::normalize(Vec3(0.6 * t, 0.8 * t, 1.0));
    const PostSky::Value value = PostSky::at(post, normal, horizons, open);
    EXPECT_NEAR(value.voidViewFactor, 0.5 * (1.0 - std::cos(beta * degree)), 2e-3) << beta;
    EXPECT_NEAR(value.skyViewFactor, 0.5 * (1.0 + std::cos(beta * degree)), 2e-3) << beta;
    EXPECT_NEAR(value.terrainSeen(), 0.0, 3e-3) << beta;
  }
  const auto valley = makeGrid(81, 81, 10.0, [](double, double y) { return 0.5 * std::abs(y - 400.0); });
  const RadiosityScene scene = sceneOf(*valley);
  const Visibility rays(scene);
  const HorizonMap map(*valley);
  const HorizonSky horizons(rays, open, &map);
  for (const int i : { 40, 0 })
  {
    const HorizonMap::Post post = map.find(valley->post(i, 40));
    ASSERT_TRUE(post);
    EXPECT_EQ(horizons.voidAt(post, Vec3(0, 0, 1)), 0.0) << i;
  }
  // A post on the valley's side, 10 m from the bottom, on the side's plane: below the
  // horizontal toward the bottom the far side rises again, so its plane sees terrain
  // there, no void. Higher up the side, sights near the valley's line leave the grid's
  // ends before the bottom and see void (legitimately: nothing is there).
  const Vec3 sideNormal = glm::normalize(Vec3(0.0, -0.5, 1.0));
  const HorizonMap::Post low = map.find(valley->post(40, 41)), high = map.find(valley->post(40, 60));
  ASSERT_TRUE(low && high);
  EXPECT_EQ(horizons.voidAt(low, sideNormal), 0.0);
  EXPECT_GT(horizons.voidAt(high, sideNormal), 1e-3);
}

TEST(HorizonSky, TellsTheSectorsAPostSeesTerrainIn)
{
  // A V valley along x whose sides rise at slope 0.5. At its bottom, a level post sees
  // each side rise in every sector as the closed form says. On the side's own plane,
  // 10 m up, a post sees next to nothing above its plane on its own side (+y; a
  // sector's plane is taken at its middle), and across the valley the bottom below the
  // horizontal and the far side. Either way the sectors sum to the terrain it sees.
  const SkyHierarchy sky(UniformSky(), 100.0, 6);
  const OpenSky open(sky);
  const auto valley = makeGrid(81, 81, 10.0, [](double, double y) { return 0.5 * std::abs(y - 400.0); });
  const RadiosityScene scene = sceneOf(*valley);
  const Visibility rays(scene);
  const HorizonMap map(*valley);
  const HorizonSky horizons(rays, open, &map);
  auto sum = [](const PerViewPart<double>& parts) {
    double total = 0.0;
    for (const double s : parts)
      total += s;
    return total;
  };
  auto inSector = [](const PerViewPart<double>& parts, int q) {
    return parts[viewPartOf(q, false)] + parts[viewPartOf(q, true)];
  };
  EXPECT_EQ(sectorOf(1.0, 0.1), 0);
  EXPECT_EQ(sectorOf(0.1, 1.0), 1);
  EXPECT_EQ(sectorOf(-1.0, -0.1), 4);
  EXPECT_EQ(sectorOf(1.0, -0.1), 7);
  const HorizonMap::Post bottom = map.find(valley->post(40, 40));
  ASSERT_TRUE(bottom);
  const PerViewPart<double> level = horizons.terrainByPart(bottom, Vec3(0, 0, 1));
  EXPECT_NEAR(sum(level) / pi, PostSky::at(bottom, Vec3(0, 0, 1), horizons, open).terrainSeen(), 0.01);
  // Toward azimuth phi the far side stands at elevation h, tan h = 0.5 |sin phi|: the
  // sector's terrain is the integral of sin^2 h / 2 over it.
  for (int q = 0; q < viewSectors; ++q)
  {
    double expected = 0.0;
    const int steps = 1000;
    for (int k = 0; k < steps; ++k)
    {
      const double phi = (q + (k + 0.5) / steps) * 0.25 * pi, t2 = 0.25 * std::pow(std::sin(phi), 2);
      expected += 0.5 * t2 / (1.0 + t2) * 0.25 * pi / steps;
    }
    EXPECT_NEAR(inSector(level, q), expected, 0.05 * expected) << q;
    // The walls rise from the bottom at the horizon's own elevation: all of it near.
    EXPECT_LT(level[viewPartOf(q, true)], 1e-3 * expected) << q;
  }
  const Vec3 sideNormal = glm::normalize(Vec3(0.0, -0.5, 1.0));
  const HorizonMap::Post side = map.find(valley->post(40, 41));
  ASSERT_TRUE(side);
  const PerViewPart<double> sloped = horizons.terrainByPart(side, sideNormal);
  const double seen = PostSky::at(side, sideNormal, horizons, open).terrainSeen();
  ASSERT_GT(seen, 0.05);
  EXPECT_NEAR(sum(sloped) / pi, seen, 0.08 * seen); // a piece's terms averaged over 45 deg
  for (const double x : { 1.0, -1.0 })
  {
    EXPECT_LT(inSector(sloped, sectorOf(x, 0.1)) + inSector(sloped, sectorOf(0.1 * x, 1.0)), 0.01 * sum(sloped)) << x;
    EXPECT_GT(inSector(sloped, sectorOf(0.1 * x, -1.0)), 0.1 * sum(sloped)) << x;
  }
  // Across the valley (-y), 10 m down to the bottom and up the far side: within 40 m
  // (4 posts) the far side rises to tan 0.25 (10 m up at 40 m), beyond to tan 0.476
  // at the grid's edge. Toward -y alone the near band, from the plane (tan -0.5) to
  // atan 0.25, is 0.237 per radian of azimuth, the far band above it 0.135; the sector
  // from -y to the next diagonal sees its far side farther off (near 0.143, far 0.099).
  const int across = sectorOf(0.1, -1.0);
  EXPECT_GT(sloped[viewPartOf(across, false)], 1.2 * sloped[viewPartOf(across, true)]);
  EXPECT_GT(sloped[viewPartOf(across, true)], 0.5 * sloped[viewPartOf(across, false)]);
}

TEST(HorizonSky, AgreesWithBruteForceRaysOnRoughTerrainUnderAClearSky)
{
  // Ridges and bowls of about 45 deg, sun low over them (the bright circumsolar sky
  // near the horizons), posts on slopes facing every way.
  const auto grid = makeGrid(65, 65, 10.0, [](double x, double y) {
    return 60.0 * std::sin(x / 40.0) * std::cos(y / 55.0) + 25.0 * std::sin((x + 2.0 * y) / 23.0);
  });
  ASSERT_TRUE(grid->facesUp());
  const RadiosityScene scene = sceneOf(*grid);
  const Visibility rays(scene);
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(75.0 * degree, 1.0)), 100.0, 7);
  const OpenSky open(sky);
  const HorizonSky horizons(rays, open);
  // The same from the posts' horizons found all at once (horizon_map.h).
  const HorizonMap map(*grid);
  const HorizonSky mapped(rays, open, &map);
  int tested = 0;
  double sumSquares = 0.0, sumSquaresMapped = 0.0;
  for (int j = 8; j < 60; j += 9)
    for (int i = 8; i < 60; i += 9)
    {
      const Vec3 p = grid->post(i, j), n = grid->postNormal(i, j);
      const Vec3 from = p + 2.0 * rays.offset() * n;
      Spectrum plane;
      double omega = 0.0;
      open.irradiance(n, plane, omega);
      const double expected = hiddenByRays(rays, open, from, n, 256);
      const HiddenSky hidden = horizons.hiddenAt(from, n, 11 * i + j);
      // Relative to what the plane would see open: the noise of 65,536 rays is about
      // 0.1 % of it, the horizon's own error smaller.
      const double error = (hidden.irradiance[0] - expected) / plane[0];
      EXPECT_NEAR(error, 0.0, 0.01) << i << " " << j << ": " << hidden.irradiance[0] << " against " << expected;
      sumSquares += error * error;
      const HorizonMap::Post post = map.find(p);
      ASSERT_TRUE(post);
      const double mappedError = (mapped.hiddenAt(post, n).irradiance[0] - expected) / plane[0];
      EXPECT_NEAR(mappedError, 0.0, 0.01) << i << " " << j << " (map)";
      sumSquaresMapped += mappedError * mappedError;
      ++tested;
    }
  EXPECT_LT(std::sqrt(sumSquares / tested), 0.004);
  EXPECT_LT(std::sqrt(sumSquaresMapped / tested), 0.004);
  std::printf("hidden sky against brute force, RMS of the open sky: rays %.5f, map %.5f\n",
    std::sqrt(sumSquares / tested), std::sqrt(sumSquaresMapped / tested));
}

TEST(HorizonSky, FoldedGridsAndPolygonsKeepTheRays)
{
  // A grid whose cells face down somewhere is not a height field.
  const auto folded = makeGrid(5, 5, 1.0, [](double, double) { return 0.0; }, [](int, int) { return true; },
    [](int i) { return i == 2 ? 5.0 : 1.0 * i; });
  EXPECT_FALSE(folded->facesUp());
  const auto plain = makeGrid(5, 5, 1.0, [](double x, double) { return 0.3 * x; });
  EXPECT_TRUE(plain->facesUp());
}
