// The horizons' map built by processes that split a grid into windows (work_split.h).
//
// Handing hulls on: a line's sweep runs from its far end and needs, at each post, only
// the upper hull of the profile ahead. So each process sweeps the stretches of the
// lines inside its own window, starting each from the hull the line reached in the
// window ahead of it, and hands on the hull it reaches where the line leaves for a
// window behind. Toward each azimuth the windows form a chain of who waits for whom
// (VTK's pieces, rectangles cut in two and in two again, admit no cycle); each process
// sweeps its azimuths in the order of how many windows lie ahead of it, so while one
// waits for a neighbour on one azimuth the others sweep another. Each process sweeps
// its window's posts only, 64 bytes a post kept, and sends a few dozen points a line
// crossing its border instead of every post of every azimuth: the same operations on
// the same points as one process's sweep, so the same horizons, bit for bit.
//
// Sharing azimuths (the fallback, where the split has no point-to-point sends): each
// process sweeps a share of the azimuths at every post and broadcasts it.

#include "horizons/horizon_map.h"

#include "base/error.h"
#include "horizons/horizon_lines.h"
#include "terrain/terrain_grid.h"
#include "parallel/work_split.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <numeric>
#include <unordered_map>

namespace terralux
{
namespace
{
using Window = WorkSplit::Window;

Window intersection(const Window& a, const Window& b)
{
  return { std::max(a.i0, b.i0), std::min(a.i1, b.i1), std::max(a.j0, b.j0), std::min(a.j1, b.j1) };
}

bool contains(const Window& outer, const Window& inner)
{
  return inner.i0 >= outer.i0 && inner.i1 <= outer.i1 && inner.j0 >= outer.j0 && inner.j1 <= outer.j1;
}

/// The posts of `from` (in the grid) that follow a post of `to` one step g on, outside
/// `to`: where a line leaves `to` for `from` looking ahead, so `from` hands `to` hulls.
/// A superset of the posts it hands on (a post held by several windows is handed on by
/// the first); empty where it hands none.
Window handedOn(const Window& from, const Window& to, int q, int p)
{
  const Window reached = intersection(Window{ to.i0 + q, to.i1 + q, to.j0 + p, to.j1 + p }, from);
  return reached.empty() || contains(to, reached) ? Window{} : reached;
}

/// The k with lo <= start + k step <= hi (an empty range: first > last).
void limitSteps(int start, int step, int lo, int hi, int& first, int& last)
{
  if (step == 0)
  {
    if (start < lo || start > hi)
      first = 1, last = 0;
    return;
  }
  int a = lo - start, b = hi - start;
  if (step < 0)
    a = -a, b = -b, std::swap(a, b), step = -step;
  first = std::max(first, -floorDivide(-a, step)); // ceil(a / step)
  last = std::min(last, floorDivide(b, step));
}

/// Hulls as bytes: whether the sender failed, then per hull its post, size and points.
class HullWriter
{
public:
  explicit HullWriter(bool failed) { this->Bytes.push_back(failed ? 1 : 0); }
  /// A hull of `values` doubles (x, z, x, z, ...) at `points`, handed on at `post`.
  void add(std::uint64_t post, const void* points, std::uint64_t values)
  {
    this->put(&post, sizeof post);
    this->put(&values, sizeof values);
    this->put(points, values * sizeof(double));
  }
  std::vector<char> Bytes;

private:
  void put(const void* data, std::size_t size)
  {
    const char* c = static_cast<const char*>(data);
    this->Bytes.insert(this->Bytes.end(), c, c + size);
  }
};
} // namespace

void HorizonMap::sweepWindows(const std::vector<std::array<int, 2>>& slotSteps, const WorkSplit& split)
{
  const int nx = this->Terrain.postsX(), ny = this->Terrain.postsY();
  const int parts = split.parts(), me = split.part();
  const std::size_t slots = slotSteps.size();
  const Window grid{ 0, nx - 1, 0, ny - 1 };
  std::vector<Window> windows;
  for (int part = 0; part < parts; ++part)
  {
    const Window w = split.window(part).clampedTo(nx, ny);
    windows.push_back(w.empty() ? Window{} : w);
  }
  // Who hands whom hulls toward each azimuth, and how many windows lie ahead of each
  // (the longest chain): every process finds the same.
  std::vector<std::vector<int>> depth(slots, std::vector<int>(static_cast<std::size_t>(parts), 0));
  for (std::size_t slot = 0; slot < slots; ++slot)
  {
    const int q = slotSteps[slot][0], p = slotSteps[slot][1];
    std::vector<int> waitingFor(static_cast<std::size_t>(parts), 0);
    for (int to = 0; to < parts; ++to)
      for (int from = 0; from < parts; ++from)
        waitingFor[static_cast<std::size_t>(to)] += from != to && !handedOn(windows[from], windows[to], q, p).empty();
    // Kahn's order: a window's depth is one more than the deepest ahead of it.
    std::vector<int> ready;
    for (int part = 0; part < parts; ++part)
      if (waitingFor[static_cast<std::size_t>(part)] == 0)
        ready.push_back(part);
    int placed = 0;
    while (!ready.empty())
    {
      const int from = ready.back();
      ready.pop_back();
      ++placed;
      for (int to = 0; to < parts; ++to)
        if (from != to && !handedOn(windows[from], windows[to], q, p).empty())
        {
          depth[slot][to] = std::max(depth[slot][to], depth[slot][from] + 1);
          if (--waitingFor[static_cast<std::size_t>(to)] == 0)
            ready.push_back(to);
        }
    }
    if (placed != parts)
    {
      // Windows that wait for each other in a ring (not VTK's pieces): share azimuths.
      this->sweepSharedAzimuths(slotSteps, split);
      return;
    }
  }
  WorkSplit::partThenShare(
    &split, [&]() { this->Elevations.resize(this->HeldCount * slots); }, []() {});
  std::vector<std::size_t> schedule(slots);
  std::iota(schedule.begin(), schedule.end(), std::size_t{ 0 });
  std::stable_sort(schedule.begin(), schedule.end(),
    [&](std::size_t a, std::size_t b) { return depth[a][me] < depth[b][me]; });
  this->dropCopiedSlots(schedule);

  const Window& own = windows[me];
  // The windows that hold posts of this one before it: a post they hold is theirs to
  // hand on.
  std::vector<int> earlierOverlapping;
  for (int part = 0; part < me; ++part)
    if (!intersection(windows[part], own).empty())
      earlierOverlapping.push_back(part);
  auto handsOnPost = [&](int i, int j) {
    return std::none_of(earlierOverlapping.begin(), earlierOverlapping.end(),
      [&](int part) { return windows[part].holds(i, j); });
  };

  std::exception_ptr failure;
  bool othersFailed = false;
  for (const std::size_t slot : schedule)
  {
    const int q = slotSteps[slot][0], p = slotSteps[slot][1];
    // The hulls the windows ahead hand on, by post.
    std::unordered_map<std::uint64_t, Hull> ahead;
    for (int from = 0; from < parts; ++from)
    {
      if (from == me || handedOn(windows[from], own, q, p).empty())
        continue;
      const std::vector<char> bytes = split.receive(from, static_cast<int>(slot));
      if (bytes.empty() || bytes[0] != 0)
      {
        othersFailed = true;
        continue;
      }
      std::size_t at = 1;
      auto take = [&](void* value, std::size_t size) {
        if (at + size > bytes.size())
          throw Error("the hulls handed on for the horizons were cut short");
        std::memcpy(value, bytes.data() + at, size);
        at += size;
      };
      try
      {
        while (at < bytes.size())
        {
          std::uint64_t post = 0, values = 0;
          take(&post, sizeof post);
          take(&values, sizeof values);
          Hull& hull = ahead[post];
          hull.resize(values / 2);
          take(hull.data(), hull.size() * sizeof(HullPoint));
        }
      }
      catch (...)
      {
        if (!failure)
          failure = std::current_exception();
      }
    }
    std::vector<int> receivers;
    std::vector<Window> reached;
    for (int to = 0; to < parts; ++to)
      if (to != me && !handedOn(own, windows[to], q, p).empty())
        receivers.push_back(to), reached.push_back(intersection(handedOn(own, windows[to], q, p), grid));
    std::vector<std::vector<std::uint64_t>> postsFor(receivers.size());
    std::vector<std::vector<std::size_t>> capturedFor(receivers.size());
    std::vector<Hull> captured;
    if (!failure && !othersFailed)
      try
      {
        std::vector<LineRun> runs = runsWithin(q, p, own);
        std::vector<Capture> captures;
        for (LineRun& run : runs)
        {
          const int ia = run.i + run.count * q, ja = run.j + run.count * p;
          if (grid.holds(ia, ja))
          {
            const auto found = ahead.find(static_cast<std::uint64_t>(ja) * nx + ia);
            if (found == ahead.end())
              throw Error("no window handed on the hull of a line entering this one (windows that do not tile the grid?)");
            run.ahead = &found->second;
          }
          // The posts of the stretch where the line enters a window behind it.
          run.firstCapture = captures.size();
          std::vector<std::array<std::size_t, 2>> here; // (k, receiver)
          for (std::size_t r = 0; r < receivers.size(); ++r)
          {
            int first = 0, last = run.count - 1;
            limitSteps(run.i, q, reached[r].i0, reached[r].i1, first, last);
            limitSteps(run.j, p, reached[r].j0, reached[r].j1, first, last);
            for (int k = first; k <= last; ++k)
            {
              const int i = run.i + k * q, j = run.j + k * p;
              if (!windows[receivers[r]].holds(i, j) && handsOnPost(i, j))
                here.push_back({ static_cast<std::size_t>(k), r });
            }
          }
          std::sort(here.begin(), here.end(), [](const auto& a, const auto& b) { return a[0] > b[0]; });
          for (const auto& [k, r] : here)
          {
            postsFor[r].push_back(static_cast<std::uint64_t>(run.j + static_cast<int>(k) * p) * nx +
              static_cast<std::uint64_t>(run.i + static_cast<int>(k) * q));
            capturedFor[r].push_back(captures.size());
            captures.push_back({ static_cast<int>(k), captures.size() });
          }
          run.captureCount = captures.size() - run.firstCapture;
        }
        captured.resize(captures.size());
        this->sweep(q, p, runs, own, this->Elevations.data() + slot * this->HeldCount, captures, &captured);
      }
      catch (...)
      {
        failure = std::current_exception();
      }
    for (std::size_t r = 0; r < receivers.size(); ++r)
    {
      HullWriter writer(failure || othersFailed);
      if (!failure && !othersFailed)
        for (std::size_t n = 0; n < postsFor[r].size(); ++n)
        {
          const Hull& hull = captured[capturedFor[r][n]];
          static_assert(sizeof(HullPoint) == 2 * sizeof(double), "a hull's points are pairs of doubles");
          writer.add(postsFor[r][n], hull.data(), 2 * hull.size());
        }
      split.send(std::move(writer.Bytes), receivers[r], static_cast<int>(slot));
    }
  }
  split.finishSends();
  const bool everyPart = split.allSucceeded(!failure && !othersFailed);
  if (failure)
    std::rethrow_exception(failure);
  if (!everyPart)
    throw Error("another process failed in a step the processes share (see its error); this one stops too");
}

void HorizonMap::sweepSharedAzimuths(const std::vector<std::array<int, 2>>& slotSteps, const WorkSplit& split)
{
  const int nx = this->Terrain.postsX();
  const std::size_t slots = slotSteps.size();
  // Processes sweep an azimuth each at a time, at every post (the lines cross the
  // whole grid), and each keeps its window of every azimuth it receives: the map per
  // process is its window's, plus two azimuths of the whole grid in flight.
  std::vector<std::uint16_t> swept, received;
  WorkSplit::partThenShare(
    &split,
    [&]() {
      this->Elevations.resize(this->HeldCount * slots);
      swept.resize(this->PostCount);
      received.resize(this->PostCount);
    },
    []() {});
  // Azimuths of alike cost sweep in the same round: a step's crossings of cell edges and
  // diagonals set its cost (none along the grid's axes, 11 for slope 2/5), and a round
  // lasts as long as its slowest.
  std::vector<std::size_t> schedule(slots), cost(slots);
  std::iota(schedule.begin(), schedule.end(), std::size_t{ 0 });
  for (std::size_t slot = 0; slot < slots; ++slot)
  {
    const int q = std::abs(slotSteps[slot][0]), p = std::abs(slotSteps[slot][1]);
    cost[slot] = static_cast<std::size_t>(std::max(0, q - 1) + std::max(0, p - 1) + std::max(0, q + p - 1));
  }
  std::stable_sort(
    schedule.begin(), schedule.end(), [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });
  this->dropCopiedSlots(schedule);
  const std::size_t rounds = schedule.size();
  const int parts = split.parts(), part = split.part();
  for (std::size_t first = 0; first < rounds; first += static_cast<std::size_t>(parts))
    WorkSplit::partThenShare(
      &split,
      [&]() {
        const std::size_t round = first + static_cast<std::size_t>(part);
        if (round < rounds)
          this->sweepWholeGrid(slotSteps[schedule[round]][0], slotSteps[schedule[round]][1], swept.data());
      },
      [&]() {
        for (int owner = 0; owner < parts && first + static_cast<std::size_t>(owner) < rounds; ++owner)
        {
          const std::size_t slot = schedule[first + static_cast<std::size_t>(owner)];
          std::vector<std::uint16_t>& whole = owner == part ? swept : received;
          split.share(whole.data(), this->PostCount * sizeof(std::uint16_t), owner);
          for (int j = this->Held.j0; j <= this->Held.j1; ++j)
            std::copy_n(&whole[static_cast<std::size_t>(j) * nx + this->Held.i0], this->HeldX,
              &this->Elevations[slot * this->HeldCount + (j - this->Held.j0) * this->HeldX]);
        }
      });
}
} // namespace terralux
