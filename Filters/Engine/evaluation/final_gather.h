#pragma once
// Final gather (Reichert 1992; Lischinski, Tampieri & Greenberg 1993): light that
// surfaces send to a point, taken from the solved radiosity of the leaves its rays
// meet. The hierarchy's links bound each exchange against a threshold, so the many small
// exchanges between nearby slopes of a rough terrain, each below it, add up to a
// large loss (a third of the reflected light on the fractal scene of the accuracy
// report); a ray from the point sees all of them at the scene's full resolution.

#include "horizons/horizon_map.h"
#include "hierarchy/radiosity_types.h"
#include "terrain/view_sectors.h"

#include <memory>

namespace terralux
{
class FarTerrain;
class HElement;
class HorizonSky;
class LeafLight;
class OpenSky;
class PolygonElement;
class PostLattice;
class PostSky;
class PostSunlight;
class SkyImportance;
class TerrainPatch;
class Visibility;

/// What a point receives from the sky and from surfaces, by the same rays.
struct GatheredLight
{
  Spectrum surfaces{};
  /// `surfaces` split by the part of the view each ray met its surface in (its sector,
  /// and whether the hit lies beyond nearViewPosts posts; they sum to it), and the view
  /// factor of the surfaces the rays met there (fronts and backs): their ratio is the
  /// mean radiosity of what the point sees in that part.
  PerViewPart<Spectrum> surfacesByPart{};
  PerViewPart<double> surfacesSeenByPart{};
  Spectrum sky{};
  double skyViewFactor = 0.0;
  int rays = 0;
  int count = 0; ///< the rays of the estimate (a pilot's aside)
  double variance = 0.0; ///< of one ray's estimate (largest band), over those rays
  /// Of surfaces + sky as estimated (largest band, W/m^2): the rays' spread over their
  /// count, the surfaces' and the hidden sky's added in quadrature (stratified rays err
  /// less: an upper estimate of their noise).
  double standardError = 0.0;
  /// Of `surfaces`, the part the hits' reflectances made of the light from surfaces they
  /// read (largest band): what a bounce beyond those reads would change.
  double interreflected = 0.0;
  /// The mean over the rays of the reflectance (largest band) of the surface each met,
  /// 0 where it met none or a surface's back: the share of a change in the light from
  /// surfaces that one bounce brings back to the point.
  double reflectanceSeen = 0.0;
  int backRays = 0; ///< of those rays, the ones that met the back of a surface
};

/// How many rays a point takes: as many as a pilot of `pilot` rays says bring the
/// standard error of what they add below relativeError x the point's irradiance, or
/// absoluteError (W/m^2) where that is more, between `minimum` and `maximum` (pilot 0:
/// always maximum).
struct GatherBudget
{
  int pilot = 64;
  int minimum = 64;
  int maximum = 1024;
  double relativeError = 0.003;
  double absoluteError = 0.0;
  /// Rays drawn by the sky's radiance (the sky a scene with buildings hides): at least
  /// this many, or maximum if less. A small occluder hides a few percent of the sky,
  /// which a pilot of 64 sees once or not at all.
  int skyMinimum = 256;
  /// The variance of one ray's estimate where neighbours tell it (>= 0): the count then
  /// follows from it and from knownSurfaces, the light from surfaces expected, with no
  /// pilot.
  double knownVariance = -1.0;
  double knownSurfaces = 0.0;
  /// The least variance of one ray's estimate a pilot's may be taken as: what the
  /// solved hierarchy's links say the point's view holds (a bright strip of a few
  /// percent of it, which a pilot of 64 meets once or not at all, still counts).
  double varianceFloor = 0.0;
  /// The variance (W/m^2 squared) of the point's other estimates by rays, which add to
  /// the same global value: these rays aim at what the target leaves, at least half
  /// of it (the hidden sky by rays aims at half: the two then meet the target together).
  double spentVariance = 0.0;
};

/// What a final gather reads, fixed for its life. The optional parts (null: absent)
/// each replace a cruder reading of the same light.
struct GatherInputs
{
  const Visibility& rays;
  /// The roots of the input polygons and of the terrains (null entries allowed), as the
  /// solver holds them; their leaves' radiosity is read at each gather.
  const std::vector<PolygonElement*>& polygons;
  const std::vector<TerrainPatch*>& terrains;
  const std::vector<HElement*>& suns; ///< the hierarchy's: the suns hits take
  /// The sky at points: the open sky of each point's plane minus what the scene hides.
  const OpenSky* sky = nullptr;
  /// With horizons (a scene that is a height field), the sky the scene hides comes from
  /// the point's horizon instead of the rays, which then gather surfaces alone. Without
  /// them, the hidden sky comes from occlusion rays drawn by the sky's radiance. At a
  /// post of the horizons' map, the surfaces' rays are drawn below the post's horizon
  /// only (TerrainDirections): the sky above it is the horizons' part.
  const HorizonSky* horizons = nullptr;
  /// The skies of the posts of the scene's one terrain (a height field): a hit on it
  /// sends the sky read between them instead of its leaf's average.
  const PostSky* postSkies = nullptr;
  /// Posts of that terrain gathered first: a hit on it receives their light from
  /// surfaces, read between them, instead of its leaf's.
  const PostLattice* lattice = nullptr;
  /// Which suns the posts of that terrain are proven to see or not (in the order of
  /// `suns`): a hit on it whose cell's posts all agree takes no shadow ray for that sun.
  const PostSunlight* postSunlight = nullptr;
  /// What leaves receive, gathered from each: a hit on one of them sends that instead
  /// of the hierarchy's values.
  const LeafLight* leafLight = nullptr;
  /// Beyond this distance (m, horizontally) from the gathering point, a hit on that
  /// terrain reads nothing of its posts (skies, proven suns, lattice) and sends its
  /// leaf's light, as a hit on other surfaces does: what a far hit adds is small, and a
  /// process evaluating a piece of the terrain then needs its posts' values only within
  /// this distance of the piece (HeldPosts). 0: every hit reads them.
  double detailDistance = 0.0;
  /// The far terrain the hierarchy's terrain leaves are built on (null: the scene's own
  /// grid): a hit's parameters, the scene grid's, map to its leaves.
  const FarTerrain* hierarchyTerrain = nullptr;
};

class FinalGather
{
public:
  explicit FinalGather(const GatherInputs& inputs);
  ~FinalGather();

