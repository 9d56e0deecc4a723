#include "final_gather.h"

#include "angles.h"
#include "horizon_sky.h"
#include "link_transport.h"
#include "open_sky.h"
#include "sampling.h"
#include "terrain_patch.h"
#include "visibility.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
CosineFrame::CosineFrame(const Vec3& n)
  : N(n)
{
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  this->U = glm::normalize(glm::cross(a, n));
  this->V = glm::cross(n, this->U);
}

Vec3 CosineFrame::direction(double s, double t) const
{
  constexpr double twoPi = 6.28318530717958647692;
  const double r = std::sqrt(s), phi = twoPi * t;
  return glm::normalize(
    r * std::cos(phi) * this->U + r * std::sin(phi) * this->V + std::sqrt(std::max(0.0, 1.0 - s)) * this->N);
}

FinalGather::FinalGather(const Visibility& rays, const std::vector<PolygonElement*>& polygons,
  const std::vector<TerrainPatch*>& terrains, const std::vector<HElement*>& suns)
  : Rays(rays)
  , Polygons(polygons)
  , Terrains(terrains)
  , Suns(suns)
{
}

void FinalGather::prepareSuns()
{
  this->SunCumulative.clear();
  if (this->Suns.size() <= maximumSunsPerHit)
    return;
  double sum = 0.0;
  for (const HElement* sun : this->Suns)
    this->SunCumulative.push_back(sum += largestBand(sun->emittance()));
}

Spectrum FinalGather::radiosityAt(
  const PolygonElement& leaf, const SurfaceHit& hit, const Vec3& front, double sunSample) const
{
  const auto& e = leaf.Irradiance;
  Spectrum sun{};
  if (this->SunCumulative.empty())
  {
    sun = directSunlight(hit.point, front, this->Suns, this->Rays);
  }
  else
  {
    const double total = this->SunCumulative.back();
    const auto picked = std::upper_bound(this->SunCumulative.begin(), this->SunCumulative.end() - 1,
                          sunSample * total) - this->SunCumulative.begin();
    HElement& chosen = *this->Suns[static_cast<std::size_t>(picked)];
    const double chance = (this->SunCumulative[picked] - (picked > 0 ? this->SunCumulative[picked - 1] : 0.0)) / total;
    const double transport = transportToPoint(hit.point, front, chosen, this->Rays, 1, 0) / chance;
    const Spectrum flux = chosen.emittance();
    for (int band = 0; band < maxBands; ++band)
      sun[band] = transport * flux[band];
  }
  Spectrum b;
  for (int band = 0; band < maxBands; ++band)
    b[band] =
      leaf.emission()[band] + leaf.reflectance()[band] * (sun[band] + e[SkyLight][band] + e[ReflectedLight][band]);
  return b;
}

const PolygonElement* FinalGather::leafAt(const SurfaceHit& hit) const
{
  if (hit.terrain >= 0)
  {
    const auto t = static_cast<std::size_t>(hit.terrain);
    return t < this->Terrains.size() && this->Terrains[t] ? this->Terrains[t]->leafHolding(hit.u, hit.v) : nullptr;
  }
  const auto p = static_cast<std::size_t>(hit.polygon);
  return p < this->Polygons.size() && this->Polygons[p] ? this->Polygons[p]->leafHolding(hit.point) : nullptr;
}

