#include "terrain/terrain_block_sums.h"

#include <tbb/parallel_for.h>

namespace terralux
{
TerrainBlockSums::TerrainBlockSums(const TerrainGrid& grid)
  : Grid(grid)
  , BlocksX(grid.cellsX() / blockSide)
  , BlocksY(grid.cellsY() / blockSide)
  , Blocks(static_cast<std::size_t>(BlocksX) * BlocksY)
{
  tbb::parallel_for(0, this->BlocksY, [this](int bj) {
    for (int bi = 0; bi < this->BlocksX; ++bi)
      this->Blocks[static_cast<std::size_t>(bj) * this->BlocksX + bi] = this->Grid.sumCells(
        bi * blockSide, bj * blockSide, (bi + 1) * blockSide, (bj + 1) * blockSide);
  });
}

TerrainRangeSummary TerrainBlockSums::summarize(int i0, int j0, int i1, int j1) const
{
  // The whole blocks inside the range; without any, the cells themselves.
  const int bi0 = (i0 + blockSide - 1) / blockSide, bj0 = (j0 + blockSide - 1) / blockSide;
  const int bi1 = std::min(i1 / blockSide, this->BlocksX), bj1 = std::min(j1 / blockSide, this->BlocksY);
  if (i0 < 0 || j0 < 0 || !(bi0 < bi1 && bj0 < bj1))
    return this->Grid.summarize(i0, j0, i1, j1);
  TerrainRangeSummary sum = TerrainGrid::emptySum();
  for (int bj = bj0; bj < bj1; ++bj)
    for (int bi = bi0; bi < bi1; ++bi)
      sum = TerrainGrid::joined(sum, this->Blocks[static_cast<std::size_t>(bj) * this->BlocksX + bi]);
  // The border: rows below and above the blocks over the range's width, then the
  // columns left and right of them beside the blocks.
  const int ib0 = bi0 * blockSide, ib1 = bi1 * blockSide, jb0 = bj0 * blockSide, jb1 = bj1 * blockSide;
  sum = TerrainGrid::joined(sum, this->Grid.sumCells(i0, j0, i1, jb0));
  sum = TerrainGrid::joined(sum, this->Grid.sumCells(i0, jb1, i1, j1));
  sum = TerrainGrid::joined(sum, this->Grid.sumCells(i0, jb0, ib0, jb1));
  sum = TerrainGrid::joined(sum, this->Grid.sumCells(ib1, jb0, i1, jb1));
  return TerrainGrid::finished(sum);
}
} // namespace terralux
