// What users read at points (point_values.h): a vertex on a crease takes each side's
// value on its own side, averaged by area; one normal across it only when asked; a
// terrain's posts, at points or averaged, within a window. Checked against closed
// forms: a sun alone over black surfaces gives E cos(angle) and nothing else.
#include "base/angles.h"
#include "sky/cie_sky.h"
#include "evaluation/point_values.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "sky/sky_model.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "terrain_grids.h"
#include "hierarchy/terrain_patch.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>

using namespace terralux;
using namespace terralux_test;

namespace
{
constexpr double sunIrradiance = 1000.0;
const Vec3 towardSun = glm::normalize(Vec3(std::sqrt(3.0), 0.0, 1.0)); // 60 deg from the zenith, over +x

// A black floor [0, 10]^2 facing up and a black wall on its edge x = 0, 5 m high, facing
// +x, sharing the points of that edge; point 6 belongs to no polygon.
RadiosityScene floorAndWall()
{
  RadiosityScene scene;
  for (const Vec3& p : { Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 10, 0), Vec3(0, 10, 0), Vec3(0, 0, 5),
         Vec3(0, 10, 5), Vec3(20, 20, 0) })
    scene.points.push_back(p);
  ScenePolygon floor, wall;
  floor.vertexCount = wall.vertexCount = 4;
  floor.vertices = { 0, 1, 2, 3 };
  wall.vertices = { 0, 3, 5, 4 };
  wall.cell = 1;
  scene.polygons = { floor, wall };
  return scene;
}

std::unique_ptr<HierarchicalRadiosity> solvedUnderTheSun(const RadiosityScene& scene)
{
  auto solver = std::make_unique<HierarchicalRadiosity>(scene, RadiosityOptions{});
  solver->addSun(towardSun, uniformSpectrum(sunIrradiance));
  EXPECT_TRUE(solver->solve());
  return solver;
}

std::vector<PointValues> pointValues(
  HierarchicalRadiosity& solver, const RadiosityScene& scene, bool oneNormal, bool atPoints, std::vector<bool>& reached)
{
  PointEvaluation how;
  how.atPoints = atPoints;
  EvaluationPlan plan;
  plan.atPoints = atPoints;
  return polygonPointValues(PointEvaluator(solver, plan), scene, 0, 0, scene.points.size(), oneNormal, how, reached);
}

// Rolling hills with ripples (20 m high, 60-80 m long), 97 x 97 posts at 30 m, under a
// sun 55 deg from the zenith and a clear sky, reflectance 0.2: light from surfaces is a
// small, smooth share of what most posts receive. Solved fine enough that the error of
// what the lattice reads from the hierarchy is small, then evaluated at the posts with
// a lattice gathered first (`lattice`), or with every post gathering.
struct LitHills
{
  std::unique_ptr<TerrainGrid> grid;
  RadiosityOptions options;
  std::unique_ptr<HierarchicalRadiosity> solver;
  std::unique_ptr<PointEvaluator> points;
  /// Post (i, j)'s values and the rays they cost.
  PointIrradiance at(int i, int j, std::uint64_t& rays) const
  {
    const TerrainPatch* leaf = this->solver->terrainRoots()[0]->mostLitLeafAt(i, j);
    rays = 0;
    if (!leaf)
    {
      ADD_FAILURE() << "no leaf at post " << i << ", " << j;
      return {};
    }
    const std::uint64_t before = this->solver->raysCast();
    const PointIrradiance result = this->points->irradianceAt(*leaf, this->grid->post(i, j), this->grid->postNormal(i, j));
    rays = this->solver->raysCast() - before;
    return result;
  }
};

