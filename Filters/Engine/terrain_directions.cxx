#include "terrain_directions.h"

#include "angles.h"

#include <algorithm>
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
} // namespace

TerrainDirectionTable::TerrainDirectionTable(const HorizonMap& map)
  : Map(map)
{
  const std::vector<double>& azimuths = map.azimuths();
  for (std::size_t a = 0; a < azimuths.size(); ++a)
  {
    const double to = a + 1 < azimuths.size() ? azimuths[a + 1] : azimuths[0] + 2.0 * pi;
    const double width = (to - azimuths[a]) / piecesPerSector;
    for (int j = 0; j < piecesPerSector; ++j)
    {
      const double phi0 = azimuths[a] + j * width, middle = phi0 + 0.5 * width;
      this->Pieces.push_back({ phi0, width, std::cos(phi0), std::sin(phi0), std::cos(phi0 + width),
        std::sin(phi0 + width), std::cos(middle), std::sin(middle) });
    }
  }
}

TerrainDirections::TerrainDirections(
  const TerrainDirectionTable& table, const HorizonMap::Post& post, const Vec3& normal)
  : Normal(normal)
{
  const HorizonMap& map = table.map();
  // The sine of the post's plane's elevation toward an azimuth (negative where it
  // dips): elevations are compared and sampled by their sines, which need no angle.
  auto planeSinAt = [&](double c, double s) {
    const double toward = normal.x * c + normal.y * s;
    return -toward / std::sqrt(toward * toward + normal.z * normal.z);
  };
  // The horizon as HorizonSky takes it: never below the plane's own or the world's.
  const int count = static_cast<int>(map.azimuths().size());
  std::array<double, HorizonMap::azimuthCount> horizons;
  std::array<bool, HorizonMap::azimuthCount> rises; // terrain above the lower bound
  const auto& pieces = table.pieces();
  for (int a = 0; a < count; ++a)
  {
    const auto& start = pieces[a * TerrainDirectionTable::piecesPerSector];
    const double sinPlane = planeSinAt(start.cos0, start.sin0);
    const double lower = sinPlane > 0.0 ? std::asin(sinPlane) : 0.0, elevation = map.elevation(post, a);
    rises[a] = elevation > lower;
    horizons[a] = std::max(elevation, lower);
  }
  double sinPlaneStart = planeSinAt(pieces[0].cos0, pieces[0].sin0);
  for (int a = 0; a < count; ++a)
  {
    for (int j = 0; j < TerrainDirectionTable::piecesPerSector; ++j)
    {
      const auto& piece = pieces[a * TerrainDirectionTable::piecesPerSector + j];
      const double t = (j + 0.5) / TerrainDirectionTable::piecesPerSector;
      const double horizon = (1.0 - t) * horizons[a] + t * horizons[(a + 1) % count];
      const double sinHorizon = sinOfElevation(horizon);
      const double sinPlaneMiddle = planeSinAt(piece.cosMiddle, piece.sinMiddle);
      // A sector with terrain above its lower bounds (HorizonSky's "open" test) reaches
      // above its higher horizon by a margin; one open at both ends does not, or every
      // flat post would cast rays for the rare peak between two open azimuths.
      const bool margin = rises[a] || rises[(a + 1) % count];
      const double sinHigh = margin
        ? sinOfElevation(std::max(horizons[a], horizons[(a + 1) % count]) + horizonMargin)
        : sinHorizon;
      const double sinPlaneEnd = planeSinAt(piece.cos1, piece.sin1);
      // Down to the plane's lowest elevation over the piece (it dips most at one end
      // or, near the slope's fall line, in between).
      const double sinLow = std::min({ sinPlaneMiddle, sinPlaneStart, sinPlaneEnd });
      sinPlaneStart = sinPlaneEnd;
      if (!(sinHigh > sinPlaneMiddle))
        continue; // only slivers in front of the plane, their cosines next to 0
      // The cosine toward the box's middle, the density's shape within it.
      const double sinMiddle = 0.5 * (sinLow + sinHigh), cosMiddle = std::sqrt(1.0 - sinMiddle * sinMiddle);
      const double cosine = std::max(0.02,
        normal.x * cosMiddle * piece.cosMiddle + normal.y * cosMiddle * piece.sinMiddle + normal.z * sinMiddle);
      // Around the interpolated horizon, where its corrections lie, rays are drawn
      // marginDensity times as densely: few there, each would carry a large weight.
      const double sinSkyLow = std::max(0.0, sinPlaneMiddle);
      const double sinSplit = margin ? std::max(sinLow, sinOfElevation(horizon - horizonMargin)) : sinHigh;
      this->addBox(piece.phi0, piece.width, sinLow, sinSplit, cosine, sinHorizon, sinSkyLow);
      this->addBox(piece.phi0, piece.width, sinSplit, sinHigh, marginDensity * cosine, sinHorizon, sinSkyLow);
    }
  }
}

void TerrainDirections::addBox(
  double phi0, double width, double sinLow, double sinHigh, double cosine, double sinHorizon, double sinSkyLow)
{
  if (!(sinHigh > sinLow))
    return;
  this->Total += width * (sinHigh - sinLow) * cosine;
  this->Boxes[this->Count++] = { phi0, width, sinLow, sinHigh - sinLow, cosine, this->Total, sinHorizon, sinSkyLow };
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
  const double azimuth = box->phi0 + within * box->width;
  const double sinU = std::clamp(box->sinLow + t * box->sinSpan, -1.0, 1.0);
  const double cosU = std::sqrt(std::max(0.0, 1.0 - sinU * sinU));
  result.direction = Vec3(cosU * std::cos(azimuth), cosU * std::sin(azimuth), sinU);
  const double cosine = glm::dot(this->Normal, result.direction);
  result.weight = cosine > 0.0 ? cosine * this->Total / (pi * box->cosine) : 0.0;
  result.skyTaken = sinU > box->sinHorizon ? -1 : (sinU >= box->sinSkyLow ? 1 : 0);
  return result;
}
} // namespace terralux
