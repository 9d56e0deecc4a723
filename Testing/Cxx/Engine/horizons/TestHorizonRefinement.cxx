// A coarse horizon map refined at chosen posts (horizon_refinement.cxx): those posts'
// horizons toward the 16 azimuths the coarse map lacks are walked along their lines,
// and must be what the standard map's sweeps find, bit for bit; the others are
// interpolated and prove nothing.

#include "horizons/horizon_map.h"
#include "base/angles.h"
#include "base/error.h"
#include "terrain_grids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace terralux;
using namespace terralux_test;

namespace
{
// Rough hills at 10 m, with a hole of missing cells (the walk's checked crossings):
// walks toward open directions cross the whole grid, those toward a ridge end early.
std::unique_ptr<TerrainGrid> roughWithHole()
{
  auto grid = makeGrid(61, 53, 10.0, [](double x, double y) {
    return rollingHills(4.0 * x, 4.0 * y) + 20.0 * std::sin(0.09 * x) * std::cos(0.13 * y);
  });
  for (int j = 20; j < 26; ++j)
    for (int i = 30; i < 41; ++i)
      grid->setCellValid(i, j, false);
  return grid;
}
} // namespace

TEST(HorizonRefinement, WalkedPostsMatchTheStandardSweepsAndTheOthersInterpolate)
{
  for (const bool complete : { false, true })
  {
    auto grid = complete ? makeGrid(61, 53, 10.0, [](double x, double y) { return rollingHills(4.0 * x, 4.0 * y); })
                         : roughWithHole();
    const HorizonMap coarse(*grid, HorizonMap::Density::Coarse), standard(*grid);
    const std::size_t posts = static_cast<std::size_t>(grid->postsX()) * grid->postsY();
    std::vector<std::uint8_t> exact(posts, 0);
    for (std::size_t index = 0; index < posts; index += 3)
      exact[index] = 1;
    const HorizonMap refined(coarse, exact);
    ASSERT_EQ(refined.azimuthCount(), 32);
    EXPECT_EQ(refined.refinedPosts(), (posts + 2) / 3);
    int walkedDifferences = 0, interpolatedDifferences = 0, copiedDifferences = 0;
    const std::vector<double>& azimuths = refined.azimuths();
    for (std::size_t index = 0; index < posts; ++index)
    {
      const HorizonMap::Post post{ true, index };
      EXPECT_EQ(refined.exactAt(index), exact[index] != 0);
      for (int a = 0; a < 32; ++a)
      {
        EXPECT_EQ(refined.azimuths()[a], standard.azimuths()[a]);
        const double got = refined.elevation(post, a);
        if (a % 2 == 0) // the coarse map's azimuths (every other standard one), copied
          copiedDifferences += refined.trueElevation(post, a) != coarse.trueElevation(post, a / 2);
        else if (exact[index])
          walkedDifferences += got != standard.elevation(post, a);
        else
        {
          // Linear in azimuth between the coarse neighbours, to the map's quantum.
          const int below = a - 1, above = (a + 1) % 32;
          const double span = azimuths[above] - azimuths[below] + (above == 0 ? twoPi : 0.0);
          const double w = (azimuths[a] - azimuths[below]) / span;
          const double expected = (1.0 - w) * refined.elevation(post, below) + w * refined.elevation(post, above);
          interpolatedDifferences += std::abs(got - expected) > 2.5e-5;
        }
      }
    }
    EXPECT_EQ(copiedDifferences, 0) << complete;
    EXPECT_EQ(walkedDifferences, 0) << complete;
    EXPECT_EQ(interpolatedDifferences, 0) << complete;
  }
}

TEST(HorizonRefinement, OnlyWalkedPostsProveSights)
{
  // A 50 m wall along x = 300 m over flat ground: from a post west of it, a sun low in
  // the east is proven hidden at a walked post; at an interpolated one nothing is proven.
  const auto grid = makeGrid(41, 41, 10.0, [](double x, double) { return x >= 299.0 ? 50.0 : 0.0; });
  const HorizonMap coarse(*grid, HorizonMap::Density::Coarse);
  std::vector<std::uint8_t> exact(static_cast<std::size_t>(41 * 41), 0);
  const HorizonMap::Post walked = coarse.find(grid->post(10, 20)), interpolated = coarse.find(grid->post(10, 22));
  ASSERT_TRUE(walked && interpolated);
  exact[walked.index] = 1;
  const HorizonMap refined(coarse, exact);
  const HorizonMap::Sight low = refined.sight(0.0, 2.0 * degree), high = refined.sight(0.0, 30.0 * degree);
  HorizonMap::View walkedView(refined, walked), interpolatedView(refined, interpolated);
  EXPECT_TRUE(walkedView.clearlyBelow(low));
  EXPECT_TRUE(walkedView.clearlyAbove(high));
  EXPECT_FALSE(interpolatedView.clearlyBelow(low));
  EXPECT_FALSE(interpolatedView.clearlyAbove(high));
}

TEST(HorizonRefinement, OnlyACoarseMapOfEveryPostIsRefined)
{
  const auto grid = makeGrid(9, 9, 10.0, [](double, double) { return 0.0; });
  const HorizonMap coarse(*grid, HorizonMap::Density::Coarse), standard(*grid);
  EXPECT_THROW(HorizonMap(standard, std::vector<std::uint8_t>(81, 0)), Error);
  EXPECT_THROW(HorizonMap(coarse, std::vector<std::uint8_t>(80, 0)), Error);
  const HorizonMap refined(coarse, std::vector<std::uint8_t>(81, 1));
  EXPECT_THROW(HorizonMap(refined, std::vector<std::uint8_t>(81, 1)), Error);
}
