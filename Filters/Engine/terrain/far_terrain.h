#pragma once
// The terrain as rays see it beyond the detail distance of their origin: every
// stride-th post of a grid (its last row and column kept), as horizon tools trace far
// terrain at a coarser resolution. What a point receives from terrain kilometres away
// is small and smooth (a far slope fills a sliver of its sky), so a coarse copy serves
// there; near the point the full resolution decides shadows and what it sees. Holding
// the full-resolution grid only near one's own piece is what lets a process of a work
// split keep memory that follows its piece (see README, MPI).

#include "terrain/terrain_grid.h"

#include <memory>
#include <vector>

namespace terralux
{
/// Which rays see the far terrain: those that leave the vertical cylinder of radius
/// detailDistance around their origin, beyond it. stride 1 (or no distance): none.
struct FarSight
{
  int stride = 1;
  double detailDistance = 0.0;
  bool active() const { return this->stride > 1 && this->detailDistance > 0.0; }
  /// Whether it applies to `scene`: active (or the scene gives its far terrain, with a
  /// detail distance), over a scene of one terrain alone.
  bool appliesTo(const RadiosityScene& scene) const
  {
    const bool given = scene.farTerrain.grid && this->detailDistance > 0.0;
    return (this->active() || given) && scene.terrains.size() == 1 && scene.polygons.empty();
  }
  bool operator==(const FarSight& other) const
  {
    return this->stride == other.stride && this->detailDistance == other.detailDistance;
  }
};

class FarTerrain
{
public:
  /// Every stride-th post of `fine` (stride >= 2), with its last row and column. A
  /// coarse cell is valid only where all the fine cells it spans are (no terrain is
  /// made up over a hole), takes their mean materials, and shares fine's origin.
  FarTerrain(const TerrainGrid& fine, int stride);
  /// A far terrain given whole (a copy of given.grid, with its own materials) for a
  /// fine grid that is a window of the full one (GivenFarTerrain). Fine posts past its
  /// last row or column (a strip narrower than the stride) map to its edge.
  explicit FarTerrain(const GivenFarTerrain& given);
  /// The far terrain of `scene` (FarSight::appliesTo): the given one, or built from
  /// its terrain.
  static std::unique_ptr<FarTerrain> of(const RadiosityScene& scene, const FarSight& sight);

  const TerrainGrid& grid() const { return this->Coarse; }
  /// The fine grid's parameters of the coarse grid's (u, v): a hit on the far terrain
  /// maps to the fine grid's leaves and posts.
  double fineU(double u) const { return fineParameter(this->ColumnPosts, u); }
  double fineV(double v) const { return fineParameter(this->RowPosts, v); }
  /// The coarse grid's parameters of the fine grid's (u, v): where a fine post or hit
  /// lies among the coarse grid's leaves.
  double coarseU(double u) const { return coarseParameter(this->ColumnPosts, u); }
  double coarseV(double v) const { return coarseParameter(this->RowPosts, v); }

private:
  static std::vector<int> coarsePosts(int finePosts, int stride);
  static double fineParameter(const std::vector<int>& posts, double coarse);
  static double coarseParameter(const std::vector<int>& posts, double fine);

  std::vector<int> ColumnPosts, RowPosts; // the fine post of each coarse column and row
  TerrainGrid Coarse;
};
} // namespace terralux
