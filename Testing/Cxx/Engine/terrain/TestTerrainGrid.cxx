// The terrain grid (terrain_grid.h, paper section 4): its surface, normals and posts.
#include "terrain_patch_checks.h"
#include "sky/sky_hierarchy.h"
#include "base/angles.h"
#include "solver/solver.h"
#include "hierarchy/terrain_edges.h"
#include "terrain_grids.h"
#include "terrain/terrain_mesh.h"
#include "hierarchy/terrain_patch.h"

#include "sky/cie_sky.h"
#include "radiosity_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <iterator>
#include <random>

using namespace terralux;
using namespace terralux_test;

TEST(TerrainGrid, SurfaceOfATiltedPlane)
{
  const double a = 0.3, b = -0.2, spacing = 10.0;
  const auto grid = makeGrid(6, 5, spacing, [&](double x, double y) { return a * x + b * y; });
  const Vec3 normal = glm::normalize(Vec3(-a, -b, 1.0));
  const TerrainRangeSummary all = grid->summarize(0, 0, 5, 4);
  EXPECT_NEAR(all.area, 50.0 * 40.0 * std::sqrt(1.0 + a * a + b * b), 1e-6);
  EXPECT_NEAR(glm::dot(glm::normalize(all.areaVector), normal), 1.0, 1e-12);
  EXPECT_EQ(all.validCells, 20u);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 5.0), v(0.0, 4.0);
  for (int k = 0; k < 100; ++k)
  {
    const double pu = u(random), pv = v(random);
    const TerrainPoint p = grid->surfacePoint(pu, pv);
    EXPECT_NEAR(p.position.x, spacing * pu, 1e-4);
    EXPECT_NEAR(p.position.y, spacing * pv, 1e-4);
    EXPECT_NEAR(p.position.z, a * p.position.x + b * p.position.y, 1e-4);
    EXPECT_NEAR(glm::dot(p.normal, normal), 1.0, 1e-6);
  }
  EXPECT_EQ(grid->surfacePoint(3.0, 2.0).position, grid->post(3, 2)); // posts exactly
  EXPECT_NEAR(glm::dot(grid->postNormal(0, 0), normal), 1.0, 1e-6);
  EXPECT_NEAR(glm::dot(grid->postNormal(3, 2), normal), 1.0, 1e-6);
}

// A post's normal is that of the triangles that have it as a corner, area-weighted:
// checked against their area vectors found one by one from the cells' triangles, on
// rough terrain, at inner posts, at edges and corners, and next to a missing cell.
TEST(TerrainGrid, PostNormalsAreTheAreaWeightedNormalsOfTheirTriangles)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> rough(-15.0, 15.0);
  std::vector<double> heights(7 * 6);
  for (double& h : heights)
    h = rough(random);
  const auto grid = makeGrid(
    7, 6, 10.0, [&](double x, double y) { return heights[static_cast<std::size_t>(std::lround(y / 10.0) * 7 + std::lround(x / 10.0))]; },
    [](int i, int j) { return !(i == 4 && j == 3); });
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 7; ++i)
    {
      Vec3 sum(0.0);
      for (int cj = std::max(0, j - 1); cj <= std::min(j, 4); ++cj)
        for (int ci = std::max(0, i - 1); ci <= std::min(i, 5); ++ci)
          if (grid->cellValid(ci, cj))
            for (const TerrainGrid::Triangle& t : grid->cellTriangles(ci, cj))
              if (std::find(t.begin(), t.end(), grid->post(i, j)) != t.end())
                sum += TerrainGrid::areaVector(t);
      const Vec3 expected = glm::normalize(sum), normal = grid->postNormal(i, j);
      EXPECT_NEAR(glm::length(normal - expected), 0.0, 1e-12) << "post " << i << ", " << j;
    }
}
