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
  // every post's target (gentle terrain). Where it misses a few posts' (rough terrain),
  // it is refined there alone (HorizonMap's refining constructor); where it misses
  // many, the standard map takes over and copies the coarse one's sweeps. A sample of
  // posts judges first, so that terrain rough throughout skips the coarse skies. A
  // window alone judges only its own posts, whose horizons must not depend on the
  // others': it keeps the standard map.
  const bool judged =
    density == HorizonMap::Density::Standard && !this->Solver.geometry()->seesGivenFarTerrain();
  // The coarse map itself is judged, even where a finer one was built before (by
  // another solve over this geometry): the values do not depend on what was.
  this->takeHorizons(judged ? HorizonMap::Density::Coarse : density, judged);
  bool judging = judged;
  if (judging && this->coarseSkyMisses(hornNormals, Tuning::coarseSkySampleStride) > Tuning::refinedPostsShare)
    this->takeHorizons(HorizonMap::Density::Standard), judging = false;
  findSkies();
  if (judging)
  {
    const HorizonMap& coarse = *this->PostHorizons;
    std::vector<std::uint8_t> missed;
    const double share = this->coarseSkyMisses(hornNormals, 1, &missed);
    if (share > Tuning::refinedPostsShare)
    {
      this->takeHorizons(HorizonMap::Density::Standard);
      findSkies();
    }
    else if (share > 0.0)
    {
      this->RefinedHorizons = std::make_unique<HorizonMap>(coarse, missed);
      this->PostHorizons = this->RefinedHorizons.get();
      this->Horizons = std::make_unique<HorizonSky>(this->PointRays, *this->SkyAtPoints, this->PostHorizons);
      this->PostSkies->findAgain(missed, *this->Horizons, *this->SkyAtPoints, hornNormals, this->Split);
      this->Stats.horizonRefinedPosts = WorkSplit::total(this->Split, this->RefinedHorizons->refinedPosts());
    }
  }
  this->Stats.horizonAzimuths = this->ProofHorizons->azimuthCount();
  this->Stats.horizonsSeconds += secondsSince(start);
}

void PointEvaluator::takeHorizons(HorizonMap::Density density, bool exactly)
{
  // The one terrain's horizons: built by the first solve over this geometry, reused by
  // the next ones.
  this->PostHorizons = this->ProofHorizons = &this->Solver.geometry()->horizons(0, density, this->Split, exactly);
  this->RefinedHorizons.reset();
  this->Horizons = std::make_unique<HorizonSky>(this->PointRays, *this->SkyAtPoints, this->PostHorizons);
}

