#include "horizons/horizon_map.h"

// A window's horizons (a process's piece of a terrain whose far terrain is given, with
// its halo): what its rays see, the window's triangles within the detail distance and
// the far terrain beyond it. Along each line of posts, swept from its far end:
// - within the detail distance D, the line is cut in blocks of at most D whose places
//   are fixed on the whole terrain's lattice (the same in every window); what lies
//   ahead of a post within D is the rest of its block (a hull swept as usual) and the
//   start of the next (a hull built forward, undone point by point as the posts step
//   back; Overmars and van Leeuwen's idea in its simplest, stack-like form);
// - beyond D, the far terrain's profile along the same line (its cells' edges and
//   diagonals crossed, as rays meet its triangles), to the far terrain's edge, added
//   to a hull as the post's distance D sweeps past it;
// - at D itself, both surfaces: a ray that leaves the cylinder of detail below the far
//   surface stops there (Visibility).
// A horizon is the steepest of these tangents, each the same set of points in any
// window that holds D around the post, so windows agree.

#include "horizons/horizon_lines.h"
#include "terrain/terrain_grid.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace terralux
{
using horizon_lines::atanOfPositive;
using horizon_lines::Crossing;
using horizon_lines::crossingsOf;

namespace
{
/// A point of a line's profile: distance along the line's mean direction, height (m),
/// relative to the window's origin.
struct Point
{
  double x, z;
};

double slopeBetween(const Point& a, const Point& b)
{
  return (b.z - a.z) / (b.x - a.x);
}

/// The steepest slope from `from` to points[0..n) (increasing x, all ahead of it, an
/// upper convex chain): the slopes rise to the tangent point and fall after it.
template <typename At>
double steepestOnChain(std::size_t n, const At& at, const Point& from)
{
  if (n == 0)
    return -std::numeric_limits<double>::infinity();
  std::size_t lo = 0, hi = n - 1;
  while (lo < hi)
  {
    const std::size_t mid = (lo + hi) / 2;
    if (slopeBetween(at(mid), at(mid + 1)) > slopeBetween(from, at(mid)))
      lo = mid + 1;
    else
      hi = mid;
  }
  return slopeBetween(from, at(lo));
}

/// The upper hull of points pushed nearest last (decreasing x), as the sweep meets them.
class HullBehind
{
public:
  void clear() { this->Points.clear(); }
  void push(const Point& point)
  {
    this->dropHiddenBy(point);
    this->Points.push_back(point);
  }
  /// The steepest slope from a point about to be pushed: the nearest point once those
  /// it hides are dropped.
  double steepestFromNext(const Point& from)
  {
    this->dropHiddenBy(from);
    return this->Points.empty() ? -std::numeric_limits<double>::infinity() : slopeBetween(from, this->Points.back());
  }
  double steepestFrom(const Point& from) const
  {
    const std::size_t n = this->Points.size();
    return steepestOnChain(n, [&](std::size_t k) { return this->Points[n - 1 - k]; }, from);
  }

private:
  /// Drops the nearest points that `point` and the next hide.
  void dropHiddenBy(const Point& point)
  {
    while (this->Points.size() >= 2)
    {
      const Point& a = this->Points[this->Points.size() - 1];
      const Point& b = this->Points[this->Points.size() - 2];
      if ((a.z - point.z) * (b.x - point.x) <= (b.z - point.z) * (a.x - point.x))
        this->Points.pop_back();
      else
        break;
    }
  }
  std::vector<Point> Points; // farthest first
};

/// The upper hull of points added in increasing x, each addition undone in reverse:
/// an addition finds its place by bisection and overwrites one point, which its undo
/// restores, so both take O(log n) and O(1) whatever the hull held.
class HullAhead
{
public:
  void clear()
  {
    this->Size = 0;
    this->Undos.clear();
  }
  void add(const Point& point)
  {
    // The most points of the hull that stay: h[m - 1] above the segment from h[m - 2]
    // to the new point, true up to some m and false beyond on a convex chain.
    std::size_t lo = std::min<std::size_t>(this->Size, 1), hi = this->Size;
    while (lo < hi)
    {
      const std::size_t mid = (lo + hi + 1) / 2;
      const Point &a = this->Points[mid - 2], &b = this->Points[mid - 1];
      if ((b.z - a.z) * (point.x - a.x) > (point.z - a.z) * (b.x - a.x))
        lo = mid;
      else
        hi = mid - 1;
    }
    Undo undo{ lo, this->Size, point.x, lo < this->Points.size() ? this->Points[lo] : Point{} };
    if (lo < this->Points.size())
      this->Points[lo] = point;
    else
      this->Points.push_back(point);
    this->Size = lo + 1;
    this->Undos.push_back(undo);
  }
  /// Undoes the additions of points beyond x.
  void undoBeyond(double x)
  {
    while (!this->Undos.empty() && this->Undos.back().x > x)
    {
      const Undo& undo = this->Undos.back();
      this->Points[undo.at] = undo.replaced;
      this->Size = undo.size;
      this->Undos.pop_back();
    }
  }
  double steepestFrom(const Point& from) const
  {
    return steepestOnChain(this->Size, [&](std::size_t k) { return this->Points[k]; }, from);
  }

private:
  struct Undo
  {
    std::size_t at, size;
    double x; // of the point added
    Point replaced;
  };
  std::vector<Point> Points; // increasing x; the first Size count
  std::size_t Size = 0;
  std::vector<Undo> Undos;
};

/// The height of a profile (increasing x, linear between its points) at a distance
/// that only decreases, as the sweep steps back: -inf outside it.
class ProfileCut
{
public:
  explicit ProfileCut(const std::vector<Point>& profile)
    : Profile(profile)
    , After(profile.size())
  {
  }
  double heightAt(double x, std::size_t first)
  {
    while (this->After > first && this->Profile[this->After - 1].x > x)
      --this->After;
    if (this->After <= first || this->After == this->Profile.size())
      return -std::numeric_limits<double>::infinity();
    const Point &a = this->Profile[this->After - 1], &b = this->Profile[this->After];
    return b.x > a.x ? a.z + (x - a.x) / (b.x - a.x) * (b.z - a.z) : a.z;
  }

private:
  const std::vector<Point>& Profile;
  std::size_t After; // the first point beyond the last distance asked
};

/// out[k] = the largest of in[k - r .. k + r] (within 0 .. n - 1), for n values
/// `step` apart: a monotone queue of candidates, each pushed and dropped once.
void maximumWithin(const float* in, float* out, std::ptrdiff_t step, int n, int r, std::vector<int>& queue)
{
  queue.assign(static_cast<std::size_t>(n), 0);
  std::size_t head = 0, tail = 0; // queue[head, tail): indices, their values decreasing
  int next = 0;                   // the next index to enter
  for (int k = 0; k < n; ++k)
  {
    for (; next < n && next <= k + r; ++next)
    {
      while (tail > head && in[queue[tail - 1] * step] <= in[next * step])
        --tail;
      queue[tail++] = next;
    }
    while (queue[head] < k - r)
      ++head;
    out[k * step] = in[queue[head] * step];
  }
}

/// The largest value within r of each of a w x h array's, in both directions.
std::vector<float> maximumWithinBox(std::vector<float> values, int w, int h, int r)
{
  std::vector<float> rows(values.size());
  tbb::parallel_for(0, h, [&](int j) {
    std::vector<int> queue;
    const std::size_t row = static_cast<std::size_t>(j) * w;
    maximumWithin(&values[row], &rows[row], 1, w, r, queue);
  });
  tbb::parallel_for(0, w, [&](int i) {
    std::vector<int> queue;
    maximumWithin(&rows[i], &values[i], w, h, r, queue);
  });
  return values;
}
} // namespace

HorizonMap::HorizonMap(const TerrainGrid& window, const GivenFarTerrain& far, double detailDistance, Density density,
  const HorizonMap* lender)
  : Terrain(window)
{
  this->fitMeanMap(window);
  const bool windowComplete = this->Complete;
  // The far terrain's mean map, the same in every window, in the window's posts: far
  // post (K, L) is window post (K s - i0, L s - j0).
  this->fitMeanMap(*far.grid);
  this->Complete = this->Complete && windowComplete;
  const double s = far.stride;
  const Vec3 shift = far.grid->origin() - window.origin();
  this->X0 += shift.x + (this->Ux * far.i0 + this->Vx * far.j0) / s;
  this->Y0 += shift.y + (this->Uy * far.i0 + this->Vy * far.j0) / s;
  this->Ux /= s, this->Uy /= s, this->Vx /= s, this->Vy /= s;
  this->placeEdges();
  this->findLocalRelief(*far.grid, detailDistance);
  this->ExtentU0 = -far.i0, this->ExtentV0 = -far.j0;
  this->ExtentU1 = (far.grid->postsX() - 1) * s - far.i0, this->ExtentV1 = (far.grid->postsY() - 1) * s - far.j0;
  const std::vector<std::array<int, 2>>& slotSteps = this->placeAzimuths(density);
  this->Held = { 0, window.postsX() - 1, 0, window.postsY() - 1 };
  this->holdPosts();
  this->findCopiedSlots(lender);
  this->Elevations.resize(this->HeldCount * slotSteps.size());
  for (std::size_t slot = 0; slot < slotSteps.size(); ++slot)
    if (!this->copied(slot))
      this->sweepWindow(
        slotSteps[slot][0], slotSteps[slot][1], far, detailDistance, &this->Elevations[slot * this->PostCount]);
  this->copyFromLender(lender);
}

void HorizonMap::findLocalRelief(const TerrainGrid& far, double detailDistance)
{
  // The far terrain's relief bounds every sight past the detail distance; within it,
  // the window's triangles in a box of posts that holds the distance around the post.
  const auto [farSteepest, farHighest] = reliefOf(far);
  this->MarginSlope = farSteepest;
  const TerrainGrid& t = this->Terrain;
  const int nx = t.postsX(), ny = t.postsY();
  const double spacing = std::min(std::hypot(this->Ux, this->Uy), std::hypot(this->Vx, this->Vy));
  const double posts = spacing > 0.0 ? std::ceil(detailDistance / spacing) + 1.0 : 0.0;
  const int r = static_cast<int>(std::min<double>(posts, std::max(nx, ny)));
  const float lowest = -std::numeric_limits<float>::infinity();
  std::vector<float> cellSlopes(static_cast<std::size_t>(t.cellsX()) * t.cellsY(), 0.0f);
  tbb::parallel_for(0, t.cellsY(), [&](int j) {
    for (int i = 0; i < t.cellsX(); ++i)
      if (t.cellValid(i, j))
        for (const TerrainGrid::Triangle& triangle : t.cellTriangles(i, j))
        {
          float& steepest = cellSlopes[static_cast<std::size_t>(j) * t.cellsX() + i];
          steepest = std::max(steepest, static_cast<float>(triangleSlope(triangle)));
        }
  });
  std::vector<float> slopes(static_cast<std::size_t>(nx) * ny, 0.0f), heights(slopes.size(), lowest);
  // Each cell's slope at its four posts (a post's box then holds the cells around it).
  tbb::parallel_for(0, ny, [&](int j) {
    for (int i = 0; i < nx; ++i)
    {
      float steepest = 0.0f;
      for (int cj = std::max(0, j - 1); cj <= std::min(j, ny - 2); ++cj)
        for (int ci = std::max(0, i - 1); ci <= std::min(i, nx - 2); ++ci)
          steepest = std::max(steepest, cellSlopes[static_cast<std::size_t>(cj) * t.cellsX() + ci]);
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      slopes[k] = steepest;
      if (t.postUsed(i, j))
        heights[k] = static_cast<float>(t.post(i, j).z);
    }
  });
  this->LocalSlope = maximumWithinBox(std::move(slopes), nx, ny, r);
  this->LocalHighest = maximumWithinBox(std::move(heights), nx, ny, r);
  // Rounded up to the next float: a bound stays a bound.
  const float farSlope = std::nextafter(static_cast<float>(farSteepest), std::numeric_limits<float>::infinity());
  const float farTop = std::nextafter(static_cast<float>(farHighest), std::numeric_limits<float>::infinity());
  tbb::parallel_for(std::size_t{ 0 }, this->LocalSlope.size(), [&](std::size_t k) {
    this->LocalSlope[k] = std::nextafter(std::max(this->LocalSlope[k], farSlope), std::numeric_limits<float>::infinity());
    this->LocalHighest[k] = std::nextafter(std::max(this->LocalHighest[k], farTop), std::numeric_limits<float>::infinity());
  });
}

void HorizonMap::sweepWindow(
  int q, int p, const GivenFarTerrain& given, double detailDistance, std::uint16_t* out) const
{
  const TerrainGrid& t = this->Terrain;
  const TerrainGrid& far = *given.grid;
  const int nx = t.postsX(), ny = t.postsY(), stride = given.stride;
  const WorkSplit::Window whole{ 0, nx - 1, 0, ny - 1 };
  const std::vector<LineRun> runs = runsWithin(q, p, whole);
  const std::vector<Crossing> crossings = crossingsOf(q, p);
  double dx = this->Ux * q + this->Vx * p, dy = this->Uy * q + this->Vy * p;
  const double length = std::hypot(dx, dy);
  if (!(length > 0.0 && detailDistance > 0.0))
  {
    std::fill_n(out, this->PostCount, horizontalCode);
    return;
  }
  dx /= length, dy /= length;
  // Posts per block: a block spans at most D, and D ahead of a post ends within the
  // next block.
  const long long block = std::max(1LL, static_cast<long long>(std::floor(detailDistance / length)));
  const long long lineNorm = static_cast<long long>(q) * q + static_cast<long long>(p) * p;
  const bool complete = this->Complete;
  const float* xyz = t.vertices();
  auto inGrid = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny; };
  auto cellValid = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx - 1 && j < ny - 1 && t.cellValid(i, j); };
  const Vec3 origin = t.origin();
  // Where the far terrain's posts lie in its parameters U, V (a window post's over s).
  const double farLastU = far.postsX() - 1, farLastV = far.postsY() - 1;
  // The far surface at (U, V) on the line, in the window's frame: on the triangle of
  // its cell that rays meet (TerrainGrid::cellTriangles' split).
  const Vec3 farShift = far.origin() - origin;
  auto farPoint = [&](double u, double v) {
    const int i = std::clamp(static_cast<int>(std::floor(u)), 0, far.postsX() - 2);
    const int j = std::clamp(static_cast<int>(std::floor(v)), 0, far.postsY() - 2);
    const double a = std::clamp(u - i, 0.0, 1.0), b = std::clamp(v - j, 0.0, 1.0);
    const Vec3 position = far.onCellTriangles(i, j, a, b) + farShift;
    return Point{ position.x * dx + position.y * dy, position.z };
  };

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs.size(), 8), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<Point> profile, farProfile;
    std::vector<std::uint8_t> onTerrain; // and a point some hull may keep
    std::vector<std::size_t> postAt;
    std::vector<double> farT;
    HullBehind rest, beyond;
    HullAhead next;
    for (std::size_t n = r.begin(); n < r.end(); ++n)
    {
      const LineRun& run = runs[n];
      // The window's profile: each post, then the crossings to the next.
      profile.clear(), onTerrain.clear(), postAt.clear();
      for (int k = 0; k < run.count; ++k)
      {
        const int i = run.i + k * q, j = run.j + k * p;
        const float* here = xyz + 3 * (static_cast<std::size_t>(j) * nx + i);
        postAt.push_back(profile.size());
        profile.push_back({ here[0] * dx + here[1] * dy, here[2] });
        onTerrain.push_back(complete || t.postUsed(i, j));
        // Where the step ahead lies inside a grid without missing cells, every crossing
        // is on terrain.
        const bool checked = !complete || !inGrid(i + q, j + p);
        for (const Crossing& c : crossings)
        {
          if (checked && !(inGrid(i + c.a0, j + c.b0) && inGrid(i + c.a1, j + c.b1) &&
                (cellValid(i + c.ci, j + c.cj) || cellValid(i + c.di, j + c.dj))))
            continue;
          const float* a = xyz + 3 * (static_cast<std::size_t>(j + c.b0) * nx + i + c.a0);
          const float* b = xyz + 3 * (static_cast<std::size_t>(j + c.b1) * nx + i + c.a1);
          const double f = c.f;
          profile.push_back(
            { (a[0] + f * (b[0] - a[0])) * dx + (a[1] + f * (b[1] - a[1])) * dy, a[2] + f * (b[2] - a[2]) });
          onTerrain.push_back(1);
        }
      }
      // A crossing below the segment between its neighbours is no hull's point, nor
      // where D cuts next to it (the profile bends up there): about two thirds of
      // them on rough terrain. The cuts still read the whole profile.
      if (complete)
        for (std::size_t k = 0, m = 1; m + 1 < profile.size(); ++m)
        {
          while (k < postAt.size() && postAt[k] < m)
            ++k;
          const Point &before = profile[m - 1], &c = profile[m], &after = profile[m + 1];
          if ((k == postAt.size() || postAt[k] != m) &&
            (c.z - before.z) * (after.x - before.x) <= (after.z - before.z) * (c.x - before.x))
            onTerrain[m] = 0;
        }
      // The line's place on the whole terrain: post k is its kLine0 + k-th, and it
      // passes through (ua, va) + t (q, p) in the whole terrain's posts (the far
      // terrain's first at 0), the same in every window.
      const long long gi = run.i + static_cast<long long>(given.i0), gj = run.j + static_cast<long long>(given.j0);
      const long long kLine0 = floorDivide<long long>(q * gi + p * gj, lineNorm);
      const double ua = static_cast<double>(gi - kLine0 * q), va = static_cast<double>(gj - kLine0 * p);
      // The far profile, from a little before D ahead of the first post to the far
      // terrain's edge: where the line crosses its cells' edges and diagonals.
      double tLow = static_cast<double>(kLine0 + block - 1 - stride), tHigh = std::numeric_limits<double>::infinity();
      auto clip = [&](double start, double step, double last) {
        // start + t step within [0, last s]
        if (step > 0.0)
          tLow = std::max(tLow, -start / step), tHigh = std::min(tHigh, (last * stride - start) / step);
        else if (step < 0.0)
          tLow = std::max(tLow, (last * stride - start) / step), tHigh = std::min(tHigh, -start / step);
        else if (start < 0.0 || start > last * stride)
          tHigh = -std::numeric_limits<double>::infinity();
      };
      clip(ua, q, farLastU);
      clip(va, p, farLastV);
      farT.clear(), farProfile.clear();
      if (tLow < tHigh)
      {
        auto crossingsOfLines = [&](double start, double step) {
          // t where start + t step is a multiple of the stride, increasing
          const auto before = static_cast<std::ptrdiff_t>(farT.size());
          if (step > 0.0)
            for (double c = std::ceil((start + tLow * step) / stride); c <= std::floor((start + tHigh * step) / stride); c += 1.0)
              farT.push_back((c * stride - start) / step);
          else if (step < 0.0)
            for (double c = std::floor((start + tLow * step) / stride); c >= std::ceil((start + tHigh * step) / stride); c -= 1.0)
              farT.push_back((c * stride - start) / step);
          std::inplace_merge(farT.begin(), farT.begin() + before, farT.end());
        };
        crossingsOfLines(ua, q);
        crossingsOfLines(va, p);
        crossingsOfLines(ua + va, q + p);
        auto segmentValid = [&](double t0, double t1) {
          const double tm = 0.5 * (t0 + t1);
          const int i = static_cast<int>(std::floor((ua + tm * q) / stride)), j = static_cast<int>(std::floor((va + tm * p) / stride));
          return i >= 0 && j >= 0 && i < far.cellsX() && j < far.cellsY() && far.cellValid(i, j);
        };
        for (std::size_t k = 0; k < farT.size(); ++k)
        {
          const double tk = farT[k];
          if (!complete && !((k > 0 && segmentValid(farT[k - 1], tk)) || (k + 1 < farT.size() && segmentValid(tk, farT[k + 1]))))
            continue;
          farProfile.push_back(farPoint((ua + tk * q) / stride, (va + tk * p) / stride));
        }
      }

      // The sweep, from the far end.
      rest.clear(), beyond.clear(), next.clear();
      std::size_t farPushed = farProfile.size();
      ProfileCut fineCut(profile), farCut(farProfile);
      long long currentBlock = std::numeric_limits<long long>::min();
      for (int k = run.count - 1; k >= 0; --k)
      {
        const std::size_t at = postAt[static_cast<std::size_t>(k)];
        const std::size_t end = k + 1 < run.count ? postAt[static_cast<std::size_t>(k) + 1] : profile.size() - 1;
        const Point post = profile[at];
        const double reach = post.x + detailDistance;
        const long long blockOfPost = floorDivide<long long>(kLine0 + k, block);
        if (blockOfPost != currentBlock)
        {
          // The last post of its block: the rest of the block is what lies up to the
          // next post, and the next block starts there.
          currentBlock = blockOfPost;
          rest.clear(), next.clear();
          if (k + 1 < run.count)
            for (std::size_t m = end; m < profile.size() && profile[m].x <= reach; ++m)
              if (onTerrain[m])
                next.add(profile[m]);
        }
        else
          next.undoBeyond(reach);
        for (std::size_t m = end + 1; m-- > at + 1;)
          if (onTerrain[m])
            rest.push(profile[m]);
        while (farPushed > 0 && farProfile[farPushed - 1].x >= reach)
          beyond.push(farProfile[--farPushed]);

        std::uint16_t& horizon = out[static_cast<std::size_t>(run.j + k * p) * nx + static_cast<std::size_t>(run.i + k * q)];
        horizon = horizontalCode; // a post of no cell
        if (!onTerrain[at])
          continue;
        double steepest = std::max({ rest.steepestFromNext(post), next.steepestFrom(post), beyond.steepestFrom(post) });
        if (complete)
        {
          // Both surfaces where the cylinder of detail ends.
          steepest = std::max(steepest, (fineCut.heightAt(reach, at) - post.z) / detailDistance);
          steepest = std::max(steepest, (farCut.heightAt(reach, 0) - post.z) / detailDistance);
        }
        horizon = codeOfTangent(steepest); // below the horizontal too
      }
    }
  });
}
} // namespace terralux
