#include "final_gather.h"

#include "angles.h"
#include "horizon_sky.h"
#include "sky_importance.h"
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

FinalGather::~FinalGather() = default;

void FinalGather::setSky(const OpenSky* sky)
{
  this->Sky = sky;
  this->SkySamples = sky ? std::make_unique<SkyImportance>(*sky) : nullptr;
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

namespace
{
// How many stratified rays bring the standard error of their mean below
// budget.relativeError x `received`, from a pilot's sum and sum of squares (as for
// independent rays), between budget.minimum and budget.maximum: a whole square of
// strata, since a partly filled last row would leave a band of directions unsampled.
int raysNeeded(const GatherBudget& budget, double sum, double sumOfSquares, double received)
{
  const double mean = sum / budget.pilot;
  const double variance = std::max(0.0, sumOfSquares / budget.pilot - mean * mean);
  const double target = budget.relativeError * std::max(received, 1e-12);
  const double needed = std::clamp<double>(std::ceil(variance / (target * target)), budget.minimum, budget.maximum);
  const int side = static_cast<int>(std::ceil(std::sqrt(needed)));
  return side * side;
}

bool pilotDecides(const GatherBudget& budget)
{
  return budget.pilot > 0 && budget.minimum < budget.maximum;
}
} // namespace

Spectrum FinalGather::hiddenSkyByRadiance(const Vec3& point, const Vec3& normal, const GatherBudget& budget,
  std::uint64_t seed, double received, double& hiddenProjectedSolidAngle, int& rays) const
{
  Spectrum hidden{};
  double sum = 0.0, sumOfSquares = 0.0;
  auto cast = [&](int count, SampleGenerator& random) {
    hidden = Spectrum{};
    hiddenProjectedSolidAngle = sum = sumOfSquares = 0.0;
    for (int k = 0; k < count; ++k)
    {
      double s, t;
      stratifiedPoint(k, count, random, s, t);
      SkyImportance::Sample sample;
      if (!this->SkySamples->sample(s, t, sample))
        continue;
      const double cosine = glm::dot(normal, sample.direction);
      if (!(cosine > 0.0))
        continue; // behind the plane: nothing to hide, no ray
      ++rays;
      if (!this->Rays.occludedToward(point, normal, sample.direction))
        continue;
      for (int band = 0; band < maxBands; ++band)
        hidden[band] += cosine * sample.weight[band];
      hiddenProjectedSolidAngle += cosine * sample.solidAngleWeight;
      const double value = cosine * largestBand(sample.weight);
      sum += value;
      sumOfSquares += value * value;
    }
  };
  // A pilot of its own sets the count, as for the surfaces' rays (see irradianceAt).
  SampleGenerator pilotRandom(seed ^ 0x2545F4914F6CDD1Dull), random(seed ^ 0x9E3779B97F4A7C15ull);
  int count = budget.maximum;
  if (pilotDecides(budget))
  {
    cast(budget.pilot, pilotRandom);
    count = raysNeeded(budget, sum, sumOfSquares, received);
  }
  cast(count, random);
  for (double& band : hidden)
    band /= count;
  hiddenProjectedSolidAngle /= count;
  return hidden;
}

GatheredLight FinalGather::irradianceAt(const Vec3& point, const Vec3& normal, const GatherBudget& budget,
  std::uint64_t seed, double directIrradiance, bool surfacesSend, const HorizonMap::Post& post) const
{
  GatheredLight result;
  Spectrum open{};
  double openOmega = 0.0;
  if (this->Sky)
    this->Sky->irradiance(normal, open, openOmega);
  // The sky the scene hides: over a height field from the point's horizon, elsewhere
  // from rays drawn by the sky's radiance. What is left is the sky the point receives.
  const bool horizons = this->Sky && this->Horizons;
  Spectrum hidden{};
  if (horizons)
  {
    const HiddenSky horizon = post && this->Horizons->map()
      ? this->Horizons->hiddenAt(post, normal)
      : this->Horizons->hiddenAt(point, normal, seed ^ 0xD1B54A32D192ED03ull, budget.coarseHorizon);
    hidden = horizon.irradiance;
    openOmega = std::max(0.0, openOmega - horizon.projectedSolidAngle);
    result.rays += horizon.rays;
  }
  else if (this->Sky)
  {
    double hiddenOmega = 0.0;
    hidden = this->hiddenSkyByRadiance(
      point, normal, budget, seed, directIrradiance + largestBand(open), hiddenOmega, result.rays);
    openOmega = std::max(0.0, openOmega - hiddenOmega);
  }
  for (int band = 0; band < maxBands; ++band)
    result.sky[band] = std::max(0.0, open[band] - hidden[band]);

  // Light from surfaces by cosine-weighted rays.
  Spectrum surfaces{};
  // Each ray's share of what surfaces send (largest band); its spread sets how many
  // rays are needed. A pilot of budget.pilot rays of their own sets how many rays the
  // point needs; the estimate then comes from that many fresh stratified rays. Rays that
  // decided when to stop would be biased: they stop early where they happened to miss
  // a bright hit.
  double sum = 0.0, sumOfSquares = 0.0;
  const CosineFrame frame(normal);
  auto cast = [&](int count, SampleGenerator& random)
  {
    // The sun each hit takes (when there are many), by a golden-ratio sequence: evenly
    // spread over the suns for any count, and unrelated to the rays' strata.
    const double sunStart = this->SunCumulative.empty() ? 0.0 : random.uniform();
    sum = sumOfSquares = 0.0;
    surfaces = Spectrum{};
    for (int k = 0; k < count; ++k)
    {
      double s, t;
      stratifiedPoint(k, count, random, s, t);
      const Vec3 d = frame.direction(s, t);
      SurfaceHit hit;
      if (!this->Rays.firstHit(point, normal, d, hit))
        continue;
      const PolygonElement* leaf = this->leafAt(hit);
      if (!leaf)
        continue;
      // The triangle's own normal, turned to the side its leaf faces; the back of a
      // one-sided surface sends nothing.
      const Vec3 front = glm::dot(hit.normal, leaf->normal()) < 0.0 ? -hit.normal : hit.normal;
      if (!(glm::dot(front, d) < 0.0))
        continue;
      const double sunSample = std::fmod(sunStart + 0.61803398874989485 * k, 1.0);
      const Spectrum b = this->radiosityAt(*leaf, hit, front, sunSample);
      for (int band = 0; band < maxBands; ++band)
        surfaces[band] += b[band];
      const double value = largestBand(b);
      sum += value;
      sumOfSquares += value * value;
    }
  };
  SampleGenerator pilotRandom(seed ^ 0x5851F42D4C957F2Dull), random(seed);
  int count = surfacesSend ? budget.maximum : 0;
  if (count > 0 && pilotDecides(budget))
  {
    cast(budget.pilot, pilotRandom);
    result.rays += budget.pilot;
    count = raysNeeded(budget, sum, sumOfSquares, directIrradiance + largestBand(result.sky) + sum / budget.pilot);
  }
  cast(count, random);
  // E = pi x the mean radiance over cosine-weighted directions: the mean radiosity.
  const double perRay = count > 0 ? 1.0 / count : 0.0;
  for (int band = 0; band < maxBands; ++band)
    result.surfaces[band] = surfaces[band] * perRay;
  if (this->Sky)
    result.skyViewFactor = openOmega / pi;
  result.rays += count;
  return result;
}
} // namespace terralux
