#pragma once
// Hierarchical radiosity with clustering (paper sections 3 and 5.3): build the
// cluster hierarchy over the scene, start from the root's self-link plus one link
// from each external source, then refine -> gather -> push/pull until radiosity
// converges. Gather and ray casting run in parallel (TBB); element creation is
// sequential, so results are identical for any thread count.
// The phases live in files of their own: refinement.cxx, push_pull.cxx (gather and
// push-pull); the values at the points users read are PointEvaluator's.

#include "solver/bf_oracle.h"
#include "solver/tuning.h"
#include "terrain/far_terrain.h"
#include "hierarchy/helement.h"
#include "hierarchy/radiosity_types.h"

#include <algorithm>
#include <memory>

namespace terralux
{
class Cluster;
class SceneGeometry;
class PolygonElement;
class SkyHierarchy;
class TerrainPatch;
class Visibility;

struct RadiosityOptions
{
  double errorTolerance = 1e-2;     ///< link power threshold / reference power
  double minimumElementArea = 0.0;  ///< m^2; 0: 1e-6 of the scene's area
  int visibilitySamples = 4;
  int maximumIterations = 30;
  double convergenceTolerance = 1e-3; ///< estimated remaining change of B / max B
  int maximumSkyLevel = 9;
  /// Refinement stops creating elements at this count, or links at four times it (the
  /// solution is then coarser than errorTolerance asks, and
  /// statistics().elementBudgetReached says so).
  std::size_t maximumElements = 1000000;
  /// Most rays of a point's final gather (FinalGather); it casts as many as bring the
  /// point's error estimate within its target (docs/tuning.md). 0: the links that reach
  /// the point's leaf, re-evaluated there.
  int gatherSamples = 4096;
  /// The error each point's value aims at (its IrradianceError): targetError x its
  /// global irradiance, or targetErrorFloor (W/m^2) where that is more. Gather rays
  /// and reads between a lattice's posts are spent until it is met.
  double targetError = 0.008;
  double targetErrorFloor = 2.0;
  /// The error a point aims at, receiving `global` (W/m^2, largest band).
  double errorTarget(double global) const { return std::max(this->targetError * global, this->targetErrorFloor); }
  /// In a scene that is a height field (terrains whose cells face up, no polygons), the
  /// sky hidden from a point comes from its horizon (HorizonSky) instead of the
  /// gather's rays: no sampling noise in the sky.
  bool skyFromHorizons = true;
  /// m; > 0: a gather hit farther than this (horizontally) from its point takes its
  /// leaf's light, not the one terrain's posts' (GatherInputs::detailDistance), and
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
  /// Draws the points' Monte-Carlo samples (their gathers, the lattice's, and the
  /// leaves') from another sequence: 0, the default, and every other value is a
  /// different draw of the same estimate, so the spread between seeds shows a solve's
  /// sampling noise (IrradianceError bounds it per point). Still a function of the
  /// points alone: a split or a second run with the same seed gives the same values.
  std::uint64_t randomSeed = 0;
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
  /// Estimated error of the global irradiance (largest band, W/m^2; PointEvaluator).
  double irradianceError = 0.0;
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

  /// Whether this solver's hierarchy is the one `scene` and `options` would build: the
  /// same shape (SceneGeometry::sameShape), materials and options. After clearSources it
  /// then serves that scene's sources as a new solver would.
  bool serves(const RadiosityScene& scene, const RadiosityOptions& options) const;

  const RadiosityStatistics& statistics() const { return this->Stats; }
  const RadiosityOptions& options() const { return this->Options; }
  /// The scene's rays and horizons, to hand to the next solve over the same shape.
  const std::shared_ptr<SceneGeometry>& geometry() const { return this->Geometry; }
  /// Rays this solver cast since the last solve began: the solve's and those of later
  /// point evaluations (PointEvaluator).
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
  /// Whether the points' rays see a far terrain beyond the detail distance.
  bool seesFarTerrain() const;
  /// Every surface and cluster with its links, for the links output (senders may be
  /// sources too).
  const ElementStore& elements() const { return *this->Store; }
  const Cluster* root() const { return this->RootCluster; }

  /// Every sun added (what points receive) and the hierarchy's: those, or them merged
  /// (mergeSuns) beyond Tuning::maximumSolveSuns.
  const std::vector<HElement*>& suns() const { return this->PointSuns; }
  const std::vector<HElement*>& hierarchySuns() const { return this->Suns; }
  const SkyHierarchy* sky() const { return this->Sky; }
  /// Whether the sky hidden from a point comes from its horizons: skyFromHorizons in a
  /// scene of terrains facing up and nothing else; and the terrain when it is alone.
  bool skyFromHorizons() const { return this->HeightField; }
  const TerrainGrid* heightFieldGrid() const { return this->HeightFieldGrid; }
  /// The terrain is a window of a grid whose far terrain is given (one MPI piece).
  bool isWindow() const { return this->Window; }
  /// The largest radiosity of a leaf after the last solve (0: no surface sends light).
  double largestRadiosity() const { return this->LargestRadiosity; }
  /// Points and terrain posts the outputs may evaluate (a window: the whole grid's).
  std::size_t pointCount() const { return this->PointCount; }
  /// The leaf surfaces of the solution, whose values point evaluation may replace by
  /// what it gathers at them (PointEvaluator).
  std::vector<PolygonElement*> surfaceLeaves();

private:
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
  OracleSettings oracleSettings() const;
  /// The hierarchy as it was built, without a solution: what every solve starts from.
  void restart();

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
  std::uint64_t RaysBefore = 0;     // what the geometry's rays had cast before this solver
  bool HeightField = false; // terrains facing up and nothing else: horizons hold (checked only when asked for)
  const TerrainGrid* HeightFieldGrid = nullptr; // the terrain, when HeightField and alone
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
  RadiosityStatistics Stats;
};
} // namespace terralux
