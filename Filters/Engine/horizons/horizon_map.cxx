#include "horizons/horizon_map.h"

#include "base/angles.h"
#include "base/error.h"
#include "horizons/horizon_lines.h"
#include "terrain/terrain_grid.h"
#include "parallel/work_split.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace terralux
{
using horizon_lines::atanOf;
using horizon_lines::crossingsOf;
using horizon_lines::Crossing;

namespace
{
/// The steps: slopes 0, 1/5, 2/5, 2/3 and 1 in each octant (32); coarse, 0, 2/5 and 1
/// (16); dense, 64: also 1/9, 1/3, 1/2 and 3/4, between them and short (few crossings a
/// step).
std::vector<std::array<int, 2>> stepsOfAllAzimuths(HorizonMap::Density density)
{
  std::vector<std::array<int, 2>> slopes{ { 1, 0 }, { 5, 2 }, { 1, 1 } };
  if (density != HorizonMap::Density::Coarse)
    slopes.insert(slopes.end(), { { 5, 1 }, { 3, 2 } });
  if (density == HorizonMap::Density::Dense)
    slopes.insert(slopes.end(), { { 9, 1 }, { 3, 1 }, { 2, 1 }, { 4, 3 } });
  std::vector<std::array<int, 2>> steps;
  for (const std::array<int, 2>& s : slopes)
    for (int mirror = 0; mirror < 8; ++mirror)
    {
      int q = mirror & 1 ? s[1] : s[0], p = mirror & 1 ? s[0] : s[1];
      q = mirror & 2 ? -q : q;
      p = mirror & 4 ? -p : p;
      if (std::find(steps.begin(), steps.end(), std::array<int, 2>{ q, p }) == steps.end())
        steps.push_back({ q, p });
    }
  return steps;
}
} // namespace

/// A line's hull as the sweep keeps it: storage that only grows, and the points in use,
/// so a post's pushes and pops run on a pointer and a count kept in registers, not on a
/// vector's bookkeeping (docs/tuning.md).
struct HorizonMap::HullStack
{
  std::vector<HullPoint> storage;
  std::size_t size = 0;
  /// Storage for `more` points past those in use.
  HullPoint* reserve(std::size_t more)
  {
    if (this->storage.size() < this->size + more)
      this->storage.resize(2 * (this->size + more));
    return this->storage.data();
  }
  void assign(const Hull* hull)
  {
    this->size = 0;
    if (hull)
    {
      std::copy(hull->begin(), hull->end(), this->reserve(hull->size()));
      this->size = hull->size();
    }
  }
  void copyTo(Hull& hull) const { hull.assign(this->storage.begin(), this->storage.begin() + this->size); }
};

HorizonMap::HorizonMap(const TerrainGrid& terrain, Density density, const WorkSplit* split, const HorizonMap* lender)
  : Terrain(terrain)
{
  this->fitMeanMap(terrain);
  this->measureRelief();
  this->ExtentU1 = terrain.postsX() - 1, this->ExtentV1 = terrain.postsY() - 1;
  const std::vector<std::array<int, 2>>& slotSteps = this->placeAzimuths(density);
  this->Held = WorkSplit::ownWindow(split, terrain.postsX(), terrain.postsY());
  this->holdPosts();
  this->findCopiedSlots(lender);
  if (!split)
  {
    this->Elevations.resize(this->HeldCount * slotSteps.size());
    for (std::size_t slot = 0; slot < slotSteps.size(); ++slot)
      if (!this->copied(slot))
        this->sweepWholeGrid(slotSteps[slot][0], slotSteps[slot][1], &this->Elevations[slot * this->PostCount]);
  }
  else if (split->sendsPointToPoint())
    this->sweepWindows(slotSteps, *split);
  else
    this->sweepSharedAzimuths(slotSteps, *split);
  UninitializedVector<ProfilePost>().swap(this->SweepProfile);
  this->copyFromLender(lender);
}

void HorizonMap::findCopiedSlots(const HorizonMap* lender)
{
  if (!lender)
    return;
  // Only from a map of the same posts: the same terrain, mean map and held window.
  if (&lender->Terrain != &this->Terrain || lender->Held.i0 != this->Held.i0 || lender->Held.i1 != this->Held.i1 ||
    lender->Held.j0 != this->Held.j0 || lender->Held.j1 != this->Held.j1)
    throw Error("HorizonMap: a map lending its sweeps must hold the same posts of the same terrain");
  this->LentSlot.assign(this->SlotSteps.size(), -1);
  for (std::size_t slot = 0; slot < this->SlotSteps.size(); ++slot)
  {
    const auto found = std::find(lender->SlotSteps.begin(), lender->SlotSteps.end(), this->SlotSteps[slot]);
    if (found != lender->SlotSteps.end())
      this->LentSlot[slot] = static_cast<int>(found - lender->SlotSteps.begin());
  }
}

void HorizonMap::copyFromLender(const HorizonMap* lender)
{
  // (A process of an empty window holds no posts: nothing to copy.)
  for (std::size_t slot = 0; slot < this->LentSlot.size() && this->HeldCount > 0; ++slot)
    if (this->copied(slot))
      std::copy_n(lender->Elevations.data() + static_cast<std::size_t>(this->LentSlot[slot]) * lender->HeldCount,
        this->HeldCount,
        this->Elevations.data() + slot * this->HeldCount);
}

void HorizonMap::dropCopiedSlots(std::vector<std::size_t>& schedule) const
{
  schedule.erase(std::remove_if(schedule.begin(), schedule.end(), [&](std::size_t slot) { return this->copied(slot); }),
    schedule.end());
}

const std::vector<std::array<int, 2>>& HorizonMap::placeAzimuths(Density density)
{
  // Azimuths in increasing order, each step's slot its rank.
  const std::vector<std::array<int, 2>> steps = stepsOfAllAzimuths(density);
  std::vector<double> azimuths;
  for (const auto& g : steps)
  {
    const double a = std::atan2(this->Uy * g[0] + this->Vy * g[1], this->Ux * g[0] + this->Vx * g[1]);
    azimuths.push_back(a < 0.0 ? a + 2.0 * pi : a);
  }
  std::vector<int> order(steps.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return azimuths[a] < azimuths[b]; });
  const double det = this->Ux * this->Vy - this->Vx * this->Uy;
  this->SlotSteps.clear();
  for (const int step : order)
  {
    const double a = azimuths[static_cast<std::size_t>(step)], x = std::cos(a), y = std::sin(a);
    this->Azimuths.push_back(a);
    this->AzimuthSteps.push_back({ (this->Vy * x - this->Vx * y) / det, (this->Ux * y - this->Uy * x) / det });
    this->AzimuthDirections.push_back({ x, y });
    this->SlotSteps.push_back(steps[static_cast<std::size_t>(step)]);
  }
  return this->SlotSteps;
}

