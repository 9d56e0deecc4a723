// Analytic point-to-polygon form factors (point_form_factor.h) against closed forms.
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
#include "solver/solver.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <functional>

using namespace terralux;
using namespace terralux_test;

TEST(PointFormFactor, ClosedForms)
{
  // Disc-like check: unit square seen from 1 m above its centre, parallel:
  // F = (2 / pi) [x/sqrt(1+x^2) atan(y/sqrt(1+x^2)) + y/sqrt(1+y^2) atan(x/sqrt(1+y^2))] with x = y = 0.5.
  const Vec3 square[4] = { { -0.5, -0.5, 0 }, { 0.5, -0.5, 0 }, { 0.5, 0.5, 0 }, { -0.5, 0.5, 0 } };
  const double x = 0.5, a = x / std::sqrt(1 + x * x);
  const double expected = 2.0 / pi * 2.0 * a * std::atan(a);
  EXPECT_NEAR(pointToPolygonFormFactor({ 0, 0, 1 }, { 0, 0, -1 }, square, 4, { 0, 0, 1 }), expected, 1e-12);
  // Behind the emitter: nothing. Polygon straddling the receiver's plane: clipped.
  EXPECT_EQ(pointToPolygonFormFactor({ 0, 0, -1 }, { 0, 0, 1 }, square, 4, { 0, 0, 1 }), 0.0);
  const double half = pointToPolygonFormFactor({ 0, 0, 1 }, { 1, 0, 0 }, square, 4, { 0, 0, 1 });
  EXPECT_GT(half, 0.0);
  EXPECT_LT(half, expected);
  // A point on the edge of a perpendicular square stays finite.
  const Vec3 wall[4] = { { -0.5, 0.5, 0 }, { 0.5, 0.5, 0 }, { 0.5, 0.5, 1 }, { -0.5, 0.5, 1 } };
  const double touching = pointToPolygonFormFactor({ 0, 0.499, 0 }, { 0, 0, 1 }, wall, 4, { 0, -1, 0 });
  EXPECT_TRUE(std::isfinite(touching));
  EXPECT_NEAR(touching, 0.5, 0.01); // a half-plane wall fills half the projected hemisphere
}
