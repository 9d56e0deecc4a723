#include "evaluation/sky_importance.h"

#include "base/angles.h"
#include "evaluation/open_sky.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
SkyImportance::SkyImportance(const OpenSky& sky)
  : Sky(sky)
  , Side(sky.cellsPerSide())
{
  const double cellHeight = 0.5 * pi / this->Side;
  this->CellWidth = 2.0 * pi / this->Side;
  for (int iu = 0; iu <= this->Side; ++iu)
    this->RowSines.push_back(std::sin(iu * cellHeight));
  this->Rows.assign(this->Side + 1, 0.0);
  this->Columns.assign(static_cast<std::size_t>(this->Side) * (this->Side + 1), 0.0);
  for (int iu = 0; iu < this->Side; ++iu)
  {
    const double solidAngle = this->CellWidth * (this->RowSines[iu + 1] - this->RowSines[iu]);
    double* columns = &this->Columns[static_cast<std::size_t>(iu) * (this->Side + 1)];
    for (int iv = 0; iv < this->Side; ++iv)
    {
      const Spectrum& l = sky.cellRadiance(iu, iv);
      columns[iv + 1] = columns[iv] + largestBand(l) * solidAngle;
    }
    this->Rows[iu + 1] = this->Rows[iu] + columns[this->Side];
  }
  this->Flux = this->Rows[this->Side];
}

bool SkyImportance::sample(double s, double t, Sample& out) const
{
  if (!(this->Flux > 0.0))
    return false;
  // The row by s, the cell in it by t; what is left of each picks the place in the cell.
  auto pick = [](const double* cumulative, int count, double x, double& rest) {
    const double target = x * cumulative[count];
    int k = static_cast<int>(std::upper_bound(cumulative + 1, cumulative + count, target) - (cumulative + 1));
    while (k > 0 && !(cumulative[k + 1] > cumulative[k]))
      --k; // an empty cell is never picked
    const double width = cumulative[k + 1] - cumulative[k];
    rest = width > 0.0 ? std::clamp((target - cumulative[k]) / width, 0.0, 1.0) : 0.5;
    return k;
  };
  double restS = 0.0, restT = 0.0;
  const int iu = pick(this->Rows.data(), this->Side, s, restS);
  const double* columns = &this->Columns[static_cast<std::size_t>(iu) * (this->Side + 1)];
  if (!(columns[this->Side] > 0.0))
    return false;
  const int iv = pick(columns, this->Side, t, restT);
  // Uniform in solid angle inside the cell: uniform in sin u and in v.
  const double s0 = this->RowSines[iu], s1 = this->RowSines[iu + 1];
  const double sinU = s0 + restS * (s1 - s0), cosU = std::sqrt(std::max(0.0, 1.0 - sinU * sinU));
  const double v = (iv + restT) * this->CellWidth;
  out.direction = Vec3(-std::sin(v) * cosU, -std::cos(v) * cosU, sinU); // directionFromSkyParameters
  const Spectrum& l = this->Sky.cellRadiance(iu, iv);
  const double drawn = largestBand(l); // density: drawn / Flux per steradian
  for (int band = 0; band < maxBands; ++band)
    out.weight[band] = this->Flux * l[band] / drawn;
  out.solidAngleWeight = this->Flux / drawn;
  return true;
}
} // namespace terralux
