#pragma once
// Local east-north-up (ENU) Cartesian frame tangent to the WGS84 ellipsoid at a
// geodetic origin. Conversions go geodetic -> ECEF -> ENU (GeographicLib's
// LocalCartesian), so Earth curvature is kept: far from the origin, ground at
// constant ellipsoidal height drops below the tangent plane (about 196 m at 50 km).

#include <array>
#include <memory>

namespace terralux
{
/// Latitude and longitude in degrees (WGS84), height above the ellipsoid in metres.
struct GeodeticPoint
{
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0;
  double heightM = 0.0;
};

/// East, north, up in metres relative to the frame origin.
using LocalPoint = std::array<double, 3>;

class LocalFrame
{
public:
  /// Throws terralux::Error when the origin is not finite or |latitude| > 90.
  explicit LocalFrame(const GeodeticPoint& origin);
  LocalFrame(const LocalFrame& other);
  LocalFrame& operator=(const LocalFrame& other);
  ~LocalFrame();

  const GeodeticPoint& origin() const { return this->Origin; }

  /// Thread-safe (const, no shared mutable state).
  LocalPoint toLocal(const GeodeticPoint& point) const;
  GeodeticPoint toGeodetic(const LocalPoint& local) const;

private:
  struct Impl;
  GeodeticPoint Origin;
  std::unique_ptr<Impl> Cartesian;
};
} // namespace terralux
