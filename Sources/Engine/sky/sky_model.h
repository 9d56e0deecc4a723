#pragma once
// Sky radiance distributions: the angular shape of the diffuse sky, up to a scale
// that the sky hierarchy sets from the diffuse horizontal irradiance.
// Directions are unit vectors in the local east-north-up frame.

#include <array>

namespace terralux
{
using Direction = std::array<double, 3>;

/// Unit vector toward zenith angle and compass azimuth (clockwise from north), radians.
Direction directionFromZenithAzimuth(double zenithRad, double azimuthRad);

/// Angle between two unit vectors, robust near 0 and pi.
double angleBetween(const Direction& a, const Direction& b);

class SkyModel
{
public:
  virtual ~SkyModel() = default;
  /// Radiance toward `direction` (up component >= 0) relative to the model's own
  /// reference; finite and >= 0 for every direction of the upper hemisphere.
  virtual double relativeRadiance(const Direction& direction) const = 0;
};

/// The same radiance in every direction.
class UniformSky : public SkyModel
{
public:
  double relativeRadiance(const Direction&) const override { return 1.0; }
};
} // namespace terralux