std::unique_ptr<LitHills> litHills(bool lattice)
{
  static const Direction sun = directionFromZenithAzimuth(55.0 * degree, 2.0);
  static const SkyHierarchy sky(CieGeneralSky(12, sun), 120.0, 6);
  auto hills = std::make_unique<LitHills>();
  hills->grid = makeGrid(97, 97, 30.0, [](double x, double y) {
    return rollingHills(x, y) + 30.0 * std::sin(x / 61.0) * std::cos(y / 83.0);
  });
  hills->grid->setUniformMaterial(uniformSpectrum(0.2), Spectrum{});
  hills->options.errorTolerance = 1e-3;
  hills->solver = std::make_unique<HierarchicalRadiosity>(sceneOf(*hills->grid), hills->options);
  hills->solver->addSun(Vec3(sun[0], sun[1], sun[2]), uniformSpectrum(800.0));
  hills->solver->setSky(&sky);
  EXPECT_TRUE(hills->solver->solve());
  EvaluationPlan plan;
  plan.postLattice = lattice;
  hills->points = std::make_unique<PointEvaluator>(*hills->solver, plan);
  return hills;
}
} // namespace

TEST(PointValues, FlattenedAndBackAreTheSame)
{
  PointValues v;
  v.irradiance = { Spectrum{ 1, 2, 3 }, Spectrum{ 4, 5, 6 }, Spectrum{ 7, 8, 9 } };
  v.radiosity = { 10, 11, 12 };
  v.skyViewFactor = 0.5;
  double flat[PointValues::flatComponents];
  v.flatten(flat);
  const PointValues back = PointValues::unflatten(flat);
  EXPECT_EQ(back.irradiance, v.irradiance);
  EXPECT_EQ(back.radiosity, v.radiosity);
  EXPECT_EQ(back.skyViewFactor, v.skyViewFactor);
  EXPECT_EQ(v.globalIrradiance(), (Spectrum{ 12, 15, 18 }));
}

TEST(PointValues, ACreaseIsEvaluatedOnEachOfItsSides)
{
  const RadiosityScene scene = floorAndWall();
  const auto solver = solvedUnderTheSun(scene);
  const double onFloor = sunIrradiance * towardSun.z, onWall = sunIrradiance * towardSun.x;
  // Floor 100 m^2, wall 50 m^2: the edge's points weigh them so.
  const double onEdge = (100.0 * onFloor + 50.0 * onWall) / 150.0;
  for (const bool atPoints : { true, false })
  {
    std::vector<bool> reached;
    const auto values = pointValues(*solver, scene, false, atPoints, reached);
    ASSERT_EQ(values.size(), 7u);
    const double expected[6] = { onEdge, onFloor, onFloor, onEdge, onWall, onWall };
    for (int p = 0; p < 6; ++p)
    {
      ASSERT_TRUE(reached[p]) << p;
      EXPECT_NEAR(values[p].irradiance[SunLight][0], expected[p], 1e-9 * sunIrradiance) << p << " at points " << atPoints;
      EXPECT_NEAR(values[p].globalIrradiance()[0], expected[p], 1e-9 * sunIrradiance) << p;
      EXPECT_EQ(values[p].sunlitHours, 0.0); // the sun has no duration here
    }
    EXPECT_FALSE(reached[6]); // a loose point has no value
  }
}

TEST(PointValues, OneNormalAveragesTheCrease)
{
  // A terrain given as polygons: one side per point, the area-weighted normal.
  const RadiosityScene scene = floorAndWall();
  const auto solver = solvedUnderTheSun(scene);
  std::vector<bool> reached;
  const auto values = pointValues(*solver, scene, true, true, reached);
  const Vec3 normal = glm::normalize(100.0 * Vec3(0, 0, 1) + 50.0 * Vec3(1, 0, 0));
  EXPECT_NEAR(values[0].irradiance[SunLight][0], sunIrradiance * glm::dot(normal, towardSun), 1e-9 * sunIrradiance);
  EXPECT_NEAR(values[1].irradiance[SunLight][0], sunIrradiance * towardSun.z, 1e-9 * sunIrradiance);
}