void HorizonMap::holdPosts()
{
  const int nx = this->Terrain.postsX(), ny = this->Terrain.postsY();
  this->PostCount = static_cast<std::size_t>(nx) * ny;
  if (this->Held.empty())
    this->Held = {};
  this->HeldX = static_cast<std::size_t>(this->Held.i1 - this->Held.i0 + 1);
  this->HeldCount = this->HeldX * static_cast<std::size_t>(this->Held.j1 - this->Held.j0 + 1);
  this->HoldsAll = this->HeldCount == this->PostCount;
}

std::size_t HorizonMap::postsX() const
{
  return static_cast<std::size_t>(this->Terrain.postsX());
}

std::uint16_t HorizonMap::codeOfTangent(double tangent)
{
  if (!(tangent > -std::numeric_limits<double>::infinity()))
    return horizontalCode - codeSteps;
  const double elevation = atanOf(tangent);
  // Rounded to the nearest (a positive value: + 0.5, truncated).
  const double code = horizontalCode + elevation / (0.5 * pi) * codeSteps + 0.5;
  return static_cast<std::uint16_t>(std::clamp(code, double{ horizontalCode - codeSteps }, double{ horizontalCode + codeSteps }));
}

bool HorizonMap::fits(const TerrainGrid& terrain, Density density)
{
  const double bytes = 2.0 * static_cast<int>(density) * terrain.postsX() * terrain.postsY();
  return bytes <= 2147483648.0;
}

