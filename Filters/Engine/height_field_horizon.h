#pragma once
// The horizon of a point over terrain grids that are height fields, found by walking
// the grid toward an azimuth (as r.horizon and horizon-map tools do) instead of
// bisecting it with grazing rays: one walk gives the highest elevation exactly, where
// each ray only says above or below. A pyramid of maximum heights with the xy bounds
// of its blocks skips every block that cannot rise above the horizon found so far, so
// a walk visits a few cells near the point and a few large blocks beyond.
//
// The surface is the grid's own triangles (TerrainGrid::cellTriangles): along a line
// its height is linear inside each triangle, and the elevation seen from the point,
// (z - z0) / distance, is monotone along each such piece, so the highest elevation lies
// where the line crosses a cell edge or a cell's diagonal; those crossings are what a
// walk evaluates, with their true 3-D positions. The walk follows the line of the
// azimuth in the grid's parameters, taken from the grid's local shape at the point: on
// a grid of straight rows (projected rasters) that is the vertical plane of the
// azimuth itself; on a georeferenced grid bent by the Earth's curvature it strays from
// that plane by a small fraction of a cell over tens of kilometres, where a cell
// subtends a negligible angle.

#include "radiosity_types.h"

#include <cstddef>
#include <vector>

namespace terralux
{
class TerrainGrid;

class HeightFieldHorizon
{
public:
  /// Grids whose cells all face up (TerrainGrid::facesUp); they must outlive this.
  explicit HeightFieldHorizon(const std::vector<const TerrainGrid*>& grids);
  ~HeightFieldHorizon();

  /// The tangent of the horizon seen from `from` toward the horizontal unit direction
  /// (dx, dy): the largest (z - from.z) / (horizontal distance) over the terrain's
  /// points in that azimuth, or `floorTangent` (>= 0) when none rises above it; terrain
  /// below the floor is skipped early. Thread-safe.
  double tangentToward(const Vec3& from, double dx, double dy, double floorTangent) const;

  std::size_t memoryBytes() const;

private:
  struct Pyramid;
  std::vector<Pyramid> Pyramids;
};
} // namespace terralux
