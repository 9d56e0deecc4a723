#pragma once
// Eight sectors of a point's view by azimuth, 45 deg each, counter-clockwise from +x
// (0: from +x to the diagonal toward +y), each in two parts: the terrain within
// nearViewPosts posts of the point (horizontally), and beyond. A post on a ridge sees
// the terrain on one side of it, and only the far terrain below it, while the lattice
// posts around it see every side, and the slopes near them: kept apart by part, the
// light they gathered from surfaces is read by the terrain the post sees in each
// (PostLattice::readByPart; docs/tuning.md, "Reads by sector of the view" and "Near
// and far terrain").

#include <array>
#include <cmath>

namespace terralux
{
constexpr int viewSectors = 8;

template <class T>
using PerSector = std::array<T, viewSectors>;
/// The near part ends this many of the grid's post spacings from the point: about the
/// lattice's step, so that what a post sees near it differs from its corners' near
/// terrain and what lies beyond is much the same for both.
constexpr double nearViewPosts = 4.0;
constexpr int viewParts = 2 * viewSectors;
template <class T>
using PerViewPart = std::array<T, viewParts>;
/// The part of sector `sector`, near or beyond.
inline int viewPartOf(int sector, bool beyond)
{
  return 2 * sector + (beyond ? 1 : 0);
}

/// The sector of the azimuth of a direction whose horizontal part is (x, y).
inline int sectorOf(double x, double y)
{
  const int quadrant = (y < 0.0 ? 2 : 0) + ((x < 0.0) != (y < 0.0) ? 1 : 0);
  // The second half of quadrants 0 and 2 lies nearer the y axis, of 1 and 3 the x axis.
  const bool second = quadrant % 2 == 0 ? std::abs(y) >= std::abs(x) : std::abs(x) >= std::abs(y);
  return 2 * quadrant + (second ? 1 : 0);
}
} // namespace terralux