void HorizonMap::fitMeanMap(const TerrainGrid& t)
{
  // Mean steps along u and v over the valid cells, and the mean offset: posts outside
  // valid cells may hold anything. Counting them also tells whether any is missing.
  // Row by row on every core, then summed in order: the same sums on every process
  // of a split, whose map must agree.
  struct Sums
  {
    double sx = 0, sy = 0, ux = 0, uy = 0, vx = 0, vy = 0, si = 0, sj = 0;
    std::size_t count = 0;
  };
  std::vector<Sums> rows(static_cast<std::size_t>(std::max(0, t.cellsY())));
  tbb::parallel_for(0, t.cellsY(), [&](int j) {
    Sums& r = rows[static_cast<std::size_t>(j)];
    for (int i = 0; i < t.cellsX(); ++i)
      if (t.cellValid(i, j))
      {
        const Vec3 p00 = t.post(i, j) - t.origin(), p10 = t.post(i + 1, j) - t.origin(),
                   p01 = t.post(i, j + 1) - t.origin();
        r.ux += p10.x - p00.x, r.uy += p10.y - p00.y, r.vx += p01.x - p00.x, r.vy += p01.y - p00.y;
        r.sx += p00.x, r.sy += p00.y, r.si += i, r.sj += j;
        ++r.count;
      }
  });
  double sx = 0, sy = 0, ux = 0, uy = 0, vx = 0, vy = 0, si = 0, sj = 0;
  std::size_t count = 0;
  for (const Sums& r : rows)
  {
    sx += r.sx, sy += r.sy, ux += r.ux, uy += r.uy, vx += r.vx, vy += r.vy, si += r.si, sj += r.sj;
    count += r.count;
  }
  this->Complete = count == static_cast<std::size_t>(t.cellsX()) * t.cellsY();
  if (count == 0)
    return;
  const double n = static_cast<double>(count);
  this->Ux = ux / n, this->Uy = uy / n, this->Vx = vx / n, this->Vy = vy / n;
  this->X0 = (sx - this->Ux * si - this->Vx * sj) / n;
  this->Y0 = (sy - this->Uy * si - this->Vy * sj) / n;
}

std::vector<HorizonMap::LineRun> HorizonMap::runsWithin(int q, int p, const WorkSplit::Window& w)
{
  // A stretch starts at each post whose step back leaves the window (in grid order): a
  // whole row where it leaves through the top or bottom, else the |q| posts next to the
  // side it leaves through.
  std::vector<LineRun> runs;
  const int width = w.i1 - w.i0 + 1;
  auto inWindow = [&](int i, int j) { return w.holds(i, j); };
  for (int j = w.j0; j <= w.j1; ++j)
  {
    int first = 0, last = width; // the whole row, as offsets from i0
    if (j - p >= w.j0 && j - p <= w.j1)
      first = q < 0 ? std::max(0, width + q) : 0, last = q > 0 ? std::min(width, q) : (q < 0 ? width : 0);
    for (int i = w.i0 + first; i < w.i0 + last; ++i)
    {
      LineRun run;
      run.i = i, run.j = j, run.count = 1;
      while (inWindow(i + run.count * q, j + run.count * p))
        ++run.count;
      runs.push_back(run);
    }
  }
  return runs;
}

void HorizonMap::sweepWholeGrid(int q, int p, std::uint16_t* out)
{
  const WorkSplit::Window whole{ 0, this->Terrain.postsX() - 1, 0, this->Terrain.postsY() - 1 };
  this->sweep(q, p, runsWithin(q, p, whole), whole, out);
}

