// A grid's cell sums kept per block (terrain_block_sums.h): any range's summary equals
// the grid's own pass over its cells, to the rounding of a different order of sums.
#include "terrain_grids.h"
#include "terrain/terrain_block_sums.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace terralux;
using namespace terralux_test;

namespace
{
void expectSameSummary(const TerrainRangeSummary& blocks, const TerrainRangeSummary& cells)
{
  const double tolerance = 1e-12 * std::max(1.0, cells.area);
  EXPECT_NEAR(blocks.area, cells.area, tolerance);
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_NEAR(blocks.areaVector[axis], cells.areaVector[axis], tolerance);
    EXPECT_EQ(blocks.low[axis], cells.low[axis]); // extremes, in any order
    EXPECT_EQ(blocks.high[axis], cells.high[axis]);
  }
  EXPECT_EQ(blocks.cells, cells.cells);
  EXPECT_EQ(blocks.validCells, cells.validCells);
  for (int band = 0; band < maxBands; ++band)
  {
    EXPECT_NEAR(blocks.reflectance[band], cells.reflectance[band], 1e-12);
    EXPECT_NEAR(blocks.emission[band], cells.emission[band], 1e-12);
  }
}
} // namespace

// Rough terrain whose sides are no multiple of a block, with holes and a material per
// cell: whole blocks, borders, ranges inside one block, single cells, empty ranges.
TEST(TerrainBlockSums, AnyRangeSumsAsTheGridItselfDoes)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto grid = makeGrid(
    75, 58, 30.0, [&](double, double) { return 400.0 * unit(random); },
    [](int i, int j) { return (i * 7 + j * 3) % 23 != 0; });
  for (int j = 0; j < grid->cellsY(); ++j)
    for (int i = 0; i < grid->cellsX(); ++i)
      grid->setCellMaterial(i, j, uniformSpectrum(0.1 + 0.8 * unit(random)), uniformSpectrum(unit(random)));
  const TerrainBlockSums sums(*grid);
  const int nx = grid->cellsX(), ny = grid->cellsY();
  expectSameSummary(sums.summarize(0, 0, nx, ny), grid->summarize(0, 0, nx, ny));
  expectSameSummary(sums.summarize(16, 16, 48, 48), grid->summarize(16, 16, 48, 48));
  expectSameSummary(sums.summarize(3, 5, 4, 6), grid->summarize(3, 5, 4, 6));
  expectSameSummary(sums.summarize(20, 20, 20, 30), grid->summarize(20, 20, 20, 30)); // empty
  std::uniform_int_distribution<int> x(0, nx), y(0, ny);
  for (int k = 0; k < 200; ++k)
  {
    int i0 = x(random), i1 = x(random), j0 = y(random), j1 = y(random);
    if (i0 > i1)
      std::swap(i0, i1);
    if (j0 > j1)
      std::swap(j0, j1);
    SCOPED_TRACE(testing::Message() << "[" << i0 << ", " << i1 << ") x [" << j0 << ", " << j1 << ")");
    expectSameSummary(sums.summarize(i0, j0, i1, j1), grid->summarize(i0, j0, i1, j1));
  }
}

// A grid smaller than a block has no whole block: every range is summed from its cells.
TEST(TerrainBlockSums, AGridSmallerThanABlockSumsItsCells)
{
  auto grid = makeGrid(6, 4, 10.0, [](double x, double y) { return 0.3 * x - 0.2 * y; });
  const TerrainBlockSums sums(*grid);
  expectSameSummary(sums.summarize(0, 0, 5, 3), grid->summarize(0, 0, 5, 3));
  expectSameSummary(sums.summarize(1, 1, 3, 2), grid->summarize(1, 1, 3, 2));
}

// The bounds of the valid cells' posts, as the summary's; none where no cell is valid.
TEST(TerrainBlockSums, ValidBoundsAreTheSummarysBounds)
{
  auto grid = makeGrid(
    40, 33, 25.0, [](double x, double y) { return 50.0 * std::sin(x / 90.0) + 0.1 * y; },
    [](int i, int j) { return i > 2 || j > 4; });
  Vec3 low, high;
  ASSERT_TRUE(grid->validBounds(low, high));
  const TerrainRangeSummary all = grid->summarize(0, 0, grid->cellsX(), grid->cellsY());
  EXPECT_EQ(low, all.low);
  EXPECT_EQ(high, all.high);
  auto holes = makeGrid(5, 5, 10.0, [](double, double) { return 0.0; }, [](int, int) { return false; });
  EXPECT_FALSE(holes->validBounds(low, high));
}
