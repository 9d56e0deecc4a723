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
  , Reflected(static_cast<std::size_t>(Nx) * Ny)
  , Variance(static_cast<std::size_t>(Nx) * Ny, -1.0)
  , PerTerrain(static_cast<std::size_t>(Nx) * Ny)
{
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
}

void PostLattice::share(const WorkSplit& split)
{
  split.shareWindows(this->Reflected, this->Nx, this->Ny, this->Step);
  split.shareWindows(this->Variance, this->Nx, this->Ny, this->Step);
  split.shareWindows(this->PerTerrain, this->Nx, this->Ny, this->Step);
}

PostLattice::Around PostLattice::around(int i, int j) const
{
  const int li = std::min(i / this->Step, std::max(0, this->Nx - 2));
  const int lj = std::min(j / this->Step, std::max(0, this->Ny - 2));
  Around result;
  result.leastPerTerrainSeen = std::numeric_limits<double>::infinity();
  for (int dj = 0; dj < 2 && lj + dj < this->Ny; ++dj)
    for (int di = 0; di < 2 && li + di < this->Nx; ++di)
    {
      const std::size_t k = this->index(li + di, lj + dj);
      if (this->Variance[k] < 0.0)
        continue;
      const Scaled& scaled = this->PerTerrain[k];
      double largest = -std::numeric_limits<double>::infinity();
      for (int band = 0; band < maxBands; ++band)
        largest = std::max(largest, scaled[band] + scaled[maxBands + band]);
      result.variance = std::max(result.variance, this->Variance[k]);
      result.largestPerTerrainSeen = std::max(result.largestPerTerrainSeen, largest);
      result.leastPerTerrainSeen = std::min(result.leastPerTerrainSeen, largest);
    }
  return result;
}

bool PostLattice::reflectedAt(double u, double v, Spectrum& reflected) const
{
  return interpolateNodes(u / this->Step, v / this->Step, this->Nx, this->Ny,
    [&](int li, int lj, Spectrum& value) {
      const std::size_t k = this->index(li, lj);
      value = this->Reflected[k];
      return this->Variance[k] >= 0.0;
    },
    reflected);
}

bool PostLattice::perTerrainSeenAt(double u, double v, PerTerrainSeen& value) const
{
  Scaled scaled;
  if (!interpolateNodes(u / this->Step, v / this->Step, this->Nx, this->Ny,
        [&](int li, int lj, Scaled& node) {
          const std::size_t k = this->index(li, lj);
          node = this->PerTerrain[k];
          return this->Variance[k] >= 0.0;
        },
        scaled))
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