void HorizonMap::sweep(int q, int p, const std::vector<LineRun>& runs, const WorkSplit::Window& window,
  std::uint16_t* out, const std::vector<Capture>& captures, std::vector<Hull>* captured)
{
  const TerrainGrid& t = this->Terrain;
  const int nx = t.postsX(), ny = t.postsY();
  const std::size_t outX = static_cast<std::size_t>(window.i1 - window.i0 + 1);
  // Azimuth by azimuth: neighbouring lines, swept one after another, write
  // neighbouring posts.
  const std::vector<Crossing> crossings = crossingsOf(q, p);
  // Each crossing's two posts as offsets in the grid's post order.
  std::vector<std::array<std::ptrdiff_t, 2>> offsets;
  for (const Crossing& c : crossings)
    offsets.push_back({ static_cast<std::ptrdiff_t>(c.b0) * nx + c.a0, static_cast<std::ptrdiff_t>(c.b1) * nx + c.a1 });
  // Distance along the line: positions projected on the step's mean direction.
  double dx = this->Ux * q + this->Vx * p, dy = this->Uy * q + this->Vy * p;
  const double length = std::hypot(dx, dy);
  if (!(length > 0.0))
  {
    // A grid without extent.
    std::fill_n(out, window.empty() ? 0 : outX * static_cast<std::size_t>(window.j1 - window.j0 + 1), horizontalCode);
    return;
  }
  dx /= length, dy /= length;
  // Each post's distance along the azimuth, found once rather than at each crossing
  // that interpolates it (docs/tuning.md), and its height.
  const float* xyz = t.vertices();
  UninitializedVector<ProfilePost>& along = this->SweepProfile;
  along.resize(static_cast<std::size_t>(nx) * ny);
  tbb::parallel_for(0, ny, [&](int j) {
    for (std::size_t at = static_cast<std::size_t>(j) * nx, end = at + nx; at < end; ++at)
      along[at] = { xyz[3 * at] * dx + xyz[3 * at + 1] * dy, xyz[3 * at + 2] };
  });
  auto inGrid = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny; };
  auto cellValid = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx - 1 && j < ny - 1 && t.cellValid(i, j); };

  const bool complete = this->Complete;
  const std::ptrdiff_t nextOffset = static_cast<std::ptrdiff_t>(p) * nx + q; // the next post on a line

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
    using Point = HullPoint;
    // Up to 128 neighbouring lines are swept in step: at each step they read and write
    // neighbouring posts, which then share cache lines (docs/tuning.md).
    std::array<HullStack, 128> hulls; // per line: the upper hull of what lies ahead; the nearest last
    std::array<int, 128> onLine{};
    std::array<std::size_t, 128> nextCapture{};
    // Drops the hull's nearest points that (x, z) and the next one hide: they are below
    // the segment between them, so no point nearer sees them as its horizon.
    auto pop = [](const Point* hull, std::size_t& size, double x, double z) {
      while (size >= 2)
      {
        const Point& a = hull[size - 1];
        const Point& b = hull[size - 2];
        if ((a.z - z) * (b.x - x) <= (b.z - z) * (a.x - x))
          --size;
        else
          break;
      }
    };
    auto push = [&pop](Point* hull, std::size_t& size, const Point& point) {
      pop(hull, size, point.x, point.z);
      hull[size++] = point;
    };
    auto pointOf = [&](const ProfilePost* post) { return Point{ post->x, post->z }; };
    // Crossing n of the step ahead of the post at `here`.
    auto crossingAhead = [&](const ProfilePost* here, std::size_t n) {
      const ProfilePost& a = here[offsets[n][0]];
      const ProfilePost& b = here[offsets[n][1]];
      const double f = crossings[n].f;
      return Point{ a.x + f * (b.x - a.x), a.z + f * (b.z - a.z) };
    };
    // A point lies below the segment between two others (in x between them, as
    // crossings between posts do): no post before them sees it as its horizon, and
    // no hull keeps it.
    auto below = [](const Point& c, const Point& far, const Point& near) {
      return (c.z - near.z) * (far.x - near.x) <= (far.z - near.z) * (c.x - near.x);
    };
    // Keeps the hull after post k where a window behind on the line needs it.
    auto captureAt = [&](const LineRun& run, std::size_t l, int k) {
      std::size_t& n = nextCapture[l];
      while (n < run.firstCapture + run.captureCount && captures[n].k == k)
        hulls[l].copyTo((*captured)[captures[n++].slot]);
    };
    // One step's profile, the post ahead first, and the crossings that may count.
    const std::size_t m = crossings.size();
    std::vector<Point> profile(m + 2), kept(m);
    for (std::size_t first = r.begin(); first < r.end(); first += hulls.size())
    {
      const std::size_t lines = std::min<std::size_t>(r.end() - first, hulls.size());
      int longest = 0;
      for (std::size_t l = 0; l < lines; ++l)
      {
        const LineRun& run = runs[first + l];
        hulls[l].assign(run.ahead);
        onLine[l] = run.count;
        nextCapture[l] = run.firstCapture;
        longest = std::max(longest, onLine[l]);
      }
      for (int k = longest - 1; k >= 0; --k)
        for (std::size_t l = 0; l < lines; ++l)
        {
          if (k >= onLine[l])
            continue;
          const LineRun& run = runs[first + l];
          // Room for this post's pushes, then the stack in registers until it is done.
          Point* hull = hulls[l].reserve(m + 1);
          std::size_t size = hulls[l].size;
          const int i = run.i + k * q, j = run.j + k * p;
          const ProfilePost* here = along.data() + static_cast<std::size_t>(j) * nx + i;
          // Where the step ahead lies inside a grid without missing cells, every
          // crossing is on terrain and needs no check (most of a DEM).
          if (!complete || !inGrid(i + q, j + p))
          {
            // The crossings ahead of this post, farthest first (past the last post,
            // those still inside the grid).
            for (std::size_t n = m; n-- > 0;)
            {
              const Crossing& c = crossings[n];
              if (inGrid(i + c.a0, j + c.b0) && inGrid(i + c.a1, j + c.b1) &&
                (cellValid(i + c.ci, j + c.cj) || cellValid(i + c.di, j + c.dj)))
                push(hull, size, crossingAhead(here, n));
            }
          }
          else
          {
            // Only the crossings above the chord to the next post and above the
            // segment between their neighbours can count (about a third on rough
            // terrain); they are sorted out without a branch each, since which way
            // each goes is as random as the terrain (the sweep took 20 % less).
            profile[0] = pointOf(here + nextOffset);
            profile[m + 1] = pointOf(here);
            for (std::size_t n = 0; n < m; ++n)
              profile[n + 1] = crossingAhead(here, m - 1 - n);
            std::size_t count = 0;
            for (std::size_t n = 1; n <= m; ++n)
            {
              kept[count] = profile[n];
              const std::size_t aboveChord = !below(profile[n], profile[0], profile[m + 1]);
              const std::size_t aboveNeighbours = !below(profile[n], profile[n - 1], profile[n + 1]);
              count += aboveChord & aboveNeighbours;
            }
            for (std::size_t n = 0; n < count; ++n)
              push(hull, size, kept[n]);
          }
          std::uint16_t& horizon =
            out[static_cast<std::size_t>(j - window.j0) * outX + static_cast<std::size_t>(i - window.i0)];
          if (!complete && !t.postUsed(i, j))
          {
            horizon = horizontalCode; // a post of no cell
            hulls[l].size = size;
            captureAt(run, l, k);
            continue;
          }
          const auto [x, z] = pointOf(here);
          pop(hull, size, x, z);
          // Below the horizontal too, where the terrain ahead falls away; nothing ahead:
          // the nadir.
          horizon = codeOfTangent(size > 0 && hull[size - 1].x > x ? (hull[size - 1].z - z) / (hull[size - 1].x - x)
                                                                     : -std::numeric_limits<double>::infinity());
          hull[size++] = { x, z };
          hulls[l].size = size;
          captureAt(run, l, k);
        }
    }
  });
}