TEST(PointValues, RadiosityIsEmissionPlusReflectedIrradiance)
{
  RadiosityScene scene = floorAndWall();
  for (ScenePolygon& polygon : scene.polygons)
  {
    polygon.reflectance = uniformSpectrum(0.3);
    polygon.emission = uniformSpectrum(7.0);
  }
  const auto solver = solvedUnderTheSun(scene);
  for (const bool atPoints : { true, false })
  {
    std::vector<bool> reached;
    const auto values = pointValues(*solver, scene, false, atPoints, reached);
    for (int p = 1; p < 3; ++p) // the floor's far corners: one side
      EXPECT_NEAR(values[p].radiosity[0], 7.0 + 0.3 * values[p].globalIrradiance()[0], 1e-9) << p;
    EXPECT_GT(values[1].irradiance[ReflectedLight][0], 0.0); // the wall lights the floor
  }
}

TEST(PointValues, TerrainPostsInAWindow)
{
  const auto grid = makeGrid(9, 7, 5.0, [](double, double) { return 0.0; });
  grid->setUniformMaterial(uniformSpectrum(0.0), uniformSpectrum(0.0));
  HierarchicalRadiosity solver(sceneOf(*grid), RadiosityOptions{});
  solver.addSun(towardSun, uniformSpectrum(sunIrradiance));
  ASSERT_TRUE(solver.solve());
  const TerrainPatch& root = *solver.terrainRoots()[0];
  const PointEvaluator points(solver, EvaluationPlan{});
  for (const bool atPoints : { true, false })
  {
    PointEvaluation how;
    how.atPoints = atPoints;
    const int window[4] = { 2, 5, -3, 3 }; // clipped to the grid: j 0 to 3
    std::vector<int> seen(9 * 7, 0);
    std::vector<double> sun(9 * 7, 0.0);
    terrainPostValues(points, root, window, how, [&](std::size_t post, const PointValues& v) {
      ++seen[post]; // distinct posts only: no race
      sun[post] = v.irradiance[SunLight][0];
    });
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 9; ++i)
      {
        const bool inside = i >= 2 && i <= 5 && j <= 3;
        EXPECT_EQ(seen[i + 9 * j], inside ? 1 : 0) << i << ", " << j << " at points " << atPoints;
        if (inside)
          EXPECT_NEAR(sun[i + 9 * j], sunIrradiance * towardSun.z, 1e-9 * sunIrradiance);
      }
  }
}

TEST(PointValues, DirectSunAtPostsCastsRaysOnlyWhereHorizonsCannotTell)
{
  // Hills under 60 suns all round the sky, an hour each: the values and hours at
  // every post are those of one ray per sun, bit for bit, with far fewer rays.
  const auto grid = makeGrid(97, 97, 30.0, rollingHills);
  // Without horizons (skyFromHorizons off), every sun takes its ray.
  auto underSuns = [&](bool horizons) {
    RadiosityOptions options;
    options.skyFromHorizons = horizons;
    auto solver = std::make_unique<HierarchicalRadiosity>(sceneOf(*grid), options);
    for (int s = 0; s < 60; ++s)
    {
      const double azimuth = 0.37 * s, elevation = (2.0 + 68.0 * ((s * 7) % 60) / 59.0) * degree;
      solver->addSun(Vec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                       std::sin(elevation)),
        uniformSpectrum(900.0), 1.0);
    }
    EXPECT_TRUE(solver->solve());
    return solver;
  };
  const auto rayTraced = underSuns(false), mapped = underSuns(true);
  EvaluationPlan averaged; // the suns' proofs alone: no post's sky, no lattice
  averaged.atPoints = false;
  auto byRays = std::make_unique<PointEvaluator>(*rayTraced, averaged);
  auto byHorizons = std::make_unique<PointEvaluator>(*mapped, averaged);
  const std::uint64_t raysBefore[2] = { rayTraced->raysCast(), mapped->raysCast() };
  int lit = 0;
  for (int j = 0; j < 97; ++j)
    for (int i = 0; i < 97; ++i)
      for (const bool horn : { false, true })
      {
        double hours[2] = { 0.0, 0.0 };
        const Spectrum a = byRays->directSunAt(grid->post(i, j), grid->normalAt(i, j, horn), &hours[0]);
        const Spectrum b = byHorizons->directSunAt(grid->post(i, j), grid->normalAt(i, j, horn), &hours[1]);
        ASSERT_EQ(a, b) << i << " " << j;
        ASSERT_EQ(hours[0], hours[1]) << i << " " << j;
        lit += hours[0] > 0.0;
      }
  EXPECT_GT(lit, 97 * 97);
  const std::uint64_t rays = rayTraced->raysCast() - raysBefore[0], fewer = mapped->raysCast() - raysBefore[1];
  EXPECT_LT(fewer, rays / 2) << fewer << " rays against " << rays;
  // A sun added afterwards: new evaluators map it too, and still agree.
  byRays.reset();
  byHorizons.reset();
  for (auto* solver : { rayTraced.get(), mapped.get() })
  {
    solver->addSun(Vec3(0.3, 0.2, 0.9), uniformSpectrum(500.0), 1.0);
    EXPECT_TRUE(solver->solve());
  }
  EXPECT_EQ(PointEvaluator(*rayTraced, averaged).directSunAt(grid->post(40, 40), grid->postNormal(40, 40)),
    PointEvaluator(*mapped, averaged).directSunAt(grid->post(40, 40), grid->postNormal(40, 40)));
}

