#pragma once
// Checks of a horizon map against Embree's rays, which know nothing of the sweep: just
// above a post's horizon a ray escapes, just below it a ray is blocked; what the map
// proves of a sun's direction, rays find so.

#include "base/angles.h"
#include "horizons/horizon_map.h"
#include "terrain/terrain_grid.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace terralux_test
{
using namespace terralux;

/// A direction from azimuth and elevation (radians).
inline Vec3 directionOf(double azimuth, double elevation)
{
  return Vec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
}

// Every azimuth of the post's horizon checked with two rays from the post: `margin`
// above the horizon open, `margin` below it blocked. Returns how many were blocked.
inline int checkAgainstRays(const HorizonMap& map, const Visibility& rays, const TerrainGrid& grid, int i, int j,
  double margin)
{
  const Vec3 point = grid.post(i, j), up(0, 0, 1);
  const HorizonMap::Post post = map.find(point);
  EXPECT_TRUE(post) << i << " " << j;
  if (!post)
    return 0;
  int blocked = 0;
  const std::vector<double>& azimuths = map.azimuths();
  for (int a = 0; a < static_cast<int>(azimuths.size()); ++a)
  {
    const double phi = azimuths[a], elevation = map.elevation(post, a);
    auto toward = [&](double u) {
      return Vec3(std::cos(u) * std::cos(phi), std::cos(u) * std::sin(phi), std::sin(u));
    };
    EXPECT_FALSE(rays.occludedToward(point, up, toward(elevation + margin)))
      << "above the horizon " << elevation / degree << " deg at azimuth " << phi / degree << " from post " << i
      << " " << j;
    if (elevation > margin)
    {
      ++blocked;
      EXPECT_TRUE(rays.occludedToward(point, up, toward(elevation - margin)))
        << "below the horizon " << elevation / degree << " deg at azimuth " << phi / degree << " from post " << i
        << " " << j;
    }
  }
  return blocked;
}

/// Shares of the directions the map proves at posts of `grid` (i0 to i1, j0 to j1,
/// every `step`-th; 40 random azimuths and elevations each): every direction proven
/// open a ray finds open, every one proven hidden lies below what a ray finds blocked.
struct Proven
{
  double open, shadowed; // shares of the open and of the shadowed directions proven so
};

inline Proven checkProofs(const HorizonMap& map, const Visibility& rays, const TerrainGrid& grid, int i0, int i1,
  int j0, int j1, int step)
{
  std::uint64_t state = 12345;
  auto uniform = [&state]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  int proven = 0, open = 0, shadowed = 0, provenShadowed = 0;
  for (int j = j0; j <= j1; j += step)
    for (int i = i0; i <= i1; i += step)
    {
      const HorizonMap::Post post = map.find(grid.post(i, j));
      EXPECT_TRUE(post);
      for (int k = 0; k < 40; ++k)
      {
        const double azimuth = twoPi * uniform(), elevation = 0.5 * pi * uniform() * uniform();
        const bool seen = !rays.occludedToward(grid.post(i, j), Vec3(0, 0, 1), directionOf(azimuth, elevation));
        HorizonMap::View view(map, post);
        const HorizonMap::Sight sight = map.sight(azimuth, elevation);
        const bool clear = view.clearlyAbove(sight);
        const bool hidden = view.clearlyBelow(sight);
        EXPECT_TRUE(seen || !clear) << "post " << i << " " << j << " azimuth " << azimuth / degree
                                    << " elevation " << elevation / degree;
        // Hidden: below the highest direction of that azimuth a ray finds blocked. (Not
        // the ray at that elevation itself: from a post at the foot of a 77 deg wall,
        // a ray a few degrees up meets the wall within its starting offset and passes
        // under it.)
        if (hidden)
        {
          double top = 0.5 * pi;
          while (top > 0.0 && !rays.occludedToward(grid.post(i, j), Vec3(0, 0, 1), directionOf(azimuth, top)))
            top -= 0.25 * degree;
          EXPECT_LT(elevation, top + 0.25 * degree) << "post " << i << " " << j << " azimuth " << azimuth / degree
                                                    << " elevation " << elevation / degree;
        }
        open += seen;
        proven += clear;
        shadowed += !seen;  // by that ray
        provenShadowed += hidden;
      }
    }
  return { static_cast<double>(proven) / std::max(open, 1), static_cast<double>(provenShadowed) / std::max(shadowed, 1) };
}
} // namespace terralux_test
