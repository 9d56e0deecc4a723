// Work split between processes (work_split.h), with threads standing in for MPI ranks:
// each builds the horizons' map and the posts' skies from its share and the others'
// broadcasts, and must hold what one process alone finds, bit for bit: the posts' skies
// and suns everywhere, the horizons in its own window of posts (a band of rows) only.

#include "base/angles.h"
#include "sky/cie_sky.h"
#include "parallel/held_posts.h"
#include "horizons/horizon_map.h"
#include "horizons/horizon_sky.h"
#include "evaluation/open_sky.h"
#include "evaluation/post_lattice.h"
#include "horizons/post_sky.h"
#include "horizons/post_sunlight.h"
#include "sky/sky_hierarchy.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"
#include "parallel/work_split.h"

#include "base/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

using namespace terralux;
using namespace terralux_test;

namespace
{
// `parts` threads that meet at each share: the owner's bytes go through a common buffer
// to the others, as MPI_Bcast sends them.
class ThreadRanks
{
public:
  /// `parts` bands of the rows of a grid `rows` posts high, neighbours sharing a row
  /// (as VTK's pieces do).
  ThreadRanks(int parts, int rows = 1, bool pointToPoint = false)
    : Parts(parts)
    , PointToPoint(pointToPoint)
  {
    for (int p = 0; p < parts; ++p)
      this->Windows.push_back({ 0, std::numeric_limits<int>::max(), p * (rows - 1) / parts, (p + 1) * (rows - 1) / parts });
  }
  /// Given windows (blocks, as VTK cuts pieces), sending point to point.
  explicit ThreadRanks(const std::vector<WorkSplit::Window>& windows)
    : Parts(static_cast<int>(windows.size()))
    , PointToPoint(true)
    , Windows(windows)
  {
  }
  class Split : public WorkSplit
  {
  public:
    Split(ThreadRanks& ranks, int part)
      : Ranks(ranks)
      , Part(part)
    {
    }
    int part() const override { return this->Part; }
    int parts() const override { return this->Ranks.Parts; }
    Window window(int part) const override { return this->Ranks.Windows[static_cast<std::size_t>(part)]; }
    void share(void* data, std::size_t size, int owner) const override
    {
      ++this->Shares;
      if (this->Part == owner)
        this->Ranks.Buffer.assign(static_cast<const char*>(data), static_cast<const char*>(data) + size);
      this->Ranks.meet();
      if (this->Part != owner)
      {
        EXPECT_EQ(this->Ranks.Buffer.size(), size);
        std::memcpy(data, this->Ranks.Buffer.data(), std::min(size, this->Ranks.Buffer.size()));
      }
      this->Ranks.meet();
    }
    bool allSucceeded(bool succeeded) const override
    {
      if (!succeeded)
        ++this->Ranks.Failures;
      this->Ranks.meet();
      const bool all = this->Ranks.Failures == 0;
      this->Ranks.meet();
      if (this->Part == 0)
        this->Ranks.Failures = 0;
      this->Ranks.meet();
      return all;
    }
    bool sendsPointToPoint() const override { return this->Ranks.PointToPoint; }
    void send(std::vector<char> bytes, int to, int tag) const override
    {
      ++this->Sends;
      std::lock_guard<std::mutex> lock(this->Ranks.Mutex);
      this->Ranks.Mail[{ this->Part, to, tag }].push_back(std::move(bytes));
      this->Ranks.Met.notify_all();
    }
    std::vector<char> receive(int from, int tag) const override
    {
      std::unique_lock<std::mutex> lock(this->Ranks.Mutex);
      std::deque<std::vector<char>>& box = this->Ranks.Mail[{ from, this->Part, tag }];
      this->Ranks.Met.wait(lock, [&]() { return !box.empty(); });
      std::vector<char> bytes = std::move(box.front());
      box.pop_front();
      return bytes;
    }
    mutable int Shares = 0, Sends = 0;

