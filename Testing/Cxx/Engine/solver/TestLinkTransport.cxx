// Link transport (link_transport.h) on its own, against closed forms: the kernel of a
// link between two facing unit squares against the exact area-to-area form factor,
// visibility of none, half and all of a blocker, the sun's cosine and shadow, and a
// uniform sky's pi and sky view factor, each source through the ExternalSource
// interface it implements.
#include "base/angles.h"
#include "sky/cie_sky.h"
#include "solver/link_transport.h"
#include "hierarchy/polygon_element.h"
#include "radiosity_scenes.h"
#include "sky/sky_hierarchy.h"
#include "emitters/sky_patch_element.h"
#include "emitters/sun_element.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

namespace
{
// Exact form factor between two directly opposed parallel a x b rectangles at distance c
// (Howell's catalogue, C-11).
double parallelRectangles(double a, double b, double c)
{
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1.0 + x * x), y1 = std::sqrt(1.0 + y * y);
  return 2.0 / (pi * x * y) *
    (std::log(std::sqrt((1.0 + x * x) * (1.0 + y * y) / (1.0 + x * x + y * y))) + x * y1 * std::atan(x / y1) +
      y * x1 * std::atan(y / x1) - x * std::atan(x) - y * std::atan(y));
}

// Exact form factor from a point to a parallel rectangle at distance c whose corner lies
// on the point's normal, of sides a and b (Howell's catalogue, B-3).
double pointToCornerRectangle(double a, double b, double c)
{
  const double x = a / c, y = b / c;
  return 1.0 / (2.0 * pi) *
    (x / std::sqrt(1.0 + x * x) * std::atan(y / std::sqrt(1.0 + x * x)) +
      y / std::sqrt(1.0 + y * y) * std::atan(x / std::sqrt(1.0 + y * y)));
}

// From a point over (px, py) of the unit square [0, 1]^2 at distance 1: four corner
// rectangles around the point's foot.
double pointToUnitSquare(double px, double py)
{
  return pointToCornerRectangle(px, py, 1.0) + pointToCornerRectangle(1.0 - px, py, 1.0) +
    pointToCornerRectangle(px, 1.0 - py, 1.0) + pointToCornerRectangle(1.0 - px, 1.0 - py, 1.0);
}

// Two unit squares: the floor [0, 1]^2 at z = 0 facing up, the ceiling at z = 1 facing
// down (in the rays' scene unless `openCeiling`); optionally a blocker at z = 0.5 over
// x < `blockerEnd`.
struct FacingSquares
{
  RadiosityScene scene;
  ElementStore store;
  PolygonElement* floor = nullptr;
  PolygonElement* ceiling = nullptr;
  std::unique_ptr<Visibility> rays;

  explicit FacingSquares(double blockerEnd = 0.0, bool openCeiling = false)
  {
    const Vec3 f[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
    const Vec3 c[4] = { { 0, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 }, { 1, 0, 1 } };
    addPolygon(this->scene, { f[0], f[1], f[2], f[3] }, 0.5);
    if (!openCeiling)
      addPolygon(this->scene, { c[0], c[1], c[2], c[3] }, 0.5, 100.0);
    if (blockerEnd > 0.0)
      addPolygon(this->scene, { { -1, -1, 0.5 }, { blockerEnd, -1, 0.5 }, { blockerEnd, 2, 0.5 }, { -1, 2, 0.5 } }, 0.5);
    this->rays = std::make_unique<Visibility>(this->scene);
    this->floor =
      this->store.make<PolygonElement>(0, &this->store, f, 4, uniformSpectrum(0.5), uniformSpectrum(0.0), 0);
    this->ceiling =
      this->store.make<PolygonElement>(0, &this->store, c, 4, uniformSpectrum(0.5), uniformSpectrum(100.0), 1);
    this->ceiling->Radiosity = uniformSpectrum(100.0);
  }
};
} // namespace

