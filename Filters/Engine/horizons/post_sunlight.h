#pragma once
// Which suns each post of a height-field terrain is proven to see, or proven not to
// see, by its horizons (HorizonMap::View's clearlyAbove and clearlyBelow), found once
// for all posts and read where a final gather's ray meets the terrain. What a hit
// sends is its reflectance times what it receives; the sun it receives took a shadow
// ray per hit, 40 % of the rays of the 1025^2 fractal's instant. Where the posts of the
// hit's cell all prove the same, the hit takes their answer; where they do not (the
// cell holds a shadow's edge, or a post proves nothing), the ray decides. Like the sky
// a hit takes from its cell's posts (post_sky.h), this reads what varies smoothly at the
// receiver (its light from surfaces) from the posts around each hit; the posts' own
// sun still comes from their horizons or a ray from the post itself.

#include "parallel/held_posts.h"
#include "horizons/horizon_map.h"
#include "solver/link_transport.h"
#include "base/uninitialized_vector.h"

#include <cstdint>
#include <vector>

namespace terralux
{
class TerrainGrid;
class WorkSplit;

class PostSunlight
{
public:
  /// Suns a post records (a bit each for seen and hidden in one byte): an instant's
  /// one sun, or the few that every gather hit takes (FinalGather::maximumSunsPerHit).
  static constexpr std::size_t maximumSuns = 4;
  /// Every used post of the map's terrain against each of `suns` (at most maximumSuns,
  /// in the order hits take them), in parallel; with `split`, each process its window's
  /// posts (whose horizons it holds), then the others' it holds received (all, or with
  /// a `halo` >= 0 those within it of its window: see HeldPosts).
  PostSunlight(const TerrainGrid& terrain, const HorizonMap& map, const std::vector<HorizonMap::Sight>& suns,
    const WorkSplit* split = nullptr, int halo = -1);

  /// Bit s set: every post of the cell holding grid parameters (u, v) proves sun s
  /// seen (`seen`) or hidden (`hidden`). A cell with a missing or unproven post proves
  /// neither. Throws where this process does not hold them.
  SunsProven between(double u, double v) const;
  /// What post (i, j), held, itself proves.
  SunsProven at(int i, int j) const
  {
    const unsigned bits = this->Bits[this->Held.index(i, j)];
    return { bits & 0xFu, bits >> maximumSuns };
  }
  std::size_t suns() const { return this->Suns; }

private:
  int PostsX, PostsY;
  std::size_t Suns;
  HeldPosts Held;
  // Per held post, row by row: the low four bits seen, the high four hidden; 0 at unused posts.
  UninitializedVector<std::uint8_t> Bits;
};
} // namespace terralux
