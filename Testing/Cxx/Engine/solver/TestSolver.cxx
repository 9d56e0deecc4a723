// Hierarchical radiosity (solver.h): closed forms for planes under sky and sun,
// furnaces, a pit's sky, convergence and the element budget.
#include "radiosity_checks.h"
#include "sky/cie_sky.h"
#include "base/angles.h"
#include "hierarchy/cluster.h"
#include "base/error.h"
#include "evaluation/point_form_factor.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "emitters/sky_patch_element.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <functional>

using namespace terralux;
using namespace terralux_test;

namespace
{
// Calls `visit` for every leaf below the input polygons.
void forEachLeaf(const HierarchicalRadiosity& solver, const std::function<void(PolygonElement&)>& visit)
{
  std::function<void(HElement*)> descend = [&](HElement* e) {
    auto* p = static_cast<PolygonElement*>(e);
    if (!p->hasChildren())
    {
      visit(*p);
      return;
    }
    for (HElement* c : p->children())
      descend(c);
  };
  for (PolygonElement* root : solver.polygonRoots())
    if (root)
      descend(root);
}

// Area-weighted mean of a leaf quantity over the leaves of the input polygons that pass `select`.
double leafAverage(const HierarchicalRadiosity& solver, const std::function<bool(const PolygonElement&)>& select,
  const std::function<double(const PolygonElement&)>& value)
{
  double sum = 0.0, area = 0.0;
  forEachLeaf(solver, [&](PolygonElement& p) {
    if (select(p))
    {
      sum += value(p) * p.area();
      area += p.area();
    }
  });
  return area > 0.0 ? sum / area : NAN;
}

RadiosityScene unitSquare(const Vec3& normal)
{
  // A 1 x 1 square through the origin with the given normal.
  const Vec3 n = glm::normalize(normal);
  const Vec3 t = glm::normalize(std::abs(n.z) < 0.9 ? glm::cross(n, Vec3(0, 0, 1)) : glm::cross(n, Vec3(1, 0, 0)));
  const Vec3 b = glm::cross(n, t);
  RadiosityScene scene;
  addPolygon(scene, { -0.5 * t - 0.5 * b, 0.5 * t - 0.5 * b, 0.5 * t + 0.5 * b, -0.5 * t + 0.5 * b }, 0.0);
  return scene;
}
} // namespace

TEST(Solver, PlanesUnderUniformAndCieSkies)
{
  const double radiance = 40.0;
  const SkyHierarchy uniform(UniformSky(), pi * radiance, 7);
  for (double tilt : { 0.0, 35.0, 90.0 })
  {
    const RadiosityScene scene = unitSquare({ std::sin(tilt * degree), 0.0, std::cos(tilt * degree) });
    RadiosityOptions options = fine();
    options.errorTolerance = 2e-5;
    HierarchicalRadiosity solver(scene, options);
    solver.setSky(&uniform);
    ASSERT_TRUE(solver.solve());
    const double expected = pi * radiance * (1.0 + std::cos(tilt * degree)) / 2.0;
    const double got = leafAverage(solver, [](const PolygonElement&) { return true; },
      [](const PolygonElement& p) { return p.Irradiance[SkyLight][0]; });
    EXPECT_NEAR(got / expected, 1.0, 0.005) << tilt;
  }
  const Direction sun = directionFromZenithAzimuth(40.0 * degree, 160.0 * degree);
  const SkyHierarchy clear(CieGeneralSky(12, sun), 110.0, 7);
  HierarchicalRadiosity solver(unitSquare({ 0, 0, 1 }), fine());
  solver.setSky(&clear);
  ASSERT_TRUE(solver.solve());
  EXPECT_NEAR(leafAverage(solver, [](const PolygonElement&) { return true; },
                [](const PolygonElement& p) { return p.Irradiance[SkyLight][0]; }) / 110.0,
    1.0, 0.005);
}

TEST(Solver, PlanesUnderTheSun)
{
  const Vec3 sun = glm::normalize(Vec3(0.3, -0.5, 0.8));
  for (const Vec3& normal : { Vec3(0, 0, 1), Vec3(0.5, -0.2, 0.7), Vec3(-0.3, 0.5, -0.8) })
  {
    HierarchicalRadiosity solver(unitSquare(normal), fine());
    solver.addSun(sun, uniformSpectrum(900.0));
    ASSERT_TRUE(solver.solve());
    const double expected = 900.0 * std::max(0.0, glm::dot(glm::normalize(normal), sun));
    const double got = leafAverage(solver, [](const PolygonElement&) { return true; },
      [](const PolygonElement& p) { return p.Irradiance[SunLight][0]; });
    EXPECT_NEAR(got, expected, 0.005 * 900.0);
  }
}

