#include "evaluation/point_evaluator.h"
// Where the posts' horizons come from (PointEvaluator's first phases): the map, its
// density, the posts' skies and the suns it proves, and the sky's part of the error
// estimate.

#include "base/angles.h"
#include "base/elapsed.h"
#include "emitters/external_source.h"
#include "evaluation/final_gather.h"
#include "evaluation/open_sky.h"
#include "horizons/horizon_map.h"
#include "horizons/horizon_sky.h"
#include "horizons/post_sky.h"
#include "horizons/post_sunlight.h"
#include "hierarchy/terrain_patch.h"
#include "parallel/work_split.h"
#include "solver/tuning.h"
#include "terrain/terrain_grid.h"
#include "visibility/scene_geometry.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace terralux
{
void PointEvaluator::findPostHorizons(bool hornNormals)
{
  // Beyond the map's memory the posts keep the rays' horizons, slower but within the
  // memory the rest of the solve needs. A window's map sees its far terrain beyond the
  // detail distance, as its rays do.
  if (!this->Horizons || !this->HeightFieldGrid)
    return;
  const HorizonMap::Density density = this->horizonDensity();
  if (!HorizonMap::fits(*this->HeightFieldGrid, density))
    return;
  const auto start = std::chrono::steady_clock::now();
  // With a split and a detail distance, each process holds the posts' skies and suns
  // within it of its window only.
  this->PostsHalo = this->Split ? HeldPosts::haloFor(*this->HeightFieldGrid, this->Options.gatherDetailDistance) : -1;
  auto findSkies = [&]() {
    this->PostSkies = std::make_unique<PostSky>(
      *this->HeightFieldGrid, *this->Horizons, *this->SkyAtPoints, hornNormals, this->Split, this->PostsHalo);
  };
  // Below the knob's coarse end the coarse map serves where the sky it gives is within
  // every post's target (gentle terrain), judged on a sample of posts first so that
  // rough terrain skips the coarse skies; elsewhere the standard map takes over and
  // copies the coarse one's sweeps. A window alone judges only its own posts, whose
  // horizons must not depend on the others': it keeps the standard map.
  const bool judged =
    density == HorizonMap::Density::Standard && !this->Solver.geometry()->seesGivenFarTerrain();
  this->takeHorizons(judged ? HorizonMap::Density::Coarse : density);
  // (A finer map once built serves a coarse ask: nothing to judge then.)
  auto judgingCoarse = [&]() {
    return judged && this->PostHorizons->azimuthCount() < static_cast<int>(HorizonMap::Density::Standard);
  };
  if (judgingCoarse() && !this->coarseSkyServes(hornNormals, Tuning::coarseSkySampleStride))
    this->takeHorizons(HorizonMap::Density::Standard);
  findSkies();
  if (judgingCoarse() && !this->coarseSkyServes(hornNormals, 1))
  {
    this->takeHorizons(HorizonMap::Density::Standard);
    findSkies();
  }
  this->Stats.horizonAzimuths = this->PostHorizons->azimuthCount();
  this->Stats.horizonsSeconds += secondsSince(start);
}

void PointEvaluator::takeHorizons(HorizonMap::Density density)
{
  // The one terrain's horizons: built by the first solve over this geometry, reused by
  // the next ones.
  this->PostHorizons = &this->Solver.geometry()->horizons(0, density, this->Split);
  this->Horizons = std::make_unique<HorizonSky>(this->PointRays, *this->SkyAtPoints, this->PostHorizons);
}

bool PointEvaluator::coarseSkyServes(bool hornNormals, int stride) const
{
  // The posts of this process's window every `stride` posts of the grid (the same
  // lattice whoever judges), their skies found (PostSkies) or found here; every
  // process's posts must pass, as one process's would.
  const TerrainGrid& grid = *this->HeightFieldGrid;
  const WorkSplit::Window own = WorkSplit::ownWindow(this->Split, grid.postsX(), grid.postsY());
  auto firstOnLattice = [stride](int from) { return (from + stride - 1) / stride * stride; };
  // The terrain's mean radiosity (its root's), what a post's view of it sends on balance.
  const std::vector<TerrainPatch*>& roots = this->Solver.terrainRoots();
  const double terrainRadiosity = roots.empty() ? 0.0 : largestBand(roots[0]->emittance());
  std::atomic<bool> serves{ true };
  tbb::parallel_for(0, own.empty() ? 0 : (own.j1 - firstOnLattice(own.j0)) / stride + 1, [&](int row) {
    const int j = firstOnLattice(own.j0) + row * stride;
    for (int i = firstOnLattice(own.i0); i <= own.i1 && serves; i += stride)
    {
      if (!grid.postUsed(i, j))
        continue;
      PostSky::Value sky;
      Vec3 normal;
      if (!this->PostSkies || !this->PostSkies->foundAt(i, j, sky, normal))
      {
        const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * grid.postsX() + i };
        normal = grid.normalAt(i, j, hornNormals);
        sky = PostSky::at(post, normal, *this->Horizons, *this->SkyAtPoints);
      }
      // The terrain the post sees, 1 - its sky view factor, errs as the sky it hides
      // does, and light from surfaces read in proportion to it (the lattice's reads)
      // with it. What the post receives is at least its sky: a target no larger than
      // its own.
      Spectrum open{};
      double openSolidAngle = 0.0;
      this->SkyAtPoints->irradiance(normal, open, openSolidAngle);
      const double terrainSeenError = Tuning::coarseHorizonSkyError *
        std::max(0.0, openSolidAngle / pi - sky.skyViewFactor) * terrainRadiosity;
      if (this->skyErrorUnder(open, sky.irradiance) + terrainSeenError >
        this->Options.errorTarget(largestBand(sky.irradiance)))
        serves = false;
    }
  });
  return this->Split ? this->Split->allSucceeded(serves) : serves.load();
}

