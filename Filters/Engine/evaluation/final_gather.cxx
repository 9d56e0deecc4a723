#include "evaluation/final_gather.h"

#include "base/angles.h"
#include "terrain/far_terrain.h"
#include "horizons/horizon_sky.h"
#include "evaluation/leaf_light.h"
#include "evaluation/sky_importance.h"
#include "solver/link_transport.h"
#include "evaluation/open_sky.h"
#include "evaluation/post_lattice.h"
#include "horizons/post_sky.h"
#include "horizons/post_sunlight.h"
#include "visibility/sampling.h"
#include "terrain/terrain_directions.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace terralux
{
CosineFrame::CosineFrame(const Vec3& n)
  : N(n)
{
  tangentsOf(n, this->U, this->V);
}

Vec3 CosineFrame::direction(double s, double t) const
{
  const double r = std::sqrt(s), phi = twoPi * t;
  return glm::normalize(
    r * std::cos(phi) * this->U + r * std::sin(phi) * this->V + std::sqrt(std::max(0.0, 1.0 - s)) * this->N);
}

FinalGather::FinalGather(const GatherInputs& inputs)
  : Rays(inputs.rays)
  , Polygons(inputs.polygons)
  , Terrains(inputs.terrains)
  , Suns(inputs.suns)
  , Sky(inputs.sky)
  , Horizons(inputs.horizons)
  , PostSkies(inputs.postSkies)
  , Lattice(inputs.lattice)
  , PostSuns(inputs.postSunlight)
  , Leaves(inputs.leafLight)
  , DetailDistance(inputs.detailDistance)
  , HierarchyTerrain(inputs.hierarchyTerrain)
  , SkySamples(inputs.sky ? std::make_unique<SkyImportance>(*inputs.sky) : nullptr)
{
  // The near part of a post's view as the map's terrainByPart takes it.
  if (this->Horizons && this->Horizons->map())
    this->NearViewDistance = nearViewPosts * this->Horizons->map()->postSpacing();
  if (this->Suns.size() <= maximumSunsPerHit)
    return;
  double sum = 0.0;
  for (const HElement* sun : this->Suns)
    this->SunCumulative.push_back(sum += largestBand(sun->emittance()));
}

FinalGather::~FinalGather() = default;

Spectrum FinalGather::radiosityAt(const PolygonElement& leaf, const SurfaceHit& hit, const Vec3& front,
  double sunSample, const Vec3& from, double* interreflected) const
{
  const auto& e = leaf.Irradiance;
  // Whether the hit reads the posts of the scene's one terrain around it (a hit on the
  // far terrain lies beyond the detail distance).
  const bool nearPosts = hit.terrain == 0 && !hit.far &&
    (!(this->DetailDistance > 0.0) ||
      std::hypot(hit.point.x - from.x, hit.point.y - from.y) <= this->DetailDistance);
  // A far hit lies on the far terrain's coarse surface: its shadow rays see that alone.
  const Visibility& rays = hit.far ? this->Rays.farRays() : this->Rays;
  Spectrum sun{};
  if (this->SunCumulative.empty())
  {
    // On the scene's one terrain, where the hit's cell's posts all prove a sun seen or
    // hidden, it takes their answer (see PostSunlight).
    const SunsProven proven = nearPosts && this->PostSuns ? this->PostSuns->between(hit.u, hit.v) : SunsProven{};
    sun = directSunlight(hit.point, front, this->Suns, rays, nullptr, proven);
  }
  else
  {
    const double total = this->SunCumulative.back();
    const auto picked = std::upper_bound(this->SunCumulative.begin(), this->SunCumulative.end() - 1,
                          sunSample * total) - this->SunCumulative.begin();
    HElement& chosen = *this->Suns[static_cast<std::size_t>(picked)];
    const double chance = (this->SunCumulative[picked] - (picked > 0 ? this->SunCumulative[picked - 1] : 0.0)) / total;
    const double transport = transportToPoint(hit.point, front, chosen, rays, 1, 0) / chance;
    const Spectrum flux = chosen.emittance();
    for (int band = 0; band < maxBands; ++band)
      sun[band] = transport * flux[band];
  }
  // On a terrain whose posts' skies are known (the scene's one terrain), the sky at a
  // hit comes from its cell's posts and the light from surfaces from the lattice's.
  Spectrum sky = e[SkyLight], reflected = e[ReflectedLight];
  if (this->Leaves)
    this->Leaves->at(leaf.id(), hit.point, sky, reflected);
  if (nearPosts && this->PostSkies)
    this->PostSkies->interpolate(hit.u, hit.v, sky);
  if (nearPosts && this->Lattice)
    this->Lattice->reflectedAt(hit.u, hit.v, reflected);
  if (interreflected)
    *interreflected = largestBand(radiosityOf(Spectrum{}, leaf.reflectance(), reflected));
  return radiosityOf(leaf.emission(), leaf.reflectance(), totalIrradiance(sun, sky, reflected));
}

int FinalGather::openRays(const Vec3& point, const Vec3& normal, int strata, std::uint64_t seed, int* skyRays) const
{
  const CosineFrame frame(normal);
  SampleGenerator random(seed);
  int open = 0, sky = 0;
  for (int k = 0; k < strata * strata; ++k)
  {
    double s, t;
    stratifiedPoint(k, strata * strata, random, s, t);
    const Vec3 d = frame.direction(s, t);
    SurfaceHit hit;
    const PolygonElement* leaf = this->Rays.firstHit(point, normal, d, hit) ? this->leafAt(hit) : nullptr;
    open += !leaf || glm::dot(frontAt(hit, *leaf), d) < 0.0;
    sky += !leaf;
  }
  if (skyRays)
    *skyRays = sky;
  return open;
}

Vec3 FinalGather::frontAt(const SurfaceHit& hit, const PolygonElement& leaf)
{
  return glm::dot(hit.normal, leaf.normal()) < 0.0 ? -hit.normal : hit.normal;
}

const PolygonElement* FinalGather::leafAt(const SurfaceHit& hit) const
{
  if (hit.terrain >= 0)
  {
    const auto t = static_cast<std::size_t>(hit.terrain);
    if (!(t < this->Terrains.size() && this->Terrains[t]))
      return nullptr;
    if (this->HierarchyTerrain)
      return this->Terrains[t]->leafHolding(this->HierarchyTerrain->coarseU(hit.u), this->HierarchyTerrain->coarseV(hit.v));
    return this->Terrains[t]->leafHolding(hit.u, hit.v);
  }
  const auto p = static_cast<std::size_t>(hit.polygon);
  return p < this->Polygons.size() && this->Polygons[p] ? this->Polygons[p]->leafHolding(hit.point) : nullptr;
}

namespace
{
// How many stratified rays bring the standard error of their mean below the budget's
// (budget.relativeError x `received`, at least budget.absoluteError), from the variance
// of one ray's estimate (as for independent rays), between budget.minimum and
// budget.maximum: whole rows of strata, since a partly filled last row would leave a
// band of directions unsampled (a square, or one row fewer where that is enough).
int raysFor(const GatherBudget& budget, double variance, double received)
{
  const double target = std::max({ budget.relativeError * received, budget.absoluteError, 1e-12 });
  const double allowed = std::max(0.5 * target * target, target * target - budget.spentVariance);
  const double needed = std::clamp<double>(std::ceil(variance / allowed), budget.minimum, budget.maximum);
  const int side = static_cast<int>(std::ceil(std::sqrt(needed)));
  return side * (side - 1) >= needed ? side * (side - 1) : side * side;
}

// The same from a pilot's sum and sum of squares.
int raysNeeded(const GatherBudget& budget, double sum, double sumOfSquares, double received)
{
  const double mean = sum / budget.pilot;
  return raysFor(budget, std::max(budget.varianceFloor, sumOfSquares / budget.pilot - mean * mean), received);
}

bool pilotDecides(const GatherBudget& budget)
{
  return budget.pilot > 0 && budget.minimum < budget.maximum;
}
} // namespace

Spectrum FinalGather::hiddenSkyByRadiance(const Vec3& point, const Vec3& normal, const GatherBudget& budget,
  std::uint64_t seed, double received, double& hiddenProjectedSolidAngle, int& rays, double& variance) const
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
    count = std::max(raysNeeded(budget, sum, sumOfSquares, received), std::min(budget.skyMinimum, budget.maximum));
  }
  cast(count, random);
  for (double& band : hidden)
    band /= count;
  hiddenProjectedSolidAngle /= count;
  const double mean = sum / count;
  variance = std::max(0.0, sumOfSquares / count - mean * mean) / count;
  return hidden;
}