  /// Irradiance (W/m^2) at a point with unit normal from the surfaces it sees: the mean
  /// radiosity met by stratified cosine-weighted rays (the fronts of surfaces only: a
  /// one-sided surface sends nothing from its back), as many as `budget` asks for
  /// against directIrradiance (the sun at the point) plus the rest. `seed` makes it
  /// repeatable.
  ///
  /// What a hit sends is its leaf's radiosity except for direct sunlight, the sharpest
  /// part of it: that is taken at the hit itself, with its own triangle's cosine and a
  /// shadow ray (a leaf of several cells of a rough terrain averages slopes the
  /// grazing sun lights very differently), or the answer its cell's posts all prove
  /// (GatherInputs::postSunlight).
  ///
  /// With a sky, the sky at the point is the open sky of its plane (exact,
  /// OpenSky) minus what the scene hides: from the point's horizon (GatherInputs::horizons), or
  /// from occlusion rays drawn by the sky's radiance with a pilot of their own
  /// (SkyImportance), which also give the sky view factor. `surfacesSend` false skips
  /// what surfaces send (every radiosity 0): no cosine-weighted rays then. `post`: the
  /// terrain post the point stands for, whose horizons the horizons' map holds; there
  /// the rays are drawn below its horizon instead (TerrainDirections) and gather light
  /// from surfaces alone (the sky is its horizons'), and a hit on the terrain sends the
  /// sky of the posts around it (GatherInputs::postSkies) and the lattice's light from surfaces
  /// (GatherInputs::lattice) instead of its leaf's.
  GatheredLight irradianceAt(const Vec3& point, const Vec3& normal, const GatherBudget& budget, std::uint64_t seed,
    double directIrradiance, bool surfacesSend = true, const HorizonMap::Post& post = {}) const;
  /// Up to maximumSunsPerHit suns each take a shadow ray at every hit; more (the sun
  /// positions of a day or a year, summed in one solve) would multiply the gather's
  /// rays, so a hit then takes one sun, chosen in proportion to its irradiance and
  /// weighted by the inverse of that chance (unbiased; the gather's error control sees
  /// the extra spread and adds rays where it matters).
  static constexpr std::size_t maximumSunsPerHit = 4;

  /// How many of strata x strata stratified cosine-weighted rays from a point escape or
  /// meet the front of a surface: how open its side is (a point that sees the back of
  /// a one-sided surface lies inside something, as a post on the line of a house's wall
  /// may).
  /// With `skyRays`, also how many met nothing at all.
  int openRays(const Vec3& point, const Vec3& normal, int strata, std::uint64_t seed, int* skyRays = nullptr) const;
  /// The triangle's own normal at a hit, turned to the side its leaf faces.
  static Vec3 frontAt(const struct SurfaceHit& hit, const PolygonElement& leaf);
  /// The leaf a ray's hit lies on (null where nothing solved is there).
  const PolygonElement* leafAt(const struct SurfaceHit& hit) const;
  /// Radiosity leaving a hit on `leaf` of a ray from `from`, its direct sunlight taken
  /// at the hit; `sunSample` in [0, 1) picks the sun when there are many. With
  /// `interreflected`, also the part of it reflected from the light from surfaces the
  /// hit read (largest band).
  Spectrum radiosityAt(const PolygonElement& leaf, const struct SurfaceHit& hit, const Vec3& front,
    double sunSample, const Vec3& from, double* interreflected = nullptr) const;

private:
  /// The sky a point does not see, by occlusion rays drawn in proportion to the sky's
  /// radiance (each carries the same share of it), as many as a pilot says bring the
  /// standard error below budget.relativeError x `received`; counts the rays. `variance`:
  /// of that estimate (largest band).
  Spectrum hiddenSkyByRadiance(const Vec3& point, const Vec3& normal, const GatherBudget& budget,
    std::uint64_t seed, double received, double& hiddenProjectedSolidAngle, int& rays, double& variance) const;

  const Visibility& Rays;
  const std::vector<PolygonElement*>& Polygons;
  const std::vector<TerrainPatch*>& Terrains;
  const std::vector<HElement*>& Suns;
  const OpenSky* Sky;
  const HorizonSky* Horizons;
  const PostSky* PostSkies;
  const PostLattice* Lattice;
  const PostSunlight* PostSuns;
  const LeafLight* Leaves;
  const double DetailDistance;
  const FarTerrain* HierarchyTerrain;
  double NearViewDistance = 0.0; // where a hit's view part is far (m, horizontally)
  std::unique_ptr<SkyImportance> SkySamples; // without horizons: rays drawn by the sky's radiance
  std::vector<double> SunCumulative; // running sums of the suns' largest bands; empty: all suns at each hit
};

/// Cosine-weighted directions about one unit normal (its frame made once).
class CosineFrame
{
public:
  explicit CosineFrame(const Vec3& n);
  /// From a point (s, t) of the unit square (Malley's method: a uniform point of the
  /// disc lifted onto the hemisphere).
  Vec3 direction(double s, double t) const;

private:
  Vec3 N, U, V;
};
} // namespace terralux