TEST(Solver, UnitSquareFormFactors)
{
  // Closed forms (Howell's catalogue): parallel unit squares 1 apart F = 0.19982;
  // perpendicular unit squares sharing an edge F = 0.20004.
  struct Case
  {
    const char* name;
    std::function<void(RadiosityScene&)> emitter;
    double expected;
  };
  const Case cases[] = {
    { "parallel",
      [](RadiosityScene& s) { addPolygon(s, { { 0, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 }, { 1, 0, 1 } }, 0.0, 1.0); },
      0.19982 },
    { "perpendicular",
      [](RadiosityScene& s) { addPolygon(s, { { 0, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 0, 0, 1 } }, 0.0, 1.0); },
      0.20004 },
  };
  for (const Case& c : cases)
  {
    RadiosityScene scene;
    addPolygon(scene, { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, 0.0); // receiver, facing up
    c.emitter(scene);
    HierarchicalRadiosity solver(scene, fine());
    ASSERT_TRUE(solver.solve());
    const double received = leafAverage(solver, [](const PolygonElement& p) { return p.rootPolygon() == 0; },
      [](const PolygonElement& p) { return p.Irradiance[ReflectedLight][0]; });
    EXPECT_NEAR(received / c.expected, 1.0, 0.01) << c.name;
  }
}

TEST(Solver, FurnacesReachEmissionOverOneMinusReflectance)
{
  for (double rho : { 0.5, 0.9 })
  {
    for (int shape = 0; shape < 2; ++shape)
    {
      RadiosityScene scene;
      if (shape == 0)
        addInwardCube(scene, 2.0, rho, 1.0);
      else
        addInwardSphere(scene, 1.0, 12, 24, rho, 1.0);
      RadiosityOptions options = fine();
      options.errorTolerance = 1e-3;
      options.maximumIterations = 200;
      options.convergenceTolerance = 1e-5;
      HierarchicalRadiosity solver(scene, options);
      ASSERT_TRUE(solver.solve());
      const double expected = 1.0 / (1.0 - rho);
      double worst = 0.0;
      forEachLeaf(solver, [&](PolygonElement& p) { worst = std::max(worst, std::abs(p.Radiosity[0] / expected - 1.0)); });
      EXPECT_LT(worst, 0.01) << (shape ? "sphere" : "cube") << " rho " << rho;
    }
  }
}

TEST(Solver, SkyViewFactorAtTheBottomOfAPit)
{
  // From the centre of the floor the open sky is a cone of half-angle atan(r / h):
  // under a uniform sky the floor gets sin^2(atan(r / h)) of the open-field irradiance.
  // The pit is a 96-sided prism; its opening is 0.07 % smaller than the circle's.
  const SkyHierarchy uniform(UniformSky(), 1.0, 7);
  // A deeper pit shows a narrower cone, whose rim needs a finer tolerance.
  for (const auto& [depth, tolerance] : { std::pair{ 0.5, 1e-4 }, std::pair{ 1.0, 1e-4 }, std::pair{ 2.0, 1e-5 } })
  {
    RadiosityScene scene;
    addPit(scene, 1.0, depth, 96, 0.0);
    RadiosityOptions options = fine();
    options.errorTolerance = tolerance;
    options.minimumElementArea = 1e-6;
    options.visibilitySamples = 16;
    options.gatherSamples = 4096; // the rim cuts strata: the point's error falls as 1 / rays
    options.targetErrorFloor = 0.0; // a sky of radiance 1: no floor in W/m^2
    HierarchicalRadiosity solver(scene, options);
    solver.setSky(&uniform);
    ASSERT_TRUE(solver.solve());
    const Vec3 centre(0, 0, -depth);
    // Any leaf of the floor touching the centre.
    const PolygonElement* leaf = solver.polygonRoots()[0];
    while (leaf->hasChildren())
      leaf = static_cast<const PolygonElement*>(const_cast<PolygonElement*>(leaf)->children()[0]);
    ASSERT_LT(glm::length(leaf->corners()[0] - centre), 1e-12);
    const PointIrradiance atCentre = PointEvaluator(solver, EvaluationPlan{}).irradianceAt(*leaf, centre);
    const double expected = std::pow(std::sin(std::atan(1.0 / depth)), 2);
    // Visibility sampled from one point (4096 gather rays): about 1 % noise.
    EXPECT_NEAR(atCentre.irradiance[SkyLight][0] / expected, 1.0, 0.02) << depth;
    // The sky view factor is the same fraction, whatever the sky's radiance.
    EXPECT_NEAR(atCentre.skyViewFactor / expected, 1.0, 0.02) << depth;
  }
}

TEST(Solver, WallCastsItsShadowWhereGeometryPutsIt)
{
  RadiosityScene scene;
  addWallOnGround(scene, 10.0, 10.0, 3.0, 0.2);
  const double zenith = 50.0 * degree;
  const Vec3 sun(0.0, -std::sin(zenith), std::cos(zenith)); // due south
  RadiosityOptions options = fine();
  options.minimumElementArea = 0.005;
  HierarchicalRadiosity solver(scene, options);
  solver.addSun(sun, uniformSpectrum(800.0));
  ASSERT_TRUE(solver.solve());
  const double shadowLength = 3.0 * std::tan(zenith);
  int inside = 0, outside = 0;
  forEachLeaf(solver, [&](PolygonElement& leaf) {
    PolygonElement* p = &leaf;
    const double size = std::sqrt(p->area());
    const Vec3 c = p->centre();
    const double sunIrradiance = p->Irradiance[SunLight][0];
    if (p->rootPolygon() == 1)
    {
      EXPECT_EQ(sunIrradiance, 0.0); // the wall faces north, away from the sun
      return;
    }
    if (c.y > size && c.y < shadowLength - size && std::abs(c.x) < 5.0 - size)
    {
      EXPECT_LT(sunIrradiance, 1e-9) << c.x << " " << c.y;
      ++inside;
    }
    else if (c.y < -size || c.y > shadowLength + size || std::abs(c.x) > 5.0 + size + shadowLength * 0.0)
    {
      EXPECT_NEAR(sunIrradiance, 800.0 * std::cos(zenith), 1e-6) << c.x << " " << c.y;
      ++outside;
    }
  });
  EXPECT_GT(inside, 10);
  EXPECT_GT(outside, 10);
}

TEST(Solver, SameResultForOneAndTwoThreads)
{
  auto run = [](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    RadiosityScene scene;
    addWallOnGround(scene, 10.0, 10.0, 3.0, 0.4);
    addPolygon(scene, { { -3, 3, 0.01 }, { -1, 3, 0.01 }, { -1, 3, 2 }, { -3, 3, 2 } }, 0.6); // facing south? no: +y
    const Direction sunDir = directionFromZenithAzimuth(40.0 * degree, 170.0 * degree);
    const SkyHierarchy sky(CieGeneralSky(12, sunDir), 100.0, 6);
    RadiosityOptions options = fine();
    options.errorTolerance = 5e-4;
    HierarchicalRadiosity solver(scene, options);
    solver.addSun(Vec3(sunDir[0], sunDir[1], sunDir[2]), uniformSpectrum(700.0));
    solver.setSky(&sky);
    EXPECT_TRUE(solver.solve());
    std::vector<double> values;
    for (const auto& element : solver.elements().all())
      for (double b : element->Radiosity)
        values.push_back(b);
    return values;
  };
  const std::vector<double> one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k)
    ASSERT_EQ(one[k], two[k]) << k; // bitwise
}

TEST(Solver, BadScenes)
{
  RadiosityScene empty;
  EXPECT_THROW(HierarchicalRadiosity(empty, fine()), Error);
  RadiosityScene degenerate;
  addPolygon(degenerate, { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, 0.5);
  EXPECT_THROW(HierarchicalRadiosity(degenerate, fine()), Error);
  addPolygon(degenerate, { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, 0.5);
  HierarchicalRadiosity mixed(degenerate, fine());
  EXPECT_EQ(mixed.degeneratePolygons(), 1u);
  EXPECT_EQ(mixed.polygonRoots()[0], nullptr);
  RadiosityScene nan;
  addPolygon(nan, { { 0, 0, 0 }, { NAN, 0, 0 }, { 0, 1, 0 } }, 0.5);
  EXPECT_THROW(HierarchicalRadiosity(nan, fine()), Error);
}
