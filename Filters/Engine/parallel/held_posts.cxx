#include "parallel/held_posts.h"

#include "terrain/terrain_grid.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace terralux
{
HeldPosts::HeldPosts(int nx, int ny, const WorkSplit* split, int halo, int step)
  : Nx(nx)
  , Ny(ny)
  , Step(std::max(1, step))
  , Split(split)
  , Halo(split ? halo : -1)
  , Own(this->of(split ? split->part() : 0))
  , Width(this->Own.empty() ? 0 : this->Own.i1 - this->Own.i0 + 1)
{
}

WorkSplit::Window HeldPosts::of(int part) const
{
  if (this->Halo < 0 || !this->Split)
    return WorkSplit::Window{ 0, this->Nx - 1, 0, this->Ny - 1 };
  const WorkSplit::Window w = this->windowOf(*this->Split, part);
  if (w.empty())
    return w;
  return WorkSplit::Window{ w.i0 - this->Halo, w.i1 + this->Halo, w.j0 - this->Halo, w.j1 + this->Halo }.clampedTo(
    this->Nx, this->Ny);
}

int HeldPosts::haloFor(const TerrainGrid& terrain, double distance)
{
  if (!(distance > 0.0) || !std::isfinite(distance))
    return -1;
  // Horizontally, a point m cells along one axis and n along the other (of a cell with
  // sides a and b) lies at least max(|m|, |n|) x |a x b| / max(|a|, |b|) from the post:
  // each axis's steps are at least that far from the line of the other.
  const int nx = terrain.postsX(), ny = terrain.postsY();
  const double narrowest = tbb::parallel_reduce(
    tbb::blocked_range<int>(0, std::max(0, ny - 1)), std::numeric_limits<double>::infinity(),
    [&](const tbb::blocked_range<int>& rows, double least) {
      for (int j = rows.begin(); j < rows.end(); ++j)
        for (int i = 0; i + 1 < nx; ++i)
        {
          if (!terrain.cellValid(i, j))
            continue;
          const Vec3 p = terrain.post(i, j), a = terrain.post(i + 1, j) - p, b = terrain.post(i, j + 1) - p;
          const double la = std::hypot(a.x, a.y), lb = std::hypot(b.x, b.y);
          const double cross = std::abs(a.x * b.y - a.y * b.x);
          least = std::min(least, la > 0.0 && lb > 0.0 ? cross / std::max(la, lb) : 0.0);
        }
      return least;
    },
    [](double a, double b) { return std::min(a, b); });
  if (!(narrowest > 0.0))
    return -1;
  if (!std::isfinite(narrowest))
    return 0; // no valid cell: nothing to read
  const double cells = std::ceil(distance / narrowest);
  // The hit's cell's far corner, and a post of margin for a grid not quite affine.
  return cells + 2.0 >= static_cast<double>(std::max(nx, ny)) ? -1 : static_cast<int>(cells) + 2;
}
} // namespace terralux
