// Horizons walked over height fields (height_field_horizon.h), against closed forms and
// against Embree's rays, which know nothing of the walk: just above the horizon a ray
// escapes, just below it a ray is blocked.

#include "height_field_horizon.h"
#include "radiosity_types.h"
#include "sampling.h"
#include "terrain_grids.h"
#include "visibility.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

namespace
{
constexpr double pi = 3.14159265358979323846;
constexpr double degree = pi / 180.0;

double rough(double x, double y)
{
  return 60.0 * std::sin(x / 40.0) * std::cos(y / 55.0) + 25.0 * std::sin((x + 2.0 * y) / 23.0) +
    8.0 * std::sin(x / 7.0 + 1.3) * std::sin(y / 9.0);
}

struct Counts
{
  int blocked = 0, walks = 0;
};

// Every walk from `from` (the rays' own lifted start) toward 48 azimuths checked with
// two rays: `margin` below the horizon blocked, `margin` above it open.
Counts checkAgainstRays(const HeightFieldHorizon& horizon, const Visibility& rays, const Vec3& point, double margin)
{
  Counts counts;
  const Vec3 up(0, 0, 1), from = point + rays.offset() * up;
  for (int k = 0; k < 48; ++k)
  {
    const double phi = (k + 0.37) * 2.0 * pi / 48.0;
    const double dx = std::cos(phi), dy = std::sin(phi);
    const double tangent = horizon.tangentToward(from, dx, dy, 0.0);
    const double elevation = std::atan(tangent);
    auto toward = [&](double u) { return Vec3(std::cos(u) * dx, std::cos(u) * dy, std::sin(u)); };
    ++counts.walks;
    EXPECT_FALSE(rays.occludedToward(point, up, toward(elevation + margin)))
      << "above the horizon " << elevation / degree << " deg at azimuth " << phi / degree << " from " << point.x
      << " " << point.y;
    if (tangent > 0.0)
    {
      ++counts.blocked;
      EXPECT_TRUE(rays.occludedToward(point, up, toward(elevation - margin)))
        << "below the horizon " << elevation / degree << " deg at azimuth " << phi / degree << " from " << point.x
        << " " << point.y;
    }
  }
  return counts;
}

RadiosityScene sceneOf(const std::vector<const TerrainGrid*>& grids)
{
  RadiosityScene scene;
  scene.terrains = grids;
  return scene;
}
} // namespace

TEST(HeightFieldHorizon, WallAtADistanceIsSeenAtItsTangent)
{
  // Flat ground, and a 50 m wall (one 10 m cell wide) whose foot is at x = 690 m and
  // top at x = 700 m with a plateau behind: from (200, 500) its top edge is 500 m away
  // along x, 500 / cos(phi) along an oblique azimuth.
  const auto grid = makeGrid(101, 101, 10.0, [](double x, double) { return x >= 699.0 ? 50.0 : 0.0; });
  const HeightFieldHorizon horizon({ grid.get() });
  const Vec3 from(200.0, 500.0, 0.0);
  EXPECT_NEAR(horizon.tangentToward(from, 1.0, 0.0, 0.0), 0.1, 1e-9);
  for (double phi : { 20.0, -35.0 })
  {
    const double c = std::cos(phi * degree), s = std::sin(phi * degree);
    EXPECT_NEAR(horizon.tangentToward(from, c, s, 0.0), 0.1 * c, 1e-9) << phi;
  }
  // Away from the wall, nothing rises: the floor comes back.
  EXPECT_EQ(horizon.tangentToward(from, -1.0, 0.0, 0.0), 0.0);
  EXPECT_EQ(horizon.tangentToward(from, -0.6, 0.8, 0.02), 0.02);
  // From above the plateau the wall hides nothing.
  EXPECT_EQ(horizon.tangentToward(Vec3(200.0, 500.0, 60.0), 1.0, 0.0, 0.0), 0.0);
  // From beyond the grid's edge the walk enters it.
  EXPECT_NEAR(horizon.tangentToward(Vec3(-300.0, 500.0, 0.0), 1.0, 0.0, 0.0), 50.0 / 1000.0, 1e-9);
}

TEST(HeightFieldHorizon, AgreesWithRaysOnRoughTerrain)
{
  const auto grid = makeGrid(129, 129, 10.0, rough);
  ASSERT_TRUE(grid->facesUp());
  const HeightFieldHorizon horizon({ grid.get() });
  const Visibility rays(sceneOf({ grid.get() }));
  Counts total;
  SampleGenerator random(5);
  for (int k = 0; k < 40; ++k)
  {
    // Posts, and points between posts a few metres above the ground.
    const int i = 1 + static_cast<int>(126 * random.uniform()), j = 1 + static_cast<int>(126 * random.uniform());
    Vec3 point = grid->post(i, j);
    if (k % 2)
    {
      const TerrainPoint p = grid->surfacePoint(i + random.uniform(), j + random.uniform());
      point = p.position + Vec3(0, 0, 0.5 + 20.0 * random.uniform());
    }
    const Counts c = checkAgainstRays(horizon, rays, point, 0.02 * degree);
    total.blocked += c.blocked;
    total.walks += c.walks;
  }
  // Most directions of this terrain are blocked somewhere: the check is not vacuous.
  EXPECT_GT(total.blocked, total.walks / 2);
}

TEST(HeightFieldHorizon, NoDataTilesAndBentGridsAgreeWithRays)
{
  // Two tiles side by side, the second with a hole whose posts hold garbage (as the
  // scene sets non-finite posts), columns spaced unevenly by 1e-4 across the tile, as
  // a georeferenced grid bends.
  auto hole = [](int i, int j) { return !(i >= 20 && i < 34 && j >= 30 && j < 41); };
  const auto west = makeGrid(65, 97, 10.0, rough, [](int, int) { return true; },
    [](int i) { return 10.0 * i * (1.0 + 1e-6 * i); });
  const auto east = makeGrid(65, 97, 10.0, [](double x, double y) { return rough(x + 640.0, y); }, hole,
    [](int i) { return 640.0 + 10.0 * i * (1.0 + 1e-6 * i); });
  auto* eastGrid = const_cast<TerrainGrid*>(east.get());
  for (int j = 32; j < 40; ++j)
    for (int i = 22; i < 33; ++i)
      eastGrid->setPost(i, j, eastGrid->origin());
  ASSERT_TRUE(west->facesUp());
  ASSERT_TRUE(east->facesUp());
  const HeightFieldHorizon horizon({ west.get(), east.get() });
  const Visibility rays(sceneOf({ west.get(), east.get() }));
  Counts total;
  for (const Vec3& point : { west->post(40, 37), west->post(60, 50), east->post(5, 20), east->post(27, 25) })
  {
    const Counts c = checkAgainstRays(horizon, rays, point, 0.02 * degree);
    total.blocked += c.blocked;
    total.walks += c.walks;
  }
  EXPECT_GT(total.blocked, total.walks / 2);
}
