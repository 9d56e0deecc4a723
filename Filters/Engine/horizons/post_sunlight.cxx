#include "horizons/post_sunlight.h"

#include "base/error.h"
#include "terrain/terrain_grid.h"
#include "parallel/work_split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
constexpr int sunlightTag = 902; // after the posts' skies' (post_sky.cxx)
}

PostSunlight::PostSunlight(
  const TerrainGrid& terrain, const HorizonMap& map, const std::vector<HorizonMap::Sight>& suns, const WorkSplit* split,
  int halo)
  : PostsX(terrain.postsX())
  , PostsY(terrain.postsY())
  , Suns(suns.size())
  , Held(terrain.postsX(), terrain.postsY(), split, halo)
{
  if (suns.size() > maximumSuns)
    throw Error("PostSunlight records at most 4 suns a post");
  const int nx = this->PostsX, ny = this->PostsY;
  const WorkSplit::Window own = WorkSplit::ownWindow(split, nx, ny);
  WorkSplit::partThenShare(
    split,
    [&]() {
      this->Bits.resize(this->Held.count());
      tbb::parallel_for(own.j0, own.j1 + 1, [&](int j) {
        for (int i = own.i0; i <= own.i1; ++i)
        {
          const std::size_t index = static_cast<std::size_t>(j) * nx + i;
          std::uint8_t bits = 0;
          if (terrain.postUsed(i, j))
          {
            HorizonMap::View horizons(map, { true, index });
            for (std::size_t s = 0; s < suns.size(); ++s)
            {
              if (horizons.clearlyAbove(suns[s]))
                bits |= static_cast<std::uint8_t>(1u << s);
              else if (horizons.clearlyBelow(suns[s]))
                bits |= static_cast<std::uint8_t>(1u << (s + maximumSuns));
            }
          }
          this->Bits[this->Held.index(i, j)] = bits;
        }
      });
    },
    [&]() { this->Held.share(this->Bits, sunlightTag); });
}

SunsProven PostSunlight::between(double u, double v) const
{
  // The cell's four posts (the last cell's for parameters on the grid's far edges).
  const int nx = this->PostsX, ny = this->PostsY;
  if (nx < 2 || ny < 2 || !(std::isfinite(u) && std::isfinite(v)))
    return {};
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, nx - 2);
  const int j = std::clamp(static_cast<int>(std::floor(v)), 0, ny - 2);
  this->Held.requireHeld(i, j, "suns");
  this->Held.requireHeld(i + 1, j + 1, "suns");
  const SunsProven a = this->at(i, j), b = this->at(i + 1, j), c = this->at(i, j + 1), d = this->at(i + 1, j + 1);
  return { a.seen & b.seen & c.seen & d.seen, a.hidden & b.hidden & c.hidden & d.hidden };
}
} // namespace terralux
