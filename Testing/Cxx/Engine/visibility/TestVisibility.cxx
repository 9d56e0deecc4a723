// Visibility (visibility.h) on its own: occlusion between points and toward infinity,
// the first surface met, ray offsets that follow the scene's size, seeds that do not
// move with the scene, and the ray counter.
#include "base/error.h"
#include "radiosity_scenes.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <limits>

using namespace terralux;
using namespace terralux_test;

namespace
{
// A 2 x 2 roof at height 1 over the origin (facing down) and a 10 x 10 ground at 0
// (facing up), offset by `shift`.
RadiosityScene roofOverGround(const Vec3& shift = Vec3(0.0))
{
  RadiosityScene scene;
  addPolygon(scene, { shift + Vec3(-1, -1, 1), shift + Vec3(-1, 1, 1), shift + Vec3(1, 1, 1), shift + Vec3(1, -1, 1) },
    0.5);
  addPolygon(scene,
    { shift + Vec3(-5, -5, 0), shift + Vec3(5, -5, 0), shift + Vec3(5, 5, 0), shift + Vec3(-5, 5, 0) }, 0.5);
  return scene;
}
const Vec3 up(0.0, 0.0, 1.0), down(0.0, 0.0, -1.0);
} // namespace

TEST(Visibility, SegmentsAreBlockedExactlyWhereTheRoofIs)
{
  const Visibility rays(roofOverGround());
  // Ground point under the roof to a point above it: through the roof.
  EXPECT_TRUE(rays.occluded(Vec3(0.0, 0.0, 0.0), up, Vec3(0.0, 0.0, 3.0), down));
  // Beside the roof, the same segment is clear.
  EXPECT_FALSE(rays.occluded(Vec3(3.0, 0.0, 0.0), up, Vec3(3.0, 0.0, 3.0), down));
  // From the ground to the roof's own underside: the ends are lifted off their
  // surfaces, so a surface does not hide itself.
  EXPECT_FALSE(rays.occluded(Vec3(0.2, 0.1, 0.0), up, Vec3(0.0, 0.0, 1.0), down));
  // Just inside and just outside the roof's edge (x = 1) on a slanted segment.
  EXPECT_TRUE(rays.occluded(Vec3(0.9, 0.0, 0.0), up, Vec3(0.9, 0.0, 2.0), down));
  EXPECT_FALSE(rays.occluded(Vec3(1.1, 0.0, 0.0), up, Vec3(1.1, 0.0, 2.0), down));
}

TEST(Visibility, RaysTowardInfinityAndTheFirstHit)
{
  const Visibility rays(roofOverGround());
  EXPECT_TRUE(rays.occludedToward(Vec3(0.0, 0.0, 0.0), up, up));
  EXPECT_FALSE(rays.occludedToward(Vec3(2.0, 0.0, 0.0), up, up));
  // 45 degrees toward -x from x = 1.5 meets the roof (x = 0.5 at z = 1); toward +x it escapes.
  const Vec3 towardMinusX = glm::normalize(Vec3(-1.0, 0.0, 1.0));
  EXPECT_TRUE(rays.occludedToward(Vec3(1.5, 0.0, 0.0), up, towardMinusX));
  EXPECT_FALSE(rays.occludedToward(Vec3(1.5, 0.0, 0.0), up, glm::normalize(Vec3(1.0, 0.0, 1.0))));

  SurfaceHit hit;
  ASSERT_TRUE(rays.firstHit(Vec3(1.5, 0.0, 0.0), up, towardMinusX, hit));
  EXPECT_EQ(hit.polygon, 0);
  EXPECT_EQ(hit.terrain, -1);
  // The ray starts lifted by offset() along the normal, so at 45 degrees it meets the
  // roof that much further along x.
  EXPECT_NEAR(hit.point.x, 0.5, 2.0 * rays.offset());
  EXPECT_NEAR(hit.point.z, 1.0, 1e-6); // Embree's single precision
  EXPECT_NEAR(std::abs(hit.normal.z), 1.0, 1e-9);
  // Down from above the roof: the roof's top (its back) is met first, then nothing below it.
  ASSERT_TRUE(rays.firstHit(Vec3(0.0, 0.0, 2.0), up, down, hit));
  EXPECT_EQ(hit.polygon, 0);
  ASSERT_TRUE(rays.firstHit(Vec3(3.0, 0.0, 2.0), up, down, hit));
  EXPECT_EQ(hit.polygon, 1);
  EXPECT_NEAR(hit.point.z, 0.0, 1e-4);
  EXPECT_FALSE(rays.firstHit(Vec3(3.0, 0.0, 0.0), up, up, hit));
}

