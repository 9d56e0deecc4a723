// Visibility (visibility.h) on its own: occlusion between points and toward infinity,
// the first surface met, ray offsets that follow the scene's size, seeds that do not
// move with the scene, and the ray counter.
#include "radiosity_scenes.h"
#include "visibility.h"

#include <gtest/gtest.h>

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
