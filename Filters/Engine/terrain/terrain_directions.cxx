#include "terrain/terrain_directions.h"

#include "base/angles.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace terralux
{
namespace
{
// sin x for an elevation, |x| <= pi / 2, by its Taylor series to x^13 (within 7e-10):
// a post's boxes take three sines each, 192 a post, a twentieth of its time.
double sinOfElevation(double x)
{
  x = std::clamp(x, -0.5 * pi, 0.5 * pi);
  const double x2 = x * x;
  return x *
    (1.0 +
      x2 * (-1.0 / 6.0 +
             x2 * (1.0 / 120.0 +
                    x2 * (-1.0 / 5040.0 +
                           x2 * (1.0 / 362880.0 + x2 * (-1.0 / 39916800.0 + x2 * (1.0 / 6227020800.0)))))));
}
// sin x and cos x for a box's width at most (a piece of a sector between two of the
// map's azimuths: 0.1 rad on square cells, within 1e-11 up to 0.5), by their series to
// x^9 and x^10: a ray's direction needs both, and libm's took a tenth of a post's
// gather's own work.
std::array<double, 2> sinCosOfSmall(double x)
{
  const double x2 = x * x;
  const double s = x * (1.0 + x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362880.0)))));
  const double c =
    1.0 + x2 * (-0.5 + x2 * (1.0 / 24.0 + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40320.0 + x2 * (-1.0 / 3628800.0)))));
  return { s, c };
}
} // namespace

TerrainDirections::TerrainDirections(const HorizonSky& horizons, const HorizonMap::Post& post, const Vec3& normal)
  : Normal(normal)
{
  // The sine of the post's plane's elevation toward an azimuth (negative where it
  // dips): elevations are compared and sampled by their sines, which need no angle.
  auto planeSinAt = [&](const HorizonSky::SinCos& a) {
    const double toward = normal.x * a.cos + normal.y * a.sin;
    return -toward / std::sqrt(toward * toward + normal.z * normal.z);
  };
  // The horizon as the hidden sky takes it, over the same pieces, so that the two
  // partition the hemisphere.
  HorizonSky::MapElevations elevations;
  std::array<bool, HorizonMap::maximumAzimuths> rises;
  horizons.mapHorizons(post, normal, elevations, rises);
  const std::vector<HorizonSky::MapPiece>& pieces = horizons.mapPieces();
  const int count = static_cast<int>(pieces.size()) / HorizonSky::piecesPerSector;
  double sinPlaneStart = planeSinAt(pieces[0].start);
  for (int a = 0; a < count; ++a)
  {
    const int b = (a + 1) % count;
    for (int j = 0; j < HorizonSky::piecesPerSector; ++j)
    {
      const HorizonSky::MapPiece& piece = pieces[a * HorizonSky::piecesPerSector + j];
      const double t = (j + 0.5) / HorizonSky::piecesPerSector;
      const double horizon = (1.0 - t) * elevations[a] + t * elevations[b];
      const double sinHorizon = sinOfElevation(horizon);
      const double sinPlaneMiddle = planeSinAt(piece.middle);
      // A sector with terrain above its lower bounds (HorizonSky's "open" test) reaches
      // above its higher horizon by a margin; one open at both ends does not, or every
      // flat post would cast rays for the rare peak between two open azimuths.
      const bool margin = rises[a] || rises[b];
      const double sinHigh =
        margin ? sinOfElevation(std::max(elevations[a], elevations[b]) + horizonMargin) : sinHorizon;
      const double sinPlaneEnd = planeSinAt(piece.end);
      // Down to the plane's lowest elevation over the piece (it dips most at one end
      // or, near the slope's fall line, in between).
      const double sinLow = std::min({ sinPlaneMiddle, sinPlaneStart, sinPlaneEnd });
      sinPlaneStart = sinPlaneEnd;
      if (!(sinHigh > sinPlaneMiddle))
        continue; // only slivers in front of the plane, their cosines next to 0
      // The cosine toward the box's middle, the density's shape within it.
      const double sinMiddle = 0.5 * (sinLow + sinHigh), cosMiddle = std::sqrt(1.0 - sinMiddle * sinMiddle);
      const double cosine = std::max(0.02,
        normal.x * cosMiddle * piece.middle.cos + normal.y * cosMiddle * piece.middle.sin + normal.z * sinMiddle);
      // Around the interpolated horizon, where terrain it misses may rise, rays are
      // drawn marginDensity times as densely: few there, each would carry a large weight.
      const double sinSplit = margin ? std::max(sinLow, sinOfElevation(horizon - horizonMargin)) : sinHigh;
      this->addBox(piece, sinLow, sinSplit, cosine);
      this->addBox(piece, sinSplit, sinHigh, marginDensity * cosine);
    }
  }
}

void TerrainDirections::addBox(const HorizonSky::MapPiece& piece, double sinLow, double sinHigh, double cosine)
{
  if (!(sinHigh > sinLow))
    return;
  const double width = piece.phi1 - piece.phi0;
  this->Total += width * (sinHigh - sinLow) * cosine;
  this->Boxes[this->Count++] = { piece.start.sin, piece.start.cos, width, sinLow, sinHigh - sinLow, cosine, this->Total };
}

TerrainDirections::Sample TerrainDirections::sample(double s, double t) const
{
  // The box by inversion of the running sums, then uniform in azimuth and in the sine
  // of the elevation within it (uniform in solid angle): the density is the box's
  // cosine over the total.
  const double x = s * this->Total;
  const Box* box = std::upper_bound(this->Boxes.data(), this->Boxes.data() + this->Count, x,
    [](double value, const Box& b) { return value < b.cumulative; });
  box = std::min(box, this->Boxes.data() + this->Count - 1);
  const double share = box->width * box->sinSpan * box->cosine;
  const double within = std::clamp((x - (box->cumulative - share)) / share, 0.0, 1.0);
  Sample result;
  // The azimuth's sine and cosine turned from the box's start by the small angle within.
  const auto [sinTurn, cosTurn] = sinCosOfSmall(within * box->width);
  const double cosPhi = box->cosPhi0 * cosTurn - box->sinPhi0 * sinTurn;
  const double sinPhi = box->sinPhi0 * cosTurn + box->cosPhi0 * sinTurn;
  const double sinU = std::clamp(box->sinLow + t * box->sinSpan, -1.0, 1.0);
  const double cosU = std::sqrt(std::max(0.0, 1.0 - sinU * sinU));
  result.direction = Vec3(cosU * cosPhi, cosU * sinPhi, sinU);
  const double cosine = glm::dot(this->Normal, result.direction);
  result.weight = cosine > 0.0 ? cosine * this->Total / (pi * box->cosine) : 0.0;
  return result;
}
} // namespace terralux
