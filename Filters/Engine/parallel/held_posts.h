#pragma once
// The posts of a terrain whose skies and proven suns a process holds (post_sky.h,
// post_sunlight.h): gather rays read them at their hits, so one process holds every
// post; with a detail distance, a gather hit farther than it from the gathering point
// takes its leaf's light instead (GatherInputs::detailDistance), and a process that
// evaluates a window of posts (a piece, under MPI) needs the posts within that distance
// of its window only: its window grown by a halo. Each process computes its window's
// values and receives, from each other process, the part of that one's window inside
// its own halo, so memory and traffic follow the piece and its halo, not the grid.
// The same holds for a lattice of every step-th post (post_lattice.h): a process
// computes the lattice posts of its window, and holds those of its window's halo.

#include "parallel/work_split.h"

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace terralux
{
class TerrainGrid;

class HeldPosts
{
public:
  /// Of an nx x ny grid: with `split`, each process's window grown by `halo` posts each
  /// way; every post without one, or where halo < 0. With `step`, the grid is a lattice
  /// of every step-th post each way of the split's posts (nx x ny lattice posts; the
  /// split's windows and the halo are counted on it).
  HeldPosts(int nx, int ny, const WorkSplit* split, int halo, int step = 1);

  /// Posts of `terrain` around a window that hold every cell a point within
  /// `distance` (m, horizontally) of a post of the window meets: the distance over
  /// the grid's narrowest cell height, plus the cell and a post of margin. -1 (every
  /// post) where distance <= 0 or a cell is degenerate.
  static int haloFor(const TerrainGrid& terrain, double distance);

  const WorkSplit::Window& own() const { return this->Own; }
  /// What process `part` holds.
  WorkSplit::Window of(int part) const;
  std::size_t count() const { return static_cast<std::size_t>(this->Width) * this->height(); }
  bool holds(int i, int j) const { return this->Own.holds(i, j); }
  /// Throws unless post (i, j) is held: a gather ray read `what` (the sky, the suns) of
  /// a post farther than the detail distance's halo reaches.
  void requireHeld(int i, int j, const char* what) const
  {
    if (!this->holds(i, j))
      throw Error(std::string("a gather ray read the ") + what +
        " of a post this process does not hold: its detail distance's halo is too narrow for this grid");
  }
  /// Where post (i, j), held, is in the held values (row by row over own()).
  std::size_t index(int i, int j) const
  {
    return static_cast<std::size_t>(j - this->Own.j0) * this->Width + static_cast<std::size_t>(i - this->Own.i0);
  }

  /// Once this process has computed `values` (count() of them, over own()) at the posts
  /// of its window: the others' posts it holds, from their processes, point to point
  /// where the split sends so (each sends another only what that one holds), else by
  /// a broadcast of each window. `tag` tells this share's messages apart. Needs the
  /// split it was made with.
  template <typename Vector>
  void share(Vector& values, int tag) const;

private:
  int height() const { return this->Own.empty() ? 0 : this->Own.j1 - this->Own.j0 + 1; }
  /// Process `part`'s window of posts within the grid (on a lattice: from its first
  /// step-th post to its last).
  WorkSplit::Window windowOf(const WorkSplit& split, int part) const
  {
    const WorkSplit::Window w = split.window(part);
    const int s = this->Step;
    auto first = [s](int post) { return post <= 0 ? 0 : post / s + (post % s != 0); };
    auto last = [s](int post) { return post < 0 ? -1 : post / s; };
    return WorkSplit::Window{ first(w.i0), last(w.i1), first(w.j0), last(w.j1) }.clampedTo(this->Nx, this->Ny);
  }
  static WorkSplit::Window intersection(const WorkSplit::Window& a, const WorkSplit::Window& b)
  {
    return { std::max(a.i0, b.i0), std::min(a.i1, b.i1), std::max(a.j0, b.j0), std::min(a.j1, b.j1) };
  }
  /// Row by row over `region` (held here): each row's first value and its length.
  template <typename Vector, typename Row>
  void forEachRow(Vector& values, const WorkSplit::Window& region, const Row& row) const
  {
    const std::size_t width = static_cast<std::size_t>(region.i1 - region.i0 + 1);
    for (int j = region.j0; j <= region.j1; ++j)
      row(&values[this->index(region.i0, j)], width);
  }

  int Nx, Ny, Step;
  const WorkSplit* Split;
  int Halo; // -1: every post
  WorkSplit::Window Own;
  int Width;
};

template <typename Vector>
void HeldPosts::share(Vector& values, int tag) const
{
  if (!this->Split)
    throw Error("held posts are shared among the processes of a split: none was given");
  const WorkSplit& split = *this->Split;
  using T = typename Vector::value_type;
  static_assert(std::is_trivially_copyable<T>::value, "held values travel as bytes");
  const int me = split.part();
  std::vector<char> bytes;
  auto pack = [&](const WorkSplit::Window& region) {
    bytes.clear();
    this->forEachRow(values, region, [&](const T* row, std::size_t width) {
      const char* first = reinterpret_cast<const char*>(row);
      bytes.insert(bytes.end(), first, first + width * sizeof(T));
    });
  };
  auto unpack = [&](const WorkSplit::Window& region, const std::vector<char>& from, std::size_t offset,
                  std::size_t fromWidth) {
    // `from` holds a window fromWidth posts wide whose first row starts at `offset`
    // posts before region's first post.
    std::size_t at = offset;
    this->forEachRow(values, region, [&](T* row, std::size_t width) {
      if ((at + width) * sizeof(T) > from.size())
        throw Error("a process sent fewer posts than its window holds");
      std::memcpy(static_cast<void*>(row), from.data() + at * sizeof(T), width * sizeof(T));
      at += fromWidth;
    });
  };
  if (split.sendsPointToPoint())
  {
    for (int other = 0; other < split.parts(); ++other)
    {
      const WorkSplit::Window region = intersection(this->windowOf(split, me), this->of(other));
      if (other == me || region.empty())
        continue;
      pack(region);
      split.send(bytes, other, tag);
    }
    for (int other = 0; other < split.parts(); ++other)
    {
      const WorkSplit::Window region = intersection(this->windowOf(split, other), this->Own);
      if (other == me || region.empty())
        continue;
      unpack(region, split.receive(other, tag), 0, static_cast<std::size_t>(region.i1 - region.i0 + 1));
    }
    split.finishSends();
    return;
  }
  for (int owner = 0; owner < split.parts(); ++owner)
  {
    const WorkSplit::Window window = this->windowOf(split, owner);
    if (window.empty())
      continue;
    const std::size_t width = static_cast<std::size_t>(window.i1 - window.i0 + 1);
    if (owner == me)
      pack(window);
    else
      bytes.assign(width * static_cast<std::size_t>(window.j1 - window.j0 + 1) * sizeof(T), 0);
    split.share(bytes.data(), bytes.size(), owner);
    const WorkSplit::Window region = intersection(window, this->Own);
    if (owner != me && !region.empty())
      unpack(region, bytes,
        static_cast<std::size_t>(region.j0 - window.j0) * width + static_cast<std::size_t>(region.i0 - window.i0), width);
  }
}
} // namespace terralux