TEST(PointValues, OpenPostsReadLightFromSurfacesBetweenLatticePosts)
{
  // Read between the lattice's gathered posts, light from surfaces agrees with each
  // post's own gather within their error estimates, for a fraction of the rays; a post
  // reads only where its estimate meets its target, and where the ripples make the
  // lattice's posts disagree, posts still gather.
  const auto reading = litHills(true), gathering = litHills(false);
  int read = 0, gathered = 0;
  double readSum = 0.0, gatheredSum = 0.0;
  std::uint64_t rays[2] = { 0, 0 };
  for (int j = 9; j < 88; j += 2) // away from the border's cells (see the next test)
    for (int i = 9; i < 88; i += 2)
    {
      std::uint64_t spent = 0, gatherRays = 0;
      const PointIrradiance a = reading->at(i, j, spent), b = gathering->at(i, j, gatherRays);
      rays[0] += spent;
      rays[1] += gatherRays;
      EXPECT_EQ(a.irradiance[SunLight], b.irradiance[SunLight]);
      const double received = a.irradiance[SunLight][0] + b.irradiance[SkyLight][0] + b.irradiance[ReflectedLight][0];
      if (spent > 1) // more than the sun's one ray: gathered
      {
        ++gathered;
        continue;
      }
      ++read;
      readSum += a.irradiance[ReflectedLight][0];
      gatheredSum += b.irradiance[ReflectedLight][0];
      // Within the errors both estimate; the read is within its target beyond what the
      // gather there estimates too (the error of the lattice both read).
      EXPECT_NEAR(a.irradiance[ReflectedLight][0] + a.irradiance[SkyLight][0],
        b.irradiance[ReflectedLight][0] + b.irradiance[SkyLight][0], a.irradianceError + b.irradianceError)
        << i << ", " << j;
      EXPECT_LE(a.irradianceError, reading->options.errorTarget(received) + b.irradianceError) << i << ", " << j;
      EXPECT_NEAR(a.skyViewFactor, b.skyViewFactor, 0.01) << i << ", " << j;
    }
  EXPECT_GT(read, 3 * gathered) << read << " posts read, " << gathered << " gathered";
  EXPECT_GT(gathered, 0);
  EXPECT_NEAR(readSum, gatheredSum, 0.05 * gatheredSum);
  EXPECT_LT(rays[0], rays[1] / 3) << rays[0] << " rays against " << rays[1];
}