TEST(Visibility, OffsetsFollowTheSceneAndSeedsDoNotMoveWithIt)
{
  const Visibility here(roofOverGround());
  const Visibility far(roofOverGround(Vec3(1e7, -3e6, 250.0)));
  // 1e-5 of the bounding diagonal (10 x 10 x 1).
  EXPECT_NEAR(here.offset(), 1e-5 * std::sqrt(201.0), 1e-12);
  EXPECT_NEAR(far.offset(), here.offset(), 1e-12);
  const Vec3 p(0.3, -0.7, 0.0);
  EXPECT_EQ(here.seedOf(p), far.seedOf(p + Vec3(1e7, -3e6, 250.0)));
  EXPECT_NE(here.seedOf(p), here.seedOf(p + Vec3(10.0 * here.offset(), 0.0, 0.0)));
  // The same queries give the same answers far from the origin.
  EXPECT_TRUE(far.occludedToward(Vec3(1e7, -3e6, 250.0), up, up));
  EXPECT_FALSE(far.occludedToward(Vec3(1e7 + 2.0, -3e6, 250.0), up, up));
}

TEST(Visibility, CountsEveryRay)
{
  const Visibility rays(roofOverGround());
  const std::uint64_t before = rays.raysCast();
  for (int k = 0; k < 10; ++k)
    rays.occludedToward(Vec3(0.1 * k, 0.0, 0.0), up, up);
  SurfaceHit hit;
  rays.firstHit(Vec3(3.0, 0.0, 2.0), up, down, hit);
  rays.occluded(Vec3(0.0, 0.0, 0.0), up, Vec3(0.0, 0.0, 3.0), down);
  EXPECT_EQ(rays.raysCast() - before, 12u);
}

namespace
{
// 2 km of flat ground, 201 x 201 posts 10 m apart, with a 100 m wall one post thick
// along row 133 and a 50 m deep valley one post wide along row 102: neither lies on a
// row of every 4th post, so the far terrain at stride 4 has no wall and no valley.
TerrainGrid wallAndValley()
{
  TerrainGrid grid(201, 201, Vec3(0.0));
  for (int j = 0; j < 201; ++j)
    for (int i = 0; i < 201; ++i)
      grid.setPost(i, j, Vec3(10.0 * i, 10.0 * j, j == 133 ? 100.0 : j == 102 ? -50.0 : 0.0));
  return grid;
}
RadiosityScene sceneOf(const TerrainGrid& grid)
{
  RadiosityScene scene;
  scene.terrains.push_back(&grid);
  return scene;
}
Vec3 atElevation(double degrees, const Vec3& horizontal)
{
  const double e = degrees * 3.14159265358979 / 180.0;
  return glm::normalize(std::cos(e) * glm::normalize(horizontal) + Vec3(0.0, 0.0, std::sin(e)));
}
} // namespace