TEST(LinkTransport, FacingSquaresKernelIsTheAreaFormFactor)
{
  FacingSquares squares;
  const Link link = evaluateLink(*squares.floor, *squares.ceiling, *squares.rays, 16);
  const double exact = parallelRectangles(1.0, 1.0, 1.0); // 0.1998
  EXPECT_NEAR(exact, 0.19982, 1e-4);
  // Five receiver points of exact point form factors (a quad's centre and the points
  // halfway to its corners), which refinement trusts where the link carries little:
  // some 7 % above the area mean at a distance of one side.
  const double fivePoints = (pointToUnitSquare(0.5, 0.5) + 4.0 * pointToUnitSquare(0.25, 0.25)) / 5.0;
  EXPECT_NEAR(link.kernel, fivePoints, 1e-9);
  EXPECT_NEAR(link.kernel / exact, 1.0, 0.08);
  EXPECT_GT(link.kernelSpread, 0.0); // the centre sees more than the corners
  EXPECT_DOUBLE_EQ(link.visibility, 1.0);
  EXPECT_EQ(link.sender, squares.ceiling);
  EXPECT_NEAR(link.direction.z, 1.0, 1e-12);
  EXPECT_EQ(lightCategoryOf(*squares.ceiling), ReflectedLight);
  EXPECT_EQ(skyViewOf(*squares.ceiling, Vec3(0, 0, 1), link.kernel), 0.0);
  // The same kernel from the receiver's own geometry, and the exact point form factor
  // at a point of the floor.
  EXPECT_DOUBLE_EQ(kernelAtSurface(*squares.floor, *squares.ceiling), link.kernel);
  EXPECT_NEAR(transportToPoint(Vec3(0.3, 0.6, 0.0), Vec3(0, 0, 1), *squares.ceiling, *squares.rays, 0, 1),
    pointToUnitSquare(0.3, 0.6), 1e-9);
}

TEST(LinkTransport, VisibilityCountsTheBlockedShare)
{
  FacingSquares open, half(0.5), full(2.0);
  EXPECT_DOUBLE_EQ(sampledVisibility(*open.floor, *open.ceiling, *open.rays, 16), 1.0);
  EXPECT_DOUBLE_EQ(sampledVisibility(*full.floor, *full.ceiling, *full.rays, 16), 0.0);
  // Half the floor and half the ceiling behind a blocker at mid-height: a pair of
  // points sees each other when their midpoint's x is beyond 0.5 (probability 1/2).
  const double v = sampledVisibility(*half.floor, *half.ceiling, *half.rays, 64);
  EXPECT_GT(v, 0.3);
  EXPECT_LT(v, 0.7);
  // Samples are seeded by the two ids: the same link, the same value.
  EXPECT_DOUBLE_EQ(sampledVisibility(*half.floor, *half.ceiling, *half.rays, 64), v);
  // At points: one under the blocker sees less of the ceiling than one beside it.
  const double under = transportToPoint(Vec3(0.05, 0.5, 0.0), Vec3(0, 0, 1), *half.ceiling, *half.rays, 64, 7);
  const double beside = transportToPoint(Vec3(0.95, 0.5, 0.0), Vec3(0, 0, 1), *half.ceiling, *half.rays, 64, 7);
  EXPECT_LT(under, beside);
  EXPECT_GT(beside, 0.0);
}

