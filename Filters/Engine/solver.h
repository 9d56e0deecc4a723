#pragma once
// Hierarchical radiosity with clustering (paper sections 3 and 5.3): build the
// cluster hierarchy over the scene, start from the root's self-link plus one link
// from each external source, then refine -> gather -> push/pull until radiosity
// converges. Gather and ray casting run in parallel (TBB); element creation is
// sequential, so results are identical for any thread count.
// The phases live in files of their own: refinement.cxx, push_pull.cxx (gather and
// push-pull), point_evaluation.cxx (values at the points users read).

#include "bf_oracle.h"
#include "far_terrain.h"
#include "helement.h"
#include "horizon_map.h"
#include "post_lattice.h"
#include "radiosity_types.h"

#include <memory>

namespace terralux
{
class WorkSplit;
class Cluster;
class FinalGather;
class HorizonSky;
class LeafLight;
class PostSky;
class PostSunlight;
class SceneGeometry;
class OpenSky;
class PolygonElement;
class SkyHierarchy;
class TerrainPatch;
class Visibility;

struct RadiosityOptions
{
  double errorTolerance = 1e-3;     ///< link power threshold / reference power
  double minimumElementArea = 0.0;  ///< m^2; 0: 1e-6 of the scene's area
  int visibilitySamples = 4;
  int maximumIterations = 30;
  double convergenceTolerance = 1e-3; ///< estimated remaining change of B / max B
  int maximumSkyLevel = 9;
  /// Refinement stops creating elements at this count, or links at four times it (the
  /// solution is then coarser than errorTolerance asks, and
  /// statistics().elementBudgetReached says so).
  std::size_t maximumElements = 1000000;
  /// Sky and light from surfaces at points come from a final gather over the solved
  /// leaves (FinalGather, after gatherLeaves): as many rays, from 64 to gatherSamples,
  /// as a pilot of 64 says bring the standard error below gatherError x the point's
  /// irradiance, and at least 256 for the sky's; over a height field, points of leaves
  /// the solution found open (sky view within 0.1 % of their plane's, light from
  /// surfaces under 0.2 %) take 64 rays and no pilot. At the posts of one terrain with
  /// horizons: rays below the horizon only (TerrainDirections), at most gatherSamples /
  /// 4, a pilot of 16 on a lattice of posts (gatherPostLattice), at least 9 rays and no
  /// pilot elsewhere. gatherSamples 0 re-evaluates the links that reach the point's
  /// leaf instead.
  int gatherSamples = 4096;
  double gatherError = 0.003;
  /// In a scene that is a height field (terrains whose cells face up, no polygons), the
  /// sky hidden from a point comes from its horizon (HorizonSky) instead of the
  /// gather's rays: no sampling noise in the sky.
  bool skyFromHorizons = true;
  /// m; > 0: a gather hit farther than this (horizontally) from its point takes its
  /// leaf's light, not the one terrain's posts' (FinalGather::setDetailDistance), and
  /// with a work split each process holds the posts' skies and suns only within it of
  /// its window (HeldPosts). 0: every hit reads the posts.
  double gatherDetailDistance = 0.0;
  /// > 1, with a gatherDetailDistance, in a scene of one terrain alone: beyond that
  /// distance from its origin a ray from a point the outputs read (its gather, sun and
  /// sky) sees the terrain's every farTerrainStride-th post (FarTerrain), as horizon
  /// tools see far terrain; the hierarchy is solved on those posts alone (its rays see
  /// them alone), while every post of the scene's grid is still evaluated. 1: the full
  /// resolution everywhere.
  int farTerrainStride = 1;
  FarSight farSight() const { return FarSight{ this->farTerrainStride, this->gatherDetailDistance }; }
};

bool operator==(const RadiosityOptions& a, const RadiosityOptions& b);
inline bool operator!=(const RadiosityOptions& a, const RadiosityOptions& b)
{
  return !(a == b);
}

struct RadiosityStatistics
{
  std::size_t elements = 0;
  std::size_t links = 0;
  std::uint64_t rays = 0;
  int iterations = 0;
  /// Estimated remaining relative change of B after the last iteration: the last change
  /// over (1 - its ratio to the one before), since gathering converges geometrically.
  double residual = 0.0;
  bool converged = false;          ///< residual below convergenceTolerance
  bool elementBudgetReached = false; ///< refinement was cut at maximumElements
  double referencePowerW = 0.0;
  double secondsHierarchyBuild = 0.0; ///< elements and clusters (0 for a solver used again)
  double secondsVisibilityBuild = 0.0; ///< the rays (0 when an earlier solve's are reused)
  double secondsRefine = 0.0;
  double secondsGather = 0.0;
  double secondsPushPull = 0.0;
  double secondsHorizons = 0.0; ///< the horizons of every post (HorizonMap), with the sky
  /// Rays of each phase of the solve (link visibility in refinement; leaf kernels in
  /// gather and push-pull); the point evaluation's are raysCast() minus their sum.
  std::uint64_t raysRefine = 0;
  std::uint64_t raysPushPull = 0;
};

/// Irradiance by light category at a point, and the sky view factor there: the
/// cosine-weighted fraction of the sky the point sees (1 on open flat ground).
struct PointIrradiance
{
  std::array<Spectrum, lightCategories> irradiance{};
  double skyViewFactor = 0.0;
  double sunlitHours = 0.0; ///< durations of the suns that reach the point (addSun)
  double gatherVariance = 0.0; ///< of one final-gather ray's estimate (largest band)
};

class RadiosityProgress
{
public:
  virtual ~RadiosityProgress() = default;
  /// Fraction in [0, 1]; return false to abort.
  virtual bool report(double fraction) = 0;
};

class HierarchicalRadiosity
{
public:
  /// The scene's polygons, and each terrain's largest complete patches, become the
  /// leaves of the initial cluster hierarchy; degenerate polygons (zero area) are left
  /// out and counted. Throws Error when nothing usable remains.
  /// `geometry`: the rays and horizons of an earlier solve over a scene of the same
  /// shape (SceneGeometry::sameShape), reused instead of built again; null, or of
  /// another shape, builds them anew (see geometry()).
  HierarchicalRadiosity(const RadiosityScene& scene, const RadiosityOptions& options,
    std::shared_ptr<SceneGeometry> geometry = nullptr);
  ~HierarchicalRadiosity();