std::array<double, 2> HorizonMap::reliefOf(const TerrainGrid& t)
{
  using Relief = std::array<double, 2>; // the steepest slope, the highest point
  return tbb::parallel_reduce(
    tbb::blocked_range<int>(0, t.cellsY()), Relief{ 0.0, -std::numeric_limits<double>::infinity() },
    [&](const tbb::blocked_range<int>& rows, Relief relief) {
      for (int j = rows.begin(); j < rows.end(); ++j)
        for (int i = 0; i < t.cellsX(); ++i)
          if (t.cellValid(i, j))
            for (const TerrainGrid::Triangle& triangle : t.cellTriangles(i, j))
            {
              relief[0] = std::max(relief[0], triangleSlope(triangle));
              for (const Vec3& corner : triangle)
                relief[1] = std::max(relief[1], corner.z);
            }
      return relief;
    },
    [](const Relief& a, const Relief& b) { return Relief{ std::max(a[0], b[0]), std::max(a[1], b[1]) }; });
}

double HorizonMap::triangleSlope(const TerrainGrid::Triangle& triangle)
{
  const Vec3 n = TerrainGrid::areaVector(triangle);
  return n.z > 0.0 ? std::sqrt(n.x * n.x + n.y * n.y) / n.z : 0.0; // not hypot: 2 M calls a grid, 5 times slower
}