  private:
    ThreadRanks& Ranks;
    int Part;
  };
  /// Runs work(split) on every part at once.
  void run(const std::function<void(const Split&)>& work)
  {
    std::vector<std::thread> threads;
    std::vector<std::unique_ptr<Split>> splits;
    for (int part = 0; part < this->Parts; ++part)
      splits.push_back(std::make_unique<Split>(*this, part));
    for (int part = 0; part < this->Parts; ++part)
      threads.emplace_back([&, part]() { work(*splits[part]); });
    for (std::thread& thread : threads)
      thread.join();
  }

private:
  void meet()
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    const long generation = this->Generation;
    if (++this->Arrived == this->Parts)
    {
      this->Arrived = 0;
      ++this->Generation;
      this->Met.notify_all();
    }
    else
      this->Met.wait(lock, [&]() { return this->Generation != generation; });
  }
  int Parts;
  bool PointToPoint = false;
  std::vector<WorkSplit::Window> Windows;
  std::map<std::array<int, 3>, std::deque<std::vector<char>>> Mail; // (from, to, tag)
  std::vector<char> Buffer;
  std::atomic<int> Failures{ 0 };
  std::mutex Mutex;
  std::condition_variable Met;
  int Arrived = 0;
  long Generation = 0;
};

/// Runs work(split, pointToPoint, parts) on an nx x ny grid cut in two bands of rows
/// and in two blocks over a band, broadcasting and sending point to point.
void runOnBandsAndBlocks(
  int nx, int ny, const std::function<void(const ThreadRanks::Split&, bool, std::size_t)>& work)
{
  using Window = WorkSplit::Window;
  const std::vector<std::vector<Window>> cuts{ { { 0, nx - 1, 0, 40 }, { 0, nx - 1, 40, ny - 1 } },
    { { 0, 48, 0, 40 }, { 48, nx - 1, 0, 40 }, { 0, nx - 1, 40, ny - 1 } } };
  for (const std::vector<Window>& windows : cuts)
    for (const bool pointToPoint : { false, true })
    {
      ThreadRanks ranks = pointToPoint ? ThreadRanks(windows) : ThreadRanks(static_cast<int>(windows.size()), ny);
      ranks.run([&](const ThreadRanks::Split& split) { work(split, pointToPoint, windows.size()); });
    }
}

constexpr Hills hills{ 60.0, 40.0, 55.0, 25.0, 23.0 };

/// How many of post (i, j)'s sky values (irradiance, sky view factor, on its Horn
/// normal) differ between a process's skies and one process's; 2 where either lacks it.
int skyDifferences(const PostSky& skies, const PostSky& alone, const TerrainGrid& grid, int i, int j)
{
  const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * grid.postsX() + i };
  PostSky::Value value, expected;
  const Vec3 normal = grid.normalAt(i, j, true);
  if (!skies.found(post, normal, value) || !alone.found(post, normal, expected))
    return 2;
  return (value.irradiance[0] != expected.irradiance[0]) + (value.skyViewFactor != expected.skyViewFactor);
}
} // namespace

TEST(WorkSplit, RanksBuildTheHorizonsAndSkiesOneProcessBuilds)
{
  const auto grid = makeGrid(97, 81, 10.0, hills);
  const Visibility rays(sceneOf({ grid.get() }));
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(50.0 * degree, 2.0)), 100.0, 5);
  const OpenSky open(sky);
  for (const HorizonMap::Density density : HorizonMap::densities)
  {
    const HorizonMap alone(*grid, density);
    const HorizonSky aloneSky(rays, open, &alone);
    const PostSky aloneSkies(*grid, aloneSky, open, true);
    const std::vector<HorizonMap::Sight> suns{ alone.sight(2.0, 15.0 * degree), alone.sight(-0.7, 30.0 * degree) };
    const PostSunlight aloneSunlight(*grid, alone, suns);
    for (const int parts : { 2, 3 })
    for (const bool pointToPoint : { false, true })
    {
      ThreadRanks ranks(parts, grid->postsY(), pointToPoint);
      ranks.run([&](const ThreadRanks::Split& split) {
        const HorizonMap map(*grid, density, &split);
        const int sweeps = split.Shares;
        // Every azimuth broadcast once, from its owner; or each window's sweeps handed
        // on along the lines, azimuth by azimuth, to the band behind.
        EXPECT_EQ(sweeps, pointToPoint ? 0 : map.azimuthCount());
        if (pointToPoint)
          EXPECT_EQ(split.Sends, (split.part() > 0) * (map.azimuthCount() / 2 - 1) +
              (split.part() < parts - 1) * (map.azimuthCount() / 2 - 1));
        const WorkSplit::Window own = split.window(split.part());
        const HorizonSky mapped(rays, open, &map);
        const int sent = split.Sends;
        const PostSky skies(*grid, mapped, open, true, &split);
        // The skies' rows too: broadcast, or each window sent to each other process.
        EXPECT_EQ(split.Shares - sweeps + split.Sends - sent, pointToPoint ? 2 * (parts - 1) : 2 * parts);
        const PostSunlight sunlight(*grid, map, suns, &split);
        int differences = 0;
        for (int j = 0; j < grid->postsY(); ++j)
          for (int i = 0; i < grid->postsX(); ++i)
          {
            const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * grid->postsX() + i };
            // The map holds its window's posts only, and finds no other.
            const bool held = own.holds(i, j);
            differences += map.holds(i, j) != held;
            differences += static_cast<bool>(map.find(grid->post(i, j))) != held;
            for (int a = 0; held && a < map.azimuthCount(); ++a)
              differences += map.trueElevation(post, a) != alone.trueElevation(post, a);
            differences += skyDifferences(skies, aloneSkies, *grid, i, j);
            differences += sunlight.at(i, j).seen != aloneSunlight.at(i, j).seen;
            differences += sunlight.at(i, j).hidden != aloneSunlight.at(i, j).hidden;
          }
        EXPECT_EQ(differences, 0) << "part " << split.part() << " of " << parts << ", " << static_cast<int>(density) << " azimuths";
      });
    }
  }
}