  /// External sources: any number of suns (their light adds up; one at or below the
  /// horizon, direction z <= 0, is ignored) and one sky (the hierarchy must outlive the
  /// solver; several skies are summed into one map first). A sun may stand for
  /// `duration` hours (a time series' step; its irradiance then in Wh/m^2), which the
  /// points it reaches add up as PointIrradiance::sunlitHours.
  void addSun(const Vec3& directionTowardSun, const Spectrum& normalIrradiance, double duration = 0.0);
  void setSky(const SkyHierarchy* sky);
  /// Drops the suns, the sky and the solution, keeping the hierarchy as it was built and
  /// the geometry (rays, horizons): new sources then solve without building either
  /// again, to the values a new solver would give them.
  void clearSources();

  /// Solves; returns false when aborted through `progress`. Each solve starts from the
  /// hierarchy as it was built (the elements and links of an earlier solve dropped), so
  /// that its values are those of a new solver with the same sources, bit for bit.
  bool solve(RadiosityProgress* progress = nullptr);
  /// Before posts are evaluated in a scene of one height-field terrain under a sky:
  /// the horizons of all its posts at once (HorizonMap, 64 bytes a post, up to 2 GiB),
  /// which their sky then reads instead of casting rays, and the sky of every post
  /// (PostSky) at the normals the outputs use (Horn's where `hornNormals`). Elsewhere it
  /// does nothing.
  void findPostHorizons(bool hornNormals = false);
  /// Before posts are evaluated in a scene of one height-field terrain without missing
  /// cells: direct sun at a post casts its ray only where the post's horizons
  /// (HorizonMap::View) prove the sun neither open nor hidden, which over a day or a year of
  /// suns is most of them. Uses findPostHorizons' map, or builds it where there is none
  /// and at least sunsForHorizonMap suns (it costs about 20 rays a post). The bounds
  /// hold for any terrain at the post itself, and a ray decides the rest; a ray starts a
  /// little above the post (Visibility::offset) and may pass over a crest a cell away
  /// that the proof, rightly, finds in the way.
  void findSunHorizons();
  /// Processes that solve this same scene (MPI ranks, each evaluating its own piece)
  /// and split what every one of them needs at every post: the horizons' map, the
  /// posts' skies (findPostHorizons, findSunHorizons) and the lattice
  /// (gatherPostLattice), each computing its share and receiving the others'. Every
  /// process must then make these calls alike. A process whose share throws makes all
  /// of them throw (WorkSplit::partThenShare), none is left waiting. Null (the
  /// default): this one alone.
  void setWorkSplit(const WorkSplit* split) { this->Split = this->Window ? nullptr : split; } // a window: alone
  static constexpr std::size_t sunsForHorizonMap = 48;
  /// From this many suns on (a few months of hours), the map is dense (64 azimuths):
  /// at 1025^2 its sweep and the posts' skies take 5.7 s instead of 2.9 s, and the suns
  /// near a post's horizon 40 % fewer rays (June's hourly suns: 42.7 M instead of
  /// 71.5 M, the month's whole solve no faster; a year's 679 M rays fell to 449 M).
  static constexpr std::size_t sunsForDenseHorizons = 1000;

