#pragma once
// CIE sky luminance distributions (CIE S 011/E:2003, ISO 15469:2004): the 15
// standard general skies, and the traditional CIE overcast sky (Moon & Spencer).
//   L(Z, a) / Lz = f(chi) phi(Z) / (f(Zs) phi(0))
//   phi(Z) = 1 + a exp(b / cos Z)          (phi = 1 at the horizon)
//   f(chi) = 1 + c (exp(d chi) - exp(d pi/2)) + e cos^2 chi

#include "sky/sky_model.h"

namespace terralux
{
struct CieParameters
{
  double a, b, c, d, e;
};

class CieGeneralSky : public SkyModel
{
public:
  /// type 1..15 (1-5 overcast, 6-10 intermediate, 11-15 clear); sun: unit vector
  /// toward the sun (it may be below the horizon). Throws Error for another type.
  CieGeneralSky(int type, const Direction& sun);

  static CieParameters parameters(int type);

  /// L / Lz: 1 at the zenith.
  double relativeRadiance(const Direction& direction) const override;

private:
  double gradation(double cosZenith) const;
  double indicatrix(double scatteringAngle) const;

  CieParameters Parameters;
  Direction Sun;
  double Normalisation; // 1 / (f(Zs) phi(0))
};

/// The traditional CIE overcast sky: L / Lz = (1 + 2 cos Z) / 3.
class CieOvercastSky : public SkyModel
{
public:
  double relativeRadiance(const Direction& direction) const override;
};
} // namespace terralux
