#include "post_lattice.h"

#include "grid_interpolation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace terralux
{
PostLattice::PostLattice(int postsX, int postsY, int step)
  : Step(std::max(1, step))
  , Nx((std::max(1, postsX) - 1) / Step + 1)
  , Ny((std::max(1, postsY) - 1) / Step + 1)
  , Reflected(static_cast<std::size_t>(Nx) * Ny)
  , Variance(static_cast<std::size_t>(Nx) * Ny, -1.0)
{
}

void PostLattice::set(int i, int j, const Spectrum& reflected, double variance)
{
  const std::size_t k = this->index(i / this->Step, j / this->Step);
  this->Reflected[k] = reflected;
  this->Variance[k] = std::max(0.0, variance);
}

double PostLattice::varianceAround(int i, int j) const
{
  const int li = std::min(i / this->Step, std::max(0, this->Nx - 2));
  const int lj = std::min(j / this->Step, std::max(0, this->Ny - 2));
  double largest = -1.0;
  for (int dj = 0; dj < 2 && lj + dj < this->Ny; ++dj)
    for (int di = 0; di < 2 && li + di < this->Nx; ++di)
      largest = std::max(largest, this->Variance[this->index(li + di, lj + dj)]);
  return largest;
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
} // namespace terralux
