#include "post_lattice.h"

#include "grid_interpolation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace terralux
{
PostLattice::PostLattice(int postsX, int postsY, int step)
  : Step(std::max(1, step))
  , Nx((std::max(1, postsX) - 1) / Step + 1)
  , Ny((std::max(1, postsY) - 1) / Step + 1)
  , CoarseX(std::max(1, Nx / 2))
  , CoarseY(std::max(1, Ny / 2))
  , Reflected(static_cast<std::size_t>(Nx) * Ny)
  , Variance(static_cast<std::size_t>(Nx) * Ny, -1.0)
  , PerTerrain(static_cast<std::size_t>(Nx) * Ny)
  , Received(static_cast<std::size_t>(Nx) * Ny, 0.0)
  , TerrainSeen(static_cast<std::size_t>(Nx) * Ny, 0.0)
  , Refined(static_cast<std::size_t>(CoarseX) * CoarseY, 1) // every cell fine until refine decides
{
}

bool PostLattice::gatheredInPass(int i, int j, bool first) const
{
  if (!this->onLattice(i, j))
    return false;
  const int li = i / this->Step, lj = j / this->Step;
  const bool coarse = li % 2 == 0 && lj % 2 == 0;
  if (first || coarse)
    return first && coarse;
  // A corner of a lattice cell (li - 1 or li, lj - 1 or lj) of a refined coarse cell.
  for (int b = std::max(0, lj - 1); b <= std::min(lj, this->Ny - 2); ++b)
    for (int a = std::max(0, li - 1); a <= std::min(li, this->Nx - 2); ++a)
      if (this->Refined[this->coarseCell(a, b)])
        return true;
  return false;
}

double PostLattice::largestPerTerrainSeen(std::size_t k) const
{
  const Scaled& scaled = this->PerTerrain[k];
  double largest = -std::numeric_limits<double>::infinity();
  for (int band = 0; band < maxBands; ++band)
    largest = std::max(largest, scaled[band] + scaled[maxBands + band]);
  return largest;
}

void PostLattice::refine(double allowedSpread)
{
  for (int cj = 0; cj < this->CoarseY; ++cj)
    for (int ci = 0; ci < this->CoarseX; ++ci)
    {
      const Cell coarse{ 2 * ci, 2 * cj, 2 };
      bool refined = 2 * ci + 2 > this->Nx - 1 || 2 * cj + 2 > this->Ny - 1; // no coarse corner at the far side
      if (!refined)
      {
        const Around corners = this->aroundCell(coarse);
        this->forEachCorner(coarse, [&](std::size_t k) {
          refined = refined || this->Variance[k] < 0.0 ||
            this->TerrainSeen[k] * (corners.largestPerTerrainSeen - corners.leastPerTerrainSeen) >
              allowedSpread * this->Received[k];
        });
      }
      this->Refined[static_cast<std::size_t>(cj) * this->CoarseX + ci] = refined;
    }
}

PostLattice::Cell PostLattice::cellAt(double u, double v) const
{
  const int li = std::clamp(static_cast<int>(std::floor(u / this->Step)), 0, std::max(0, this->Nx - 2));
  const int lj = std::clamp(static_cast<int>(std::floor(v / this->Step)), 0, std::max(0, this->Ny - 2));
  if (this->Refined[this->coarseCell(li, lj)])
    return { li, lj, 1 };
  return { li - li % 2, lj - lj % 2, 2 };
}

template <class Value, class NodeValue>
bool PostLattice::interpolate(double u, double v, const NodeValue& nodeValue, Value& result) const
{
  // Bilinear between the corners of the cell's own lattice (every post, or every second).
  const Cell cell = this->cellAt(u, v);
  const double size = static_cast<double>(this->Step * cell.side);
  const int nodesX = cell.side == 1 ? this->Nx : (this->Nx - 1) / 2 + 1;
  const int nodesY = cell.side == 1 ? this->Ny : (this->Ny - 1) / 2 + 1;
  return interpolateNodes(u / size, v / size, nodesX, nodesY,
    [&](int a, int b, Value& value) {
      const std::size_t k = this->index(a * cell.side, b * cell.side);
      if (this->Variance[k] < 0.0)
        return false;
      value = nodeValue(k);
      return true;
    },
    result);
}

void PostLattice::set(int i, int j, const Gathered& gathered)
{
  const std::size_t k = this->index(i / this->Step, j / this->Step);
  this->Reflected[k] = gathered.reflected;
  this->Variance[k] = std::max(0.0, gathered.variance);
  // A post that sees next to no terrain tells nothing per terrain seen: 0.
  Scaled scaled{};
  if (gathered.terrainSeen > 1e-6)
  {
    for (int band = 0; band < maxBands; ++band)
    {
      scaled[band] = gathered.reflected[band] / gathered.terrainSeen;
      scaled[maxBands + band] = gathered.skyCorrection[band] / gathered.terrainSeen;
    }
    scaled[2 * maxBands] = gathered.skyViewCorrection / gathered.terrainSeen;
  }
  this->PerTerrain[k] = scaled;
  this->Received[k] = gathered.received;
  this->TerrainSeen[k] = gathered.terrainSeen;
}

void PostLattice::share(const WorkSplit& split)
{
  split.shareWindows(this->Reflected, this->Nx, this->Ny, this->Step);
  split.shareWindows(this->Variance, this->Nx, this->Ny, this->Step);
  split.shareWindows(this->PerTerrain, this->Nx, this->Ny, this->Step);
  split.shareWindows(this->Received, this->Nx, this->Ny, this->Step);
  split.shareWindows(this->TerrainSeen, this->Nx, this->Ny, this->Step);
}

template <class Corner>
void PostLattice::forEachCorner(const Cell& cell, const Corner& corner) const
{
  for (int dj = 0; dj < 2 && cell.lj + dj * cell.side < this->Ny; ++dj)
    for (int di = 0; di < 2 && cell.li + di * cell.side < this->Nx; ++di)
      corner(this->index(cell.li + di * cell.side, cell.lj + dj * cell.side));
}

PostLattice::Around PostLattice::aroundCell(const Cell& cell) const
{
  Around result;
  result.leastPerTerrainSeen = std::numeric_limits<double>::infinity();
  this->forEachCorner(cell, [&](std::size_t k) {
    if (this->Variance[k] < 0.0)
      return;
    const double largest = this->largestPerTerrainSeen(k);
    result.variance = std::max(result.variance, this->Variance[k]);
    result.largestPerTerrainSeen = std::max(result.largestPerTerrainSeen, largest);
    result.leastPerTerrainSeen = std::min(result.leastPerTerrainSeen, largest);
  });
  return result;
}

PostLattice::Around PostLattice::around(int i, int j) const
{
  return this->aroundCell(this->cellAt(i, j));
}

bool PostLattice::reflectedAt(double u, double v, Spectrum& reflected) const
{
  return this->interpolate(u, v, [&](std::size_t k) { return this->Reflected[k]; }, reflected);
}

bool PostLattice::perTerrainSeenAt(double u, double v, PerTerrainSeen& value) const
{
  Scaled scaled;
  if (!this->interpolate(u, v, [&](std::size_t k) { return this->PerTerrain[k]; }, scaled))
    return false;
  for (int band = 0; band < maxBands; ++band)
  {
    value.reflected[band] = scaled[band];
    value.skyCorrection[band] = scaled[maxBands + band];
  }
  value.skyViewCorrection = scaled[2 * maxBands];
  return true;
}
} // namespace terralux
