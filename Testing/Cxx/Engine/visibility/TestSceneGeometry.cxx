// SceneGeometry (scene_geometry.h): the rays and horizons of a scene's shape, shared by
// solves over it. A second solve over the same shape (another sun, other materials)
// builds neither again and gives what a solver of its own gives, value for value; a
// scene of another shape gets geometry of its own.
#include "base/angles.h"
#include "sky/cie_sky.h"
#include "visibility/scene_geometry.h"
#include "sky/sky_hierarchy.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "terrain_grids.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

using namespace terralux;
using namespace terralux_test;

namespace
{
// Hills `height` m high (and a ridge 0.4 of that) over 10 m posts: gentle at 3 m, steep
// enough at 10 m that the coarse map's sky misses a few posts, at 30 m many.
std::unique_ptr<TerrainGrid> hillsOf(double height, double reflectance = 0.2)
{
  auto grid = makeGrid(41, 41, 10.0, Hills{ height, 40.0, 55.0, 0.4 * height, 23.0 });
  grid->setUniformMaterial(uniformSpectrum(reflectance), uniformSpectrum(0.0));
  return grid;
}

std::unique_ptr<TerrainGrid> hills(double reflectance)
{
  return hillsOf(30.0, reflectance);
}

struct Solved
{
  std::unique_ptr<HierarchicalRadiosity> solver;
  std::vector<PointIrradiance> posts;
  int horizonAzimuths = 0; // of the map the posts' skies came from
  std::size_t horizonRefinedPosts = 0;
};

// Sun from `azimuth` and a CIE clear sky; every 5th post evaluated as the filter does.
Solved solve(const TerrainGrid& grid, double azimuth, std::shared_ptr<SceneGeometry> geometry,
  double targetError = RadiosityOptions{}.targetError)
{
  static const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(50.0 * degree, 2.0)), 120.0, 6);
  RadiosityOptions options;
  options.errorTolerance = 1e-2;
  options.gatherSamples = 256;
  options.targetError = targetError;
  Solved result;
  result.solver = std::make_unique<HierarchicalRadiosity>(sceneOf(grid), options, std::move(geometry));
  const Direction sun = directionFromZenithAzimuth(50.0 * degree, azimuth);
  result.solver->addSun(Vec3(sun[0], sun[1], sun[2]), uniformSpectrum(800.0));
  result.solver->setSky(&sky);
  EXPECT_TRUE(result.solver->solve());
  const PointEvaluator points(*result.solver, EvaluationPlan{});
  const TerrainPatch& root = *result.solver->terrainRoots()[0];
  for (int j = 2; j < grid.postsY(); j += 5)
    for (int i = 2; i < grid.postsX(); i += 5)
    {
      const TerrainPatch* leaf = root.mostLitLeafAt(i, j);
      result.posts.push_back(points.irradianceAt(*leaf, grid.post(i, j), grid.postNormal(i, j)));
    }
  result.horizonAzimuths = points.statistics().horizonAzimuths;
  result.horizonRefinedPosts = points.statistics().horizonRefinedPosts;
  return result;
}
} // namespace

TEST(SceneGeometry, ASecondSolveOverTheSameShapeReusesRaysAndHorizonsAndAgreesExactly)
{
  const auto grid = hills(0.2);
  const Solved first = solve(*grid, 1.0, nullptr);
  const std::shared_ptr<SceneGeometry> geometry = first.solver->geometry();
  EXPECT_GT(first.solver->statistics().secondsVisibilityBuild, 0.0);

  // Another sun and another reflectance over a copy of the same terrain.
  const auto again = hills(0.35);
  const Solved reused = solve(*again, 4.0, geometry);
  const Solved fresh = solve(*again, 4.0, nullptr);
  EXPECT_EQ(reused.solver->geometry(), geometry);
  EXPECT_NE(fresh.solver->geometry(), geometry);
  EXPECT_EQ(reused.solver->statistics().secondsVisibilityBuild, 0.0);
  // Each solver counts its own rays, the same whether or not it built the geometry.
  EXPECT_EQ(reused.solver->raysCast(), fresh.solver->raysCast());
  ASSERT_EQ(reused.posts.size(), fresh.posts.size());
  double differs = 0.0;
  for (std::size_t k = 0; k < fresh.posts.size(); ++k)
    for (int c = 0; c < lightCategories; ++c)
    {
      EXPECT_EQ(reused.posts[k].irradiance[c][0], fresh.posts[k].irradiance[c][0]) << k << " " << c;
      differs = std::max(differs, std::abs(reused.posts[k].irradiance[c][0] - first.posts[k].irradiance[c][0]));
    }
  EXPECT_GT(differs, 1.0); // the second sun and reflectance did change the values
}

TEST(SceneGeometry, AnotherShapeGetsGeometryOfItsOwn)
{
  const auto grid = hills(0.2);
  const Solved first = solve(*grid, 1.0, nullptr);
  auto raised = hills(0.2);
  raised->setPost(20, 20, raised->post(20, 20) + Vec3(0.0, 0.0, 5.0));
  EXPECT_FALSE(first.solver->geometry()->sameShape(sceneOf(*raised), FarSight{}));
  EXPECT_TRUE(first.solver->geometry()->sameShape(sceneOf(*hills(0.5)), FarSight{}));
  // Seen from afar otherwise, its rays are others.
  EXPECT_FALSE(first.solver->geometry()->sameShape(sceneOf(*hills(0.5)), FarSight{ 4, 100.0 }));
  const Solved other = solve(*raised, 1.0, first.solver->geometry());
  EXPECT_NE(other.solver->geometry(), first.solver->geometry());
  EXPECT_GT(other.solver->statistics().secondsVisibilityBuild, 0.0);
}