  /// Whether this solver's hierarchy is the one `scene` and `options` would build: the
  /// same shape (SceneGeometry::sameShape), materials and options. After clearSources it
  /// then serves that scene's sources as a new solver would.
  bool serves(const RadiosityScene& scene, const RadiosityOptions& options) const;

  const RadiosityStatistics& statistics() const { return this->Stats; }
  /// The scene's rays and horizons, to hand to the next solve over the same shape.
  const std::shared_ptr<SceneGeometry>& geometry() const { return this->Geometry; }
  /// Rays this solver cast since the last solve began: the solve's and those of later
  /// point evaluations.
  std::uint64_t raysCast() const;
  std::size_t degeneratePolygons() const { return this->Degenerate; }
  /// Root element of each input polygon (null for degenerate ones).
  const std::vector<PolygonElement*>& polygonRoots() const { return this->Roots; }
  /// Root of each terrain's patch tree (null for a terrain without a valid cell).
  const std::vector<TerrainPatch*>& terrainRoots() const { return this->TerrainRoots; }
  /// The grid of posts of a terrain root, whose posts the outputs read: the scene's
  /// grid, also where the hierarchy is solved on the far terrain (root.grid()).
  const TerrainGrid& postGrid(const TerrainPatch& root) const;
  /// The leaf post (i, j) of postGrid(root) takes its light from: of the leaves around
  /// it, the most lit (TerrainPatch::mostLitLeafAt); null where no cell is valid.
  const TerrainPatch* leafAtPost(const TerrainPatch& root, int i, int j) const;
  /// With a far sight, the far terrain the hierarchy is built on (its grid is the
  /// roots' grid(), its maps lead between that and postGrid's parameters); else null.
  const FarTerrain* hierarchyTerrain() const { return this->HierarchyTerrain.get(); }
  /// Every surface and cluster with its links, for the links output (senders may be
  /// sources too).
  const ElementStore& elements() const { return *this->Store; }
  const Cluster* root() const { return this->RootCluster; }

