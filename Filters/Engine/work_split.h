#pragma once
// How processes that solve the same scene (MPI ranks, each evaluating its own piece of
// a terrain) split work whose results every one of them needs: the horizons of every
// post, their skies and the lattice's gathers, which gather rays read wherever they
// land. Each value is computed the same way whoever computes it, so each process takes
// its share of blocks and then receives the others' (a broadcast from each block's
// owner): the results equal one process's, bit for bit. The engine knows no MPI; the
// VTK adapter passes its controller in.

#include "error.h"

#include <algorithm>
#include <cstddef>
#include <exception>

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
  /// Every process calls it alike: whether every process says `succeeded`.
  virtual bool allSucceeded(bool succeeded) const = 0;

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

  /// Blocks dealt in turn (neighbouring rows cost alike, so the shares balance).
  int ownerOf(std::size_t block) const { return static_cast<int>(block % static_cast<std::size_t>(this->parts())); }
  bool owns(std::size_t block) const { return this->ownerOf(block) == this->part(); }
  /// Rows dealt in blocks of `rowsPerBlock`: whether this process computes `row`.
  bool ownsRow(int row, int rowsPerBlock) const { return this->owns(static_cast<std::size_t>(row / rowsPerBlock)); }
  /// Once each process has computed its rows: send(firstRow, rowCount, owner) for every
  /// block of the `rows`, in the same order everywhere (send calls share).
  template <typename Send>
  void shareRows(int rows, int rowsPerBlock, Send&& send) const
  {
    for (int first = 0; first < rows; first += rowsPerBlock)
      send(first, std::min(rowsPerBlock, rows - first), this->ownerOf(static_cast<std::size_t>(first / rowsPerBlock)));
  }
};
} // namespace terralux
