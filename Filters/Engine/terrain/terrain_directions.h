#pragma once
// The directions in which a post of a height field can see terrain: above its own
// plane and below its horizon (the horizons' map, interpolated between the map's
// azimuths over the same pieces as the sky it hides, HorizonSky, so that the two
// partition the hemisphere). A final gather that draws its rays there instead of over
// the whole hemisphere spends none on the open sky, which HorizonSky integrates
// exactly: on an open slope whose terrain fills 5 % of the view, 95 % of cosine-weighted
// rays find nothing and their mean is mostly the binomial noise of hit or miss; drawn
// below the horizon, nearly every ray meets terrain and the noise left is the spread of
// what the terrain sends. A flat, open post has no such directions and takes no ray.
// Between the map's azimuths the true horizon can rise above the interpolated one (a
// peak between two azimuths): the boxes reach a little above the higher of the two, so
// that the terrain there sends its light. The sky stays what HorizonSky takes: rays
// that corrected it where the interpolated line was wrong (terrain above it, sky below
// it) carried far more noise than the error they removed (docs/tuning.md).

#include "horizons/horizon_map.h"
#include "horizons/horizon_sky.h"
#include "hierarchy/radiosity_types.h"

#include <array>

namespace terralux
{
/// One post's terrain directions, as boxes of azimuth and elevation a piece wide, from
/// which rays are drawn with a density close to the cosine's.
class TerrainDirections
{
public:
  /// `horizons` must hold the map (HorizonSky::map) whose post this is.
  TerrainDirections(const HorizonSky& horizons, const HorizonMap::Post& post, const Vec3& normal);
  /// No direction where terrain can be seen (rays would all be wasted).
  bool empty() const { return !(this->Total > 0.0); }
  struct Sample
  {
    Vec3 direction;
    /// The cosine to the normal over pi x the density, so that the mean of radiosity x
    /// weight over the samples estimates the irradiance the terrain sends (0 behind
    /// the plane).
    double weight = 0.0;
  };
  /// The sample at a point (s, t) of the unit square; stratified points give
  /// stratified directions.
  Sample sample(double s, double t) const;

  /// How far above the higher of two azimuths' horizons the boxes reach (radians).
  static constexpr double horizonMargin = 0.01;
  /// How much denser rays are drawn within horizonMargin of the interpolated horizon.
  static constexpr double marginDensity = 2.0;

private:
  struct Box
  {
    double sinPhi0, cosPhi0, width, sinLow, sinSpan, cosine, cumulative;
  };
  void addBox(const HorizonSky::MapPiece& piece, double sinLow, double sinHigh, double cosine);
  std::array<Box, 2 * HorizonMap::maximumAzimuths * HorizonSky::piecesPerSector> Boxes;
  int Count = 0;
  double Total = 0.0;
  Vec3 Normal;
};
} // namespace terralux