TEST(WorkSplit, RanksRefineACoarseMapAndFindItsSkiesAgainAsOneProcessDoes)
{
  // A coarse map refined at every third post (horizon_refinement.cxx), and the posts'
  // skies found again there (PostSky::findAgain): each rank refines its window's posts
  // from the whole grid and shares their skies, as one process would.
  const auto grid = makeGrid(97, 81, 10.0, hills);
  const Visibility rays(sceneOf({ grid.get() }));
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(50.0 * degree, 2.0)), 100.0, 5);
  const OpenSky open(sky);
  const int nx = grid->postsX(), ny = grid->postsY();
  auto flagged = [](int i, int j) { return (i + 2 * j) % 3 == 0; };
  auto flagsOf = [&](const WorkSplit::Window& w) {
    std::vector<std::uint8_t> flags;
    for (int j = w.j0; j <= w.j1; ++j)
      for (int i = w.i0; i <= w.i1; ++i)
        flags.push_back(flagged(i, j));
    return flags;
  };
  const WorkSplit::Window whole{ 0, nx - 1, 0, ny - 1 };
  const HorizonMap coarse(*grid, HorizonMap::Density::Coarse);
  const HorizonMap alone(coarse, flagsOf(whole));
  const HorizonSky coarseSky(rays, open, &coarse), aloneSky(rays, open, &alone);
  PostSky aloneSkies(*grid, coarseSky, open, true);
  aloneSkies.findAgain(flagsOf(whole), aloneSky, open, true);
  for (const int parts : { 2, 3 })
    for (const bool pointToPoint : { false, true })
    {
      ThreadRanks ranks(parts, ny, pointToPoint);
      ranks.run([&](const ThreadRanks::Split& split) {
        EXPECT_EQ(WorkSplit::total(&split, static_cast<std::size_t>(split.part() + 1)),
          static_cast<std::size_t>(parts * (parts + 1) / 2));
        const WorkSplit::Window own = WorkSplit::ownWindow(&split, nx, ny);
        const HorizonMap coarseOwn(*grid, HorizonMap::Density::Coarse, &split);
        const HorizonMap refined(coarseOwn, flagsOf(own));
        const HorizonSky coarseOwnSky(rays, open, &coarseOwn), refinedSky(rays, open, &refined);
        PostSky skies(*grid, coarseOwnSky, open, true, &split);
        skies.findAgain(flagsOf(own), refinedSky, open, true, &split);
        int differences = 0, flaggedHeld = 0;
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i)
          {
            const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * nx + i };
            for (int a = 0; own.holds(i, j) && a < refined.azimuthCount(); ++a)
              differences += refined.trueElevation(post, a) != alone.trueElevation(post, a);
            flaggedHeld += own.holds(i, j) && flagged(i, j);
            differences += skyDifferences(skies, aloneSkies, *grid, i, j);
          }
        EXPECT_EQ(refined.refinedPosts(), static_cast<std::size_t>(flaggedHeld));
        EXPECT_EQ(differences, 0) << "part " << split.part() << " of " << parts;
      });
    }
}

