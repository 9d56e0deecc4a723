#pragma once
// How processes that solve the same scene (MPI ranks, each evaluating its own piece of
// a terrain, its window) split work whose results every one of them needs: the posts'
// skies and the lattice's gathers, which gather rays read wherever they land, and the
// horizons' sweeps, which cross the whole grid. Each value is computed the same way
// whoever computes it, so each process computes its share (its window's posts, its
// azimuths) and then receives the others' (a broadcast from each share's process): the
// results equal one process's, bit for bit. The engine knows no MPI; the VTK adapter
// passes its controller in.

#include "error.h"

#include <algorithm>
#include <cstddef>
#include <exception>
#include <vector>

namespace terralux
{
class WorkSplit
{
public:
  virtual ~WorkSplit() = default;
  /// This process, of parts(): 0 <= part() < parts().
  virtual int part() const = 0;
  virtual int parts() const = 0;
  /// Every process calls it alike: `owner`'s `size` bytes at `data` replace the others'.
  virtual void share(void* data, std::size_t size, int owner) const = 0;
  /// The posts a process evaluates (its piece: grid indices, inclusive; neighbouring
  /// pieces may share their border posts). What is needed only there (the posts'
  /// horizons) each process keeps for its own window alone.
  struct Window
  {
    int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
    bool holds(int i, int j) const { return i >= this->i0 && i <= this->i1 && j >= this->j0 && j <= this->j1; }
    bool empty() const { return this->i1 < this->i0 || this->j1 < this->j0; }
    /// Its posts within an nx x ny grid.
    Window clampedTo(int nx, int ny) const
    {
      return { std::max(0, this->i0), std::min(nx - 1, this->i1), std::max(0, this->j0), std::min(ny - 1, this->j1) };
    }
  };
  virtual Window window(int part) const = 0;
  /// The posts of an nx x ny grid this process computes: its window's with `split`,
  /// every post without one.
  static Window ownWindow(const WorkSplit* split, int nx, int ny)
  {
    return split ? split->window(split->part()).clampedTo(nx, ny) : Window{ 0, nx - 1, 0, ny - 1 };
  }
  /// Once each process has computed `values` at the posts of its window (one value per
  /// post of an nx x ny grid, in grid order; or, with `step`, per post of a lattice of
  /// every step-th post each way, nx x ny of them): every window's values, from its
  /// process. Where windows share posts, each computed them alike.
  template <typename Vector>
  void shareWindows(Vector& values, int nx, int ny, int step = 1) const
  {
    using T = typename Vector::value_type;
    std::vector<T> packed;
    for (int owner = 0; owner < this->parts(); ++owner)
    {
      // The window's posts on the lattice: from the first step-th post in it to the last.
      const Window w = this->window(owner);
      auto first = [step](int post) { return post <= 0 ? 0 : (post + step - 1) / step; };
      auto last = [step](int post) { return post < 0 ? -1 : post / step; };
      const Window lattice = Window{ first(w.i0), last(w.i1), first(w.j0), last(w.j1) }.clampedTo(nx, ny);
      if (lattice.empty())
        continue;
      const int i0 = lattice.i0, j0 = lattice.j0, j1 = lattice.j1;
      const std::size_t width = static_cast<std::size_t>(lattice.i1 - i0 + 1);
      packed.resize(width * static_cast<std::size_t>(j1 - j0 + 1));
      auto row = [&](int j) { return values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(j) * nx + i0); };
      auto packedRow = [&](int j) { return packed.begin() + static_cast<std::ptrdiff_t>((j - j0) * width); };
      if (owner == this->part())
        for (int j = j0; j <= j1; ++j)
          std::copy_n(row(j), width, packedRow(j));
      this->share(packed.data(), packed.size() * sizeof(T), owner);
      if (owner != this->part())
        for (int j = j0; j <= j1; ++j)
          std::copy_n(packedRow(j), width, row(j));
    }
  }
  /// Every process calls it alike: whether every process says `succeeded`.
  virtual bool allSucceeded(bool succeeded) const = 0;

  /// Point to point, for work handed from window to window (the horizons' sweeps hand
  /// their lines' hulls on): whether this split has it (else such work uses shares).
  virtual bool sendsPointToPoint() const { return false; }
  /// Sends `bytes` to process `to` without waiting for it to take them; they arrive in
  /// the order sent, for each `tag` (0 <= tag < 1000).
  virtual void send(std::vector<char> bytes, int to, int tag) const
  {
    (void)bytes, (void)to, (void)tag;
    throw Error("this split of the work sends no bytes point to point");
  }
  /// Waits for the next bytes `from` sent with `tag`.
  virtual std::vector<char> receive(int from, int tag) const
  {
    (void)from, (void)tag;
    throw Error("this split of the work receives no bytes point to point");
  }
  /// Waits until every process this one sent to has taken what it sent.
  virtual void finishSends() const {}

  /// A step whose results every process needs: this process's part, then `share`. A
  /// process whose part throws (out of memory, say, on one node) must not leave the
  /// others waiting in a broadcast: every process learns it, and all of them throw.
  template <typename Part, typename Share>
  static void partThenShare(const WorkSplit* split, Part&& part, Share&& share)
  {
    if (!split)
    {
      part();
      return;
    }
    std::exception_ptr failure;
    try
    {
      part();
    }
    catch (...)
    {
      failure = std::current_exception();
    }
    const bool everyPart = split->allSucceeded(!failure);
    if (failure)
      std::rethrow_exception(failure);
    if (!everyPart)
      throw Error("another process failed in a step the processes share (see its error); this one stops too");
    share();
  }
};
} // namespace terralux
