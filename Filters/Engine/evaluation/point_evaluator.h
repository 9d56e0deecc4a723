#pragma once
// The values at the points users read (terrain posts, polygon vertices), from a solved
// hierarchy but with what varies sharply taken at the point: direct sun by a ray (or
// the post's horizons), sky and light from surfaces by a final gather (Reichert 1992)
// over the leaves' radiosity. Its constructor runs the phases in the engine's order
// (docs/architecture.md); once built, it only answers.

#include "evaluation/post_lattice.h"
#include "horizons/horizon_map.h"
#include "hierarchy/radiosity_types.h"
#include "solver/solver.h"

#include <memory>
#include <vector>

namespace terralux
{
class FinalGather;
class HorizonSky;
struct GatheredLight;
class LeafLight;
class OpenSky;
class PolygonElement;
class PostSky;
class PostSunlight;
class TerrainPatch;
class WorkSplit;

/// What the outputs read, for PointEvaluator.
struct EvaluationPlan
{
  bool atPoints = true;      ///< values at points (final gathers); false: the leaves' own
  bool hornNormals = false;  ///< posts' normals as Horn's (r.slope.aspect), else area-weighted
  const WorkSplit* split = nullptr; ///< processes sharing the work (MPI ranks); null: alone
  bool postLattice = true;   ///< at points on one terrain, a lattice of posts gathered first
  /// Gather hits read what their leaf receives gathered from it first (LeafLight, one
  /// bounce more); false: the hierarchy's values (to measure what that brings).
  bool leavesGathered = true;
};

struct EvaluationStatistics
{
  double horizonsSeconds = 0.0; ///< the posts' horizons (HorizonMap), skies and sun proofs
  int horizonAzimuths = 0;      ///< the azimuths of the map the posts' skies came from (0: none)
  /// Posts whose horizons a coarse map missing their target found toward 32 azimuths
  /// (every process's), the others' toward 16.
  std::size_t horizonRefinedPosts = 0;
  double latticeSeconds = 0.0;  ///< the lattice of posts gathered first
  std::uint64_t latticeRays = 0;
};

class PointEvaluator
{
public:
  /// Everything the point values need, in this order: the posts' horizons and skies,
  /// the suns they prove, the leaves' own gather (which becomes the leaves' values), the
  /// lattice of posts. With plan.split each process computes its share and receives
  /// the others': every process must then build one. While it lives, the leaves hold
  /// the values gathered at them (what averaged outputs and the leaf mesh show); it
  /// must not outlive the solve (`solved` solving again or changing its sources).
  PointEvaluator(HierarchicalRadiosity& solved, const EvaluationPlan& plan);
  ~PointEvaluator();
  PointEvaluator(const PointEvaluator&) = delete;
  PointEvaluator& operator=(const PointEvaluator&) = delete;

  const HierarchicalRadiosity& solver() const { return this->Solver; }
  const EvaluationStatistics& statistics() const { return this->Stats; }