TEST(WorkSplit, ProcessesHoldThePostsWithinTheDetailDistanceOfTheirWindowsOnly)
{
  // A turned grid of oblong cells (10 x 14 m): the halo counts the narrowest cell
  // height, 10 m, whatever the turn.
  const int nx = 97, ny = 81;
  const double turn = 30.0 * degree, c = std::cos(turn), s = std::sin(turn);
  TerrainGrid grid(nx, ny, Vec3(0.0));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
      const double x = 10.0 * i, y = 14.0 * j;
      grid.setPost(i, j, Vec3(c * x - s * y, s * x + c * y, hills(x, y)));
    }
  EXPECT_EQ(HeldPosts::haloFor(grid, 0.0), -1);
  EXPECT_EQ(HeldPosts::haloFor(grid, 35.0), 6); // 3.5 cells, the hit's cell, a margin
  EXPECT_EQ(HeldPosts::haloFor(grid, 1e6), -1); // beyond the grid: every post
  const int halo = HeldPosts::haloFor(grid, 35.0);

  const Visibility rays(sceneOf({ &grid }));
  const SkyHierarchy sky(CieGeneralSky(12, directionFromZenithAzimuth(50.0 * degree, 2.0)), 100.0, 5);
  const OpenSky open(sky);
  const HorizonMap alone(grid);
  const HorizonSky aloneSky(rays, open, &alone);
  const PostSky aloneSkies(grid, aloneSky, open, true);
  const std::vector<HorizonMap::Sight> suns{ alone.sight(2.0, 15.0 * degree) };
  const PostSunlight aloneSunlight(grid, alone, suns);
  runOnBandsAndBlocks(nx, ny, [&](const ThreadRanks::Split& split, bool pointToPoint, std::size_t parts) {
    const HorizonMap map(grid, HorizonMap::Density::Standard, &split);
    const HorizonSky mapped(rays, open, &map);
    const PostSky skies(grid, mapped, open, true, &split, halo);
    const PostSunlight sunlight(grid, map, suns, &split, halo);
    const HeldPosts held(nx, ny, &split, halo);
    const WorkSplit::Window own = split.window(split.part()).clampedTo(nx, ny);
    EXPECT_EQ(held.own().i0, std::max(0, own.i0 - halo));
    EXPECT_EQ(held.own().j1, std::min(ny - 1, own.j1 + halo));
    EXPECT_LT(held.count(), static_cast<std::size_t>(nx) * ny);
    int differences = 0, heldPosts = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * nx + i };
        PostSky::Value value, expected;
        const Vec3 normal = grid.normalAt(i, j, true);
        ASSERT_TRUE(aloneSkies.found(post, normal, expected));
        if (!held.holds(i, j))
        {
          differences += skies.found(post, normal, value); // none of it kept
          continue;
        }
        ++heldPosts;
        ASSERT_TRUE(skies.found(post, normal, value));
        differences += value.irradiance[0] != expected.irradiance[0];
        differences += value.skyViewFactor != expected.skyViewFactor;
        differences += sunlight.at(i, j).seen != aloneSunlight.at(i, j).seen;
        differences += sunlight.at(i, j).hidden != aloneSunlight.at(i, j).hidden;
      }
    EXPECT_EQ(differences, 0) << "part " << split.part() << " of " << parts;
    EXPECT_EQ(static_cast<std::size_t>(heldPosts), held.count());
    // A read outside what the process holds is an error, not a wrong value.
    const double farRow = own.j0 > 0 ? 0.5 : ny - 1.5;
    Spectrum irradiance;
    EXPECT_THROW(skies.interpolate(own.i0 + 0.5, farRow, irradiance), Error);
    EXPECT_THROW(sunlight.between(own.i0 + 0.5, farRow), Error);
    EXPECT_TRUE(skies.interpolate(own.i0 + 0.5, own.j0 + 0.5, irradiance));
  });
}

