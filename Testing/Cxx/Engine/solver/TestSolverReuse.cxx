// A solver used again (HierarchicalRadiosity::clearSources, solve): new sources over
// the same hierarchy and geometry give, value for value, what a new solver gives them,
// whatever the earlier solves refined; the hierarchy as built (a terrain's structural
// patches around missing cells included) survives them.
#include "base/angles.h"
#include "sky/cie_sky.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "terrain_grids.h"
#include "hierarchy/terrain_patch.h"

#include <gtest/gtest.h>

using namespace terralux;
using namespace terralux_test;

namespace
{
struct Sources
{
  double sunAzimuth;
  double sunZenith;
  std::unique_ptr<SkyHierarchy> sky; // null: sun alone
};

Sources sources(double zenith, double azimuth, bool sky)
{
  const Direction sun = directionFromZenithAzimuth(zenith * degree, azimuth);
  return { azimuth, zenith * degree, sky ? std::make_unique<SkyHierarchy>(CieGeneralSky(12, sun), 120.0, 6) : nullptr };
}

void light(HierarchicalRadiosity& solver, const Sources& with)
{
  const Direction sun = directionFromZenithAzimuth(with.sunZenith, with.sunAzimuth);
  solver.addSun(Vec3(sun[0], sun[1], sun[2]), uniformSpectrum(800.0));
  solver.setSky(with.sky.get());
}

// Everything a user reads: the statistics, each element's radiosity, and points.
struct Values
{
  std::size_t elements = 0, links = 0;
  std::uint64_t rays = 0;
  std::vector<double> numbers;
  bool operator==(const Values& other) const
  {
    return this->elements == other.elements && this->links == other.links && this->rays == other.rays &&
      this->numbers == other.numbers; // bitwise
  }
};

void addPoint(Values& values, const PointIrradiance& at)
{
  for (const Spectrum& category : at.irradiance)
    values.numbers.push_back(largestBand(category));
  values.numbers.push_back(at.skyViewFactor);
}

// Every 4th post of the terrain, evaluated as the filter does.
Values solveTerrain(HierarchicalRadiosity& solver, const TerrainGrid& grid)
{
  EXPECT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  const TerrainPatch& root = *solver.terrainRoots()[0];
  Values values;
  for (int j = 1; j < grid.postsY(); j += 4)
    for (int i = 1; i < grid.postsX(); i += 4)
      if (const TerrainPatch* leaf = root.mostLitLeafAt(i, j))
        addPoint(values, points.irradianceAt(*leaf, grid.post(i, j), grid.postNormal(i, j)));
  values.elements = solver.statistics().elements;
  values.links = solver.statistics().links;
  values.rays = solver.raysCast();
  return values;
}

// The element radiosities and points across the wall's foot.
Values solvePolygons(HierarchicalRadiosity& solver)
{
  EXPECT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  Values values;
  for (const auto& element : solver.elements().all())
    for (double b : element->Radiosity)
      values.numbers.push_back(b);
  const PolygonElement& ground = *solver.polygonRoots()[0];
  for (double y = -2.0; y <= 2.0; y += 0.5)
  {
    const Vec3 point(0.3, y, 0.0);
    addPoint(values, points.irradianceAt(*ground.leafHolding(point), point));
  }
  values.elements = solver.statistics().elements;
  values.links = solver.statistics().links;
  values.rays = solver.raysCast();
  return values;
}

RadiosityOptions options()
{
  RadiosityOptions result;
  result.errorTolerance = 3e-3;
  result.gatherSamples = 256;
  return result;
}
} // namespace

TEST(SolverReuse, NewSourcesOverATerrainGiveWhatANewSolverGives)
{
  // Hills with a missing patch: the hierarchy holds structural patches around it.
  const auto grid = makeGrid(
    41, 41, 10.0,
    [](double x, double y) { return 30.0 * std::sin(x / 40.0) * std::cos(y / 55.0) + 9.0 * std::sin((x + 2.0 * y) / 23.0); },
    [](int i, int j) { return !(i > 25 && i < 31 && j > 8 && j < 13); });
  const Sources morning = sources(60.0, 1.4, true), noon = sources(25.0, 3.1, true);

  HierarchicalRadiosity used(sceneOf(*grid), options());
  light(used, morning);
  const Values first = solveTerrain(used, *grid);
  const std::size_t refined = used.elements().size();
  used.clearSources();
  EXPECT_LT(used.elements().size(), refined); // what refinement made is gone
  light(used, noon);
  const Values again = solveTerrain(used, *grid);
  EXPECT_EQ(used.statistics().secondsVisibilityBuild, 0.0); // nor were rays built again

  HierarchicalRadiosity fresh(sceneOf(*grid), options());
  light(fresh, noon);
  const Values expected = solveTerrain(fresh, *grid);
  ASSERT_FALSE(expected.numbers.empty());
  EXPECT_TRUE(again == expected);
  EXPECT_FALSE(first == expected); // the sun did move

  // The sun alone after a sky: none of the sky's horizons or lattice stay behind.
  const Sources sunAlone = sources(25.0, 3.1, false);
  used.clearSources();
  light(used, sunAlone);
  const Values withoutSky = solveTerrain(used, *grid);
  HierarchicalRadiosity freshSun(sceneOf(*grid), options());
  light(freshSun, sunAlone);
  EXPECT_TRUE(withoutSky == solveTerrain(freshSun, *grid));
}

TEST(SolverReuse, PolygonsSolvedAgainAgreeBitForBit)
{
  RadiosityScene scene;
  addWallOnGround(scene, 6.0, 8.0, 3.0, 0.5);
  const Sources low = sources(70.0, 0.3, false), high = sources(35.0, 2.8, true);

  HierarchicalRadiosity used(scene, options());
  light(used, high);
  const Values first = solvePolygons(used);
  // The same sources solved again: the same values, not those of a finer hierarchy.
  EXPECT_TRUE(solvePolygons(used) == first);
  used.clearSources();
  light(used, low);
  const Values sunAlone = solvePolygons(used);
  used.clearSources();
  light(used, high);
  EXPECT_TRUE(solvePolygons(used) == first);

  HierarchicalRadiosity fresh(scene, options());
  light(fresh, low);
  EXPECT_TRUE(solvePolygons(fresh) == sunAlone);
}

TEST(SolverReuse, WithoutSourcesNothingIsLit)
{
  RadiosityScene scene;
  addWallOnGround(scene, 6.0, 8.0, 3.0, 0.5);
  HierarchicalRadiosity solver(scene, options());
  const Sources high = sources(35.0, 2.8, true);
  light(solver, high);
  ASSERT_TRUE(solver.solve());
  solver.clearSources();
  ASSERT_TRUE(solver.solve());
  const Vec3 point(0.3, 1.0, 0.0);
  const PointIrradiance at = PointEvaluator(solver, EvaluationPlan{}).irradianceAt(*solver.polygonRoots()[0]->leafHolding(point), point);
  for (const Spectrum& category : at.irradiance)
    EXPECT_EQ(largestBand(category), 0.0);
  EXPECT_EQ(at.skyViewFactor, 0.0);
}
