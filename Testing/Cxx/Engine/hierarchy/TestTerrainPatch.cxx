// Terrain patches (terrain_patch.h, paper section 4.2): splitting, holes, and a
// terrain solved with them against closed forms and the triangle path.
#include "terrain_patch_checks.h"
#include "sky/sky_hierarchy.h"
#include "base/angles.h"
#include "evaluation/point_evaluator.h"
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

namespace
{
RadiosityOptions terrainOptions(double tolerance)
{
  RadiosityOptions options;
  options.errorTolerance = tolerance;
  options.visibilitySamples = 4;
  return options;
}

// Sun and uniform sky at every post of `grid` selected by `where`, through irradianceAt.
template <typename Check>
void forEachPost(HierarchicalRadiosity& solver, const TerrainGrid& grid, Check check)
{
  const PointEvaluator points(solver, EvaluationPlan{});
  const TerrainPatch* root = solver.terrainRoots()[0];
  for (int j = 0; j < grid.postsY(); ++j)
    for (int i = 0; i < grid.postsX(); ++i)
    {
      const TerrainPatch* leaf = root->leafHolding(i, j);
      ASSERT_NE(leaf, nullptr) << i << ", " << j;
      check(i, j, points.irradianceAt(*leaf, grid.post(i, j), grid.postNormal(i, j)));
    }
}
} // namespace

TEST(TerrainPatch, SplitRanges)
{
  using R = std::array<double, 4>;
  auto split = [](const ParameterRange& r) {
    std::vector<R> out;
    for (const ParameterRange& c : TerrainPatch::splitRange(r))
      out.push_back({ c.u0, c.v0, c.u1, c.v1 });
    return out;
  };
  EXPECT_EQ(split({ 0, 0, 5, 3 }), (std::vector<R>{ { 0, 0, 2, 1 }, { 2, 0, 5, 1 }, { 2, 1, 5, 3 }, { 0, 1, 2, 3 } }));
  EXPECT_EQ(split({ 4, 0, 5, 3 }), (std::vector<R>{ { 4, 0, 5, 1 }, { 4, 1, 5, 3 } }));
  EXPECT_EQ(split({ 2, 2, 3, 3 }),
    (std::vector<R>{ { 2, 2, 2.5, 2.5 }, { 2.5, 2, 3, 2.5 }, { 2.5, 2.5, 3, 3 }, { 2, 2.5, 2.5, 3 } }));
}

TEST(TerrainPatch, TrueAreaNormalAndBoundsOfAHill)
{
  const auto grid = makeGrid(17, 17, 10.0, [](double x, double y) {
    return 60.0 * std::exp(-((x - 80) * (x - 80) + (y - 80) * (y - 80)) / (2 * 30.0 * 30.0));
  });
  ElementStore store;
  std::vector<TerrainPatch*> complete;
  TerrainPatch* root = TerrainPatch::buildTree(store, *grid, 0, complete);
  ASSERT_EQ(complete.size(), 1u);
  ASSERT_EQ(complete[0], root);
  // The coarse quad is the flat square of the corner posts; the patch keeps the hill's area and height.
  EXPECT_GT(root->area(), 160.0 * 160.0 * 1.02);
  EXPECT_NEAR(root->normal().z, 1.0, 1e-9); // symmetric hill: the mean normal is up
  EXPECT_GT(root->unalignedArea(), 0.01 * root->area());
  Vec3 low, high;
  root->bounds(low, high);
  EXPECT_NEAR(high.z, 60.0, 1e-3);
  // Samples lie on the hill, not on the coarse quad.
  SampleGenerator random(7);
  for (int k = 0; k < 16; ++k)
  {
    const SurfaceSample s = root->sample(k, 16, random);
    const double u = s.position.x / 10.0, v = s.position.y / 10.0;
    EXPECT_NEAR(s.position.z, grid->surfacePoint(u, v).position.z, 1e-3);
  }
  // Children: the four quadrants, whose areas add up to the parent's.
  double sum = 0.0;
  for (HElement* c : root->children())
    sum += c->area();
  EXPECT_NEAR(sum, root->area(), 1e-6 * root->area());
}

TEST(TerrainPatch, HolesSplitUntilTheValidPartIsRepresented)
{
  // 8 x 8 cells without the 2 x 3 cells [3, 5) x [2, 5).
  auto hole = [](int i, int j) { return i >= 3 && i < 5 && j >= 2 && j < 5; };
  const auto grid = makeGrid(9, 9, 10.0, [](double x, double) { return 0.1 * x; }, [&](int i, int j) { return !hole(i, j); });
  ElementStore store;
  std::vector<TerrainPatch*> complete;
  TerrainPatch* root = TerrainPatch::buildTree(store, *grid, 0, complete);
  ASSERT_NE(root, nullptr);
  EXPECT_FALSE(root->complete());
  double area = 0.0;
  for (TerrainPatch* p : complete)
  {
    EXPECT_TRUE(p->complete());
    area += p->area();
    const ParameterRange& r = p->range();
    for (int j = static_cast<int>(r.v0); j < r.v1; ++j)
      for (int i = static_cast<int>(r.u0); i < r.u1; ++i)
        EXPECT_FALSE(hole(i, j)) << "patch over the hole at " << i << ", " << j;
  }
  EXPECT_NEAR(area, 58 * 100.0 * std::sqrt(1.01), 1e-6);
  // A grid with no valid cell has no tree.
  const auto empty = makeGrid(3, 3, 1.0, [](double, double) { return 0.0; }, [](int, int) { return false; });
  complete.clear();
  EXPECT_EQ(TerrainPatch::buildTree(store, *empty, 1, complete), nullptr);
  EXPECT_TRUE(complete.empty());
}