HorizonMap::Density PointEvaluator::horizonDensity() const
{
  if (this->Solver.suns().size() >= Tuning::sunsForDenseHorizons &&
    HorizonMap::fits(*this->HeightFieldGrid, HorizonMap::Density::Dense))
    return HorizonMap::Density::Dense;
  return this->Options.targetError >= Tuning::coarseHorizonsTarget ? HorizonMap::Density::Coarse
                                                                    : HorizonMap::Density::Standard;
}

void PointEvaluator::findSunHorizons()
{
  const TerrainGrid* grid = this->HeightFieldGrid;
  const std::vector<HElement*>& suns = this->Solver.suns();
  if (!grid || suns.empty())
    return;
  const HorizonMap* map = this->PostHorizons;
  const HorizonMap::Density density = this->horizonDensity();
  if (!map && suns.size() >= Tuning::sunsForHorizonMap && HorizonMap::fits(*grid, density))
  {
    const auto start = std::chrono::steady_clock::now();
    map = &this->Solver.geometry()->horizons(0, density, this->Split);
    this->Stats.horizonsSeconds += secondsSince(start);
  }
  if (!map || !map->complete())
    return;
  for (HElement* sun : suns)
  {
    const ExternalSource& source = *sun->asExternal();
    const Vec3& d = source.direction();
    this->MappedSuns.push_back({ map->sight(std::atan2(d.y, d.x), std::asin(std::max(-1.0, std::min(1.0, d.z)))), d,
      sun->emittance(), source.duration() });
  }
  this->SunHorizons = map;
  // Gather hits on the terrain read the suns its posts prove (where each hit takes
  // every sun, the hierarchy's suns being the points' own, all parallel).
  const bool everySunParallel =
    std::all_of(suns.begin(), suns.end(), [](const HElement* sun) { return sun->asExternal()->parallel(); });
  if (this->PostSkies && map == this->PostHorizons && this->Solver.hierarchySuns() == suns && everySunParallel &&
    suns.size() <= std::min(PostSunlight::maximumSuns, FinalGather::maximumSunsPerHit))
  {
    const auto start = std::chrono::steady_clock::now();
    std::vector<HorizonMap::Sight> sights;
    for (const MappedSun& sun : this->MappedSuns)
      sights.push_back(sun.sight);
    this->PostSuns = std::make_unique<PostSunlight>(*grid, *map, sights, this->Split, this->PostsHalo);
    this->Stats.horizonsSeconds += secondsSince(start);
  }
}

double PointEvaluator::skyError(const Vec3& normal, const Spectrum& sky, bool byRays) const
{
  if (byRays || !this->SkyAtPoints)
    return Tuning::openSkyError * largestBand(sky);
  Spectrum open{};
  double projectedSolidAngle = 0.0;
  this->SkyAtPoints->irradiance(normal, open, projectedSolidAngle);
  return this->skyErrorUnder(open, sky);
}

double PointEvaluator::skyErrorUnder(const Spectrum& open, const Spectrum& sky) const
{
  const double own = Tuning::openSkyError * largestBand(sky);
  const bool coarse = this->PostHorizons &&
    this->PostHorizons->azimuthCount() <= static_cast<int>(HorizonMap::Density::Coarse);
  const double share = coarse ? Tuning::coarseHorizonSkyError : Tuning::horizonSkyError;
  return own + share * std::max(0.0, largestBand(open) - largestBand(sky));
}
} // namespace terralux
