#pragma once
// How processes that solve the same scene (MPI ranks, each evaluating its own piece of
// a terrain, its window) split work whose results others need: the posts' skies and
// the lattice's gathers, which gather rays read where they land (each process holds
// those near its window: held_posts.h), and the horizons' sweeps, which cross the whole
// grid (handed on: horizon_map.h). Each value is computed the same way whoever computes
// it, so each process computes its share (its window's posts) and then receives the
// others' it needs: the results equal one process's, bit for bit. The engine knows no
// MPI; the VTK adapter passes its controller in.

#include "base/error.h"

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
  /// Every process calls it alike: whether every process says `succeeded`.
  virtual bool allSucceeded(bool succeeded) const = 0;
  /// Every process calls it alike: the sum of every process's `count` (this one's
  /// alone without a split), the same on each.
  static std::size_t total(const WorkSplit* split, std::size_t count)
  {
    if (!split)
      return count;
    std::size_t sum = 0;
    for (int part = 0; part < split->parts(); ++part)
    {
      std::size_t value = part == split->part() ? count : 0;
      split->share(&value, sizeof value, part);
      sum += value;
    }
    return sum;
  }

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
