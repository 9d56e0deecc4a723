#pragma once
// The posts one process holds at full resolution when it evaluates its piece of a
// terrain with the far terrain given (MPI ranks, streaming): the piece and a halo of
// three detail distances and the lattice, from a multiple of the lattice's cell, so
// that its lattice is the whole grid's. Extents are in the whole grid's post indices.

#include "parallel/work_split.h"

namespace terralux
{
class TerrainGrid;

struct TerrainWindow
{
  using Extent = WorkSplit::Window;

  /// Posts of halo around a piece for posts `postSpacing` m apart: a post's rays see the
  /// full resolution within `detailDistance`, its hits' shadow rays as far again, and a
  /// lattice read at hits once more; then the lattice posts a read weighs
  /// (PostLattice::readReach) and a margin. -1: the whole grid.
  static int haloPosts(double detailDistance, double postSpacing);
  /// The window to ask the source for: `piece` grown by `halo` within `whole`, its low
  /// ends moved down to a multiple of the lattice's cell from whole's.
  static Extent requested(const Extent& whole, const Extent& piece, int halo);
  /// Throws Error naming the fix when `held` (the posts given, as `grid`) is short of
  /// what `piece` needs on a grid whose posts are `whole`, or is not aligned with the
  /// lattice's cell.
  static void checkHeld(
    const TerrainGrid& grid, double detailDistance, const Extent& whole, const Extent& held, const Extent& piece);
};
} // namespace terralux