TEST(PointValues, PostsBesideTheBorderGatherRatherThanReadFromIt)
{
  // A lattice post on the DEM's border sees terrain on one side only and counts the void
  // beyond as terrain seen: per terrain seen it finds less than the posts inside. Posts
  // inside a lattice cell with a corner on the border gather; posts on the border read
  // between their own kind. What the band inside receives from surfaces agrees with
  // every post's own gather.
  const auto reading = litHills(true), gathering = litHills(false);
  int bandRead = 0, bandPosts = 0, borderRead = 0;
  double bandSum = 0.0, gatheredSum = 0.0, errorSum = 0.0;
  for (int j = 0; j < 97; ++j)
    for (int i = 0; i < 97; i += (j == 0 || j == 96) ? 1 : 96)
    {
      std::uint64_t spent = 0;
      reading->at(i, j, spent);
      borderRead += spent <= 1;
    }
  for (int j = 9; j < 88; j += 3)
    for (int i : { 1, 2, 3, 93, 94, 95 }) // in a cell with a corner on the border, refined or not
      for (const bool transposed : { false, true })
      {
        const int pi = transposed ? j : i, pj = transposed ? i : j;
        std::uint64_t spent = 0, gatherRays = 0;
        const PointIrradiance a = reading->at(pi, pj, spent), b = gathering->at(pi, pj, gatherRays);
        ++bandPosts;
        bandRead += spent <= 1;
        bandSum += a.irradiance[ReflectedLight][0];
        gatheredSum += b.irradiance[ReflectedLight][0];
        errorSum += a.irradianceError + b.irradianceError;
      }
  EXPECT_EQ(bandRead, 0) << "of " << bandPosts << " posts beside the border";
  EXPECT_GT(borderRead, 2 * 96) << "of 388 posts on the border read between their own kind";
  EXPECT_NEAR(bandSum, gatheredSum, 0.03 * gatheredSum) << "error estimates sum to " << errorSum;
}

TEST(PointValues, APostSeesTheThinBandOfALowRidgeAsItsOwnPlaneDoes)
{
  // Flat ground at 30 m posts with a ridge 3 m high along row 32: a post two rows away
  // (60 m from the crest) sees the ridge's near slope only as a band 3 m / 60 m high
  // above its plane, where most light from surfaces on gentle terrain comes from. Its
  // gather must start at the post itself: lifted a few decimetres the band shrinks by
  // as many percent. The slope is black with emission E under a sky next to black:
  // light from surfaces is E x the slope's view factor, integrated here directly.
  constexpr int posts = 65;
  constexpr double spacing = 30.0, ridge = 3.0, emission = 1.0e5;
  const auto grid = makeGrid(posts, posts, spacing, [&](double, double y) {
    return std::abs(y - 32 * spacing) < 1.0 ? ridge : 0.0;
  });
  grid->setUniformMaterial(uniformSpectrum(0.0), uniformSpectrum(emission));
  const SkyHierarchy sky(UniformSky(), 1e-6, 6);
  RadiosityOptions options;
  options.targetErrorFloor = 0.01;
  HierarchicalRadiosity solver(sceneOf(*grid), options);
  solver.setSky(&sky);
  ASSERT_TRUE(solver.solve());
  const PointEvaluator points(solver, EvaluationPlan{});
  const int i = 32, j = 30;
  const Vec3 post = grid->post(i, j), normal = grid->postNormal(i, j);
  ASSERT_NEAR(normal.z, 1.0, 1e-12);
  // The view factor of the near slope (rows 31 to 32, a plane), by the midpoint rule.
  double viewFactor = 0.0;
  const Vec3 slopeNormal = glm::normalize(Vec3(0.0, -ridge, spacing));
  constexpr int along = 4096, up = 64;
  const double width = spacing * (posts - 1), depth = std::hypot(spacing, ridge);
  for (int a = 0; a < along; ++a)
    for (int b = 0; b < up; ++b)
    {
      const double f = (b + 0.5) / up;
      const Vec3 q((a + 0.5) * width / along, (31 + f) * spacing, f * ridge);
      const Vec3 d = q - post;
      const double r2 = glm::dot(d, d), r = std::sqrt(r2);
      viewFactor += glm::dot(normal, d) / r * -glm::dot(slopeNormal, d) / r / (pi * r2) * (width / along) * (depth / up);
    }
  const PointIrradiance e = points.irradianceAt(*solver.terrainRoots()[0]->mostLitLeafAt(i, j), post, normal);
  const double exact = emission * viewFactor;
  // The one offset every ray starts above its point (1e-5 of the scene's diagonal, 2.7
  // cm here) costs 1 %; the gather lifted two more and moved into its leaf, 4.4 %.
  EXPECT_NEAR(e.irradiance[ReflectedLight][0], exact, 0.02 * exact) << "view factor " << viewFactor;
}

