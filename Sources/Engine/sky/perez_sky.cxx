#include "sky/perez_sky.h"

#include "base/angles.h"
#include "sun/clear_sky.h"
#include "base/error.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
constexpr double halfPi = 1.57079632679489661923;

// Upper bounds of the eight clearness bins.
const double clearnessBins[7] = { 1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200 };

// Per bin, for x in a, b, c, d, e: x1, x2, x3, x4 with x = x1 + x2 Z + Delta (x3 + x4 Z)
// (Perez et al. 1993, table 1; bin 1 uses other forms for c and d).
const double perezTable[8][5][4] = {
  { { 1.3525, -0.2576, -0.2690, -1.4366 }, { -0.7670, 0.0007, 1.2734, -0.1233 },
    { 2.8000, 0.6004, 1.2375, 1.0000 }, { 1.8734, 0.6297, 0.9738, 0.2809 },
    { 0.0356, -0.1246, -0.5718, 0.9938 } },
  { { -1.2219, -0.7730, 1.4148, 1.1016 }, { -0.2054, 0.0367, -3.9128, 0.9156 },
    { 6.9750, 0.1774, 6.4477, -0.1239 }, { -1.5798, -0.5081, -1.7812, 0.1080 },
    { 0.2624, 0.0672, -0.2190, -0.4285 } },
  { { -1.1000, -0.2515, 0.8952, 0.0156 }, { 0.2782, -0.1812, -4.5000, 1.1766 },
    { 24.7219, -13.0812, -37.7000, 34.8438 }, { -5.0000, 1.5218, 3.9229, -2.6204 },
    { -0.0156, 0.1597, 0.4199, -0.5562 } },
  { { -0.5484, -0.6654, -0.2672, 0.7117 }, { 0.7234, -0.6219, -5.6812, 2.6297 },
    { 33.3389, -18.3000, -62.2500, 52.0781 }, { -3.5000, 0.0016, 1.1477, 0.1062 },
    { 0.4659, -0.3296, -0.0876, -0.0329 } },
  { { -0.6000, -0.3566, -2.5000, 2.3250 }, { 0.2937, 0.0496, -5.6812, 1.8415 },
    { 21.0000, -4.7656, -21.5906, 7.2492 }, { -3.5000, -0.1554, 1.4062, 0.3988 },
    { 0.0032, 0.0766, -0.0656, -0.1294 } },
  { { -1.0156, -0.3670, 1.0078, 1.4051 }, { 0.2875, -0.5328, -3.8500, 3.3750 },
    { 14.0000, -0.9999, -7.1406, 7.5469 }, { -3.4000, -0.1078, -1.0750, 1.5702 },
    { -0.0672, 0.4016, 0.3017, -0.4844 } },
  { { -1.0000, 0.0211, 0.5025, -0.5119 }, { -0.3000, 0.1922, 0.7023, -1.6317 },
    { 19.0000, -5.0000, 1.2438, -1.9094 }, { -4.0000, 0.0250, 0.3844, 0.2656 },
    { 1.0468, -0.3788, -2.4517, 1.4656 } },
  { { -1.0500, 0.0289, 0.4260, 0.3590 }, { -0.3250, 0.1156, 0.7781, 0.0025 },
    { 31.0625, -14.5000, -46.1148, 55.3750 }, { -7.2312, 0.4050, 13.3500, 0.6234 },
    { 1.5000, -0.6426, 1.8564, 0.5636 } },
};
} // namespace

PerezSky::PerezSky(const Direction& sun, double directNormalWm2, double diffuseHorizontalWm2,
  double extraterrestrialWm2)
  : Sun(sun)
{
  if (!(directNormalWm2 >= 0.0) || !(diffuseHorizontalWm2 >= 0.0) || !(extraterrestrialWm2 > 0.0) ||
    !std::isfinite(directNormalWm2) || !std::isfinite(diffuseHorizontalWm2) ||
    !std::isfinite(extraterrestrialWm2))
  {
    throw Error("the Perez sky needs finite irradiances: direct normal and diffuse horizontal >= 0 W/m^2");
  }
  // The model is defined for the sun above the horizon; hold it there.
  const double zenith = std::min(angleBetween(sun, { 0.0, 0.0, 1.0 }), halfPi);
  const double z3 = 1.041 * zenith * zenith * zenith;
  this->Clearness = diffuseHorizontalWm2 > 0.0
    ? ((diffuseHorizontalWm2 + directNormalWm2) / diffuseHorizontalWm2 + z3) / (1.0 + z3)
    : 1.0;
  const double airMass = std::min(kastenYoungAirMass(zenith * 180.0 / pi), 40.0);
  this->Brightness = diffuseHorizontalWm2 * airMass / extraterrestrialWm2;
  // Bounds of the fitted data set, as Radiance's gendaylit applies them.
  this->Clearness = std::clamp(this->Clearness, 1.0, 12.0);
  this->Brightness = std::clamp(this->Brightness, 0.01, 0.6);
  double delta = this->Brightness;
  if (this->Clearness > 1.065 && this->Clearness < 2.8)
  {
    delta = std::max(delta, 0.2);
  }

  const int bin = static_cast<int>(std::upper_bound(clearnessBins, clearnessBins + 7, this->Clearness) - clearnessBins);
  const auto& x = perezTable[bin];
  for (int k = 0; k < 5; ++k)
  {
    this->Coefficients[k] = x[k][0] + x[k][1] * zenith + delta * (x[k][2] + x[k][3] * zenith);
  }
  if (bin == 0)
  {
    this->Coefficients[2] = std::exp(std::pow(delta * (x[2][0] + x[2][1] * zenith), x[2][2])) - x[2][3];
    this->Coefficients[3] = -std::exp(delta * (x[3][0] + x[3][1] * zenith)) + x[3][2] + delta * x[3][3];
  }
}

double PerezSky::relativeRadiance(const Direction& direction) const
{
  const double* k = this->Coefficients;
  // cos(zeta) is bounded below, as in Radiance's perezlum.cal, so that a positive b
  // does not blow up at the horizon.
  const double cosZeta = std::max(direction[2], 0.01);
  const double gamma = angleBetween(direction, this->Sun);
  const double cosGamma = std::cos(gamma);
  const double value = (1.0 + k[0] * std::exp(k[1] / cosZeta)) *
    (1.0 + k[2] * std::exp(k[3] * gamma) + k[4] * cosGamma * cosGamma);
  return std::max(0.0, value); // some coefficient sets dip below zero near the horizon
}
} // namespace terralux