TEST(TerrainPatch, FlatAndTiltedPlanesAgainstClosedForms)
{
  const double radiance = 30.0, sunFlux = 900.0;
  const SkyHierarchy sky(UniformSky(), pi * radiance, 7);
  const Vec3 sun = glm::normalize(Vec3(0.2, -0.4, 0.7));
  for (double slope : { 0.0, 30.0 })
  {
    const double t = std::tan(slope * degree);
    const auto grid = makeGrid(33, 33, 10.0, [&](double, double y) { return t * y; });
    RadiosityScene scene;
    scene.terrains.push_back(grid.get());
    HierarchicalRadiosity solver(scene, terrainOptions(2e-4));
    solver.addSun(sun, uniformSpectrum(sunFlux));
    solver.setSky(&sky);
    ASSERT_TRUE(solver.solve());
    // Lazy: at a coarse tolerance a plane's patches stay far larger than its cells; all
    // elements (sky patches and clusters too) are fewer than a quarter of the 2048
    // triangles the plain path starts from.
    HierarchicalRadiosity coarse(scene, terrainOptions(1e-2));
    coarse.addSun(sun, uniformSpectrum(sunFlux));
    ASSERT_TRUE(coarse.solve());
    EXPECT_LT(coarse.statistics().elements, 2048u / 4u);
    const Vec3 normal = glm::normalize(Vec3(0.0, -t, 1.0));
    const double expectedSun = sunFlux * glm::dot(normal, sun);
    const double expectedSky = pi * radiance * (1.0 + std::cos(slope * degree)) / 2.0;
    forEachPost(solver, *grid, [&](int i, int j, const PointIrradiance& e) {
      // A plane neither shadows nor lights itself, however coarse its patches.
      EXPECT_NEAR(e.irradiance[SunLight][0], expectedSun, 1e-6 * sunFlux) << slope << " at " << i << ", " << j;
      EXPECT_NEAR(e.irradiance[SkyLight][0] / expectedSky, 1.0, 0.01) << slope << " at " << i << ", " << j;
      EXPECT_NEAR(e.irradiance[ReflectedLight][0], 0.0, 1e-9);
    });
    // The leaves' own sky view factor (what interpolated outputs use).
    const TerrainLeafMesh leaves(*solver.terrainRoots()[0]);
    for (const TerrainPatch* leaf : leaves.leaves())
      EXPECT_NEAR(leaf->SkyViewFactor, (1.0 + std::cos(slope * degree)) / 2.0, 0.01) << slope;
  }
}

TEST(TerrainPatch, GaussianHillAgainstClosedFormsOnItsConvexTop)
{
  // sigma 60 m, 40 m high: slopes below 21 degrees, so a sun 60 degrees high casts no
  // shadow, and the top (r < sigma / 2) lies below its tangent planes: it sees the
  // whole sky above them.
  const double sigma = 60.0, radiance = 30.0, sunFlux = 900.0;
  auto height = [&](double x, double y) {
    return 40.0 * std::exp(-((x - 160) * (x - 160) + (y - 160) * (y - 160)) / (2 * sigma * sigma));
  };
  const auto grid = makeGrid(65, 65, 5.0, height);
  RadiosityScene scene;
  scene.terrains.push_back(grid.get());
  const SkyHierarchy sky(UniformSky(), pi * radiance, 7);
  const Vec3 sun = glm::normalize(Vec3(std::cos(60 * degree), 0.0, std::sin(60 * degree)));
  // The foot's view of the slopes carries little of the scene's power: a fine tolerance
  // keeps those links.
  HierarchicalRadiosity solver(scene, terrainOptions(1e-4));
  solver.addSun(sun, uniformSpectrum(sunFlux));
  solver.setSky(&sky);
  ASSERT_TRUE(solver.solve());
  int top = 0;
  double reflectedAtFoot = 0.0;
  forEachPost(solver, *grid, [&](int i, int j, const PointIrradiance& e) {
    const Vec3 n = grid->postNormal(i, j);
    EXPECT_NEAR(e.irradiance[SunLight][0], sunFlux * glm::dot(n, sun), 1e-6 * sunFlux);
    const double r = std::hypot(5.0 * i - 160, 5.0 * j - 160);
    if (r < 0.5 * sigma)
    {
      ++top;
      EXPECT_NEAR(e.irradiance[SkyLight][0] / (pi * radiance * (1.0 + n.z) / 2.0), 1.0, 0.01);
      EXPECT_NEAR(e.skyViewFactor, (1.0 + n.z) / 2.0, 0.01);
    }
    if (std::abs(r - 2.0 * sigma) < 5.0)
      reflectedAtFoot = std::max(reflectedAtFoot, e.irradiance[ReflectedLight][0]);
  });
  EXPECT_GT(top, 100);
  EXPECT_GT(reflectedAtFoot, 0.0); // the concave foot sees the lit hill
}

