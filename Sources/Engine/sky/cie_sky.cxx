#include "sky/cie_sky.h"

#include "base/error.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
constexpr double halfPi = 1.57079632679489661923;

// ISO 15469 / CIE S 011 table of gradation (a, b) and indicatrix (c, d, e) parameters.
const CieParameters cieTable[15] = {
  { 4.0, -0.70, 0.0, -1.0, 0.00 },
  { 4.0, -0.70, 2.0, -1.5, 0.15 },
  { 1.1, -0.80, 0.0, -1.0, 0.00 },
  { 1.1, -0.80, 2.0, -1.5, 0.15 },
  { 0.0, -1.00, 0.0, -1.0, 0.00 },
  { 0.0, -1.00, 2.0, -1.5, 0.15 },
  { 0.0, -1.00, 5.0, -2.5, 0.30 },
  { 0.0, -1.00, 10.0, -3.0, 0.45 },
  { -1.0, -0.55, 2.0, -1.5, 0.15 },
  { -1.0, -0.55, 5.0, -2.5, 0.30 },
  { -1.0, -0.55, 10.0, -3.0, 0.45 },
  { -1.0, -0.32, 10.0, -3.0, 0.45 },
  { -1.0, -0.32, 16.0, -3.0, 0.30 },
  { -1.0, -0.15, 16.0, -3.0, 0.30 },
  { -1.0, -0.15, 24.0, -2.8, 0.15 },
};
} // namespace

CieParameters CieGeneralSky::parameters(int type)
{
  if (type < 1 || type > 15)
  {
    throw Error("CIE standard general sky type " + std::to_string(type) + " does not exist: use 1..15");
  }
  return cieTable[type - 1];
}

CieGeneralSky::CieGeneralSky(int type, const Direction& sun)
  : Parameters(parameters(type))
  , Sun(sun)
{
  const double sunZenith = angleBetween(sun, { 0.0, 0.0, 1.0 });
  this->Normalisation = 1.0 / (this->indicatrix(sunZenith) * this->gradation(1.0));
}

double CieGeneralSky::gradation(double cosZenith) const
{
  // At and below the horizon exp(b / cos Z) -> 0 (b < 0 for every type): phi = 1.
  if (cosZenith <= 0.0)
  {
    return 1.0;
  }
  return 1.0 + this->Parameters.a * std::exp(this->Parameters.b / cosZenith);
}

double CieGeneralSky::indicatrix(double chi) const
{
  const auto& p = this->Parameters;
  const double cosChi = std::cos(chi);
  return 1.0 + p.c * (std::exp(p.d * chi) - std::exp(p.d * halfPi)) + p.e * cosChi * cosChi;
}

double CieGeneralSky::relativeRadiance(const Direction& direction) const
{
  const double chi = angleBetween(direction, this->Sun);
  const double value =
    this->indicatrix(chi) * this->gradation(std::clamp(direction[2], -1.0, 1.0)) * this->Normalisation;
  return std::max(0.0, value);
}

double CieOvercastSky::relativeRadiance(const Direction& direction) const
{
  return (1.0 + 2.0 * std::clamp(direction[2], 0.0, 1.0)) / 3.0;
}
} // namespace terralux
