// What a leaf receives, fitted across it from its points' gathers (leaf_light.h).
#include "evaluation/leaf_light.h"

#include <gtest/gtest.h>

using namespace terralux;

namespace
{
LeafLight::Sample sampleAt(const Vec3& p, double sky, double reflected)
{
  LeafLight::Sample s;
  s.point = p;
  for (int band = 0; band < maxBands; ++band)
    s.sky[band] = sky, s.reflected[band] = reflected;
  return s;
}
} // namespace

TEST(LeafLight, APlaneThroughItsPointsReadAtTheHitAndKeptWithinTheirRange)
{
  // A wall (normal +y) whose light grows with height, as at the foot of a shaded wall:
  // sky 10 + 4 z, reflected 20 + 8 z, sampled at four points.
  LeafLight light(10, { 3, 7 });
  std::vector<LeafLight::Sample> samples;
  for (double x : { 0.25, 0.75 })
    for (double z : { 0.25, 0.75 })
      samples.push_back(sampleAt(Vec3(x, 0.0, z), 10.0 + 4.0 * z, 20.0 + 8.0 * z));
  light.set(0, Vec3(0.0, 1.0, 0.0), samples);
  Spectrum sky, reflected;
  ASSERT_TRUE(light.at(3, Vec3(0.5, 0.0, 0.4), sky, reflected));
  EXPECT_NEAR(sky[0], 11.6, 1e-9);
  EXPECT_NEAR(reflected[2], 23.2, 1e-9);
  // Beyond the points (the wall's very foot): the lowest value they saw, not below.
  ASSERT_TRUE(light.at(3, Vec3(0.5, 0.0, 0.0), sky, reflected));
  EXPECT_NEAR(sky[0], 11.0, 1e-9);
  ASSERT_TRUE(light.mean(3, sky, reflected));
  EXPECT_NEAR(sky[1], 12.0, 1e-9);
  EXPECT_NEAR(reflected[1], 24.0, 1e-9);
  // A leaf gathered without any open point, and one not gathered: no values.
  light.set(1, Vec3(0.0, 1.0, 0.0), {});
  EXPECT_FALSE(light.at(7, Vec3(0.0), sky, reflected));
  EXPECT_FALSE(light.mean(5, sky, reflected));
  EXPECT_FALSE(light.at(100, Vec3(0.0), sky, reflected));
}

TEST(LeafLight, TwoPointsGiveTheirMean)
{
  // Too few points for a plane (or all on a line): the mean everywhere.
  LeafLight light(4, { 2 });
  light.set(0, Vec3(0.0, 0.0, 1.0), { sampleAt(Vec3(0.0, 0.0, 0.0), 10.0, 1.0), sampleAt(Vec3(1.0, 0.0, 0.0), 30.0, 3.0) });
  Spectrum sky, reflected;
  ASSERT_TRUE(light.at(2, Vec3(0.9, 0.0, 0.0), sky, reflected));
  EXPECT_DOUBLE_EQ(sky[0], 20.0);
  EXPECT_DOUBLE_EQ(reflected[0], 2.0);
}