  /// Irradiance by light category at a point of a leaf surface, every link that reaches
  /// the leaf (at any level) re-evaluated at that point: exact form factors and
  /// visibility sampled from the point. This is what per-vertex outputs use, so
  /// values at vertices are not smeared over the elements around them.
  /// The sky view factor needs a sky (it is 0 without one).
  PointIrradiance irradianceAt(const PolygonElement& leaf, const Vec3& point) const;
  /// The same with another unit normal at the point (e.g. a terrain post's, averaged over
  /// the cells around it), still through the links that reach `leaf`.
  PointIrradiance irradianceAt(const PolygonElement& leaf, const Vec3& point, const Vec3& normal) const;
  /// The same with the centre the point is moved toward (two ray offsets) given: for a
  /// vertex of a polygonal surface, the area-weighted centroid of the cells around it
  /// that share its orientation (the limit of the value from inside that surface,
  /// whatever leaf holds the point; the accuracy report's reference takes the same).
  /// The others move toward their leaf's centre.
  PointIrradiance irradianceAt(
    const PolygonElement& leaf, const Vec3& point, const Vec3& normal, const Vec3& toward) const;
  /// Direct sunlight at a point with a unit normal: normal irradiance x cosine, 0 where
  /// the point is shadowed (one ray per sun); zero without a sun. With `sunlitHours`,
  /// also the durations of the suns that reach the point.
  Spectrum directSunAt(const Vec3& point, const Vec3& normal, double* sunlitHours = nullptr) const;
  /// Before the posts of the scene's one terrain (a height field with horizons, see
  /// findPostHorizons) are evaluated: a lattice of them (PostLattice) first, in
  /// parallel, at the normals the outputs use (Horn's where `hornNormals`), so that the
  /// others take their light from surfaces one bounce more exact and cast no pilot.
  /// Does nothing for other scenes.
  void gatherPostLattice(const TerrainPatch& root, bool hornNormals);
  /// After gatherPostLattice, a post between lattice posts that agree, per terrain seen,
  /// on what their gathers found beyond their horizons' sky (within
  /// latticeSpreadAllowance x gatherError of what the post receives), and whose light
  /// from surfaces is at most this share of it, reads that between them instead of
  /// gathering (no rays).
  static constexpr double smallReflectedShare = 0.01;
  /// The corners' values differ mostly by each one's own small terrain, which the post
  /// between them does not share: reading between them errs by about half their spread,
  /// so a spread of twice a gather's error leaves about a gather's error. Measured
  /// against the accuracy report's references at 1e-3 (1 -> 2): the fractal's global
  /// RMS 0.492 -> 0.497 %, the hills' 0.069 -> 0.063 %, the crater and Olinda unchanged;
  /// the 1025^2 fractal's instant 15.7 M -> 9.4 M rays, 4.05 -> 3.10 x r.sun.
  static constexpr double latticeSpreadAllowance = 2.0;
  /// The lattice's coarse cells (PostLattice::refine) are gathered at every lattice post
  /// where a corner's spread of what the corners found exceeds this x gatherError of what
  /// that corner receives: half what a post may read across, since a post reads across
  /// twice the distance there. Measured against the accuracy report's references at
  /// 1e-3, global RMS: the fractal 0.497 % (as refined everywhere; 0.511 % at 2, over
  /// its acceptance), the hills 0.064 % (0.063 %), Olinda 0.023 % (0.023 %); the 4097^2
  /// fractal's instant 22.8 M -> 8.5 M rays, 61.9 s -> 44.9 s, its posts' values 0.016 %
  /// RMS from those refined everywhere.
  static constexpr double latticeRefineAllowance = 1.0;
  /// After the solve (and findPostHorizons): what every leaf receives from the sky and
  /// from surfaces, by a gather of leafGatherRays from 4 of its points (16 where some
  /// lie inside something), fitted by a plane across the leaf (LeafLight), in parallel;
  /// leafGatherPasses passes, the first over the hierarchy's values, each next over the
  /// last pass's (one more bounce each). Gather rays that meet a leaf then send that,
  /// and the leaf's own values become the gathered means. Leaves of a terrain whose
  /// posts' skies are known are left out (their hits read PostSky and PostLattice), and
  /// all terrain leaves when `terrains` is false (averaged outputs of a DEM stay fast) or
  /// the hierarchy is solved on the far terrain (its leaves' points lie on the coarse
  /// surface, which the points' rays see only beyond the detail distance).
  /// The canyon's street (RMS of global): 64 rays 0.84 %, 256 0.65 %, 1024 0.61 % at
  /// twice the time (at most 1024 rays a point); at 4096 a point, 1 pass 0.44 %, 2 0.39 %
  /// and its wall foot's mean bias from 1.8 % to 1.0 %, 3 0.38 % and 0.5 %.
  void gatherLeaves(bool terrains = true);
  static constexpr int leafGatherRays = 256;
  static constexpr int leafGatherPasses = 3;
  /// Many points at once, in parallel, each moved toward its own centre (see above).
  void irradianceAt(const std::vector<const PolygonElement*>& leaves, const std::vector<Vec3>& points,
    const std::vector<Vec3>& normals, const std::vector<Vec3>& towards, std::vector<PointIrradiance>& results) const;

private:
  /// Whether points take a final gather: rays to cast and something for them to see (a
  /// sky, or surfaces that send light).
  bool gathersAtPoints() const;
  /// Where a point's gather starts ("just above" it): `inside` (the point moved into its
  /// leaf) unless that sees the back of a surface, then the most open of four points two
  /// ray offsets from it diagonally in its plane, if clearly more open (the reference's
  /// rule, Testing/Reference): a post on the line of a house's wall is judged from
  /// outside the house, not from its dark inside.
  Vec3 openSideOf(const Vec3& point, const Vec3& inside, const Vec3& normal, std::uint64_t seed) const;
  // The lattice's posts of one pass this process gathers (its share where the work is
  // split).
  void gatherLatticePosts(const TerrainPatch& root, bool hornNormals, bool firstPass, PostLattice& lattice) const;
  /// Post (i, j), between gathered lattice posts that agree on the radiosity of the
  /// terrain they see, takes its light from surfaces from them and its sky from its
  /// horizons, without a gather: true, with `result` (its sun already in it) filled.
  bool readFromLattice(const HorizonMap::Post& post, const Vec3& normal, int i, int j,
    const PostLattice::Around& around, PointIrradiance& result) const;
  /// Refines pending links; returns how many were split.
  std::size_t refine(std::vector<std::pair<HElement*, Link>>& pending, bool evaluated);
  std::size_t splitShadowedLeaves();
  std::size_t restrictTerrainMeshes();
  std::size_t splitLeaves(const std::vector<PolygonElement*>& leaves);
  void gather();
  /// Gathered radiosity down and up the hierarchy; returns the largest change of B
  /// (W/m^2) and keeps the largest B in LargestRadiosity. With `extrapolation` > 0 each leaf moves that many times its change
  /// further (geometric extrapolation of a slowly converging, highly reflective scene).
  double pushPull(double extrapolation = 0.0);
  /// Whether refinement may still create elements.
  bool mayGrow();
  /// Surfaces, clusters and sources.
  std::size_t elementCount() const;
  double referencePower() const;
  /// The hierarchy's suns: the added ones, or, beyond maximumSolveSuns (the sun
  /// positions of a month or a year), those within the same few degrees of the sky
  /// merged into one (flux-weighted direction, summed flux). Light from surfaces varies
  /// slowly with the sun's direction, and sunlight at points still takes every sun.
  void mergeSuns();
  static constexpr std::size_t maximumSolveSuns = 64;
  static constexpr double mergedSunDegrees = 2.0;
  OracleSettings oracleSettings() const;
  /// The hierarchy as it was built, without a solution: what every solve starts from.
  void restart();
  /// The sky's horizons before findPostHorizons: those the rays find (none without a
  /// sky or outside a height field).
  void resetHorizons();
  /// Drops the suns' bearings on the horizons' map (directSunAt casts every ray again).
  void forgetMappedSuns();
  bool wantsDenseHorizons() const; // for the suns; HeightFieldGrid must be set