GatheredLight FinalGather::irradianceAt(const Vec3& point, const Vec3& normal, const GatherBudget& budget,
  std::uint64_t seed, double directIrradiance, bool surfacesSend, const HorizonMap::Post& post) const
{
  GatheredLight result;
  // The sky the scene hides: over a height field from the point's horizon (at a post of
  // the horizons' map, read from it), elsewhere from rays drawn by the sky's radiance.
  // What is left of the open sky is the sky the point receives.
  const bool horizons = this->Sky && this->Horizons;
  double openOmega = 0.0; // projected solid angle of the sky seen
  double skyVariance = 0.0; // of the hidden sky by rays
  if (horizons && post && this->Horizons->map())
  {
    PostSky::Value value;
    if (!this->PostSkies || !this->PostSkies->found(post, normal, value))
      value = PostSky::at(post, normal, *this->Horizons, *this->Sky);
    result.sky = value.irradiance;
    openOmega = pi * value.skyViewFactor;
  }
  else if (this->Sky)
  {
    Spectrum open{}, hidden{};
    this->Sky->irradiance(normal, open, openOmega);
    double hiddenOmega = 0.0;
    if (horizons)
    {
      const HiddenSky horizon =
        this->Horizons->hiddenAt(point, normal, seed ^ 0xD1B54A32D192ED03ull);
      hidden = horizon.irradiance;
      hiddenOmega = horizon.projectedSolidAngle;
      result.rays += horizon.rays;
    }
    else
    {
      // Half the target's variance for the sky, the rest for the surfaces' rays below.
      GatherBudget skyBudget = budget;
      skyBudget.spentVariance = std::numeric_limits<double>::infinity();
      hidden = this->hiddenSkyByRadiance(
        point, normal, skyBudget, seed, directIrradiance + largestBand(open), hiddenOmega, result.rays, skyVariance);
    }
    openOmega = std::max(0.0, openOmega - hiddenOmega);
    for (int band = 0; band < maxBands; ++band)
      result.sky[band] = std::max(0.0, open[band] - hidden[band]);
  }

  // Light from surfaces by rays: at a post of the horizons' map drawn below its horizon
  // (the sky above it is counted already, and stays its horizons': see
  // TerrainDirections), elsewhere cosine-weighted over the hemisphere.
  std::optional<TerrainDirections> belowHorizon;
  if (horizons && post && this->Horizons->map())
    belowHorizon.emplace(*this->Horizons, post, normal);
  Spectrum surfaces{};
  PerViewPart<Spectrum> byPart{};
  PerViewPart<double> seenByPart{};
  // Each ray's estimate of what surfaces send (largest band); its spread sets how many
  // rays are needed. A pilot of budget.pilot rays of their own sets how many rays the
  // point needs; the estimate then comes from that many fresh stratified rays. Rays that
  // decided when to stop would be biased: they stop early where they happened to miss
  // a bright hit.
  double sum = 0.0, sumOfSquares = 0.0, interreflected = 0.0, reflectanceSeen = 0.0;
  int backRays = 0;
  const CosineFrame frame(normal);
  auto cast = [&](int count, SampleGenerator& random)
  {
    // The sun each hit takes (when there are many), by a golden-ratio sequence: evenly
    // spread over the suns for any count, and unrelated to the rays' strata.
    const double sunStart = this->SunCumulative.empty() ? 0.0 : random.uniform();
    sum = sumOfSquares = interreflected = reflectanceSeen = 0.0;
    backRays = 0;
    surfaces = Spectrum{};
    byPart = PerViewPart<Spectrum>{};
    seenByPart = PerViewPart<double>{};
    // One ray's estimate of what surfaces send (largest band).
    auto gather = [&](int k, double s, double t) -> double {
      TerrainDirections::Sample below;
      if (belowHorizon)
        below = belowHorizon->sample(s, t);
      const double weight = belowHorizon ? below.weight : 1.0;
      const Vec3 d = belowHorizon ? below.direction : frame.direction(s, t);
      if (!(weight > 0.0))
        return 0.0;
      SurfaceHit hit;
      const PolygonElement* leaf = this->Rays.firstHit(point, normal, d, hit) ? this->leafAt(hit) : nullptr;
      if (!leaf)
        return 0.0;
      const double dx = hit.point.x - point.x, dy = hit.point.y - point.y;
      const int part = viewPartOf(sectorOf(d.x, d.y), dx * dx + dy * dy > this->NearViewDistance * this->NearViewDistance);
      seenByPart[part] += weight;
      // The back of a one-sided surface sends nothing.
      const Vec3 front = frontAt(hit, *leaf);
      if (!(glm::dot(front, d) < 0.0))
      {
        ++backRays;
        return 0.0;
      }
      const double sunSample = std::fmod(sunStart + 0.61803398874989485 * k, 1.0);
      double bounced = 0.0;
      const Spectrum b = this->radiosityAt(*leaf, hit, front, sunSample, point, &bounced);
      for (int band = 0; band < maxBands; ++band)
        surfaces[band] += weight * b[band], byPart[part][band] += weight * b[band];
      interreflected += weight * bounced;
      reflectanceSeen += weight * largestBand(leaf->reflectance());
      return weight * largestBand(b);
    };
    for (int k = 0; k < count; ++k)
    {
      double s, t;
      stratifiedPoint(k, count, random, s, t);
      const double value = gather(k, s, t);
      sum += value;
      sumOfSquares += value * value;
    }
  };
  SampleGenerator pilotRandom(seed ^ 0x5851F42D4C957F2Dull), random(seed);
  GatherBudget surfacesBudget = budget;
  surfacesBudget.spentVariance += skyVariance;
  int count = surfacesSend && !(belowHorizon && belowHorizon->empty()) ? budget.maximum : 0;
  if (count > 0 && pilotDecides(budget))
  {
    cast(budget.pilot, pilotRandom);
    result.rays += budget.pilot;
    count = raysNeeded(surfacesBudget, sum, sumOfSquares, directIrradiance + largestBand(result.sky) + sum / budget.pilot);
  }
  else if (count > 0 && budget.knownVariance >= 0.0)
    count = raysFor(surfacesBudget, budget.knownVariance, directIrradiance + largestBand(result.sky) + budget.knownSurfaces);
  cast(count, random);
  // E = pi x the mean radiance over cosine-weighted directions: the mean radiosity.
  const double perRay = count > 0 ? 1.0 / count : 0.0;
  for (int band = 0; band < maxBands; ++band)
  {
    result.surfaces[band] = surfaces[band] * perRay;
    for (int part = 0; part < viewParts; ++part)
      result.surfacesByPart[part][band] = byPart[part][band] * perRay;
  }
  for (int part = 0; part < viewParts; ++part)
    result.surfacesSeenByPart[part] = seenByPart[part] * perRay;
  if (this->Sky)
    result.skyViewFactor = openOmega / pi;
  result.rays += count;
  result.count = count;
  result.backRays = backRays;
  if (count > 0)
    result.variance = std::max(0.0, sumOfSquares * perRay - sum * perRay * sum * perRay);
  result.standardError = std::sqrt(result.variance * perRay + skyVariance);
  result.interreflected = interreflected * perRay;
  result.reflectanceSeen = reflectanceSeen * perRay;
  return result;
}
} // namespace terralux
