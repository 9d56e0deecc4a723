#include "horizons/horizon_map.h"

// What a post's mapped horizons prove about a sight (a sun's direction) without a ray:
// the bearing between the map's azimuths, the distances a line runs on the grid, and
// the View that reads one post's horizons for many sights (see horizon_map.h).

#include "base/angles.h"
#include "terrain/terrain_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace terralux
{
HorizonMap::Bearing HorizonMap::bearing(double azimuth) const
{
  const std::vector<double>& a = this->Azimuths;
  const double angle = azimuth - twoPi * std::floor(azimuth / twoPi);
  // The map's azimuths increase in [0, 2 pi): the one at or below, cyclically.
  const auto above = std::upper_bound(a.begin(), a.end(), angle);
  const int k = above == a.begin() ? static_cast<int>(a.size()) - 1 : static_cast<int>(above - a.begin()) - 1;
  const int next = (k + 1) % static_cast<int>(a.size());
  Bearing b;
  b.k = k;
  b.fromBelow = angle - a[k] + (angle < a[k] ? twoPi : 0.0);
  b.toAbove = a[next] - angle + (a[next] < angle ? twoPi : 0.0);
  return b;
}

double HorizonMap::edgeDistance(int i, int j, int edge) const
{
  // Across a column (edges u = const) or a row: the cell's area over its side along
  // the edge.
  const double area = std::abs(this->Ux * this->Vy - this->Vx * this->Uy);
  const double across = edge < 2 ? area / std::sqrt(this->Vx * this->Vx + this->Vy * this->Vy)
                                 : area / std::sqrt(this->Ux * this->Ux + this->Uy * this->Uy);
  switch (edge)
  {
    case 0:
      return (i - this->ExtentU0) * across;
    case 1:
      return (this->ExtentU1 - i) * across;
    case 2:
      return (j - this->ExtentV0) * across;
    default:
      return (this->ExtentV1 - j) * across;
  }
}

double HorizonMap::exitDistance(int i, int j, int k) const
{
  const double du = this->AzimuthSteps[k][0], dv = this->AzimuthSteps[k][1];
  double r = std::numeric_limits<double>::infinity();
  if (du > 0.0)
    r = std::min(r, (this->ExtentU1 - i) / du);
  else if (du < 0.0)
    r = std::min(r, (this->ExtentU0 - i) / du);
  if (dv > 0.0)
    r = std::min(r, (this->ExtentV1 - j) / dv);
  else if (dv < 0.0)
    r = std::min(r, (this->ExtentV0 - j) / dv);
  return r;
}

double HorizonMap::riseOver(int i, int j, double distance) const
{
  const double rise = this->highestAt(i, j) - this->Terrain.post(i, j).z;
  if (rise <= 0.0)
    return 0.0;
  // A little nearer for the grid's departures from its mean map.
  const double r = 0.999 * distance;
  return r > 0.0 ? rise / r : std::numeric_limits<double>::infinity();
}

bool HorizonMap::cornerWithin(int i, int j, int k) const
{
  const auto [x0, y0] = this->AzimuthDirections[k];
  const auto [x1, y1] = this->AzimuthDirections[(k + 1) % this->azimuthCount()];
  for (const double ci : { this->ExtentU0, this->ExtentU1 })
    for (const double cj : { this->ExtentV0, this->ExtentV1 })
    {
      const double du = ci - i, dv = cj - j;
      const double x = this->Ux * du + this->Vx * dv, y = this->Uy * du + this->Vy * dv;
      // Strictly: a corner on a bracket's end (rounding aside) is that end's distance.
      const double below = x0 * y - y0 * x, above = x * y1 - y * x1, tolerance = 1e-18 * (x * x + y * y);
      if (below > 0.0 && above > 0.0 && below * below > tolerance && above * above > tolerance)
        return true;
    }
  return false;
}

HorizonMap::Sight HorizonMap::sight(double azimuth, double elevation) const
{
  Sight s;
  s.bearing = this->bearing(azimuth);
  s.elevation = elevation;
  s.chordBelow = 2.0 * std::sin(0.5 * s.bearing.fromBelow);
  s.chordAbove = 2.0 * std::sin(0.5 * s.bearing.toAbove);
  const double raised = elevation + this->proofMargin();
  s.tanWithMargin = raised < 0.5 * pi ? std::tan(raised) : std::numeric_limits<double>::infinity();
  const double lowered = elevation - this->proofMargin();
  s.tanLessMargin = lowered > -0.5 * pi ? std::tan(lowered) : -std::numeric_limits<double>::infinity();
  return s;
}

HorizonMap::View::View(const HorizonMap& map, const Post& post)
  : Map(map)
  , Cell(map.cellOf(post))
  , I(static_cast<int>(post.index % static_cast<std::size_t>(map.Terrain.postsX())))
  , J(static_cast<int>(post.index / static_cast<std::size_t>(map.Terrain.postsX())))
  , Count(map.azimuthCount())
  , Margin(map.complete() && map.exactAt(this->Cell) ? map.proofMargin() : std::numeric_limits<double>::infinity())
  , Slope(map.slopeAt(this->I, this->J))
{
}

double HorizonMap::View::tangent(int k)
{
  if (!(this->Tangent >> k & 1u))
  {
    this->Tangents[k] = static_cast<float>(std::tan(this->elevation(k)));
    this->Tangent |= std::uint64_t{ 1 } << k;
  }
  return this->Tangents[k];
}

HorizonMap::View::Reach& HorizonMap::View::reach(int k)
{
  Reach& reach = this->Reaches[k];
  if (this->Reached >> k & 1u)
    return reach;
  this->Reached |= std::uint64_t{ 1 } << k;
  const HorizonMap& map = this->Map;
  const double r0 = map.exitDistance(this->I, this->J, k), r1 = map.exitDistance(this->I, this->J, this->next(k));
  reach.pastLeast = -1.0;
  reach.longer = r1 > r0 ? 1 : 0;
  reach.shorter = std::min(r0, r1);
  reach.pastShorter = map.riseOver(this->I, this->J, reach.shorter);
  reach.pastLonger = map.cornerWithin(this->I, this->J, k) ? map.riseOver(this->I, this->J, std::max(r0, r1)) : 0.0;
  return reach;
}

double HorizonMap::View::pastLeast(int k)
{
  Reach& reach = this->reach(k);
  if (reach.pastLeast >= 0.0)
    return reach.pastLeast;
  const HorizonMap& map = this->Map;
  const double a0 = map.Azimuths[k], a1 = map.Azimuths[this->next(k)];
  // The distance to a convex edge along an azimuth is least at the bracket's ends or
  // where it meets an edge square on.
  double least = reach.shorter;
  for (int edge = 0; edge < 4; ++edge)
  {
    const double a = map.EdgeAzimuths[edge];
    const bool inside = a0 <= a1 ? (a >= a0 && a <= a1) : (a >= a0 || a <= a1);
    if (inside)
      least = std::min(least, map.edgeDistance(this->I, this->J, edge));
  }
  return reach.pastLeast = map.riseOver(this->I, this->J, least);
}

bool HorizonMap::View::clearPastNeighbours(const Sight& sight, double fromBelow, double fromAbove)
{
  // The margin: quantisation (2.4e-5 rad), and lines placed by the mean map (their
  // azimuths off by a small fraction of a degree, their horizons by S times that).
  // In tangents: elevation > atan(t) + margin, the same as tan(elevation - margin) > t.
  const Reach& reach = this->reach(sight.bearing.k);
  const double fromLonger = reach.longer ? fromAbove : fromBelow;
  return (sight.elevation > fromLonger + this->Margin || sight.tanLessMargin > reach.pastShorter) &&
    sight.tanLessMargin > reach.pastLonger;
}

bool HorizonMap::View::clearlyBelow(const Sight& sight)
{
  const double margin = this->Margin;
  if (std::isinf(margin))
    return false; // the map proves nothing
  const int k = sight.bearing.k;
  // In tangents: tan(elevation + margin) < tan H_k - drop, the same as elevation below
  // atan(tan H_k - drop) - margin.
  for (const auto& [side, drop] :
    { std::pair<int, double>{ k, this->Slope * sight.chordBelow }, { this->next(k), this->Slope * sight.chordAbove } })
  {
    const double horizon = this->elevation(side);
    if (horizon > margin && horizon < 0.5 * pi && sight.tanWithMargin < this->tangent(side) - drop &&
      std::tan(horizon - margin) > this->pastLeast(k))
      return true;
  }
  return false;
}
} // namespace terralux