  /// Irradiance by light category at a point of a leaf surface. With final gathers
  /// (MaximumGatherRays > 0) sky and light from surfaces come from rays from the point;
  /// without, every link that reaches the leaf (at any level) is re-evaluated at the
  /// point: exact form factors and visibility sampled from it. Either way values at
  /// vertices are not smeared over the elements around them. The sky view factor needs
  /// a sky (it is 0 without one).
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
  /// Many points at once, in parallel, each moved toward its own centre (see above).
  void irradianceAt(const std::vector<const PolygonElement*>& leaves, const std::vector<Vec3>& points,
    const std::vector<Vec3>& normals, const std::vector<Vec3>& towards, std::vector<PointIrradiance>& results) const;
  /// How open a point's side is where irradianceAt moves it toward `toward`: of the 36
  /// rays its gather first casts from there (openSideOf), those that meet no surface's
  /// back, and those that meet nothing; both -1 without a final gather.
  struct Openness
  {
    int open = -1, sky = -1;
    /// Whether this side is clearly more open than `other` (by more than noise: the
    /// rule openSideOf picks a gather's start by), or unknown (no final gather).
    bool clearlyMoreOpenThan(const Openness& other) const;
  };
  Openness opennessAt(const Vec3& point, const Vec3& normal, const Vec3& toward) const;
  /// Direct sunlight at a point with a unit normal: normal irradiance x cosine, 0 where
  /// the point is shadowed (one ray per sun, or the post's horizons); zero without a
  /// sun. With `sunlitHours`, also the durations of the suns that reach the point.
  Spectrum directSunAt(const Vec3& point, const Vec3& normal, double* sunlitHours = nullptr) const;

private:
  // The phases, in the constructor's order.
  /// The horizons of every post of the one height-field terrain under a sky (HorizonMap)
  /// and each post's sky (PostSky) at the normals the outputs use.
  void findPostHorizons(bool hornNormals);
  /// The suns each post's horizons prove seen or hidden (PostSunlight); direct sun casts
  /// rays only for the rest. Builds the map from Tuning::sunsForHorizonMap suns on.
  void findSunHorizons();
  /// What every leaf receives from the sky and from surfaces, gathered from the leaf
  /// (LeafLight); terrain leaves only when `terrains` and no post reads its own sky.
  void gatherLeaves(bool terrains);
  /// A lattice of the terrain's posts gathered first (PostLattice), so that the others
  /// read from it or take their ray count from its spread.
  void gatherPostLattice(const TerrainPatch& root, bool hornNormals);
  /// irradianceAt's; with `gathered`, also what its final gather found (a lattice
  /// post's light from surfaces by sector; untouched where it takes none).
  PointIrradiance evaluate(const PolygonElement& leaf, const Vec3& point, const Vec3& normal, const Vec3& toward,
    GatheredLight* gathered) const;
  /// The gather over what the phases so far have found (each phase's gathers read the
  /// earlier phases' results).
  std::unique_ptr<FinalGather> makeGather() const;

  /// Whether points take a final gather: rays to cast and something for them to see (a
  /// sky, or surfaces that send light).
  bool gathersAtPoints() const;
  /// The horizon map's azimuths: dense for many suns, coarse at the speed knob's coarse
  /// end (Tuning::coarseHorizonsTarget), else standard (which findPostHorizons narrows
  /// to coarse where that serves every post, or refines at the few it misses:
  /// coarseSkyMisses).
  HorizonMap::Density horizonDensity() const;
  /// PostHorizons toward `density` (the geometry's map; `exactly` that density, not a
  /// finer one built before) and Horizons over it.
  void takeHorizons(HorizonMap::Density density, bool exactly = false);
  /// The share of the posts of the grid's lattice of `stride` posts (1: every post)
  /// whose sky from a coarse PostHorizons errs beyond their target (their sky at least
  /// what they receive), by a share of the sky it hides or, where that misses, by its
  /// band between azimuths; with a split, of every process's. `missed`, where given: a
  /// flag per post of this process's window, set where it misses; and the bands found
  /// kept (BetweenAzimuths).
  double coarseSkyMisses(bool hornNormals, int stride, std::vector<std::uint8_t>* missed = nullptr);
  /// The error estimate's part for the sky a point receives: the open sky's own error
  /// (Tuning::openSkyError) and, at a post whose sky comes from its horizons rather
  /// than from rays (no post), a share of the sky they hide from the plane at `normal`
  /// (Tuning::horizonSkyError), or where they are interpolated between a coarse map's
  /// 16 azimuths, coarseHorizonSkyError of it or betweenAzimuthsError times the band
  /// found between them.
  double skyError(const Vec3& normal, const Spectrum& sky, const HorizonMap::Post& post) const;
  /// Where a point's gather starts ("just above" it): `inside` (the point moved into its
  /// leaf) unless that sees the back of a surface, then the most open of four points two
  /// ray offsets from it diagonally in its plane, if clearly more open (the reference's
  /// rule, Testing/Reference): a post on the line of a house's wall is judged from
  /// outside the house, not from its dark inside.
  Vec3 openSideOf(const Vec3& point, const Vec3& inside, const Vec3& normal, std::uint64_t seed) const;
  /// A point moved two ray offsets toward `toward` (at most half way): inside its leaf.
  Vec3 movedInside(const Vec3& point, const Vec3& toward) const;
  /// The seed of a point's gather: its rays belong to the point alone, so that two
  /// discretisations of one surface (terrain patches, triangles) cast the same rays.
  std::uint64_t gatherSeedOf(const Vec3& point) const;
  /// The lattice's posts of one pass this process gathers (its share where the work is
  /// split).
  void gatherLatticePosts(const TerrainPatch& root, bool hornNormals, bool firstPass, PostLattice& lattice) const;
  /// The shares of the terrain a post sees in each part of its view (summing to 1;
  /// even where its horizons show none; HorizonSky::terrainByPart): what its read
  /// weighs the lattice's by.
  PerViewPart<double> terrainSharesAt(const HorizonMap::Post& post, const Vec3& normal, bool nearAndFar) const;
  /// Post (i, j), between gathered lattice posts that agree on the radiosity of the
  /// terrain they see, takes its light from surfaces from them and its sky from its
  /// horizons, without a gather: true, with `result` (its sun already in it) filled.
  /// A post inside the terrain never reads from a corner on its edge (Around::edgeCorner).
  bool readFromLattice(const HorizonMap::Post& post, const Vec3& normal, int i, int j,
    const PostLattice::Around& around, PointIrradiance& result) const;

