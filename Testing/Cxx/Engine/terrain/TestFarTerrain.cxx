// The hierarchy solved on the far terrain (RadiosityOptions::farTerrainStride with a
// gatherDetailDistance): its leaves are every 4th post's cells, while every post of the
// full grid is still evaluated, at points and averaged, once each, close to what the
// hierarchy on the full grid gives.
#include "base/angles.h"
#include "sky/cie_sky.h"
#include "terrain/far_terrain.h"
#include "evaluation/point_values.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "terrain_grids.h"
#include "hierarchy/terrain_patch.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

namespace
{
void expectEveryPostServed(bool withSky)
{
  // Rolling hills, 97 x 97 posts 30 m apart, under a sun and a clear sky.
  const auto grid = makeGrid(97, 97, 30.0, rollingHills);
  grid->setUniformMaterial(uniformSpectrum(0.2), Spectrum{});
  const Direction sun = directionFromZenithAzimuth(55.0 * degree, 2.0);
  const SkyHierarchy sky(CieGeneralSky(12, sun), 120.0, 6);
  // Without a sky the posts have no skies of their own: their gathers' hits on the
  // terrain then read leaves (of the far terrain's hierarchy) beyond their lattice.
  auto lit = [&](int stride) {
    RadiosityOptions options;
    options.gatherDetailDistance = 900.0;
    options.farTerrainStride = stride;
    auto solver = std::make_unique<HierarchicalRadiosity>(sceneOf(*grid), options);
    solver->addSun(Vec3(sun[0], sun[1], sun[2]), uniformSpectrum(800.0));
    if (withSky)
      solver->setSky(&sky);
    EXPECT_TRUE(solver->solve());
    auto points = std::make_unique<PointEvaluator>(*solver, EvaluationPlan{});
    return std::make_pair(std::move(solver), std::move(points));
  };
  const auto fullLit = lit(1), farLit = lit(4);
  const HierarchicalRadiosity *full = fullLit.first.get(), *far = farLit.first.get();
  const TerrainPatch& root = *far->terrainRoots()[0];
  ASSERT_NE(far->hierarchyTerrain(), nullptr);
  EXPECT_EQ(full->hierarchyTerrain(), nullptr);
  EXPECT_EQ(root.grid().postsX(), 25); // every 4th of 97
  EXPECT_EQ(&far->postGrid(root), grid.get());
  // Post (5, 7) lies in the far terrain's cell (1, 1); post (8, 12) is its post (2, 3).
  const TerrainPatch* inside = far->leafAtPost(root, 5, 7);
  ASSERT_NE(inside, nullptr);
  EXPECT_LE(inside->range().u0, 1.25);
  EXPECT_GE(inside->range().u1, 1.25);
  EXPECT_LE(inside->range().v0, 1.75);
  EXPECT_GE(inside->range().v1, 1.75);
  EXPECT_EQ(far->leafAtPost(root, 8, 12), root.mostLitLeafAt(2, 3));

  for (const bool atPoints : { true, false })
  {
    SCOPED_TRACE(atPoints ? "at points" : "averaged");
    PointEvaluation how;
    how.atPoints = atPoints;
    const int all[4] = { 0, 96, 0, 96 };
    std::vector<double> global[2];
    std::vector<int> seen(97 * 97, 0);
    for (int k = 0; k < 2; ++k)
    {
      const PointEvaluator& points = *(k == 0 ? fullLit : farLit).second;
      global[k].assign(97 * 97, std::nan(""));
      terrainPostValues(points, *points.solver().terrainRoots()[0], all, how, [&](std::size_t post, const PointValues& v) {
        seen[post] += k; // distinct posts only: no race
        global[k][post] = v.globalIrradiance()[0];
      });
    }
    double squares = 0.0;
    for (std::size_t p = 0; p < seen.size(); ++p)
    {
      ASSERT_EQ(seen[p], 1) << p;
      ASSERT_TRUE(std::isfinite(global[1][p])) << p;
      const double difference = (global[1][p] - global[0][p]) / global[0][p];
      squares += difference * difference;
    }
    const double rms = std::sqrt(squares / seen.size());
    // Measured: 2.3e-5 and 6.8e-4 with the sky, 4.0e-4 and 2.8e-3 under the sun alone.
    EXPECT_LT(rms, atPoints ? 0.002 : 0.01);
    EXPECT_GT(rms, 0.0); // the far terrain did change something
  }
}
} // namespace

TEST(FarTerrain, EveryPostOfTheFullGridIsServedAsTheFullHierarchyServesIt)
{
  expectEveryPostServed(true);
}

TEST(FarTerrain, AndSoUnderTheSunAlone)
{
  expectEveryPostServed(false);
}
