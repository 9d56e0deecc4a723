// Final gather at points (final_gather.h): light from surfaces and the sky hidden from
// a point, against closed forms and the leaves gathered first.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "evaluation/final_gather.h"
#include "evaluation/open_sky.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "visibility/sampling.h"
#include "sky/sky_hierarchy.h"
#include "evaluation/sky_importance.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

TEST(FinalGather, ClosedBoxReadsItsRadiosityAtCornersEdgesAndFaces)
{
  // Inward cube, emission 100, reflectance 0.5: B = 200 and E = 200 everywhere, the
  // points users read included (corners and edges are where links saw edge-on walls).
  RadiosityScene scene;
  addInwardCube(scene, 1.0, 0.5, 100.0);
  HierarchicalRadiosity solver(scene, RadiosityOptions{});
  ASSERT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  const PolygonElement& floor = *solver.polygonRoots()[0];
  for (const Vec3& p : { Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0.5, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0.1, 0.9, 0) })
  {
    const PolygonElement& leaf = *floor.leafHolding(p);
    const PointIrradiance e = points.irradianceAt(leaf, p);
    EXPECT_NEAR(e.irradiance[ReflectedLight][0], 200.0, 2.0) << p.x << " " << p.y;
  }
}

TEST(FinalGather, OpenGroundTakesTheFewestRaysAndThePitMore)
{
  // Work follows the scene: a post that sees nothing but sky needs only the pilots'
  // verdicts (of the sky's rays and of the surfaces' rays) and the fewest rays of each
  // (skyMinimum for the sky's); the floor of a pit needs many more, and its sky there
  // is the open cone's.
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(40.0 * degree, 2.0)), 100.0, 6);
  const OpenSky open(sky);
  RadiosityScene scene;
  addPit(scene, 1.0, 1.0, 48, 0.3);
  const Visibility rays(scene);
  const std::vector<PolygonElement*> none;
  const std::vector<TerrainPatch*> noTerrain;
  const std::vector<HElement*> noSun;
  GatherInputs inputs{ rays, none, noTerrain, noSun };
  inputs.sky = &open;
  const FinalGather gather(inputs);
  const GatherBudget budget;
  const GatheredLight high = gather.irradianceAt(Vec3(5, 5, 0.0), Vec3(0, 0, 1), budget, 1, 0.0);
  EXPECT_EQ(high.rays, 2 * budget.pilot + budget.skyMinimum + budget.minimum);
  EXPECT_NEAR(high.sky[0], 100.0, 0.1);
  EXPECT_DOUBLE_EQ(high.skyViewFactor, 1.0);
  const GatheredLight floor = gather.irradianceAt(Vec3(0, 0, -1), Vec3(0, 0, 1), budget, 1, 0.0);
  EXPECT_GT(floor.rays, 5 * high.rays / 2);
  // The pit's opening is a cone of half-angle 45 deg: sky view factor sin^2 45 deg.
  EXPECT_NEAR(floor.skyViewFactor, 0.5, 0.02);
}

TEST(FinalGather, PointsOfOpenGroundTakeTheFewestRays)
{
  // Open flat ground under a clear sky: its points take the fewest rays (the pilots',
  // then 256 drawn by the sky's radiance and 64 for the surfaces); the sky there is
  // still exact. Only over a height field does a leaf the solution found open skip the
  // pilots: with buildings, a tree or a house the leaf's links missed may hide a few
  // percent of the sky.
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(40.0 * degree, 2.0)), 100.0, 6);
  RadiosityScene scene;
  addPolygon(scene, { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 } }, 0.2);
  HierarchicalRadiosity solver(scene, RadiosityOptions{});
  solver.setSky(&sky);
  ASSERT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  const PolygonElement& ground = *solver.polygonRoots()[0];
  const Vec3 p(1.0, 2.0, 0.0);
  const std::uint64_t before = solver.raysCast();
  const PointIrradiance open = points.irradianceAt(*ground.leafHolding(p), p);
  const GatherBudget defaults;
  // Besides, 36 probes of the point's open side (PointEvaluator::openSideOf).
  EXPECT_EQ(solver.raysCast() - before, 2u * defaults.pilot + defaults.skyMinimum + defaults.minimum + 36u);
  EXPECT_NEAR(open.irradiance[SkyLight][0], 100.0, 0.1);
  // Beside a wall the leaf is not open: a pilot and more rays.
  RadiosityScene walled;
  addWallOnGround(walled, 10.0, 10.0, 3.0, 0.2);
  HierarchicalRadiosity beside(walled, RadiosityOptions{});
  beside.setSky(&sky);
  ASSERT_TRUE(beside.solve());
  const Vec3 q(0.0, 0.5, 0.0);
  const PolygonElement& floor = *beside.polygonRoots()[0];
  const PointEvaluator besidePoints(beside, EvaluationPlan{});
  const std::uint64_t start = beside.raysCast();
  besidePoints.irradianceAt(*floor.leafHolding(q), q);
  EXPECT_GT(beside.raysCast() - start, 2u * (2u * defaults.pilot + defaults.skyMinimum + defaults.minimum));
}

