#include "cumulative_sky.h"

#include "base/angles.h"
#include "base/error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
const double nearPeakCosine = std::cos(25.0 * pi / 180.0);
} // namespace

CumulativeSky::CumulativeSky(int finestLevel)
  : Level(finestLevel)
{
  if (finestLevel < 1 || finestLevel > 10)
    throw Error("a cumulative sky's level must be in 1..10");
  const std::size_t side = static_cast<std::size_t>(SkyHierarchy::cellsPerSide(finestLevel));
  this->Sums.assign(side * side, 0.0);
  this->Integrals.assign(side * side, 0.0);
  // The centre rule's directions, made once: most of a step's cost otherwise.
  this->Centres.resize(side * side);
  for (std::size_t iu = 0; iu < side; ++iu)
  {
    const SkyPatch row{ finestLevel, static_cast<int>(iu), 0 };
    const double u = std::asin(0.5 * (std::sin(row.u0()) + std::sin(row.u1())));
    for (std::size_t iv = 0; iv < side; ++iv)
    {
      const SkyPatch cell{ finestLevel, static_cast<int>(iu), static_cast<int>(iv) };
      this->Centres[iu * side + iv] = directionFromSkyParameters(u, 0.5 * (cell.v0() + cell.v1()));
    }
  }
}

void CumulativeSky::add(const SkyModel& model, const Direction& peak, double diffuseHorizontalWm2, double hours)
{
  if (!(diffuseHorizontalWm2 >= 0.0) || !std::isfinite(diffuseHorizontalWm2) || !(hours >= 0.0) ||
    !std::isfinite(hours))
    throw Error("a sky is added with a finite diffuse irradiance >= 0 and hours >= 0");
  const int side = SkyHierarchy::cellsPerSide(this->Level);
  // Integrals over dOmega = ds dv (s = sin u), and each row's horizontal share.
  std::vector<double> rowHorizontal(static_cast<std::size_t>(side), 0.0);
  const double cellWidth = SkyPatch{ this->Level, 0, 0 }.v1();
  tbb::parallel_for(0, side, [&](int iu) {
    const SkyPatch row{ this->Level, iu, 0 };
    const double s0 = std::sin(row.u0()), s1 = std::sin(row.u1());
    double horizontal = 0.0;
    for (int iv = 0; iv < side; ++iv)
    {
      const std::size_t k = static_cast<std::size_t>(iu) * side + iv;
      const Direction& centre = this->Centres[k];
      const bool nearPeak = centre[0] * peak[0] + centre[1] * peak[1] + centre[2] * peak[2] > nearPeakCosine;
      if (!nearPeak)
      {
        const double value = (s1 - s0) * cellWidth * model.relativeRadiance(centre);
        this->Integrals[k] = value;
        horizontal += value * 0.5 * (s0 + s1);
        continue;
      }
      double integral = 0.0;
      forCellGaussPoints(SkyPatch{ this->Level, iu, iv }, [&](const Direction& d, double weight, double s, double, double) {
        const double value = weight * model.relativeRadiance(d);
        integral += value;
        horizontal += value * s;
      });
      this->Integrals[k] = integral;
    }
    rowHorizontal[static_cast<std::size_t>(iu)] = horizontal;
  });
  double modelHorizontal = 0.0;
  for (double value : rowHorizontal)
    modelHorizontal += value;
  if (!(modelHorizontal > 0.0) || !std::isfinite(modelHorizontal))
    throw Error("the sky model gives no light on a horizontal plane; check its parameters");
  const double scale = hours * diffuseHorizontalWm2 / modelHorizontal;
  for (int iu = 0; iu < side; ++iu)
  {
    const double omega = SkyPatch{ this->Level, iu, 0 }.solidAngle();
    for (int iv = 0; iv < side; ++iv)
    {
      const std::size_t k = static_cast<std::size_t>(iu) * side + iv;
      this->Sums[k] += scale * this->Integrals[k] / omega;
    }
  }
  ++this->Steps;
}

std::unique_ptr<SkyHierarchy> CumulativeSky::hierarchy() const
{
  if (this->Steps == 0)
    return nullptr;
  return std::make_unique<SkyHierarchy>(SkyHierarchy::fromCellAverages(this->Level, 1, this->Sums));
}
} // namespace terralux
