// Sky patch elements (sky_patch_element.h): solid angles and radiance of the patches
// of the hierarchical sky (paper section 5.1).
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

TEST(SkyPatchElement, ProjectedSolidAngleAgainstBruteForce)
{
  // Integral of max(0, n . d) over a patch: closed form (vector solid angle) or Gauss
  // quadrature, against a fine midpoint rule over (u, v) with dOmega = cos u du dv.
  const SkyHierarchy sky(UniformSky(), 1.0, 4);
  ElementStore store;
  store.MaximumSkyLevel = 8;
  for (const Vec3& normal : { Vec3(0, 0, 1), glm::normalize(Vec3(0.3, -0.2, 0.9)), glm::normalize(Vec3(1, 0.5, 0.2)) })
    for (const SkyPatch& patch : { SkyPatch{ 3, 2, 5 }, SkyPatch{ 4, 0, 9 }, SkyPatch{ 6, 40, 17 }, SkyPatch{ 2, 1, 3 } })
    {
      SkyPatchElement element(0, patch.level, &store, &sky, patch);
      double brute = 0.0;
      const int steps = 200;
      for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j)
        {
          const double u = patch.u0() + (i + 0.5) * (patch.u1() - patch.u0()) / steps;
          const double v = patch.v0() + (j + 0.5) * (patch.v1() - patch.v0()) / steps;
          const Direction d = directionFromSkyParameters(u, v);
          brute += std::max(0.0, normal.x * d[0] + normal.y * d[1] + normal.z * d[2]) * std::cos(u) *
            (patch.u1() - patch.u0()) / steps * (patch.v1() - patch.v0()) / steps;
        }
      EXPECT_NEAR(element.projectedSolidAngle(normal), brute, 1e-3 * patch.solidAngle() + 1e-6)
        << patch.level << " " << patch.iu << " " << patch.iv;
    }
}