double PointEvaluator::coarseSkyMisses(bool hornNormals, int stride, std::vector<std::uint8_t>* missed)
{
  // The posts of this process's window every `stride` posts of the grid (the same
  // lattice whoever judges), their skies found (PostSkies) or found here; counted over
  // every process's posts, as one process's would be.
  const TerrainGrid& grid = *this->HeightFieldGrid;
  const WorkSplit::Window own = WorkSplit::ownWindow(this->Split, grid.postsX(), grid.postsY());
  const std::size_t ownX = own.empty() ? 0 : static_cast<std::size_t>(own.i1 - own.i0 + 1);
  const std::size_t ownCount = own.empty() ? 0 : ownX * static_cast<std::size_t>(own.j1 - own.j0 + 1);
  if (missed)
  {
    missed->assign(ownCount, 0);
    this->BetweenAzimuths.assign(ownCount, -1.0f);
  }
  auto firstOnLattice = [stride](int from) { return (from + stride - 1) / stride * stride; };
  // The terrain's mean radiosity (its root's), what a post's view of it sends on balance.
  const std::vector<TerrainPatch*>& roots = this->Solver.terrainRoots();
  const double terrainRadiosity = roots.empty() ? 0.0 : largestBand(roots[0]->emittance());
  const int rows = own.empty() ? 0 : (own.j1 - firstOnLattice(own.j0)) / stride + 1;
  std::vector<std::array<std::size_t, 2>> counts(static_cast<std::size_t>(std::max(0, rows))); // judged, missed
  tbb::parallel_for(0, rows, [&](int row) {
    const int j = firstOnLattice(own.j0) + row * stride;
    for (int i = firstOnLattice(own.i0); i <= own.i1; i += stride)
    {
      if (!grid.postUsed(i, j))
        continue;
      const HorizonMap::Post post{ true, static_cast<std::size_t>(j) * grid.postsX() + i };
      const std::size_t cell = static_cast<std::size_t>(j - own.j0) * ownX + (i - own.i0); // in `missed`
      PostSky::Value sky;
      Vec3 normal;
      if (!this->PostSkies || !this->PostSkies->foundAt(i, j, sky, normal))
      {
        normal = grid.normalAt(i, j, hornNormals);
        sky = PostSky::at(post, normal, *this->Horizons, *this->SkyAtPoints);
      }
      // The terrain the post sees, 1 - its sky view factor, errs as the sky it hides
      // does, and light from surfaces read in proportion to it (the lattice's reads)
      // with it. What the post receives is at least its sky: a target no larger than
      // its own. A share of the sky hidden first (most posts of gentle terrain end
      // there); where that misses, the band between azimuths, closer.
      const double target = this->Options.errorTarget(largestBand(sky.irradiance));
      const double openError = Tuning::openSkyError * largestBand(sky.irradiance);
      const double hidden = std::max(0.0, sky.openLargestBand - largestBand(sky.irradiance));
      bool misses = openError + Tuning::coarseHorizonSkyError *
          (hidden + std::max(0.0, sky.openProjectedSolidAngle / pi - sky.skyViewFactor) * terrainRadiosity) >
        target;
      if (misses)
      {
        const HiddenSky band = this->Horizons->hiddenAt(post, normal, true);
        const double between = largestBand(band.betweenAzimuths);
        const double terrainBetween = band.betweenAzimuthsSolidAngle / pi * terrainRadiosity;
        misses = openError + Tuning::betweenAzimuthsError * (between + terrainBetween) > target;
        if (missed)
          this->BetweenAzimuths[cell] = static_cast<float>(between);
      }
      ++counts[static_cast<std::size_t>(row)][0];
      counts[static_cast<std::size_t>(row)][1] += misses;
      if (missed && misses)
        (*missed)[cell] = 1;
    }
  });
  std::size_t judged = 0, misses = 0;
  for (const auto& count : counts)
    judged += count[0], misses += count[1];
  judged = WorkSplit::total(this->Split, judged);
  misses = WorkSplit::total(this->Split, misses);
  return judged > 0 ? static_cast<double>(misses) / judged : 0.0;
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
  const HorizonMap* map = this->ProofHorizons;
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
  if (this->PostSkies && map == this->ProofHorizons && this->Solver.hierarchySuns() == suns && everySunParallel &&
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

double PointEvaluator::skyError(const Vec3& normal, const Spectrum& sky, const HorizonMap::Post& post) const
{
  const double own = Tuning::openSkyError * largestBand(sky);
  if (!post || !this->SkyAtPoints)
    return own;
  // The open sky as the post's sky was found on the same normal (most points), else
  // evaluated again.
  PostSky::Value found;
  const bool kept = this->PostSkies && this->PostSkies->found(post, normal, found);
  if (!kept)
  {
    Spectrum open{};
    this->SkyAtPoints->irradiance(normal, open, found.openProjectedSolidAngle);
    found.openLargestBand = largestBand(open);
  }
  const double hidden = std::max(0.0, found.openLargestBand - largestBand(sky));
  // Horizons interpolated between a coarse map's azimuths (every post of one, a
  // refined map's but those it found) err by a share of the sky they hide, or where
  // that missed the post's target, as its band between azimuths tells (on the post's
  // own plane).
  const HorizonMap& map = *this->PostHorizons;
  const std::size_t cell = map.cellOf(post);
  if (map.azimuthCount() > static_cast<int>(HorizonMap::Density::Coarse) && map.exactAt(cell))
    return own + Tuning::horizonSkyError * hidden;
  if (cell < this->BetweenAzimuths.size() && this->BetweenAzimuths[cell] >= 0.0f && kept)
    return own + Tuning::betweenAzimuthsError * this->BetweenAzimuths[cell];
  return own + Tuning::coarseHorizonSkyError * hidden;
}
} // namespace terralux
