#include "sky/sky_model.h"

#include <cmath>

namespace terralux
{
Direction directionFromZenithAzimuth(double zenithRad, double azimuthRad)
{
  const double horizontal = std::sin(zenithRad);
  return { horizontal * std::sin(azimuthRad), horizontal * std::cos(azimuthRad), std::cos(zenithRad) };
}

double angleBetween(const Direction& a, const Direction& b)
{
  // atan2 of |a x b| and a.b stays accurate where acos(a.b) loses digits.
  const double cx = a[1] * b[2] - a[2] * b[1];
  const double cy = a[2] * b[0] - a[0] * b[2];
  const double cz = a[0] * b[1] - a[1] * b[0];
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot);
}
} // namespace terralux
