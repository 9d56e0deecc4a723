#include "horizons/horizon_map.h"
// A coarse map refined at chosen posts (HorizonMap's refining constructor): the
// standard azimuths the coarse map lacks, walked from those posts alone and
// interpolated elsewhere.

#include "base/angles.h"
#include "base/error.h"
#include "horizons/horizon_lines.h"
#include "terrain/terrain_grid.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace terralux
{
using horizon_lines::atanOfPositive;
using horizon_lines::crossingsOf;
using horizon_lines::Crossing;

/// A step's crossings and the line's direction, found once for every post walked, and
/// the highest point of each block of the grid's posts: a walk skips the steps through
/// a block that cannot rise above the horizon found so far (open directions, downhill,
/// otherwise walked to the grid's edge).
struct HorizonMap::LineWalk
{
  int q = 0, p = 0;
  std::vector<Crossing> crossings;
  double dx = 0.0, dy = 0.0; // the step's mean direction (0, 0: a grid without extent)
  static constexpr int blockSize = 16;
  /// A step's posts lie within a post of the box between its ends (|q|, |p| <= 5): a
  /// block's highest is taken over it grown by this many posts.
  static constexpr int blockMargin = 6;
  int blocksX = 0;
  const std::vector<float>* highest = nullptr;
  float highestAt(int i, int j) const
  {
    return (*this->highest)[static_cast<std::size_t>(j / blockSize) * this->blocksX + i / blockSize];
  }
  /// The highest used post of each block, grown by the margin, blocksX a row.
  static std::vector<float> highestOfBlocks(const TerrainGrid& t, int blocksX, int blocksY)
  {
    const int nx = t.postsX(), ny = t.postsY();
    std::vector<float> highest(static_cast<std::size_t>(blocksX) * blocksY);
    auto first = [](int block) { return std::max(0, block * blockSize - blockMargin); };
    auto end = [](int block, int posts) { return std::min(posts, (block + 1) * blockSize + blockMargin); };
    tbb::parallel_for(0, blocksY, [&](int bj) {
      for (int bi = 0; bi < blocksX; ++bi)
      {
        float top = -std::numeric_limits<float>::infinity();
        for (int j = first(bj); j < end(bj, ny); ++j)
          for (int i = first(bi); i < end(bi, nx); ++i)
            if (t.postUsed(i, j))
              top = std::max(top, t.vertices()[3 * (static_cast<std::size_t>(j) * nx + i) + 2]);
        highest[static_cast<std::size_t>(bj) * blocksX + bi] = top;
      }
    });
    return highest;
  }
};

HorizonMap::HorizonMap(const HorizonMap& coarse, const std::vector<std::uint8_t>& exact)
  : HorizonMap(coarse)
{
  if (coarse.azimuthCount() != static_cast<int>(Density::Coarse) || !coarse.Exact.empty())
    throw Error("HorizonMap: only a coarse map of every post's horizons is refined");
  if (exact.size() != coarse.HeldCount)
    throw Error("HorizonMap: a refinement flags each post the coarse map holds");
  this->Azimuths.clear(), this->AzimuthSteps.clear(), this->AzimuthDirections.clear();
  const std::vector<std::array<int, 2>>& slotSteps = this->placeAzimuths(Density::Standard);
  this->findCopiedSlots(&coarse);
  this->Elevations = {}; // the coarse map's copy: copyFromLender takes them from it
  this->Elevations.resize(this->HeldCount * slotSteps.size());
  this->copyFromLender(&coarse);
  this->Exact = exact;
  this->RefinedPosts =
    static_cast<std::size_t>(std::count_if(exact.begin(), exact.end(), [](std::uint8_t flag) { return flag != 0; }));
  const int count = this->azimuthCount();
  const TerrainGrid& t = this->Terrain;
  const int blocksX = (t.postsX() + LineWalk::blockSize - 1) / LineWalk::blockSize;
  const std::vector<float> highest =
    LineWalk::highestOfBlocks(t, blocksX, (t.postsY() + LineWalk::blockSize - 1) / LineWalk::blockSize);
  for (int slot = 0; slot < count; ++slot)
  {
    if (this->copied(static_cast<std::size_t>(slot)))
      continue;
    LineWalk line;
    line.q = slotSteps[slot][0], line.p = slotSteps[slot][1];
    line.crossings = crossingsOf(line.q, line.p);
    line.blocksX = blocksX, line.highest = &highest;
    const double dx = this->Ux * line.q + this->Vx * line.p, dy = this->Uy * line.q + this->Vy * line.p;
    const double length = std::hypot(dx, dy);
    if (length > 0.0)
      line.dx = dx / length, line.dy = dy / length;
    // The coarse azimuths either side (every other standard one), for the posts that
    // interpolate between them.
    const int below = (slot + count - 1) % count, above = (slot + 1) % count;
    double from = this->Azimuths[slot] - this->Azimuths[below], span = this->Azimuths[above] - this->Azimuths[below];
    from += from < 0.0 ? twoPi : 0.0;
    span += span <= 0.0 ? twoPi : 0.0;
    const double weight = from / span;
    std::uint16_t* out = this->Elevations.data() + static_cast<std::size_t>(slot) * this->HeldCount;
    const std::uint16_t* lower = this->Elevations.data() + static_cast<std::size_t>(below) * this->HeldCount;
    const std::uint16_t* upper = this->Elevations.data() + static_cast<std::size_t>(above) * this->HeldCount;
    auto between = [weight](std::uint16_t low, std::uint16_t high) {
      return static_cast<std::uint16_t>(low + weight * (high - low) + 0.5);
    };
    tbb::parallel_for(this->Held.j0, this->Held.j1 + 1, [&](int j) {
      for (int i = this->Held.i0; i <= this->Held.i1; ++i)
      {
        const std::size_t cell = static_cast<std::size_t>(j - this->Held.j0) * this->HeldX + (i - this->Held.i0);
        // Above the horizontal, the walk's horizon or the horizons between as before;
        // below it, what the terrain ahead falls away to, between too (a walk ends at
        // the horizontal).
        const std::uint16_t falling =
          between(std::min(lower[cell], horizontalCode), std::min(upper[cell], horizontalCode));
        if (exact[cell])
        {
          const double walked = this->walkedTangent(i, j, line);
          out[cell] = walked > 0.0 ? codeOfTangent(walked) : falling;
          continue;
        }
        const std::uint16_t rising =
          between(std::max(lower[cell], horizontalCode), std::max(upper[cell], horizontalCode));
        out[cell] = rising > horizontalCode ? rising : falling;
      }
    });
  }
}

double HorizonMap::walkedTangent(int i, int j, const LineWalk& line) const
{
  const TerrainGrid& t = this->Terrain;
  const int nx = t.postsX(), ny = t.postsY(), q = line.q, p = line.p;
  const bool complete = this->Complete;
  if ((line.dx == 0.0 && line.dy == 0.0) || (!complete && !t.postUsed(i, j)))
    return 0;
  const float* xyz = t.vertices();
  auto position = [&](int a, int b) { return xyz + 3 * (static_cast<std::size_t>(b) * nx + a); };
  auto inGrid = [&](int a, int b) { return a >= 0 && b >= 0 && a < nx && b < ny; };
  auto cellValid = [&](int a, int b) { return a >= 0 && b >= 0 && a < nx - 1 && b < ny - 1 && t.cellValid(a, b); };
  const float* post = position(i, j);
  const double x0 = post[0] * line.dx + post[1] * line.dy, z0 = post[2];
  // The steepest tangent from the post to the profile ahead: the sweep's hull's
  // tangent, its points the same crossings and posts (the same arithmetic).
  double steepest = 0.0;
  auto see = [&](double x, double z) {
    if (x > x0)
      steepest = std::max(steepest, (z - z0) / (x - x0));
  };
  const double rise = this->HighestZ - z0;
  // Steps from (a, b) on that stay in its block, of this many posts each way.
  auto stepsInBlock = [](int from, int step) {
    constexpr int size = LineWalk::blockSize;
    if (step == 0)
      return std::numeric_limits<int>::max();
    const int edge = step > 0 ? (from / size + 1) * size : from / size * size - 1; // the first post past the block
    return (edge - from + step + (step > 0 ? -1 : 1)) / step;
  };
  for (int a = i, b = j; inGrid(a, b); a += q, b += p)
  {
    // A block whose highest stands below the horizon found, as seen from its nearest
    // point (this step's first post), hides nothing: its steps are skipped.
    if (a != i || b != j)
    {
      const float* start = position(a, b);
      const double distance = start[0] * line.dx + start[1] * line.dy - x0;
      if (distance > 0.0 && line.highestAt(a, b) - z0 <= steepest * distance)
      {
        const int skipped = std::min(stepsInBlock(a, q), stepsInBlock(b, p));
        a += (skipped - 1) * q, b += (skipped - 1) * p;
        continue;
      }
    }
    const bool nextInGrid = inGrid(a + q, b + p);
    for (const Crossing& c : line.crossings)
    {
      if ((!complete || !nextInGrid) &&
        !(inGrid(a + c.a0, b + c.b0) && inGrid(a + c.a1, b + c.b1) &&
          (cellValid(a + c.ci, b + c.cj) || cellValid(a + c.di, b + c.dj))))
        continue;
      const float* e0 = position(a + c.a0, b + c.b0);
      const float* e1 = position(a + c.a1, b + c.b1);
      const double f = c.f;
      const double x = (e0[0] + f * (e1[0] - e0[0])) * line.dx + (e0[1] + f * (e1[1] - e0[1])) * line.dy;
      see(x, e0[2] + f * (e1[2] - e0[2]));
    }
    if (!nextInGrid)
      break;
    const float* next = position(a + q, b + p);
    const double x = next[0] * line.dx + next[1] * line.dy;
    if (complete || t.postUsed(a + q, b + p))
      see(x, next[2]);
    // Past here nothing can stand above the horizon found: the grid's highest point
    // at this distance is already below it.
    if (x > x0 && rise <= steepest * (x - x0))
      break;
  }
  return steepest;
}
} // namespace terralux