TEST(PointValues, APostsSkyIsItsHorizonsWhateverItsRays)
{
  // A post's sky comes from its horizons alone, interpolated between the map's
  // azimuths: rays below them gather light from surfaces only (sky they found or lost
  // there added more noise than the interpolation's error; docs/tuning.md).
  // At the floor of a V valley whose walls rise at beta, under a uniform sky of
  // diffuse horizontal irradiance D, the horizon toward azimuth phi from the axis is
  // atan(tan beta sin phi) at any distance, and the sky is D cos beta.
  constexpr int posts = 65;
  constexpr double spacing = 30.0, beta = 25.0 * degree, diffuse = 100.0;
  const auto valley = makeGrid(posts, posts, spacing, [&](double x, double) {
    return std::abs(x - 32 * spacing) * std::tan(beta);
  });
  // Black walls that glow a little, so that every post gathers.
  valley->setUniformMaterial(uniformSpectrum(0.0), uniformSpectrum(10.0));
  const SkyHierarchy sky(UniformSky(), diffuse, 6);
  auto skyAt = [&](const TerrainGrid& grid, double targetError, int i, int j) {
    RadiosityOptions options;
    options.targetError = targetError;
    HierarchicalRadiosity solver(sceneOf(grid), options);
    solver.setSky(&sky);
    EXPECT_TRUE(solver.solve());
    const PointEvaluator points(solver, EvaluationPlan{});
    return points.irradianceAt(*solver.terrainRoots()[0]->mostLitLeafAt(i, j), grid.post(i, j), grid.postNormal(i, j));
  };
  const PointIrradiance floor = skyAt(*valley, 0.008, 32, 32);
  EXPECT_NEAR(floor.irradiance[SkyLight][0], diffuse * std::cos(beta), 0.005 * diffuse * std::cos(beta));
  EXPECT_NEAR(floor.skyViewFactor, std::cos(beta), 0.005);
  EXPECT_GT(floor.irradiance[ReflectedLight][0], 0.0);
  // On rough terrain, where interpolated horizons miss peaks between azimuths, the sky
  // is the same for a gather of a few rays and one of many (on the same map: below
  // Tuning::coarseHorizonsTarget).
  const auto rough = makeGrid(posts, posts, spacing, [](double x, double y) {
    return 40.0 * std::sin(x / 37.0) * std::cos(y / 29.0) + 15.0 * std::sin(x / 11.0 + y / 13.0);
  });
  rough->setUniformMaterial(uniformSpectrum(0.0), uniformSpectrum(10.0));
  for (const auto [i, j] : { std::array<int, 2>{ 20, 31 }, { 33, 40 }, { 45, 17 } })
  {
    const PointIrradiance few = skyAt(*rough, 0.02, i, j), many = skyAt(*rough, 0.001, i, j);
    EXPECT_GT(many.irradiance[ReflectedLight][0], 0.0);
    EXPECT_EQ(few.irradiance[SkyLight][0], many.irradiance[SkyLight][0]) << i << ", " << j;
    EXPECT_EQ(few.skyViewFactor, many.skyViewFactor) << i << ", " << j;
  }
}
