#include "evaluation/point_evaluator.h"

#include "base/elapsed.h"
#include "evaluation/final_gather.h"
#include "evaluation/leaf_gather.h"
#include "evaluation/open_sky.h"
#include "horizons/horizon_sky.h"
#include "visibility/scene_geometry.h"
#include "sky/sky_hierarchy.h"
#include "horizons/horizon_map.h"
#include "evaluation/leaf_light.h"
#include "emitters/external_source.h"
#include "solver/link_transport.h"
#include "hierarchy/polygon_element.h"
#include "evaluation/post_lattice.h"
#include "horizons/post_sky.h"
#include "horizons/post_sunlight.h"
#include "terrain/terrain_grid.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/sampling.h"
#include "visibility/visibility.h"
#include "parallel/work_split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace terralux
{
namespace
{
// What a post receives beside the light from surfaces (its sun and its horizons' sky,
// largest bands): what the lattice's spread is measured against, when its cells are
// refined and when a post reads between them.
double receivedBesideSurfaces(const Spectrum& sun, const PostSky::Value& sky)
{
  return largestBand(sun) + largestBand(sky.irradiance);
}

// Standard errors in an error estimate: about 95 % of normal errors lie within two. The
// same margin on estimated biases.
constexpr double errorCoverage = 2.0;

// Where a point's gather starts: 6 x 6 probes of how open its side is; one side is
// clearly more open than another where more than 3 more of them are open (not noise).
constexpr int openStrata = 6, clearlyMoreOpen = 3;

// The variance of one cosine-weighted ray's estimate of light from surfaces, as the
// solved links from surfaces to a leaf and its ancestors (together all it sees, each
// part once) give it: sum F_i B_i^2 - (sum F_i B_i)^2, F_i the seen form factor and B_i
// the sender's radiosity (largest band). Variation within a sender adds to it: a floor.
double linkVariance(const PolygonElement& leaf)
{
  double mean = 0.0, square = 0.0;
  for (const HElement* element = &leaf; element; element = element->Parent)
    for (const Link& link : element->Incoming)
    {
      if (link.sender->asExternal())
        continue;
      const double seen = link.kernel * link.visibility, b = largestBand(link.sender->emittance());
      mean += seen * b;
      square += seen * b * b;
    }
  return std::max(0.0, square - mean * mean);
}
} // namespace

PointEvaluator::PointEvaluator(HierarchicalRadiosity& solved, const EvaluationPlan& plan)
  : Solver(solved)
  , Options(solved.options())
  , Rays(solved.geometry()->hierarchyRays())
  , PointRays(solved.geometry()->pointRays())
  , HeightFieldGrid(solved.heightFieldGrid())
  // A window computes all it needs itself: its horizons see its far terrain.
  , Split(solved.isWindow() ? nullptr : plan.split)
{
  if (const SkyHierarchy* sky = solved.sky())
  {
    this->SkyAtPoints = std::make_unique<OpenSky>(*sky);
    // Many points to evaluate: the open sky of each point's plane from a table over
    // normals rather than one exact evaluation per point (docs/tuning.md).
    if (this->Options.gatherSamples > 0 && solved.pointCount() > Tuning::openSkyTableFewestPoints)
      this->SkyAtPoints->tabulate(solved.pointCount() > Tuning::openSkyTablePoints ? 128 : 64);
    // Until the posts' horizons are found, those the rays find.
    if (solved.skyFromHorizons())
      this->Horizons = std::make_unique<HorizonSky>(this->PointRays, *this->SkyAtPoints, nullptr);
  }
  if (plan.atPoints)
    this->findPostHorizons(plan.hornNormals);
  this->findSunHorizons();
  // How far the hierarchy's light from surfaces is off, for the points' error estimates:
  // gathered over the hierarchy's own surface, the same for every process, reading its
  // leaves alone (no post's values, which a process holds near its window only). A
  // window solves a hierarchy of its own, whose deficit would differ with the split:
  // it takes the bound instead, the same for any split.
  HierarchyDeficit deficit;
  if (plan.atPoints && this->gathersAtPoints() && solved.largestRadiosity() > 0.0)
  {
    if (solved.isWindow())
      deficit = HierarchyDeficit::unknown();
    else
    {
      const GatherInputs overHierarchy{ this->Rays, solved.polygonRoots(), solved.terrainRoots(),
        solved.hierarchySuns() };
      const LeafGather probe(solved.surfaceLeaves(), this->Rays,
        std::min(Tuning::deficitProbeRays(this->Options.targetError), this->Options.gatherSamples), true,
        this->Options.randomSeed);
      deficit = HierarchyDeficit::measure(probe, FinalGather(overHierarchy), Tuning::deficitProbeLeaves);
    }
  }
  // At points, what gather rays meet; averaged, the polygons' values themselves
  // (terrain patches keep the hierarchy's: the fast mode of a DEM).
  if (plan.leavesGathered)
    this->gatherLeaves(plan.atPoints);
  const std::vector<TerrainPatch*>& terrains = solved.terrainRoots();
  if (plan.atPoints && plan.postLattice && terrains.size() == 1 && terrains.front())
  {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t raysBefore = solved.raysCast();
    this->gatherPostLattice(*terrains.front(), plan.hornNormals);
    this->Stats.latticeSeconds = secondsSince(start);
    this->Stats.latticeRays = solved.raysCast() - raysBefore;
  }
  this->Gather = this->makeGather();
  // What the final gathers' hits read of light from surfaces: the lattice's (one bounce
  // gathered above the hierarchy's values), the leaves' (each pass one bounce), or the
  // hierarchy's own.
  this->ReadRelativeError = deficit.after(this->Lattice ? 1 : this->Leaves ? Tuning::leafGatherPasses : 0);
}

PointEvaluator::~PointEvaluator()
{
  for (const ReplacedLeaf& replaced : this->Replaced)
  {
    replaced.leaf->Irradiance[SkyLight] = replaced.sky;
    replaced.leaf->Irradiance[ReflectedLight] = replaced.reflected;
    replaced.leaf->Radiosity = replaced.radiosity;
  }
}

std::unique_ptr<FinalGather> PointEvaluator::makeGather() const
{
  GatherInputs inputs{ this->PointRays, this->Solver.polygonRoots(), this->Solver.terrainRoots(),
    this->Solver.hierarchySuns() };
  inputs.sky = this->SkyAtPoints.get();
  inputs.horizons = this->Horizons.get();
  inputs.postSkies = this->PostSkies.get();
  inputs.lattice = this->Lattice.get();
  inputs.postSunlight = this->PostSuns.get();
  inputs.leafLight = this->Leaves.get();
  inputs.detailDistance = this->Options.gatherDetailDistance;
  inputs.hierarchyTerrain = this->Solver.hierarchyTerrain();
  return std::make_unique<FinalGather>(inputs);
}

PointIrradiance PointEvaluator::irradianceAt(const PolygonElement& leaf, const Vec3& point) const
{
  return this->irradianceAt(leaf, point, leaf.normal());
}

PointIrradiance PointEvaluator::irradianceAt(
  const PolygonElement& leaf, const Vec3& point, const Vec3& normal) const
{
  return this->irradianceAt(leaf, point, normal, leaf.centre());
}

PointIrradiance PointEvaluator::irradianceAt(
  const PolygonElement& leaf, const Vec3& point, const Vec3& normal, const Vec3& toward) const
{
  return this->evaluate(leaf, point, normal, toward, nullptr);
}

PointIrradiance PointEvaluator::evaluate(const PolygonElement& leaf, const Vec3& point, const Vec3& normal,
  const Vec3& toward, GatheredLight* gathered) const
{
  PointIrradiance result;
  auto& irradiance = result.irradiance;
  // Visibility from a point is noisier than over an element: more samples where the
  // element saw the sender only in part, as many as the link had elsewhere.
  const int partialSamples = Tuning::partialVisibilityFactor * this->Options.visibilitySamples;
  const int clearSamples = this->Options.visibilitySamples;
  // Seeded by the point itself: points sharing a leaf (posts inside a terrain patch)
  // must not share their jitter, or the noise would be the same pattern at each.
  const std::uint64_t pointSeed = reseeded(this->Rays.seedOf(point), this->Options.randomSeed);
  std::uint64_t salt = pointSeed ^ (leaf.id() * 31);
  const std::uint64_t gatherSeed = this->gatherSeedOf(point);
  const Vec3 inside = this->movedInside(point, toward);
  const bool gathers = this->gathersAtPoints();
  double visibilityVariance = 0.0; // of the links' sampled visibility, without a gather
  // Without a gather, every link that reaches the leaf, re-evaluated at the point.
  for (const HElement* element = gathers ? nullptr : &leaf; element; element = element->Parent)
  {
    for (const Link& link : element->Incoming)
    {
      const ExternalSource* source = link.sender->asExternal();
      if (source && source->parallel())
        continue; // direct sun is taken below, by a ray from the point itself
      const std::uint64_t seed = linkSeed(salt++, link.sender->id());
      // Sky visibility from the point itself: a ray that starts on a wall's plane skips
      // it and then meets the building from inside, so the sky is judged right whatever
      // leaf holds the point; form factors need the point inside its leaf.
      const Vec3& from = source ? point : inside;
      const int samples = link.visibility < 1.0 ? partialSamples : clearSamples;
      const double transport = transportToPoint(from, normal, *link.sender, this->PointRays, samples, seed);
      const Spectrum e = link.sender->emittance();
      // Visibility sampled by `samples` rays: a binomial fraction, about the link's.
      const double seen = std::max(link.visibility, 1.0 / samples);
      visibilityVariance += std::pow(transport * largestBand(e), 2) * (1.0 - seen) / (seen * samples);
      const int category = lightCategoryOf(*link.sender);
      for (int band = 0; band < maxBands; ++band)
        irradiance[category][band] += transport * e[band];
      // Sky links cover the whole sky once: their projected solid angles, seen, over pi.
      result.skyViewFactor += skyViewOf(*link.sender, normal, transport);
    }
  }
  // Direct sun is what a ray from just above the point sees, whatever leaf the point
  // was assigned to and whether or not the links there still hold the sun (a shadowed
  // element's sun link is dropped, yet its border posts may be lit).
  irradiance[SunLight] = this->directSunAt(point, normal, &result.sunlitHours);
  result.irradianceError = errorCoverage * std::sqrt(visibilityVariance);
  // Sky and light from surfaces by a final gather from the point (inside its leaf, as
  // form factors), over the leaves' solved radiosity.
  if (gathers)
  {
    GatherBudget budget;
    budget.maximum = this->Options.gatherSamples;
    budget.minimum = std::min(budget.minimum, budget.maximum);
    // The rays' noise, at errorCoverage standard errors, within the point's target.
    budget.relativeError = this->Options.targetError / errorCoverage;
    budget.absoluteError = this->Options.targetErrorFloor / errorCoverage;
    // A terrain post's horizons come from the map, found for all posts at once.
    const HorizonMap::Post post = this->PostHorizons ? this->PostHorizons->find(point) : HorizonMap::Post{};
    // There the rays are drawn below the post's horizon, where nearly every one meets
    // terrain (TerrainDirections): far fewer are needed than over the hemisphere.
    if (post)
      budget.maximum = std::max(1, budget.maximum / Tuning::postGatherDivisor),
      budget.pilot = budget.minimum = std::min(budget.maximum, Tuning::postPilotRays);
    // Posts beside a gathered lattice take their count from its spread, with no pilot.
    if (post && this->Lattice)
    {
      const int nx = this->HeightFieldGrid->postsX(), i = static_cast<int>(post.index % nx);
      const int j = static_cast<int>(post.index / nx);
      const PostLattice::Around around = this->Lattice->around(i, j);
      if (around.variance >= 0.0 && this->readFromLattice(post, normal, i, j, around, result))
        return result;
      Spectrum expected;
      if (around.variance >= 0.0 && this->Lattice->reflectedAt(i, j, expected))
        budget.knownVariance = around.variance, budget.pilot = 0, budget.minimum = std::min(budget.maximum, Tuning::latticeKnownRays),
        budget.knownSurfaces = largestBand(expected);
    }
    // Elsewhere the hierarchy's links tell how the point's view is lit: their spread
    // is the least the rays' can be.
    if (!post)
      budget.varianceFloor = linkVariance(leaf);
    const Spectrum& sun = irradiance[SunLight];
    // A post's rays start at the post itself, one offset along its normal (as every
    // ray does), which clears the grid's triangles around it: any higher, the thin band
    // of terrain a gentle slope sees above its plane shrinks, and posts moved into their
    // leaves disagree with their neighbours, which costs the lattice's reads
    // (docs/tuning.md). Elsewhere they start two more offsets above (three in all): on
    // rough terrain the move into the leaf, toward a centre across a crease, can end
    // that far below the surface the normal lifts from.
    const Vec3 lifted =
      post ? point : this->openSideOf(point, inside, normal, gatherSeed) + 2.0 * this->Rays.offset() * normal;
    const GatheredLight light = this->Gather->irradianceAt(lifted, normal, budget, gatherSeed,
      largestBand(sun), this->Solver.largestRadiosity() > 0.0, post);
    irradiance[ReflectedLight] = light.surfaces;
    if (gathered)
      *gathered = light;
    result.gatherVariance = light.variance;
    // The rays' noise and the sky's error, independent of each other (in quadrature),
    // and the error of the light from surfaces their hits read, which the hierarchy's
    // measured deficit estimates (as well as its sample tells: the same margin).
    const double noise = errorCoverage * light.standardError, skyError = this->skyError(normal, light.sky, post);
    result.irradianceError = std::sqrt(noise * noise + skyError * skyError) +
      errorCoverage * this->ReadRelativeError * light.interreflected;
    // Rays that met no lit surface say nothing of a rare one they missed: the terrain and
    // objects the point sees (all but its sky) send at most the scene's largest radiosity.
    if (!(largestBand(light.surfaces) > 0.0))
      result.irradianceError += std::max(0.0, 1.0 - light.skyViewFactor) * this->Solver.largestRadiosity();
    irradiance[SkyLight] = light.sky;
    result.skyViewFactor = light.skyViewFactor;
  }
  return result;
}

bool PointEvaluator::readFromLattice(const HorizonMap::Post& post, const Vec3& normal, int i, int j,
  const PostLattice::Around& around, PointIrradiance& result) const
{
  // A post inside the terrain does not read from a corner on its edge, which sees
  // terrain on one side only: posts beside a DEM's border read 10-17 % too little light
  // from surfaces (docs/tuning.md; reading there still costs the steep crop's faint
  // posts a third more bias, the void taken off or not).
  PostSky::Value sky;
  if ((around.edgeCorner && this->HeightFieldGrid->surroundedByCells(i, j)) || !this->PostSkies ||
    !this->PostSkies->found(post, normal, sky))
    return false;
  // The sky is its horizons'. The light from surfaces comes from the terrain the post
  // sees, 1 - its sky view factor less the void (directions that leave the terrain
  // below the horizontal; docs/tuning.md): that times what the lattice's posts around
  // found per terrain seen, in each part of the view by the post's share of terrain
  // there (a ridge's post sees one side of it and the far terrain below, its corners
  // every side and the slopes near them).
  // Read between them it errs by at most their spread, plus the bias of reading light
  // from surfaces between posts (Tuning::latticeReadBias); the post reads it where that
  // meets its target, else gathers. The error of what the lattice's posts read from the
  // hierarchy is in both (a gather's hits read the lattice too), so it does not decide;
  // nor does the sky's (no ray corrects it), nor anything else a process computes for
  // itself (a window's own hierarchy), and pieces read where one process does.
  // Its terrain seen as rays meet it, as the lattice's posts take theirs: the map's,
  // less what the map shows beyond the rays there (most of a post's terrain where it
  // sees little of it, a ridge's; docs/tuning.md).
  double mapExcess = 0.0;
  if (!this->Lattice->mapExcessAt(i, j, sky.terrainSeen(), sky.voidViewFactor, mapExcess))
    return false;
  const double terrainSeen = std::max(0.0, sky.terrainSeen() - mapExcess);
  const double received = receivedBesideSurfaces(result.irradiance[SunLight], sky);
  const double largestReflected = terrainSeen * std::max(0.0, around.largestPerTerrainSeen);
  const double limit = this->Options.errorTarget(received + largestReflected) - Tuning::latticeReadBias * largestReflected;
  const double wholeSpread = terrainSeen * (around.largestPerTerrainSeen - around.leastPerTerrainSeen);
  if (wholeSpread > limit)
    return false;
  // It errs by the corners' spread in the whole or in its parts; and where the reads
  // by part and of the whole disagree, the post's view is not its corners': either
  // may be off by their difference. Only the whole's spread decides (as the lattice's
  // cells were refined by it): deciding by all of it gathered a quarter more rays on
  // steep DEMs for no gain in accuracy (docs/tuning.md).
  // Where the corners' sectors differ too little to matter (most posts of gentle
  // terrain, which see little of it), the post reads the whole and errs by the width
  // across their parts instead: its shares of terrain took a third of their points'
  // time. Likewise a post reads by sector alone where the corners' near and far parts
  // differ too little to matter, and errs by that difference too: its near terrain
  // costs more than its sectors.
  const bool bySector = terrainSeen * around.sectorWidth > Tuning::latticeSectorWidthShare * limit;
  bool byDistance = bySector && terrainSeen * around.distanceWidth > Tuning::latticeDistanceWidthShare * limit;
  PostLattice::PartRead read;
  double spread = 0.0;
  auto readAndSpread = [&]() {
    if (!this->Lattice->readByPart(
          i, j, bySector ? this->terrainSharesAt(post, normal, byDistance) : PerViewPart<double>{}, byDistance, read))
      return false;
    spread = bySector ? std::max(wholeSpread, terrainSeen * read.spread) +
        terrainSeen * std::abs(largestBand(read.perTerrainSeen) - largestBand(read.whole)) +
        (byDistance ? 0.0 : terrainSeen * around.distanceWidth)
                      : wholeSpread + terrainSeen * around.partWidth;
    return true;
  };
  if (!readAndSpread())
    return false;
  // By sector, it may miss its target by what the skipped parts could change: then by part.
  if (bySector && !byDistance && spread > limit && around.distanceWidth > 0.0)
  {
    byDistance = true;
    if (!readAndSpread())
      return false;
  }
  // Read by part, it may still miss its target: it gathers then.
  if (spread > limit)
    return false;
  const Spectrum& perTerrainSeen = bySector ? read.perTerrainSeen : read.whole;
  for (int band = 0; band < maxBands; ++band)
    result.irradiance[ReflectedLight][band] = std::max(0.0, terrainSeen * perTerrainSeen[band]);
  result.irradiance[SkyLight] = sky.irradiance;
  result.skyViewFactor = sky.skyViewFactor;
  result.gatherVariance = around.variance;
  // The lattice's posts cast no ray below their horizons where nothing sends light.
  const double readRelativeError = errorCoverage * this->ReadRelativeError + Tuning::latticeReadBias;
  result.irradianceError = spread + readRelativeError * largestBand(result.irradiance[ReflectedLight]) +
    this->skyError(normal, sky.irradiance, post);
  return true;
}

PerViewPart<double> PointEvaluator::terrainSharesAt(const HorizonMap::Post& post, const Vec3& normal, bool nearAndFar) const
{
  PerViewPart<double> shares =
    this->Horizons ? this->Horizons->terrainByPart(post, normal, nearAndFar) : PerViewPart<double>{};
  double sum = 0.0;
  for (const double share : shares)
    sum += share;
  for (double& share : shares)
    share = sum > 0.0 ? share / sum : 1.0 / viewParts;
  return shares;
}

std::uint64_t PointEvaluator::gatherSeedOf(const Vec3& point) const
{
  return reseeded(this->Rays.seedOf(point), this->Options.randomSeed) * 0x9E3779B97F4A7C15ull;
}

Vec3 PointEvaluator::movedInside(const Vec3& point, const Vec3& toward) const
{
  // A point on the leaf's border is the limit from inside the leaf: at a concave
  // junction (a wall's foot, a box's corner) the point itself lies in the plane of the
  // other surface, which it would see edge-on with a form factor of 0, and rays that
  // skip their first offset would skip that surface too.
  const Vec3 toCentre = toward - point;
  const double distance = glm::length(toCentre);
  return distance > 0.0 ? point + std::min(0.5, 2.0 * this->Rays.offset() / distance) * toCentre : point;
}

bool PointEvaluator::Openness::clearlyMoreOpenThan(const Openness& other) const
{
  return this->open < 0 || this->open > other.open + clearlyMoreOpen || this->sky > other.sky + clearlyMoreOpen;
}

PointEvaluator::Openness PointEvaluator::opennessAt(const Vec3& point, const Vec3& normal, const Vec3& toward) const
{
  Openness result;
  if (this->gathersAtPoints() && this->Gather)
    result.open = this->Gather->openRays(
      this->movedInside(point, toward), normal, openStrata, this->gatherSeedOf(point), &result.sky);
  return result;
}

Vec3 PointEvaluator::openSideOf(
  const Vec3& point, const Vec3& inside, const Vec3& normal, std::uint64_t seed) const
{
  const double offset = this->Rays.offset();
  auto openness = [&](const Vec3& p) { return this->Gather->openRays(p, normal, openStrata, seed); };
  int most = openness(inside);
  if (most == openStrata * openStrata)
    return inside;
  Vec3 u, v;
  tangentsOf(normal, u, v);
  Vec3 best = inside;
  for (const Vec3& along : { u + v, u - v, -u + v, -u - v })
  {
    const Vec3 candidate = point + 2.0 * offset * glm::normalize(along);
    const int open = openness(candidate);
    if (open > most + clearlyMoreOpen)
      best = candidate, most = open;
  }
  return best;
}

Spectrum PointEvaluator::directSunAt(const Vec3& point, const Vec3& normal, double* sunlitHours) const
{
  const HorizonMap::Post post = this->SunHorizons ? this->SunHorizons->find(point) : HorizonMap::Post{};
  if (!post)
    return directSunlight(point, normal, this->Solver.suns(), this->PointRays, sunlitHours);
  // A sun the post's horizons prove open or hidden takes no ray. Every point sun is a
  // parallel SunElement: its kernel and flux, kept beside its sight, need no virtual
  // call on this path (a year of hours tests 5 G suns at the posts of a 1025^2 DEM).
  // The post's proofs were found for every post at once where gather hits read them.
  const int nx = this->HeightFieldGrid->postsX();
  const SunsProven proven = this->PostSuns
    ? this->PostSuns->at(static_cast<int>(post.index % nx), static_cast<int>(post.index / nx))
    : SunsProven{};
  HorizonMap::View horizons(*this->SunHorizons, post);
  Spectrum result{};
  for (std::size_t s = 0; s < this->MappedSuns.size(); ++s)
  {
    const MappedSun& sun = this->MappedSuns[s];
    const double kernel = glm::dot(normal, sun.direction);
    if (!(kernel > 0.0))
      continue;
    const bool seen = this->PostSuns ? proven.seenAt(s) : horizons.clearlyAbove(sun.sight);
    const bool hidden = !seen && (this->PostSuns ? proven.hiddenAt(s) : horizons.clearlyBelow(sun.sight));
    const bool open = seen || (!hidden && !this->PointRays.occludedToward(point, normal, sun.direction));
    if (open)
      addSunlight(kernel, sun.flux, sun.duration, result, sunlitHours);
  }
  return result;
}

bool PointEvaluator::gathersAtPoints() const
{
  // Nothing to gather without a sky where no surface sends light.
  return this->Options.gatherSamples > 0 && (this->Solver.sky() || this->Solver.largestRadiosity() > 0.0);
}

void PointEvaluator::gatherPostLattice(const TerrainPatch& root, bool hornNormals)
{
  if (!this->gathersAtPoints() || !this->PostHorizons || &this->Solver.postGrid(root) != this->HeightFieldGrid)
    return;
  // The lattice's own posts gather from the leaves, with pilots.
  this->Gather = this->makeGather();
  const TerrainGrid& grid = this->Solver.postGrid(root);
  // With a work split, each process holds the lattice within its posts' halo (the
  // detail distance's) of its window.
  auto lattice = std::make_unique<PostLattice>(
    grid.postsX(), grid.postsY(), PostLattice::defaultStep, this->Split, this->PostsHalo);
  // Every second lattice post first; then the rest of the cells whose corners disagree
  // (see Tuning::latticeRefineShare), decided alike by every process from the shared first
  // pass.
  for (const bool first : { true, false })
  {
    if (!first)
      lattice->refine(Tuning::latticeRefineShare * this->Options.targetError,
        Tuning::latticeRefineShare * this->Options.targetErrorFloor);
    WorkSplit::partThenShare(
      this->Split, [&]() { this->gatherLatticePosts(root, hornNormals, first, *lattice); },
      [&]() { lattice->share(); });
  }
  this->Lattice = std::move(lattice);
}

void PointEvaluator::gatherLatticePosts(
  const TerrainPatch& root, bool hornNormals, bool firstPass, PostLattice& lattice) const
{
  const TerrainGrid& grid = this->Solver.postGrid(root);
  const int step = lattice.step();
  tbb::parallel_for(0, (grid.postsY() - 1) / step + 1, [&](int lj) {
    const int j = lj * step;
    for (int i = 0; i < grid.postsX(); i += step)
    {
      if (!PostLattice::gathers(i, j, this->Split) || !lattice.gatheredInPass(i, j, firstPass))
        continue;
      const TerrainPatch* leaf = grid.postUsed(i, j) ? this->Solver.leafAtPost(root, i, j) : nullptr;
      if (!leaf)
        continue;
      const Vec3 normal = grid.normalAt(i, j, hornNormals);
      GatheredLight light;
      const PointIrradiance result = this->evaluate(*leaf, grid.post(i, j), normal, leaf->centre(), &light);
      PostSky::Value sky;
      const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * grid.postsX() + i };
      if (!this->PostSkies || !this->PostSkies->found(post, normal, sky))
        continue;
      PostLattice::Gathered gathered;
      gathered.reflected = result.irradiance[ReflectedLight];
      gathered.reflectedByPart = light.surfacesByPart;
      gathered.variance = result.gatherVariance;
      gathered.terrainSeen = sky.terrainSeen();
      gathered.voidSeen = sky.voidViewFactor;
      // Its terrain by part: the surfaces its rays met there. From the map's shares
      // instead, a part whose horizons show next to no terrain where its rays met some
      // (the thin band of flat ground) would divide their light by next to nothing.
      gathered.terrainByPart = light.surfacesSeenByPart;
      gathered.received = receivedBesideSurfaces(result.irradiance[SunLight], sky);
      gathered.edge = !grid.surroundedByCells(i, j);
      lattice.set(i, j, gathered);
    }
  });
}