TEST(Visibility, BeyondTheDetailDistanceRaysSeeTheFarTerrain)
{
  const TerrainGrid grid = wallAndValley();
  const Visibility fine(sceneOf(grid));
  const Visibility near(sceneOf(grid), FarSight{ 4, 1500.0 });
  const Visibility farFromWall(sceneOf(grid), FarSight{ 4, 300.0 });
  ASSERT_NE(near.farTerrain(), nullptr);
  EXPECT_EQ(near.farTerrain()->grid().postsX(), 51);
  // No far terrain for stride 1 or without a distance.
  EXPECT_EQ(Visibility(sceneOf(grid), FarSight{ 1, 300.0 }).farTerrain(), nullptr);
  EXPECT_EQ(Visibility(sceneOf(grid), FarSight{ 4, 0.0 }).farTerrain(), nullptr);

  // From post (100, 80), 530 m from the wall, 5 degrees up toward it: within 1.5 km the
  // wall is the fine one and blocks; beyond 300 m the far terrain has none.
  const Vec3 post(1000.0, 800.0, 0.0), towardWall = atElevation(5.0, Vec3(0.0, 1.0, 0.0));
  EXPECT_TRUE(fine.occludedToward(post, up, towardWall));
  EXPECT_TRUE(near.occludedToward(post, up, towardWall));
  EXPECT_FALSE(farFromWall.occludedToward(post, up, towardWall));
  const Vec3 beyondWall = post + 1000.0 * towardWall;
  EXPECT_TRUE(near.occluded(post, up, beyondWall, down));
  EXPECT_FALSE(farFromWall.occluded(post, up, beyondWall, down));
  SurfaceHit hit;
  ASSERT_TRUE(near.firstHit(post, up, towardWall, hit));
  EXPECT_FALSE(hit.far);
  EXPECT_NEAR(hit.v, 133.0, 1.0);

  // Down onto the ground 1 km away (tan 0.2 from 200 m up): a far hit, its parameters
  // the fine grid's at the point met, facing up.
  const Vec3 high(1000.0, 200.0, 200.0), down20 = glm::normalize(Vec3(0.0, 1.0, -0.2));
  ASSERT_TRUE(farFromWall.firstHit(high, up, down20, hit));
  EXPECT_TRUE(hit.far);
  EXPECT_EQ(hit.terrain, 0);
  EXPECT_NEAR(hit.point.y, 1200.0, 0.2); // from 200 m and one offset up
  EXPECT_NEAR(hit.u, hit.point.x / 10.0, 1e-3);
  EXPECT_NEAR(hit.v, hit.point.y / 10.0, 1e-3);
  EXPECT_NEAR(std::abs(hit.normal.z), 1.0, 1e-6);
  // The same ray within the detail distance is a fine hit at the same place.
  SurfaceHit fineHit;
  ASSERT_TRUE(near.firstHit(high, up, down20, fineHit));
  EXPECT_FALSE(fineHit.far);
  EXPECT_NEAR(fineHit.v, hit.v, 1e-3);
  // A far hit's own rays see the far terrain alone: from the ground beside the wall,
  // straight over it, nothing is in the way.
  EXPECT_TRUE(near.occludedToward(Vec3(1000.0, 1300.0, 0.0), up, towardWall));
  EXPECT_FALSE(near.farRays().occludedToward(Vec3(1000.0, 1300.0, 0.0), up, towardWall));
  EXPECT_EQ(&fine.farRays(), &fine);

  // Along the valley floor, 3 degrees up: within 1.5 km the ray rises out of the fine
  // valley; beyond 300 m it is under the far terrain (which spans the valley at 0 m),
  // inside it, and stops at its surface above.
  const Vec3 floor(200.0, 1020.0, -50.0), alongValley = atElevation(3.0, Vec3(1.0, 0.0, 0.0));
  EXPECT_FALSE(fine.occludedToward(floor, up, alongValley));
  EXPECT_FALSE(near.occludedToward(floor, up, alongValley));
  EXPECT_FALSE(near.firstHit(floor, up, alongValley, hit));
  EXPECT_TRUE(farFromWall.occludedToward(floor, up, alongValley));
  ASSERT_TRUE(farFromWall.firstHit(floor, up, alongValley, hit));
  EXPECT_TRUE(hit.far);
  EXPECT_NEAR(hit.point.x, 200.0 + 300.0, 0.1);
  EXPECT_NEAR(hit.point.z, 0.0, 1e-3);
  EXPECT_NEAR(hit.v, 102.0, 1e-3);

  // A ray is one ray, whichever terrains it meets, counted once for both.
  const std::uint64_t before = farFromWall.raysCast();
  farFromWall.occludedToward(post, up, towardWall);
  farFromWall.firstHit(high, up, down20, hit);
  farFromWall.farRays().occludedToward(hit.point, hit.normal, up);
  EXPECT_EQ(farFromWall.raysCast() - before, 3u);
  EXPECT_EQ(farFromWall.farRays().raysCast(), farFromWall.raysCast());
}

TEST(Visibility, TheFarTerrainHasNoCellOverAHole)
{
  TerrainGrid grid = wallAndValley();
  grid.setCellValid(57, 21, false);
  const FarTerrain far(grid, 4);
  EXPECT_EQ(far.grid().postsX(), 51);
  EXPECT_FALSE(far.grid().cellValid(14, 5)); // spans fine cells 56..59 x 20..23
  EXPECT_TRUE(far.grid().cellValid(13, 5));
  EXPECT_TRUE(far.grid().cellValid(14, 6));
  // 7 posts at stride 4: 0, 4, 6 (the last kept); parameters map back linearly.
  const FarTerrain odd(TerrainGrid(7, 7, Vec3(0.0)), 4);
  EXPECT_EQ(odd.grid().postsX(), 3);
  EXPECT_DOUBLE_EQ(odd.fineU(1.5), 5.0);
  EXPECT_DOUBLE_EQ(odd.fineU(0.25), 1.0);
  EXPECT_THROW(FarTerrain(grid, 1), Error);
  // A stride past the grid keeps its corners: one cell.
  const FarTerrain corners(grid, std::numeric_limits<int>::max());
  EXPECT_EQ(corners.grid().postsX(), 2);
  EXPECT_DOUBLE_EQ(corners.fineU(0.5), 100.0);
}