GatheredLight FinalGather::irradianceAt(const Vec3& point, const Vec3& normal, const GatherBudget& budget,
  std::uint64_t seed, double directIrradiance, bool surfacesSend) const
{
  GatheredLight result;
  Spectrum open{};
  double openOmega = 0.0;
  if (this->Sky)
    this->Sky->irradiance(normal, open, openOmega);
  // Over a height field the sky the scene hides comes from the point's horizon, and the
  // rays only gather what surfaces send.
  const bool skyByRays = this->Sky && !this->Horizons;
  HiddenSky horizon;
  if (this->Sky && this->Horizons)
  {
    horizon = this->Horizons->hiddenAt(point, normal, seed ^ 0xD1B54A32D192ED03ull);
    for (int band = 0; band < maxBands; ++band)
      open[band] = std::max(0.0, open[band] - horizon.irradiance[band]);
    openOmega = std::max(0.0, openOmega - horizon.projectedSolidAngle);
  }
  Spectrum hidden{}, surfaces{};
  int hiddenSky = 0;
  // Each ray's share of the point's irradiance beyond the open sky (largest band):
  // what it meets minus the sky it hides; its spread sets how many rays are needed.
  double sum = 0.0, sumOfSquares = 0.0;
  // A pilot of budget.pilot rays of their own sets how many rays the point needs
  // (their standard error, as for independent rays, against the irradiance it
  // receives); the estimate then comes from that many fresh stratified rays. Rays that
  // decided when to stop would be biased: they stop early where they happened to miss
  // a bright hit.
  const CosineFrame frame(normal);
  auto cast = [&](int count, SampleGenerator& random)
  {
    // The sun each hit takes (when there are many), by a golden-ratio sequence: evenly
    // spread over the suns for any count, and unrelated to the rays' strata.
    const double sunStart = this->SunCumulative.empty() ? 0.0 : random.uniform();
    sum = sumOfSquares = 0.0;
    hidden = surfaces = Spectrum{};
    hiddenSky = 0;
    for (int k = 0; k < count; ++k)
    {
      double s, t;
      stratifiedPoint(k, count, random, s, t);
      const Vec3 d = frame.direction(s, t);
      SurfaceHit hit;
      if (!this->Rays.firstHit(point, normal, d, hit))
        continue;
      double value = 0.0;
      if (skyByRays && d.z > 0.0)
      {
        const Spectrum l = this->Sky->radiance(d);
        for (int band = 0; band < maxBands; ++band)
          hidden[band] += l[band];
        ++hiddenSky;
        value -= pi * largestBand(l);
      }
      const PolygonElement* leaf = surfacesSend ? this->leafAt(hit) : nullptr;
      if (leaf)
      {
        // The triangle's own normal, turned to the side its leaf faces; the
        // back of a one-sided surface sends nothing.
        const Vec3 front = glm::dot(hit.normal, leaf->normal()) < 0.0 ? -hit.normal : hit.normal;
        if (glm::dot(front, d) < 0.0)
        {
          const double sunSample = std::fmod(sunStart + 0.61803398874989485 * k, 1.0);
          const Spectrum b = this->radiosityAt(*leaf, hit, front, sunSample);
          for (int band = 0; band < maxBands; ++band)
            surfaces[band] += b[band];
          value += largestBand(b);
        }
      }
      sum += value;
      sumOfSquares += value * value;
    }
  };
  SampleGenerator pilotRandom(seed ^ 0x5851F42D4C957F2Dull), random(seed);
  int count = budget.maximum;
  if (!skyByRays && !surfacesSend)
    count = 0; // nothing left for rays to find
  if (count > 0 && budget.pilot > 0 && budget.minimum < budget.maximum)
  {
    cast(budget.pilot, pilotRandom);
    const double mean = sum / budget.pilot;
    const double variance = std::max(0.0, sumOfSquares / budget.pilot - mean * mean);
    const double received = directIrradiance + largestBand(open) + mean;
    const double target = budget.relativeError * std::max(received, 1e-12);
    // A whole square of strata: a partly filled last row would leave a band of the
    // hemisphere unsampled.
    const double needed =
      std::clamp<double>(std::ceil(variance / (target * target)), budget.minimum, budget.maximum);
    const int side = static_cast<int>(std::ceil(std::sqrt(needed)));
    count = side * side;
  }
  cast(count, random);
  // E = pi x the mean radiance over cosine-weighted directions: the mean radiosity.
  const double perRay = count > 0 ? 1.0 / count : 0.0;
  for (int band = 0; band < maxBands; ++band)
  {
    result.surfaces[band] = surfaces[band] * perRay;
    result.sky[band] = std::max(0.0, open[band] - pi * hidden[band] * perRay);
  }
  if (this->Sky)
    result.skyViewFactor = std::max(0.0, openOmega / pi - static_cast<double>(hiddenSky) * perRay);
  result.rays = count + horizon.rays;
  return result;
}
} // namespace terralux
