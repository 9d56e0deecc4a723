// The error estimate of the values at points (PointIrradiance::irradianceError) and the
// hierarchy's deficit behind it (HierarchyDeficit), against closed forms.
#include "evaluation/final_gather.h"
#include "evaluation/leaf_gather.h"
#include "evaluation/point_evaluator.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "solver/solver.h"
#include "visibility/scene_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace terralux;
using namespace terralux_test;

namespace
{
// Inside a closed sphere of reflectance 0.8 and emission 20 W/m^2 every point receives
// B = 20 / (1 - 0.8) = 100 W/m^2 from surfaces, whatever its place.
constexpr double exactIrradiance = 100.0;

RadiosityScene closedSphere(double reflectance = 0.8)
{
  RadiosityScene scene;
  addInwardSphere(scene, 1.0, 12, 24, reflectance, 20.0);
  return scene;
}
} // namespace

TEST(IrradianceError, HoldsTheErrorInsideAClosedSphereAtAnyTolerance)
{
  const RadiosityScene scene = closedSphere();
  for (const int iterations : { 30, 3 }) // converged, and stopped early: a hierarchy far off
  {
    RadiosityOptions options;
    options.errorTolerance = 1e-2;
    options.maximumIterations = iterations;
    HierarchicalRadiosity solver(scene, options);
    ASSERT_TRUE(solver.solve());
    const PointEvaluator points(solver, EvaluationPlan{});
    int count = 0, covered = 0;
    std::vector<double> estimates;
    double largestError = 0.0;
    for (const PolygonElement* root : solver.polygonRoots())
    {
      const Vec3 p = root->centre();
      const PointIrradiance e = points.irradianceAt(*root->leafHolding(p), p);
      const double error = std::abs(e.irradiance[ReflectedLight][0] - exactIrradiance);
      ASSERT_TRUE(std::isfinite(e.irradianceError) && e.irradianceError >= 0.0);
      covered += error <= e.irradianceError;
      estimates.push_back(e.irradianceError);
      largestError = std::max(largestError, error);
      ++count;
    }
    std::sort(estimates.begin(), estimates.end());
    std::printf("%d iterations: largest error %.3f W/m^2, estimate holds it at %d of %d points, median %.3f\n",
      iterations, largestError, covered, count, estimates[estimates.size() / 2]);
    EXPECT_GE(covered, 0.9 * count) << iterations << " iterations";
    // And not far above it: the errors here are all alike (the hierarchy's, carried on).
    EXPECT_LE(estimates[estimates.size() / 2], 4.0 * largestError) << iterations << " iterations";
  }
}

TEST(IrradianceError, TheHierarchysDeficitIsMeasuredByGatheringOverIt)
{
  // Stopped after one iteration, the hierarchy holds emission plus a bounce or two: its
  // leaves' light from surfaces is well below 100 W/m^2. The probe's gathers find how far.
  const RadiosityScene scene = closedSphere();
  RadiosityOptions options;
  options.maximumIterations = 1;
  HierarchicalRadiosity solver(scene, options);
  ASSERT_TRUE(solver.solve());
  double held = 0.0, area = 0.0;
  for (PolygonElement* leaf : solver.surfaceLeaves())
  {
    held += leaf->area() * leaf->Irradiance[ReflectedLight][0];
    area += leaf->area();
  }
  const double trueDeficit = (exactIrradiance - held / area) / (held / area);
  ASSERT_GT(trueDeficit, 0.1);
  GatherInputs inputs{ solver.geometry()->pointRays(), solver.polygonRoots(), solver.terrainRoots(),
    solver.hierarchySuns() };
  const FinalGather gather(inputs);
  const LeafGather leaves(solver.surfaceLeaves(), solver.geometry()->hierarchyRays(), 256, true);
  const HierarchyDeficit deficit = HierarchyDeficit::measure(leaves, gather, 512);
  std::printf("deficit %.3f measured, %.3f true; bounce factor %.3f\n", deficit.relative, trueDeficit,
    deficit.bounceFactor);
  // Every hit is a lit surface of reflectance 0.8: each bounce carries 0.8 of the error on.
  EXPECT_NEAR(deficit.relative, trueDeficit, 0.3 * trueDeficit);
  EXPECT_NEAR(deficit.bounceFactor, 0.8, 0.02);
  EXPECT_LT(deficit.after(3), deficit.after(1));
}

TEST(IrradianceError, AGatheredBounceOverALightlessHierarchyErrsByWhatItBringsBack)
{
  // Leaves that hold no light from surfaces at all (R0 = 0) in a sphere of reflectance
  // 0.2: a bounce gathered over them finds the emission, R1 = 20, where 25 arrives, so
  // what it reads is 0.25 of itself off: the bounce factor's share, s / (1 - s), not the
  // bound for leaves that hold nothing (4, which made the estimates 16 times too wide).
  const RadiosityScene scene = closedSphere(0.2);
  HierarchicalRadiosity solver(scene, RadiosityOptions{});
  ASSERT_TRUE(solver.solve());
  for (PolygonElement* leaf : solver.surfaceLeaves())
    leaf->Irradiance[ReflectedLight] = Spectrum{};
  GatherInputs inputs{ solver.geometry()->pointRays(), solver.polygonRoots(), solver.terrainRoots(),
    solver.hierarchySuns() };
  const FinalGather gather(inputs);
  const LeafGather leaves(solver.surfaceLeaves(), solver.geometry()->hierarchyRays(), 256, true);
  const HierarchyDeficit deficit = HierarchyDeficit::measure(leaves, gather, 512);
  std::printf("after one bounce %.3f, bounce factor %.3f\n", deficit.after(1), deficit.bounceFactor);
  EXPECT_EQ(deficit.after(0), HierarchyDeficit::maximumRelative);
  EXPECT_NEAR(deficit.bounceFactor, 0.2, 0.01);
  EXPECT_NEAR(deficit.after(1), 0.25, 0.03);
}