TEST(LinkTransport, TheSunSendsItsCosineWhereARayReachesIt)
{
  FacingSquares open(0.0, true), covered(2.0, true);
  const Vec3 toward = glm::normalize(Vec3(1.0, 0.0, 2.0));
  SunElement sun(100, 0, toward, uniformSpectrum(800.0), 0.5);
  const ExternalSource& source = sun;
  EXPECT_TRUE(source.parallel());
  EXPECT_EQ(source.category(), SunLight);
  EXPECT_EQ(source.hemisphereShare(), 0.0);
  EXPECT_EQ(source.skyView(Vec3(0, 0, 1), 1.0), 0.0);
  EXPECT_DOUBLE_EQ(source.kernel(Vec3(0, 0, 1)), toward.z);
  EXPECT_DOUBLE_EQ(source.kernel(Vec3(0, 0, -1)), 0.0);

  // The open floor: the cosine, fully visible; under the blocker: the cosine, hidden.
  const Link lit = evaluateLink(*open.floor, sun, *open.rays, 8);
  EXPECT_DOUBLE_EQ(lit.kernel, toward.z);
  EXPECT_DOUBLE_EQ(lit.visibility, 1.0);
  EXPECT_EQ(lightCategoryOf(sun), SunLight);
  const Link shadowed = evaluateLink(*covered.floor, sun, *covered.rays, 8);
  EXPECT_DOUBLE_EQ(shadowed.kernel, toward.z);
  EXPECT_DOUBLE_EQ(shadowed.visibility, 0.0);
  // The ceiling faces away: no transport, no rays.
  const Link away = evaluateLink(*open.ceiling, sun, *open.rays, 8);
  EXPECT_EQ(away.kernel, 0.0);

  // At points: one ray decides; sunlit hours add the sun's duration where it reaches.
  const std::vector<HElement*> suns{ &sun };
  double hours = 0.0;
  const Spectrum litPoint = directSunlight(Vec3(0.5, 0.5, 0.0), Vec3(0, 0, 1), suns, *open.rays, &hours);
  EXPECT_NEAR(litPoint[0], 800.0 * toward.z, 1e-9);
  EXPECT_DOUBLE_EQ(hours, 0.5);
  hours = 0.0;
  const Spectrum darkPoint = directSunlight(Vec3(0.5, 0.5, 0.0), Vec3(0, 0, 1), suns, *covered.rays, &hours);
  EXPECT_EQ(darkPoint[0], 0.0);
  EXPECT_EQ(hours, 0.0);
}

TEST(LinkTransport, AUniformSkySendsPiTimesItsRadianceAndCountsItsView)
{
  FacingSquares open(0.0, true), closed;
  const double radiance = 30.0;
  const SkyHierarchy sky(UniformSky(), pi * radiance, 6);
  ElementStore store;
  SkyPatchElement whole(200, 0, &store, &sky, SkyPatch{ 0, 0, 0 });
  const ExternalSource& source = whole;
  EXPECT_FALSE(source.parallel());
  EXPECT_EQ(source.category(), SkyLight);
  EXPECT_NEAR(source.hemisphereShare(), whole.solidAngle() / (2.0 * pi), 1e-15);
  EXPECT_NEAR(source.directionalKernel(), whole.solidAngle(), 1e-15);
  EXPECT_NEAR(whole.emittance()[0], radiance, 1e-9);

  // A horizontal surface receives pi L, a vertical one pi L / 2; the sky view factor of
  // the open floor is 1.
  const double up = source.kernel(Vec3(0, 0, 1));
  EXPECT_NEAR(up, pi, 1e-6);
  EXPECT_NEAR(source.kernel(Vec3(1, 0, 0)), pi / 2.0, 1e-3);
  EXPECT_NEAR(skyViewOf(whole, Vec3(0, 0, 1), up), 1.0, 1e-6);
  const Link link = evaluateLink(*open.floor, whole, *open.rays, 16);
  EXPECT_NEAR(link.kernel, pi, 1e-6);
  EXPECT_DOUBLE_EQ(link.visibility, 1.0);
  // A point at the floor's centre under the unit ceiling: the ceiling hides its point
  // form factor (0.2394) of pi, to the sampling error of 256 cosine-weighted rays.
  const double hidden = pointToUnitSquare(0.5, 0.5);
  const double seen = transportToPoint(Vec3(0.5, 0.5, 0.0), Vec3(0, 0, 1), whole, *closed.rays, 256, 3);
  EXPECT_NEAR(seen / pi, 1.0 - hidden, 0.08);
}