void PointEvaluator::gatherLeaves(bool terrains)
{
  if (!this->gathersAtPoints())
    return;
  std::vector<PolygonElement*> leaves = this->Solver.surfaceLeaves();
  leaves.erase(std::remove_if(leaves.begin(), leaves.end(),
                 [&](const PolygonElement* leaf) {
                   const auto* patch = dynamic_cast<const TerrainPatch*>(leaf);
                   return patch &&
                     (!terrains || this->Solver.hierarchyTerrain() ||
                       (this->PostSkies && this->HeightFieldGrid && patch->terrain() == 0));
                 }),
    leaves.end());
  if (leaves.empty())
    return;
  const LeafGather gathering(leaves, this->Rays, std::min(Tuning::leafGatherRays, this->Options.gatherSamples),
    this->Solver.largestRadiosity() > 0.0, this->Options.randomSeed);
  std::vector<std::uint64_t> ids(leaves.size());
  for (std::size_t k = 0; k < leaves.size(); ++k)
    ids[k] = leaves[k]->id();
  for (int pass = 0; pass < Tuning::leafGatherPasses; ++pass)
  {
    // The first pass gathers over the hierarchy's values, the next over the last pass's.
    this->Gather = this->makeGather();
    auto next = std::make_unique<LeafLight>(this->Solver.elements().size(), ids);
    tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t k) {
      next->set(k, leaves[k]->normal(), gathering.at(k, *this->Gather, static_cast<std::uint64_t>(pass)));
    });
    this->Leaves = std::move(next);
  }
  // The leaves' own values become the gathered means (what averaged outputs show),
  // once every gather has read the hierarchy's; the destructor gives them back.
  this->Replaced.resize(leaves.size());
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t k) {
    PolygonElement& leaf = *leaves[k];
    this->Replaced[k] = { &leaf, leaf.Irradiance[SkyLight], leaf.Irradiance[ReflectedLight], leaf.Radiosity };
    if (!this->Leaves->mean(leaf.id(), leaf.Irradiance[SkyLight], leaf.Irradiance[ReflectedLight]))
      return;
    leaf.Radiosity = radiosityOf(leaf.emission(), leaf.reflectance(),
      totalIrradiance(leaf.Irradiance[SunLight], leaf.Irradiance[SkyLight], leaf.Irradiance[ReflectedLight]));
  });
}

void PointEvaluator::irradianceAt(const std::vector<const PolygonElement*>& leaves,
  const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const std::vector<Vec3>& towards,
  std::vector<PointIrradiance>& results) const
{
  results.resize(points.size());
  tbb::parallel_for(std::size_t(0), points.size(),
    [&](std::size_t k) { results[k] = this->irradianceAt(*leaves[k], points[k], normals[k], towards[k]); });
}

} // namespace terralux