  RadiosityOptions Options;
  /// The surfaces and clusters; its first InitialElements are the hierarchy as built.
  std::unique_ptr<ElementStore> Store;
  std::size_t InitialElements = 0;
  std::unique_ptr<ElementStore> Sources;    // the suns and sky patches added
  std::unique_ptr<ElementStore> MergedSuns; // of the last solve (mergeSuns)
  // Ids of the three stores' elements start apart, so that the seeds of two links never coincide.
  static constexpr std::uint64_t firstSourceId = std::uint64_t(1) << 40;
  static constexpr std::uint64_t firstMergedSunId = std::uint64_t(1) << 41;
  bool Solved = false; // a solve has run since the solver was built
  std::shared_ptr<SceneGeometry> Geometry;
  const Visibility* Rays = nullptr; // the geometry's: the hierarchy's
  const Visibility* PointRays = nullptr; // and the points' (SceneGeometry::pointRays), one count with Rays
  std::uint64_t RaysBefore = 0;     // what the geometry's rays had cast before this solver
  std::unique_ptr<FinalGather> Gather;
  std::unique_ptr<OpenSky> SkyAtPoints;
  std::unique_ptr<HorizonSky> Horizons;
  bool HeightField = false; // terrains facing up and nothing else: horizons hold (checked only when asked for)
  const TerrainGrid* HeightFieldGrid = nullptr; // the terrain, when HeightField and alone
  const HorizonMap* PostHorizons = nullptr;      // its posts' horizons (findPostHorizons), the geometry's
  const HorizonMap* SunHorizons = nullptr;       // the same map, for direct sun (findSunHorizons)
  const WorkSplit* Split = nullptr;              // the processes sharing the work (setWorkSplit)
  int PostsHalo = -1;                            // HeldPosts::haloFor the detail distance, with a split
  struct MappedSun // each of PointSuns on that map
  {
    HorizonMap::Sight sight;
    Vec3 direction;
    Spectrum flux;
    double duration;
  };
  std::vector<MappedSun> MappedSuns;
  std::unique_ptr<PostSky> PostSkies;            // and the sky each of them receives
  std::unique_ptr<PostSunlight> PostSuns;        // and the suns they prove seen or hidden (findSunHorizons)
  std::unique_ptr<PostLattice> Lattice;          // its posts gathered first (gatherPostLattice)
  std::unique_ptr<LeafLight> Leaves;             // what leaves receive, gathered (gatherLeaves)
  std::vector<PolygonElement*> Roots;
  std::vector<TerrainPatch*> TerrainRoots;
  std::vector<const TerrainGrid*> PostGrids;    // the scene's terrains: what outputs read
  bool Window = false; // the terrain is a window of a grid whose far terrain is given
  std::unique_ptr<FarTerrain> HierarchyTerrain; // with a far sight: the grid the hierarchy is built on
  std::vector<PolygonElement*> TopSurfaces; // what the clusters are built on
  Cluster* RootCluster = nullptr;
  std::vector<HElement*> PointSuns; // every sun added: direct sunlight at points
  std::vector<HElement*> Suns;      // the hierarchy's: PointSuns, or them merged (mergeSuns)
  HElement* SkyRoot = nullptr;
  const SkyHierarchy* Sky = nullptr;
  double SceneArea = 0.0;
  double LargestRadiosity = 0.0; // over the leaves, after the last push-pull
  std::size_t StoredLinks = 0;   // links held by elements
  std::size_t PendingLinks = 0;  // links refine() holds while it runs
  std::size_t Degenerate = 0;
  std::size_t PointCount = 0; // points and terrain posts the outputs may evaluate
  static constexpr std::size_t openSkyTablePoints = 200000;
  RadiosityStatistics Stats;
};
} // namespace terralux
