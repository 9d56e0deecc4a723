#pragma once
// Eight sectors of a point's view by azimuth, 45 deg each, counter-clockwise from +x
// (0: from +x to the diagonal toward +y). A post on a ridge sees the terrain on one
// side of it, while the lattice posts around it see every side: kept apart by sector,
// the light they gathered from surfaces is read by the terrain the post sees in each
// (PostLattice::readBySector; docs/tuning.md, "Reads by sector of the view").

#include <array>
#include <cmath>

namespace terralux
{
constexpr int viewSectors = 8;

template <class T>
using PerSector = std::array<T, viewSectors>;

/// The sector of the azimuth of a direction whose horizontal part is (x, y).
inline int sectorOf(double x, double y)
{
  const int quadrant = (y < 0.0 ? 2 : 0) + ((x < 0.0) != (y < 0.0) ? 1 : 0);
  // The second half of quadrants 0 and 2 lies nearer the y axis, of 1 and 3 the x axis.
  const bool second = quadrant % 2 == 0 ? std::abs(y) >= std::abs(x) : std::abs(x) >= std::abs(y);
  return 2 * quadrant + (second ? 1 : 0);
}
} // namespace terralux
