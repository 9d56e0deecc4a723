#pragma once
// Perez all-weather sky (Perez, Seals & Michalsky, Solar Energy 50(3), 1993, with
// its erratum): relative radiance
//   lv = (1 + a exp(b / cos zeta)) (1 + c exp(d gamma) + e cos^2 gamma)
// whose coefficients follow from the sky clearness epsilon and brightness Delta,
// which come from the direct normal and diffuse horizontal irradiance.

#include "sky/sky_model.h"

namespace terralux
{
class PerezSky : public SkyModel
{
public:
  /// sun: unit vector toward the sun; directNormalWm2 and diffuseHorizontalWm2 the
  /// measured (or clear-sky) irradiances; extraterrestrialWm2 the normal irradiance at
  /// the top of the atmosphere. Throws Error on negative or non-finite irradiances.
  PerezSky(const Direction& sun, double directNormalWm2, double diffuseHorizontalWm2,
    double extraterrestrialWm2);

  double clearness() const { return this->Clearness; }
  double brightness() const { return this->Brightness; }
  /// The five coefficients a..e for this sky.
  const double* coefficients() const { return this->Coefficients; }

  double relativeRadiance(const Direction& direction) const override;

private:
  Direction Sun;
  double Clearness;
  double Brightness;
  double Coefficients[5];
};
} // namespace terralux
