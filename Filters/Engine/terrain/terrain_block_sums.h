#pragma once
// A grid's cell sums (TerrainGrid::sumCells) kept per block of cells, found in one
// pass, so that a range's summary costs its whole blocks and the cells of its border
// instead of a pass over every cell: the terrain hierarchy summarises each level's
// patches, and each level covers the whole grid again.

#include "terrain/terrain_grid.h"

#include <vector>

namespace terralux
{
class TerrainBlockSums
{
public:
  /// Cells per block side.
  static constexpr int blockSide = 16;
  /// The sums of `grid`'s blocks; the grid must not change while this is used.
  explicit TerrainBlockSums(const TerrainGrid& grid);
  /// TerrainGrid::summarize over the whole cells of [i0, i1) x [j0, j1): the same
  /// sums, added in another order.
  TerrainRangeSummary summarize(int i0, int j0, int i1, int j1) const;
  const TerrainGrid& grid() const { return this->Grid; }

private:
  const TerrainGrid& Grid;
  int BlocksX = 0, BlocksY = 0; // whole blocks only: the cells past them are summed as a border
  std::vector<TerrainRangeSummary> Blocks; // row by row
};
} // namespace terralux