TEST(FinalGather, AWallHidingTheBrightSkyNearTheSunIsFound)
{
  // North of a wall 3 m tall, a low sun behind it: the wall hides the bright sky around
  // the sun. Cosine-weighted rays saw it with one ray of 64 or none (posts off by 10 %
  // either way); rays drawn by the sky's radiance find it within 1 % of the open sky.
  RadiosityScene scene;
  addWallOnGround(scene, 20.0, 40.0, 3.0, 0.0);
  const Visibility rays(scene);
  const std::vector<PolygonElement*> none;
  const std::vector<TerrainPatch*> noTerrain;
  const std::vector<HElement*> noSun;
  for (double azimuth : { 0.0, pi })
  {
    const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(70.0 * degree, azimuth)), 100.0, 7);
    const OpenSky open(sky);
    GatherInputs inputs{ rays, none, noTerrain, noSun };
    inputs.sky = &open;
    const FinalGather gather(inputs);
    const Vec3 n(0, 0, 1);
    for (const Vec3& p : { Vec3(0.0, 2.0, 0.0), Vec3(4.0, 4.0, 0.0), Vec3(-3.0, 1.0, 0.0) })
    {
      const Vec3 from = p + 3.0 * rays.offset() * n;
      Spectrum plane;
      double omega = 0.0;
      open.irradiance(n, plane, omega);
      // By brute force: 65,536 stratified cosine-weighted rays.
      constexpr int side = 256;
      const CosineFrame frame(n);
      SampleGenerator random(3);
      double hidden = 0.0;
      for (int k = 0; k < side * side; ++k)
      {
        double s, t;
        stratifiedPoint(k, side * side, random, s, t);
        const Vec3 d = frame.direction(s, t);
        if (rays.occludedToward(from, n, d))
          hidden += pi * open.radiance(d)[0];
      }
      const double expected = plane[0] - hidden / (side * side);
      EXPECT_GT(plane[0] - expected, 0.05 * plane[0]); // the wall hides a good part of it
      const GatheredLight light = gather.irradianceAt(from, n, GatherBudget{}, 17, 0.0);
      EXPECT_NEAR(light.sky[0], expected, 0.01 * plane[0]) << azimuth << " " << p.x << " " << p.y;
    }
  }
}

TEST(FinalGather, LeavesGatheredFirstBringTheBoxOneBounceCloser)
{
  // Inward cube, emission 100, reflectance 0.5: E = 200 everywhere. A hit sends
  // emission + 0.5 x its leaf's irradiance: from the hierarchy, whose links each carry
  // a bounded error, or gathered at the leaf first (gatherLeaves), which halves that
  // error at every point (one more bounce of reflectance 0.5).
  // Each face of 8 x 8 cells, each two triangles (as vtkTessellatedBoxSource makes).
  RadiosityScene scene;
  const Vec3 corners[6][3] = { { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 } }, { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 } },
    { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 } }, { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 } }, { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } } };
  constexpr int cells = 8;
  for (const auto& face : corners)
    for (int i = 0; i < cells; ++i)
      for (int j = 0; j < cells; ++j)
      {
        // origin + a-step x i + b-step x j; a x b points into the cube.
        const Vec3 o = face[0], a = face[2] / double(cells), b = face[1] / double(cells);
        const Vec3 p00 = o + double(i) * a + double(j) * b, p10 = p00 + a, p01 = p00 + b, p11 = p00 + a + b;
        addPolygon(scene, { p00, p10, p11 }, 0.5, 100.0);
        addPolygon(scene, { p00, p11, p01 }, 0.5, 100.0);
      }
  RadiosityOptions options;
  HierarchicalRadiosity solver(scene, options);
  ASSERT_TRUE(solver.solve());
  // Points of the floor's triangles (the first 128 polygons): corners, edges, inside.
  auto meanError = [&](const PointEvaluator& points) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < 2 * cells * cells; k += 7)
    {
      const PolygonElement& cell = *solver.polygonRoots()[k];
      for (const Vec3& p : { cell.centre(), scene.points[scene.polygons[k].vertices[0]] })
      {
        const double e = points.irradianceAt(*cell.leafHolding(p), p).irradiance[ReflectedLight][0] - 200.0;
        sum += e;
        ++count;
      }
    }
    return sum / count;
  };
  EvaluationPlan hierarchyValues;
  hierarchyValues.leavesGathered = false;
  const double fromHierarchy = meanError(PointEvaluator(solver, hierarchyValues));
  const double fromLeaves = meanError(PointEvaluator(solver, EvaluationPlan{}));
  std::printf("box: mean error %.3f W/m^2 from the hierarchy, %.3f from the leaves\n", fromHierarchy, fromLeaves);
  // (The hierarchy's leaves hold 3.6 % too much here, 0.25 % at tolerance 1e-2: its
  // links overcount the exchange between small triangles; found, not yet fixed.)
  EXPECT_LT(std::abs(fromLeaves), 0.6 * std::abs(fromHierarchy));
}