TEST(TerrainPatch, VerticalStepCastsItsShadowAndNoLightLeaks)
{
  // Posts 0..10 at x = 0..100 m, height 0; posts 11..20 at x = 100..190 m, height 100:
  // cells of column 10 form a vertical wall facing -x. Sun from +x, 60 degrees high:
  // the wall shades the low ground for 100 / tan 60 = 57.7 m, to x = 42.3 m.
  auto xOf = [](int i) { return i <= 10 ? 10.0 * i : 10.0 * (i - 1); };
  const auto grid = makeGrid(21, 9, 10.0, [](double, double) { return 0.0; }, [](int, int) { return true; }, xOf);
  for (int j = 0; j < 9; ++j)
    for (int i = 11; i < 21; ++i)
      grid->setPost(i, j, Vec3(xOf(i), 10.0 * j, 100.0));
  RadiosityScene scene;
  scene.terrains.push_back(grid.get());
  const Vec3 sun = glm::normalize(Vec3(std::cos(60 * degree), 0.0, std::sin(60 * degree)));
  HierarchicalRadiosity solver(scene, terrainOptions(1e-3));
  solver.addSun(sun, uniformSpectrum(1000.0));
  ASSERT_TRUE(solver.solve());
  const double lit = 1000.0 * std::sin(60 * degree);
  {
    const PointEvaluator points(solver, EvaluationPlan{});
  for (int j = 1; j < 8; ++j) // away from the open ends of the wall
  {
    for (int i = 0; i <= 9; ++i)
    {
      const double x = xOf(i);
      const Spectrum e = points.directSunAt(grid->post(i, j), grid->postNormal(i, j));
      EXPECT_NEAR(e[0], x < 42.3 ? lit : 0.0, 1e-6) << "x " << x;
    }
    for (int i = 12; i < 21; ++i) // the plateau is lit
      EXPECT_NEAR(points.directSunAt(grid->post(i, j), grid->postNormal(i, j))[0], lit, 1e-6);
  }
  }
  // Uneven refinement along the shadow, yet restricted: no leaf has a neighbour two
  // levels finer (more than one T-vertex on an edge).
  const TerrainLeafMesh mesh(*solver.terrainRoots()[0]);
  int levels[64] = {};
  for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
  {
    ++levels[std::min(63, mesh.leaves()[k]->level())];
    if (mesh.leaves()[k]->canSplit())
      EXPECT_LE(mesh.mostTVerticesOnAnEdge(k), 1) << "leaf " << k;
  }
  EXPECT_GE(std::count_if(std::begin(levels), std::end(levels), [](int n) { return n > 0; }), 3);
  // The wall element faces away from the sun; the low ground in its shadow still gets
  // light reflected by the lit ground in front (not through the wall).
  forEachPost(solver, *grid, [&](int i, int j, const PointIrradiance& e) {
    if (j >= 1 && j < 8 && i >= 6 && i <= 9)
    {
      EXPECT_EQ(e.irradiance[SunLight][0], 0.0) << i << ", " << j;
    }
  });
}

TEST(TerrainPatch, LightPassesThroughAHoleOnlyWhereItIs)
{
  // A 16 x 16-cell terrain at z = 50 with a 4 x 4-cell hole over a floor at z = 0; sun
  // straight down: the floor is lit exactly below the hole.
  auto hole = [](int i, int j) { return i >= 6 && i < 10 && j >= 6 && j < 10; };
  const auto grid = makeGrid(17, 17, 10.0, [](double, double) { return 50.0; }, [&](int i, int j) { return !hole(i, j); });
  RadiosityScene scene;
  scene.terrains.push_back(grid.get());
  addPolygon(scene, { { 0, 0, 0 }, { 160, 0, 0 }, { 160, 160, 0 }, { 0, 160, 0 } }, 0.0);
  HierarchicalRadiosity solver(scene, terrainOptions(1e-3));
  solver.addSun(Vec3(0.0, 0.0, 1.0), uniformSpectrum(1000.0));
  ASSERT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  for (double x = 5.0; x < 160.0; x += 10.0)
    for (double y = 5.0; y < 160.0; y += 10.0)
    {
      const bool below = x > 60.0 && x < 100.0 && y > 60.0 && y < 100.0;
      EXPECT_NEAR(points.directSunAt(Vec3(x, y, 0.0), Vec3(0, 0, 1))[0], below ? 1000.0 : 0.0, 1e-6) << x << ", " << y;
    }
  // The terrain itself is lit everywhere it exists, and nothing comes from the hole.
  for (int j = 0; j < 17; ++j)
    for (int i = 0; i < 17; ++i)
      if (grid->postUsed(i, j))
        EXPECT_NEAR(points.directSunAt(grid->post(i, j), grid->postNormal(i, j))[0], 1000.0, 1e-6);
}