TEST(SceneGeometry, TheKnobsCoarseEndMapsHorizonsCoarselyAndAFinerMapOnceBuiltServesIt)
{
  // From Tuning::coarseHorizonsTarget the posts' horizons are found toward 16
  // azimuths; a solve at the default then builds the map of 32, which serves both.
  const auto grid = hills(0.2);
  const Solved coarse = solve(*grid, 1.0, nullptr, 0.04);
  const std::shared_ptr<SceneGeometry> geometry = coarse.solver->geometry();
  const HorizonMap& coarseMap = geometry->horizons(0, HorizonMap::Density::Coarse);
  EXPECT_EQ(coarseMap.azimuthCount(), 16);
  const Solved standard = solve(*grid, 1.0, geometry);
  EXPECT_EQ(geometry->horizons(0, HorizonMap::Density::Standard).azimuthCount(), 32);
  EXPECT_EQ(geometry->horizons(0, HorizonMap::Density::Coarse).azimuthCount(), 32);
  // The sky at posts comes from their horizons alone: the coarse map's differs from
  // the standard one's, by little.
  ASSERT_EQ(coarse.posts.size(), standard.posts.size());
  double largest = 0.0, sum = 0.0;
  for (std::size_t k = 0; k < standard.posts.size(); ++k)
  {
    const double a = coarse.posts[k].irradiance[SkyLight][0], b = standard.posts[k].irradiance[SkyLight][0];
    largest = std::max(largest, std::abs(a - b) / b);
    sum += b;
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(largest, 0.04); // 2.3 %; the report holds it against the reference
  EXPECT_GT(sum, 0.0);
}

TEST(SceneGeometry, AtTheDefaultsACoarseMapServesWhereItsSkyMeetsEveryPostsTarget)
{
  // Gentle hills: the sky from 16 azimuths errs within every post's target, and the
  // standard map is never built. Steep ones (30 m of relief over 10 m posts): it
  // misses too many, and the standard map serves.
  const auto gentle = hillsOf(3.0);
  const Solved coarse = solve(*gentle, 1.0, nullptr);
  EXPECT_EQ(coarse.horizonAzimuths, 16);
  EXPECT_EQ(coarse.horizonRefinedPosts, 0u);
  const std::shared_ptr<SceneGeometry> geometry = coarse.solver->geometry();
  EXPECT_EQ(geometry->horizons(0, HorizonMap::Density::Coarse).azimuthCount(), 16);
  const Solved steep = solve(*hills(0.2), 1.0, nullptr);
  EXPECT_EQ(steep.horizonAzimuths, 32);
  EXPECT_EQ(steep.horizonRefinedPosts, 0u);
  // Once a standard map is built over the same geometry, the coarse one is still what
  // is judged: the values do not depend on what was built before.
  EXPECT_EQ(geometry->horizons(0, HorizonMap::Density::Standard).azimuthCount(), 32);
  const Solved again = solve(*gentle, 1.0, geometry);
  EXPECT_EQ(again.horizonAzimuths, 16);
  ASSERT_EQ(coarse.posts.size(), again.posts.size());
  for (std::size_t k = 0; k < again.posts.size(); ++k)
    ASSERT_EQ(again.posts[k].irradiance[SkyLight][0], coarse.posts[k].irradiance[SkyLight][0]) << "post " << k;
}

TEST(SceneGeometry, ACoarseMapMissingAFewPostsTargetsIsRefinedAtThoseAlone)
{
  // Hills between: the sky from 16 azimuths misses the target of a few posts (in the
  // hollows), whose horizons toward the other 16 of 32 are then walked. Elsewhere the
  // sky is the coarse map's, as at the knob's coarse end (no judgement there); where
  // it differs, by less than that end's error estimate.
  const auto grid = hillsOf(10.0);
  const Solved refined = solve(*grid, 1.0, nullptr);
  EXPECT_EQ(refined.horizonAzimuths, 16);
  EXPECT_GT(refined.horizonRefinedPosts, 0u);
  EXPECT_LT(refined.horizonRefinedPosts, 41u * 41u / 5u);
  const Solved coarseEnd = solve(*grid, 1.0, nullptr, 0.04);
  EXPECT_EQ(coarseEnd.horizonAzimuths, 16);
  ASSERT_EQ(coarseEnd.posts.size(), refined.posts.size());
  int differing = 0;
  for (std::size_t k = 0; k < refined.posts.size(); ++k)
  {
    const double a = refined.posts[k].irradiance[SkyLight][0], b = coarseEnd.posts[k].irradiance[SkyLight][0];
    EXPECT_LE(std::abs(a - b), coarseEnd.posts[k].irradianceError) << "post " << k;
    differing += a != b;
  }
  EXPECT_GT(differing, 0);
  EXPECT_LT(differing, static_cast<int>(refined.posts.size()) / 5);
}