TEST(FinalGather, ABrightStripAPilotMissesStillSetsThePointsRays)
{
  // Dark ground beside a long dark wall whose top, 12-15 m up, sends 200 W/m^2: from
  // 1.5 m off the wall's foot that strip is 1.2 % of the view (0.5 (d / sqrt(d^2 + 144)
  // - d / sqrt(d^2 + 225))), which a pilot of 64 rays misses half the time, and then
  // took as few rays as it saw spread. The solved links see the strip: every point takes
  // the rays its spread needs, about 480 at an aim of 1 W/m^2, whatever its pilot met.
  RadiosityScene scene;
  addPolygon(scene, { { -100, -20, 0 }, { 100, -20, 0 }, { 100, 0, 0 }, { -100, 0, 0 } }, 0.0);
  addPolygon(scene, { { -100, 0, 0 }, { 100, 0, 0 }, { 100, 0, 12 }, { -100, 0, 12 } }, 0.0);
  addPolygon(scene, { { -100, 0, 12 }, { 100, 0, 12 }, { 100, 0, 15 }, { -100, 0, 15 } }, 0.0, 200.0);
  HierarchicalRadiosity solver(scene, RadiosityOptions{});
  ASSERT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  const PolygonElement& ground = *solver.polygonRoots()[0];
  const double d = 1.5, exact = 200.0 * 0.5 * (d / std::sqrt(d * d + 144.0) - d / std::sqrt(d * d + 225.0));
  const GatherBudget defaults;
  double sum = 0.0;
  int count = 0;
  for (double x = -40.0; x <= 40.0; x += 10.0, ++count)
  {
    const Vec3 p(x, -d, 0.0);
    const std::uint64_t before = solver.raysCast();
    const PointIrradiance e = points.irradianceAt(*ground.leafHolding(p), p);
    EXPECT_GE(solver.raysCast() - before, static_cast<std::uint64_t>(defaults.pilot + 400)) << x;
    sum += e.irradiance[ReflectedLight][0];
  }
  // Each point's estimate has 40 % noise at that count: their mean is within 25 %.
  EXPECT_NEAR(sum / count, exact, 0.25 * exact);
}

TEST(FinalGather, TheSkyAndTheSurfacesByRaysMeetTheTargetTogether)
{
  // Beside a wall that sends light and hides much of a clear sky, a point's hidden sky
  // and its light from surfaces are both sampled by rays, and both add to its global.
  // Each aiming at the whole target left the sum's standard error up to sqrt 2 x the
  // target; the sky now takes half the target's variance and the surfaces what it
  // leaves, so together they are within it (the rays' own variance estimates scatter a
  // little about the pilots' that set the counts).
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(50.0 * degree, 1.0)), 100.0, 6);
  const OpenSky open(sky);
  RadiosityScene scene;
  addPolygon(scene, { { -50, -20, 0 }, { 50, -20, 0 }, { 50, 0, 0 }, { -50, 0, 0 } }, 0.0);
  addPolygon(scene, { { -50, 0, 0 }, { 50, 0, 0 }, { 50, 0, 6 }, { -50, 0, 6 } }, 0.0, 100.0);
  HierarchicalRadiosity solver(scene, RadiosityOptions{});
  ASSERT_TRUE(solver.solve());
  const Visibility rays(scene);
  const std::vector<TerrainPatch*> noTerrain;
  const std::vector<HElement*> noSun;
  GatherInputs inputs{ rays, solver.polygonRoots(), noTerrain, noSun };
  inputs.sky = &open;
  const FinalGather gather(inputs);
  GatherBudget budget;
  budget.relativeError = 0.0;
  budget.absoluteError = 1.0; // W/m^2, one standard error
  budget.maximum = 1 << 16;
  double worst = 0.0;
  for (double d : { 1.0, 2.0, 4.0 })
    for (std::uint64_t seed = 1; seed <= 4; ++seed)
    {
      const Vec3 n(0, 0, 1), p(3.0 * seed, -d, 3.0 * rays.offset());
      const GatheredLight light = gather.irradianceAt(p, n, budget, seed, 0.0);
      ASSERT_GT(light.count, budget.minimum) << d; // the surfaces' rays set by the aim
      EXPECT_LT(light.sky[0], 0.9 * 100.0) << d;    // the wall hides a good part of the sky
      worst = std::max(worst, light.standardError / budget.absoluteError);
    }
  EXPECT_LT(worst, 1.15);
  EXPECT_GT(worst, 0.7); // the aim is what sets the rays, not a floor of them
}
