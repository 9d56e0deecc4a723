#pragma once
// What the sky tests share: integrals of sky models and maps.

#include "sky/cie_sky.h"
#include "base/angles.h"
#include "base/error.h"
#include "sky/perez_sky.h"
#include "sky/sky_hierarchy.h"

#include <gtest/gtest.h>

#include <cmath>

namespace terralux_test
{

using namespace terralux;

// Brute force: midpoint rule over (zenith, azimuth), independent of the hierarchy.
inline double horizontalIntegral(const SkyModel& model, int steps = 360)
{
  double sum = 0.0;
  const double dz = 0.5 * pi / steps, da = 2.0 * pi / (4 * steps);
  for (int i = 0; i < steps; ++i)
  {
    const double z = (i + 0.5) * dz;
    for (int j = 0; j < 4 * steps; ++j)
    {
      const Direction d = directionFromZenithAzimuth(z, (j + 0.5) * da);
      sum += model.relativeRadiance(d) * std::cos(z) * std::sin(z) * dz * da;
    }
  }
  return sum;
}

// Horizontal irradiance from the finest-level cell averages: sum of L * int sin u dOmega.
inline double mapHorizontalIrradiance(const SkyHierarchy& sky, int band = 0)
{
  const int n = SkyHierarchy::cellsPerSide(sky.finestLevel());
  double sum = 0.0;
  for (int iu = 0; iu < n; ++iu)
    for (int iv = 0; iv < n; ++iv)
    {
      const SkyPatch p{ sky.finestLevel(), iu, iv };
      const double weight =
        (p.v1() - p.v0()) * 0.5 * (std::pow(std::sin(p.u1()), 2) - std::pow(std::sin(p.u0()), 2));
      sum += sky.radiance(p, band) * weight;
    }
  return sum;
}

inline SkyPatch brightestFinestPatch(const SkyHierarchy& sky)
{
  const int n = SkyHierarchy::cellsPerSide(sky.finestLevel());
  SkyPatch best;
  double value = -1.0;
  for (int iu = 0; iu < n; ++iu)
    for (int iv = 0; iv < n; ++iv)
    {
      const SkyPatch p{ sky.finestLevel(), iu, iv };
      if (sky.radiance(p, 0) > value)
      {
        value = sky.radiance(p, 0);
        best = p;
      }
    }
  return best;
}
} // namespace terralux_test
