#include "sun/clear_sky.h"

#include "base/angles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace terralux
{
namespace
{
}

double kastenYoungAirMass(double zenithDeg)
{
  if (zenithDeg >= 96.07995)
  {
    return std::numeric_limits<double>::infinity();
  }
  return 1.0 / (std::cos(zenithDeg * degree) + 0.50572 * std::pow(96.07995 - zenithDeg, -1.6364));
}

ClearSkyIrradiance esraClearSky(
  double geometricAltitudeDeg, double heightM, double linkeTurbidity, double extraterrestrialWm2)
{
  ClearSkyIrradiance result;
  if (geometricAltitudeDeg <= 0.0)
  {
    return result;
  }
  const double h0 = geometricAltitudeDeg * degree;
  // Refraction-corrected altitude (radians) and air mass corrected for the site pressure.
  const double refraction =
    0.061359 * (0.1594 + 1.123 * h0 + 0.065656 * h0 * h0) / (1.0 + 28.9344 * h0 + 277.3971 * h0 * h0);
  const double h0ref = h0 + refraction;
  const double h0refDeg = h0ref / degree;
  const double pressureRatio = std::exp(-heightM / 8434.5);
  const double m = pressureRatio / (std::sin(h0ref) + 0.50572 * std::pow(h0refDeg + 6.07995, -1.6364));
  // Rayleigh optical thickness at air mass m (Kasten 1996 as revised in ESRA).
  const double rayleigh = m <= 20.0
    ? 1.0 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - m * 0.00013))))
    : 1.0 / (10.4 + 0.718 * m);
  result.directNormalWm2 = extraterrestrialWm2 * std::exp(-0.8662 * linkeTurbidity * m * rayleigh);

  // Diffuse: transmission at zenith Trd and angular function Fd.
  const double tl = linkeTurbidity;
  const double trd = -1.5843e-2 + 3.0543e-2 * tl + 3.797e-4 * tl * tl;
  double a0 = 2.6463e-1 - 6.1581e-2 * tl + 3.1408e-3 * tl * tl;
  if (a0 * trd < 2.0e-3)
  {
    a0 = 2.0e-3 / trd;
  }
  const double a1 = 2.0402 + 1.8945e-2 * tl - 1.1161e-2 * tl * tl;
  const double a2 = -1.3025 + 3.9231e-2 * tl + 8.5079e-3 * tl * tl;
  const double s = std::sin(h0);
  const double fd = a0 + a1 * s + a2 * s * s;
  result.diffuseHorizontalWm2 = std::max(0.0, extraterrestrialWm2 * trd * fd);
  result.globalHorizontalWm2 = result.directNormalWm2 * s + result.diffuseHorizontalWm2;
  return result;
}

ClearSkyIrradiance ineichenPerezClearSky(
  double apparentZenithDeg, double heightM, double linkeTurbidity, double extraterrestrialWm2)
{
  ClearSkyIrradiance result;
  if (apparentZenithDeg >= 90.0)
  {
    return result;
  }
  const double cosZenith = std::cos(apparentZenithDeg * degree);
  const double airMass = kastenYoungAirMass(apparentZenithDeg) * std::exp(-heightM / 8434.5);
  const double tl = linkeTurbidity;
  const double fh1 = std::exp(-heightM / 8000.0);
  const double fh2 = std::exp(-heightM / 1250.0);
  const double cg1 = 5.09e-5 * heightM + 0.868;
  const double cg2 = 3.92e-5 * heightM + 0.0387;
  const double global =
    cg1 * extraterrestrialWm2 * cosZenith * std::exp(-cg2 * airMass * (fh1 + fh2 * (tl - 1.0)));
  // Beam: the turbidity-based estimate, bounded by the global-consistent one.
  const double b = 0.664 + 0.163 / fh1;
  const double beam = b * std::exp(-0.09 * airMass * (tl - 1.0)) * extraterrestrialWm2;
  const double beamBound =
    global * std::clamp((1.0 - (0.1 - 0.2 * std::exp(-tl)) / (0.1 + 0.882 / fh1)) / cosZenith, 0.0, 1e20);
  // At high sites (b > 1 above about 3.5 km, c_g1 > 1) the fits exceed what reaches the
  // top of the atmosphere: no clear sky gives more than the extraterrestrial irradiance.
  result.globalHorizontalWm2 = std::clamp(global, 0.0, extraterrestrialWm2 * cosZenith);
  result.directNormalWm2 = std::clamp(std::min(beam, beamBound), 0.0, extraterrestrialWm2);
  result.diffuseHorizontalWm2 =
    std::max(0.0, result.globalHorizontalWm2 - result.directNormalWm2 * cosZenith);
  return result;
}
ClearSkyIrradiance clearSkyIrradiance(ClearSkyModel model, double apparentZenithDeg, double geometricZenithDeg,
  double heightM, double linkeTurbidity, double extraterrestrialWm2)
{
  if (!(apparentZenithDeg < 90.0))
    return {};
  return model == ClearSkyModel::Esra
    ? esraClearSky(90.0 - geometricZenithDeg, heightM, linkeTurbidity, extraterrestrialWm2)
    : ineichenPerezClearSky(apparentZenithDeg, heightM, linkeTurbidity, extraterrestrialWm2);
}

ClearSkyIrradiance givenIrradiance(double apparentZenithDeg, double directNormalWm2, double diffuseHorizontalWm2)
{
  ClearSkyIrradiance result;
  if (!(apparentZenithDeg < 90.0))
    return result;
  result.directNormalWm2 = directNormalWm2;
  result.diffuseHorizontalWm2 = diffuseHorizontalWm2;
  result.globalHorizontalWm2 = directNormalWm2 * std::cos(apparentZenithDeg * degree) + diffuseHorizontalWm2;
  return result;
}
} // namespace terralux