  HierarchicalRadiosity& Solver;
  const RadiosityOptions& Options;
  const Visibility& Rays;      // the hierarchy's: seeds and offsets
  const Visibility& PointRays; // the points' (SceneGeometry::pointRays)
  const TerrainGrid* HeightFieldGrid; // the one terrain of a height field, else null
  const WorkSplit* Split;      // the processes sharing the work (none for a window)
  int PostsHalo = -1;          // HeldPosts::haloFor the detail distance, with a split
  EvaluationStatistics Stats;
  std::unique_ptr<OpenSky> SkyAtPoints;     // the sky, for points' planes
  std::unique_ptr<HorizonSky> Horizons;     // the sky a height field's horizons hide
  const HorizonMap* PostHorizons = nullptr; // its posts' horizons: the geometry's, or RefinedHorizons
  std::unique_ptr<HorizonMap> RefinedHorizons; // a coarse map refined at the posts it missed
  const HorizonMap* ProofHorizons = nullptr; // the geometry's map: every post's horizons prove sights
  const HorizonMap* SunHorizons = nullptr;  // that map, for direct sun
  struct MappedSun // each of the solver's suns on that map
  {
    HorizonMap::Sight sight;
    Vec3 direction;
    Spectrum flux;
    double duration;
  };
  std::vector<MappedSun> MappedSuns;
  std::unique_ptr<PostSky> PostSkies;     // the sky each post receives
  /// Per post of this process's window, the band between a coarse map's azimuths
  /// (W/m^2, largest band) where coarseSkyMisses found it; -1 elsewhere.
  std::vector<float> BetweenAzimuths;
  std::unique_ptr<PostSunlight> PostSuns; // the suns they prove seen or hidden
  std::unique_ptr<LeafLight> Leaves;      // what leaves receive, gathered
  std::unique_ptr<PostLattice> Lattice;   // posts gathered first
  std::unique_ptr<FinalGather> Gather;    // over all of the above
  struct ReplacedLeaf // the hierarchy's values of a leaf gatherLeaves replaced
  {
    PolygonElement* leaf;
    Spectrum sky, reflected, radiosity;
  };
  std::vector<ReplacedLeaf> Replaced;
  // The relative error of the light from surfaces gather hits read: the hierarchy's
  // measured deficit through the bounces gathered above it (HierarchyDeficit::after).
  double ReadRelativeError = 0.0;
};
} // namespace terralux