void HorizonMap::measureRelief()
{
  const auto [steepest, highest] = reliefOf(this->Terrain);
  this->SteepestSlope = this->MarginSlope = steepest;
  this->HighestZ = highest;
  this->placeEdges();
}

void HorizonMap::placeEdges()
{
  // The shortest way to the edge u = 0 runs square to v's direction, against u's.
  const Vec3 u(this->Ux, this->Uy, 0.0), v(this->Vx, this->Vy, 0.0);
  const Vec3 acrossU = u - glm::dot(u, v) / glm::dot(v, v) * v, acrossV = v - glm::dot(v, u) / glm::dot(u, u) * u;
  const Vec3 ways[4] = { -acrossU, acrossU, -acrossV, acrossV };
  for (int edge = 0; edge < 4; ++edge)
  {
    const double a = std::atan2(ways[edge].y, ways[edge].x);
    this->EdgeAzimuths[edge] = a < 0.0 ? a + twoPi : a;
  }
}

double HorizonMap::postSpacing() const
{
  return std::sqrt(std::abs(this->Ux * this->Vy - this->Vx * this->Uy));
}

double HorizonMap::nearTangent(const Post& post, int a, double distance, double enough) const
{
  const TerrainGrid& t = this->Terrain;
  const int nx = t.postsX(), ny = t.postsY();
  const double z0 = t.vertices()[3 * post.index + 2];
  const double u0 = static_cast<double>(post.index % nx), v0 = static_cast<double>(post.index / nx);
  const double step = this->postSpacing(), du = this->AzimuthSteps[a][0], dv = this->AzimuthSteps[a][1];
  double highest = -std::numeric_limits<double>::infinity();
  for (double r = step; r <= distance * (1.0 + 1e-9) && step > 0.0; r += step)
  {
    const double u = u0 + r * du, v = v0 + r * dv;
    if (!(u >= 0.0 && v >= 0.0 && u <= nx - 1 && v <= ny - 1))
      break;
    const int i = std::min(static_cast<int>(u), nx - 2), j = std::min(static_cast<int>(v), ny - 2);
    if (i < 0 || j < 0 || (!this->Complete && !t.cellValid(i, j)))
      break;
    const double z = t.onCellTriangles(i, j, u - i, v - j).z;
    highest = std::max(highest, (z - z0) / r);
    if (highest >= enough)
      break;
  }
  return highest;
}

HorizonMap::Post HorizonMap::find(const Vec3& point) const
{
  const TerrainGrid& t = this->Terrain;
  const Vec3 r = point - t.origin();
  const double det = this->Ux * this->Vy - this->Vx * this->Uy;
  if (!(std::abs(det) > 0.0))
    return {}; // a grid without area has no posts to find
  const double x = r.x - this->X0, y = r.y - this->Y0;
  const double u = (this->Vy * x - this->Vx * y) / det, v = (this->Ux * y - this->Uy * x) / det;
  if (!(u > -1.0 && v > -1.0 && u < t.postsX() && v < t.postsY()))
    return {}; // also for points that are not numbers
  // A hundredth of the shorter cell side, squared (a post is found once each, 1 M a grid).
  const double tolerance2 =
    1e-4 * std::min(this->Ux * this->Ux + this->Uy * this->Uy, this->Vx * this->Vx + this->Vy * this->Vy);
  const int ic = static_cast<int>(std::lround(u)), jc = static_cast<int>(std::lround(v));
  auto at = [&](int i, int j) {
    const Vec3 offset = t.post(i, j) - point;
    return glm::dot(offset, offset) <= tolerance2 && t.postUsed(i, j);
  };
  auto post = [&](int i, int j) {
    return this->holds(i, j) ? Post{ true, static_cast<std::size_t>(j) * t.postsX() + i } : Post{};
  };
  // The nearest post by the mean map first (nearly always the one), then its neighbours
  // (on a grid bent from the mean).
  if (ic >= 0 && jc >= 0 && ic < t.postsX() && jc < t.postsY() && at(ic, jc))
    return post(ic, jc);
  for (int j = std::max(0, jc - 1); j <= std::min(t.postsY() - 1, jc + 1); ++j)
    for (int i = std::max(0, ic - 1); i <= std::min(t.postsX() - 1, ic + 1); ++i)
      if (at(i, j))
        return post(i, j);
  return {};
}

} // namespace terralux