TEST(WorkSplit, ProcessesHoldTheLatticeWithinTheDetailDistanceOfTheirWindowsOnly)
{
  // Each process gathers the lattice posts of its window in two passes, refining alike
  // the cells whose corners disagree, and holds what the others gathered within its
  // halo: there every reading equals one process's, bit for bit; beyond, it throws.
  const int nx = 97, ny = 81, step = 4, halo = 6;
  auto gathered = [](int i, int j) {
    PostLattice::Gathered g;
    // Smooth in the west, rough in the east: some cells refine, some do not.
    const double light = 10.0 + (i > 60 ? 8.0 * std::sin(1.7 * i) * std::cos(0.9 * j) : 0.01 * i + 0.02 * j);
    g.reflected = { light, 0.5 * light, 0.25 * light };
    g.variance = 0.5 + 0.01 * i;
    g.terrainSeen = 0.3 + 0.002 * j;
    g.terrainByPart[0] = 0.29 + 0.002 * j; // its rays met a little less than its horizons show
    g.voidSeen = 0.01;
    g.received = 100.0;
    g.edge = i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
    return g;
  };
  auto gatherLattice = [&](PostLattice& lattice, const WorkSplit* split) {
    for (const bool first : { true, false })
    {
      if (!first)
        lattice.refine(0.02);
      for (int j = 0; j < ny; j += step)
        for (int i = 0; i < nx; i += step)
          if (PostLattice::gathers(i, j, split) && lattice.gatheredInPass(i, j, first) && !(i == 24 && j == 40))
            lattice.set(i, j, gathered(i, j)); // (24, 40): a lattice post with no data
      if (split)
        lattice.share();
    }
  };
  PostLattice alone(nx, ny, step);
  gatherLattice(alone, nullptr);
  runOnBandsAndBlocks(nx, ny, [&](const ThreadRanks::Split& split, bool pointToPoint, std::size_t parts) {
    PostLattice lattice(nx, ny, step, &split, halo);
    gatherLattice(lattice, &split);
    // Each share sends to (or broadcasts from) each other process, per vector (six).
    EXPECT_EQ(split.Shares + split.Sends, 2 * 6 * static_cast<int>(pointToPoint ? parts - 1 : parts));
    const HeldPosts read(nx, ny, &split, halo); // where gather rays read
    int differences = 0, coarse = 0, refined = 0;
    for (int j = read.own().j0; j <= read.own().j1; ++j)
      for (int i = read.own().i0; i <= read.own().i1; ++i)
      {
        const PostLattice::Around a = lattice.around(i, j), b = alone.around(i, j);
        differences += a.variance != b.variance || a.largestPerTerrainSeen != b.largestPerTerrainSeen ||
          a.leastPerTerrainSeen != b.leastPerTerrainSeen || a.edgeCorner != b.edgeCorner;
        Spectrum r, s;
        const bool found = lattice.reflectedAt(i + 0.3, j + 0.6, r);
        differences += found != alone.reflectedAt(i + 0.3, j + 0.6, s) || (found && r != s);
        Spectrum p, q;
        const bool foundPer = lattice.perTerrainSeenAt(i, j, p);
        differences += foundPer != alone.perTerrainSeenAt(i, j, q) || (foundPer && p != q);
        if (i % (2 * step) == 1 && j % (2 * step) == 1)
          (alone.gatheredInPass(i - 1 + step, j - 1, false) ? refined : coarse) += 1;
      }
    // The window's own posts read the 4 x 4 lattice posts around them (mapExcessAt).
    const WorkSplit::Window window = split.window(split.part()).clampedTo(nx, ny);
    for (int j = window.j0; j <= window.j1; ++j)
      for (int i = window.i0; i <= window.i1; ++i)
      {
        double e = 0.0, f = 0.0;
        const bool found = lattice.mapExcessAt(i, j, 0.1, 0.02, e);
        differences += found != alone.mapExcessAt(i, j, 0.1, 0.02, f) || e != f;
      }
    EXPECT_EQ(differences, 0) << "part " << split.part() << " of " << parts;
    EXPECT_GT(coarse, 0);
    EXPECT_GT(refined, 0);
    // Beyond the halo: an error, not a wrong value.
    const WorkSplit::Window own = split.window(split.part()).clampedTo(nx, ny);
    const double farRow = own.j0 > 0 ? 0.5 : ny - 1.5;
    Spectrum r;
    EXPECT_THROW(lattice.reflectedAt(own.i0 + 0.5, farRow, r), Error);
    EXPECT_THROW(lattice.around(own.i0, static_cast<int>(farRow)), Error);
  });
}

TEST(WorkSplit, WindowsHandingHullsOnSweepTheHorizonsOneProcessSweeps)
{
  // A turned grid of oblong cells with a hole of no data across the windows' borders
  // (the sweep's checked crossings), cut as VTK cuts pieces (blocks sharing their
  // border posts), in a pinwheel (windows that wait for each other in a ring toward
  // some azimuths), and with a process whose window is empty.
  const int n = 65;
  const double turn = 30.0 * degree, c = std::cos(turn), s = std::sin(turn);
  auto inHole = [](int i, int j) { return i >= 28 && i < 37 && j >= 20 && j < 45; };
  TerrainGrid grid(n, n, Vec3(0.0));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const double x = 10.0 * i, y = 14.0 * j;
      grid.setPost(i, j, Vec3(c * x - s * y, s * x + c * y, hills(x, y) + 40.0 * std::sin(0.9 * i) * std::cos(1.3 * j)));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i)
      grid.setCellValid(i, j, !inHole(i, j));
  ASSERT_TRUE(grid.facesUp());
  using Window = WorkSplit::Window;
  const std::vector<std::vector<Window>> cuts{
    { { 0, 32, 0, 32 }, { 32, 64, 0, 32 }, { 0, 32, 32, 64 }, { 32, 64, 32, 64 } },
    { { 0, 32, 0, 64 }, { 32, 64, 0, 40 }, { 32, 64, 40, 64 } },
    { { 0, 39, 0, 19 }, { 40, 64, 0, 39 }, { 25, 64, 40, 64 }, { 0, 24, 20, 64 }, { 25, 39, 20, 39 } },
    { { 0, 64, 0, 64 }, { 0, -1, 0, -1 } },
  };
  for (std::size_t k = 0; k < HorizonMap::densities.size(); ++k)
  {
    const HorizonMap::Density density = HorizonMap::densities[k];
    const HorizonMap alone(grid, density);
    for (std::size_t cut = 0; cut < cuts.size(); ++cut)
    {
      ThreadRanks ranks(cuts[cut]);
      ranks.run([&](const ThreadRanks::Split& split) {
        const HorizonMap map(grid, density, &split);
        const int sends = split.Sends;
        // A finer map that copies a coarser one's sweeps (every other azimuth) sweeps
        // and hands on only its own.
        std::unique_ptr<HorizonMap> coarser, copying;
        if (k > 0)
        {
          coarser = std::make_unique<HorizonMap>(grid, HorizonMap::densities[k - 1], &split);
          const int coarserSends = split.Sends;
          copying = std::make_unique<HorizonMap>(grid, density, &split, coarser.get());
          EXPECT_EQ(split.Sends - coarserSends, sends - (coarserSends - sends));
        }
        const Window own = split.window(split.part()).clampedTo(n, n);
        int differences = 0, held = 0;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
          {
            differences += map.holds(i, j) != own.holds(i, j);
            if (!own.holds(i, j))
              continue;
            ++held;
            const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * n + i };
            for (int a = 0; a < map.azimuthCount(); ++a)
            {
              differences += map.trueElevation(post, a) != alone.trueElevation(post, a);
              differences += copying && copying->trueElevation(post, a) != alone.trueElevation(post, a);
            }
          }
        EXPECT_EQ(differences, 0) << "cut " << cut << ", part " << split.part() << ", " << static_cast<int>(density) << " azimuths";
        EXPECT_EQ(held, own.empty() ? 0 : (own.i1 - own.i0 + 1) * (own.j1 - own.j0 + 1));
        // Blocks hand hulls on, and broadcast nothing.
        if (cut < 2)
          EXPECT_EQ(split.Shares, 0);
      });
    }
  }
}

TEST(WorkSplit, OneFailedPartStopsEveryPartBeforeItShares)
{
  for (const int failing : { -1, 0, 2 })
  {
    ThreadRanks ranks(3);
    std::array<std::string, 3> outcome;
    ranks.run([&](const ThreadRanks::Split& split) {
      std::vector<int> values(8, split.part() == 1 ? 7 : 0);
      try
      {
        WorkSplit::partThenShare(
          &split,
          [&]() {
            if (split.part() == failing)
              throw std::bad_alloc();
          },
          [&]() { split.share(values.data(), values.size() * sizeof(int), 1); });
        outcome[split.part()] = values == std::vector<int>(8, 7) ? "shared" : "wrong values";
      }
      catch (const std::bad_alloc&)
      {
        outcome[split.part()] = "own failure";
      }
      catch (const Error& error)
      {
        outcome[split.part()] = std::string(error.what()).find("another process") == 0 ? "other's failure" : error.what();
      }
      EXPECT_EQ(split.Shares, failing < 0 ? 1 : 0) << "part " << split.part();
    });
    for (int part = 0; part < 3; ++part)
      EXPECT_EQ(outcome[part], failing < 0 ? "shared" : part == failing ? "own failure" : "other's failure")
        << "part " << part << ", failing " << failing;
  }
}
