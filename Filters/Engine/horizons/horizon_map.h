#pragma once
// The horizon of every post of a height-field terrain grid toward 32 azimuths (16 or
// 64), found for all posts at once (a scene of one terrain: several grids would hide
// each other). Toward an azimuth whose step in the grid is a whole number of posts, g =
// (q, p) (slopes 0, 1/5, 2/5, 2/3, 1 and their mirrors: azimuths 10.5 to 11.9 deg apart
// on square cells; coarse, 0, 2/5 and 1; dense, also 1/9, 1/3, 1/2, 3/4: 3.2 to 8.1 deg
// apart), the posts lie on lines that repeat g, and the terrain along a line is linear
// between its crossings of cell edges and diagonals, whose pattern is the same on every
// step. Swept from its far end, a line keeps the
// upper convex hull of the crossings ahead; the horizon of each post is its tangent to
// that hull (Dozier, Bruno & Downey 1981; Stewart 1998 for the sectors): amortised
// constant work per crossing, a few per post and azimuth, instead of a search per post.
// The horizons are those of the grid's own triangles, as rays see them, at the post
// itself. Each line is placed by the grid's mean map from parameters to positions: on
// a grid bent by the Earth's curvature its azimuth is the mean one, to a small fraction
// of a degree.

#include "base/angles.h"
#include "hierarchy/radiosity_types.h"
#include "base/uninitialized_vector.h"
#include "parallel/work_split.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace terralux
{
class TerrainGrid;

class HorizonMap
{
public:
  /// How many azimuths a map holds. Standard, 32: slopes 0, 1/5, 2/5, 2/3 and 1 in each
  /// octant. Coarse, 16 (the speed knob's coarse end, Tuning::coarseHorizonsTarget):
  /// slopes 0, 2/5 and 1, 21.8 to 23.2 deg apart; half the sweep and the posts' skies,
  /// the sky between azimuths about 2.5 times less exact (Tuning::coarseHorizonSkyError).
  /// Dense, 64, for many suns (a year of hours): about half as far from a sun's bearing
  /// to the nearest mapped azimuth, so fewer suns near a post's horizon need a ray (a
  /// year's on the 1025^2 fractal: 449 M rays instead of 679 M), for 2.4 times the
  /// sweep's work.
  enum class Density
  {
    Coarse = 16,
    Standard = 32,
    Dense = 64
  };
  /// Every density, fewest azimuths first.
  static constexpr std::array<Density, 3> densities{ Density::Coarse, Density::Standard, Density::Dense };
  /// A grid whose cells all face up (TerrainGrid::facesUp), alone in its scene; it
  /// must outlive this.
  /// `split`: processes that build the map together (null: this one alone), each
  /// keeping the horizons of its own window of posts only (holds). Where the split
  /// sends point to point, each sweeps its window's stretch of every line and hands
  /// the hull it reaches to the window the line enters next (horizon_handoff.cxx);
  /// else each sweeps a share of the azimuths over the whole grid and broadcasts it.
  /// Either way every held horizon is one process's, bit for bit.
  /// `lender`: another map of the same terrain and split (or null), whose sweeps
  /// toward the azimuths both hold this one copies instead of sweeping them again (the
  /// coarse azimuths are every other standard one); the map is the same, bit for bit.
  explicit HorizonMap(const TerrainGrid& terrain, Density density = Density::Standard,
    const WorkSplit* split = nullptr, const HorizonMap* lender = nullptr);
  /// The horizons of a window of a terrain whose far terrain is given (a process's
  /// piece and halo; RadiosityScene::farTerrain), as its rays see them (Visibility):
  /// the window's own triangles within `detailDistance` of the post (horizontally),
  /// the far terrain beyond, and where the far surface stands above a sight at that
  /// distance. Each horizon is a function of the terrain within detailDistance of its
  /// post and of the far terrain alone, so overlapping windows agree on the posts
  /// they share, bit for bit, as long as each holds detailDistance of terrain around
  /// them (posts nearer its edge see it cut short). The azimuths are those of the far
  /// terrain's mean map, the same on every window; proofs bound both surfaces.
  HorizonMap(const TerrainGrid& window, const GivenFarTerrain& far, double detailDistance,
    Density density = Density::Standard, const HorizonMap* lender = nullptr);
  /// The standard map of `coarse`'s posts, refined at chosen posts only: its coarse
  /// azimuths copied, the others found at the posts `exact` flags (one flag per held
  /// post, in the map's order) by walking each line from the post out as far as the
  /// terrain can still rise above the horizon found (horizon_refinement.cxx), and
  /// interpolated between the coarse azimuths elsewhere. Where the coarse sky misses
  /// the target of a few posts (rough terrain), those take the standard sky for a walk
  /// each instead of 16 more sweeps of the whole grid. Only exact posts' horizons prove
  /// sights (View); the others' prove nothing.
  HorizonMap(const HorizonMap& coarse, const std::vector<std::uint8_t>& exact);
  static constexpr int maximumAzimuths = static_cast<int>(Density::Dense);
  int azimuthCount() const { return static_cast<int>(this->Azimuths.size()); }
  /// Whether the map of `terrain` fits the 2 GiB it may take (2 bytes a post and
  /// azimuth: grids up to about 5,800^2 posts at 32 azimuths, 4,100^2 at 64); beyond,
  /// posts keep the rays' horizons.
  static bool fits(const TerrainGrid& terrain, Density density = Density::Standard);

  /// A post of the grid.
  struct Post
  {
    bool found = false;
    std::size_t index = 0; ///< j * postsX + i
    explicit operator bool() const { return this->found; }
  };
  /// The post at `point` (within a hundredth of a cell) whose horizons the map holds,
  /// or none.
  Post find(const Vec3& point) const;
  /// Whether the map holds the horizons of post (i, j): every post, or with a split
  /// this process's window.
  bool holds(int i, int j) const { return this->Held.holds(i, j); }
  /// Whether a held post's horizons are all found (none interpolated: every post but
  /// in a map refined at chosen posts).
  bool exactAt(std::size_t cell) const { return this->Exact.empty() || this->Exact[cell] != 0; }
  /// The posts a refined map found exact (of those this process holds); 0 otherwise.
  std::size_t refinedPosts() const { return this->RefinedPosts; }

  /// The azimuths: radians counter-clockwise from +x, increasing, in [0, 2 pi).
  const std::vector<double>& azimuths() const { return this->Azimuths; }
  /// The horizon's elevation at a post toward azimuth a (radians, 0 where nothing
  /// rises above the horizontal), to 2.4e-5 rad.
  double elevation(const Post& post, int a) const { return this->elevationAt(this->cellOf(post), a); }
  /// The same as it lies: below the horizontal where the terrain ahead falls away,
  /// -pi/2 where none lies ahead (the DEM's edge or missing data beyond the post).
  double trueElevation(const Post& post, int a) const { return this->trueElevationAt(this->cellOf(post), a); }
  /// The mean distance between neighbouring posts (m), by the mean map.
  double postSpacing() const;
  /// tan of the highest elevation, seen from `post`, of the terrain toward azimuth a
  /// within `distance` (m, horizontally): the grid's triangles sampled every post
  /// spacing, up to the grid's edge or a missing cell, or until one reaches `enough`;
  /// -inf where none is sampled.
  double nearTangent(const Post& post, int a, double distance, double enough) const;
  /// Where a post's horizons lie in the map (its window's order), for elevationAt.
  std::size_t cellOf(const Post& post) const
  {
    if (this->HoldsAll)
      return post.index;
    const std::size_t nx = this->postsX(), i = post.index % nx, j = post.index / nx;
    return (j - this->Held.j0) * this->HeldX + (i - this->Held.i0);
  }
  double elevationAt(std::size_t cell, int a) const { return std::max(0.0, this->trueElevationAt(cell, a)); }
  double trueElevationAt(std::size_t cell, int a) const { return elevationOfCode(this->Elevations[a * this->HeldCount + cell]); }
  /// Elevations as the map keeps them: -pi/2 to pi/2 in steps of pi/2 / codeSteps
  /// (4.8e-5 rad), rounded to the nearest; the horizontal is horizontalCode, the nadir
  /// horizontalCode - codeSteps.
  static constexpr std::uint16_t horizontalCode = 32768;
  static constexpr int codeSteps = 32767;
  static double elevationOfCode(std::uint16_t code)
  {
    return (static_cast<int>(code) - static_cast<int>(horizontalCode)) * (0.5 * pi / codeSteps);
  }
  /// The code of a horizon's tangent (-inf: nothing ahead, the nadir's).
  static std::uint16_t codeOfTangent(double tangent);

  /// A direction between two of the map's azimuths: the one below it (k) and how far
  /// it lies from it and from the next (radians).
  struct Bearing
  {
    int k = 0;
    double fromBelow = 0.0, toAbove = 0.0;
  };
  Bearing bearing(double azimuth) const;
  /// A direction to test at many posts (a sun over a day or a year), with what the
  /// proofs below take from it found once.
  struct Sight
  {
    Bearing bearing;
    double elevation = 0.0;        ///< radians
    double chordBelow = 0.0, chordAbove = 0.0; ///< 2 sin(turn / 2) to the mapped azimuths
    double tanWithMargin = 0.0;    ///< tan(elevation + margin); +inf at or past the zenith
    double tanLessMargin = 0.0;    ///< tan(elevation - margin); -inf at or below the nadir
  };
  Sight sight(double azimuth, double elevation) const;

  /// One post's horizons, read from the map as the proofs need them, for many sights.
  /// Proofs hold only for grids without missing cells (complete(); holes have no such
  /// bound); elsewhere they prove nothing. Not shared between threads.
  class View
  {
  public:
    View(const HorizonMap& map, const Post& post);
    /// Whether the terrain's own triangles (what rays meet) leave the sight open from
    /// the post, proven with a margin for the map's quantisation and mean directions;
    /// false where only a ray can tell. The bounds (Lipschitz, as horizon sectors are
    /// bounded; Stewart 1998): a point Q at distance r along the sight lies within the
    /// chord r 2 sin(da/2) of the point at the same distance along a mapped azimuth, so
    /// no higher than S times that above it (S the steepest triangle's slope; the grid
    /// is convex, so the chord is on it) wherever that azimuth's line still runs on the
    /// grid (r <= its exit distance). The two mapped horizons bound Q up to the shorter
    /// exit distance; beyond it the longer side's, or the highest point of the terrain
    /// seen from there (atan((highest height - z0) / distance)); beyond the longer
    /// (only where a corner of the grid lies within the bracket) that alone.
    bool clearlyAbove(const Sight& sight)
    {
      // The mapped horizons alone first (most suns over a day or a year end here):
      // where they do not prove the sight open, the distances need not be found.
      const int k = sight.bearing.k;
      const double fromBelow = this->elevation(k) + this->Slope * sight.bearing.fromBelow;
      const double fromAbove = this->elevation(this->next(k)) + this->Slope * sight.bearing.toAbove;
      return sight.elevation > std::min(fromBelow, fromAbove) + this->Margin &&
        this->clearPastNeighbours(sight, fromBelow, fromAbove);
    }
    /// Whether they hide the sight, proven from a mapped neighbour's horizon: the
    /// terrain point P that makes horizon H_k lies at some distance d, and the point Q
    /// at the same distance along the sight is at most the chord d 2 sin(da / 2) from
    /// it, so no lower than S times that below it: Q rises above the post at least
    /// atan(tan H_k - 2 S sin(da / 2)), and a ray below Q's elevation meets the terrain
    /// before Q. Only where H_k is above the highest point seen from the least exit
    /// distance R over the bracket (so d < R and Q is on the grid), with the same
    /// margin.
    bool clearlyBelow(const Sight& sight);

  private:
    /// Distances R of a bracket k (azimuths k, k + 1), as the tangent of the highest
    /// point's elevation seen from them, rise / R (no angle: compared with a sight's
    /// tangents).
    /// No member initialisers: a View holds one per azimuth, each written when first
    /// asked, and zeroing them all took more than a post's proofs.
    struct Reach
    {
      double shorter;     // the shorter exit distance of the two azimuths (m)
      double pastShorter; // R: that one
      double pastLonger;  // the longer, where a corner lies within; else 0
      double pastLeast;   // the least over the bracket (found when first asked; < 0 until)
      int longer;         // 0: azimuth k, 1: k + 1
    };
    int next(int k) const { return k + 1 == this->Count ? 0 : k + 1; }
    double elevation(int k)
    {
      if (!(this->Read >> k & 1u))
      {
        this->Elevations[k] = static_cast<float>(this->Map.elevationAt(this->Cell, k));
        this->Read |= std::uint64_t{ 1 } << k;
      }
      return this->Elevations[k];
    }
    double tangent(int k);
    bool clearPastNeighbours(const Sight& sight, double fromBelow, double fromAbove);
    Reach& reach(int k);
    double pastLeast(int k);
    const HorizonMap& Map;
    std::size_t Cell; // where the map keeps the post's horizons
    int I, J;         // the post's grid indices
    int Count;
    double Margin; // proofMargin(), or +inf where the map proves nothing
    double Slope;  // S around the post
    std::array<float, maximumAzimuths> Elevations, Tangents;
    std::array<Reach, maximumAzimuths> Reaches;
    std::uint64_t Read = 0, Tangent = 0, Reached = 0; // bit k: found
  };
  /// Whether every cell of the grid is valid (clearlyAbove and clearlyBelow need it).
  bool complete() const { return this->Complete; }
  /// The steepest slope (tan) of the triangles that bound post (i, j)'s sights: S
  /// above. The grid's steepest; in a window's map, the steepest within the detail
  /// distance of the post (a box of posts around it) or of the far terrain, which
  /// windows holding that box agree on.
  double slopeAt(int i, int j) const
  {
    return this->LocalSlope.empty() ? this->SteepestSlope : this->LocalSlope[this->localIndex(i, j)];
  }
  /// The highest point that can rise in post (i, j)'s sights past an exit distance:
  /// the grid's highest; in a window's map, the highest within the detail distance of
  /// the post or of the far terrain.
  double highestAt(int i, int j) const
  {
    return this->LocalHighest.empty() ? this->HighestZ : this->LocalHighest[this->localIndex(i, j)];
  }

private:
  /// The map's azimuths from its mean map; the steps of the slots, in order (SlotSteps).
  const std::vector<std::array<int, 2>>& placeAzimuths(Density density);
  /// The slots whose step `lender` holds (LentSlot), which the sweeps skip; then
  /// copyFromLender fills them once the map is sized.
  void findCopiedSlots(const HorizonMap* lender);
  void copyFromLender(const HorizonMap* lender);
  bool copied(std::size_t slot) const { return !this->LentSlot.empty() && this->LentSlot[slot] >= 0; }
  /// Takes the copied slots out of a sweep's schedule of slots.
  void dropCopiedSlots(std::vector<std::size_t>& schedule) const;
  std::vector<std::array<int, 2>> SlotSteps;
  std::vector<int> LentSlot; // per slot, the lender map's slot it copies, or -1: swept
  /// Sizes the map to the posts of Held.
  void holdPosts();
  void fitMeanMap(const TerrainGrid& grid);
  /// A point of a line's profile: distance along the azimuth, height (m).
  struct HullPoint
  {
    double x, z;
  };
  /// A post as a sweep sees it: its distance along the azimuth and its height.
  struct ProfilePost
  {
    double x;
    float z;
  };
  /// The upper convex hull of a line's profile ahead of a post, the nearest point last.
  using Hull = std::vector<HullPoint>;
  struct HullStack; // the sweep's working copy of a hull (horizon_map.cxx)
  /// The stretch of a line inside a window: posts (i, j) + k g for k < count, swept from
  /// k = count - 1 down, `ahead` the hull of the line beyond it (null: none, or what
  /// the sweep reads from the grid). After post k = captures[n].k it copies its hull to
  /// captured[captures[n].slot], for n from firstCapture, in decreasing k.
  struct LineRun
  {
    int i = 0, j = 0, count = 0;
    const Hull* ahead = nullptr;
    std::size_t firstCapture = 0, captureCount = 0;
  };
  struct Capture
  {
    int k;
    std::size_t slot;
  };
  /// The stretches of the lines of step (q, p) inside `window`, in grid order of their
  /// nearest posts.
  static std::vector<LineRun> runsWithin(int q, int p, const WorkSplit::Window& window);
  /// One azimuth's horizons at the posts of `runs`, into `out`, the posts of `window`
  /// in grid order (the runs write each post of it once).
  void sweep(int q, int p, const std::vector<LineRun>& runs, const WorkSplit::Window& window, std::uint16_t* out,
    const std::vector<Capture>& captures = {}, std::vector<Hull>* captured = nullptr);
  /// The same at every post of the grid.
  void sweepWholeGrid(int q, int p, std::uint16_t* out);
  /// The posts as the sweep under way sees them, kept from one sweep to the next (they
  /// run one at a time) rather than allocated for each; emptied once the map is built.
  UninitializedVector<ProfilePost> SweepProfile;
  /// One post's horizon toward step (q, p) found alone, along its line from the post
  /// out (the sweep's profile, the same value), as its tangent where above the
  /// horizontal (0 elsewhere: the walk ends where nothing can rise above it): a refined
  /// map's exact posts.
  struct LineWalk;
  double walkedTangent(int i, int j, const LineWalk& line) const;
  /// A window's horizons toward step (q, p), at every post of its grid
  /// (horizon_window.cxx).
  void sweepWindow(int q, int p, const GivenFarTerrain& far, double detailDistance, std::uint16_t* out) const;
  /// The split's two ways (horizon_handoff.cxx): each process sweeps its window and
  /// hands hulls on along the lines; or each sweeps a share of the azimuths at every
  /// post and broadcasts it.
  void sweepWindows(const std::vector<std::array<int, 2>>& slotSteps, const WorkSplit& split);
  void sweepSharedAzimuths(const std::vector<std::array<int, 2>>& slotSteps, const WorkSplit& split);
  std::size_t postsX() const;

  const TerrainGrid& Terrain;
  /// The mean affine map from parameters to xy: x = X0 + Ux u + Vx v, and so on.
  double X0 = 0.0, Y0 = 0.0, Ux = 1.0, Uy = 0.0, Vx = 0.0, Vy = 1.0;
  bool Complete = true; ///< no missing cells (from fitMeanMap)
  double SteepestSlope = 0.0, HighestZ = 0.0; // of the valid cells
  /// A window's: slopeAt and highestAt of each post (horizon_window.cxx), and the
  /// slope its margin takes (the far terrain's, the same in every window).
  std::vector<float> LocalSlope, LocalHighest;
  double MarginSlope = 0.0;
  std::size_t localIndex(int i, int j) const { return static_cast<std::size_t>(j) * this->postsX() + i; }
  void findLocalRelief(const TerrainGrid& far, double detailDistance);
  /// Where the terrain the sights pass over ends, in the map's post parameters: the
  /// grid's own edges, or a window's far terrain's.
  double ExtentU0 = 0.0, ExtentU1 = 0.0, ExtentV0 = 0.0, ExtentV1 = 0.0;
  // Toward the edges u = 0, u = max, v = 0, v = max: the azimuth of the shortest way.
  std::array<double, 4> EdgeAzimuths{};
  double edgeDistance(int i, int j, int edge) const;
  /// Distance from post (i, j) to the grid's edge along map azimuth k.
  double exitDistance(int i, int j, int k) const;
  /// tan of the elevation of the grid's highest point seen from post (i, j) at a
  /// distance: 0 where nothing rises above the post, +inf at no distance.
  double riseOver(int i, int j, double distance) const;
  /// Whether one of the grid's corners seen from post (i, j) lies strictly between
  /// azimuths k and k + 1 (where the exit distance can exceed both ends'): brackets
  /// are narrower than pi, so by the signs of two cross products.
  bool cornerWithin(int i, int j, int k) const;
  static std::array<double, 2> reliefOf(const TerrainGrid& grid); // the steepest slope, the highest point
  /// tan of a triangle's slope; 0 where it does not face up.
  static double triangleSlope(const std::array<Vec3, 3>& triangle);
  /// SteepestSlope and HighestZ over the grid; EdgeAzimuths.
  void measureRelief();
  /// EdgeAzimuths, from the mean map.
  void placeEdges();
  /// What clearlyAbove and clearlyBelow allow for the map's quantisation and mean directions.
  double proofMargin() const { return 1e-3 + 2e-3 * this->MarginSlope; }
  std::vector<double> Azimuths;
  /// A metre along each azimuth in grid parameters (the mean map inverted).
  std::vector<std::array<double, 2>> AzimuthSteps;
  std::vector<std::array<double, 2>> AzimuthDirections; // (cos, sin) of each
  /// Azimuth by azimuth, the held posts in order; codeOfTangent's.
  UninitializedVector<std::uint16_t> Elevations; // every value written by a sweep or a share
  std::size_t PostCount = 0;
  /// A refined map's held posts whose horizons are all found (empty: every post).
  std::vector<std::uint8_t> Exact;
  std::size_t RefinedPosts = 0;
  WorkSplit::Window Held; // the posts whose horizons are kept
  std::size_t HeldX = 0, HeldCount = 0;
  bool HoldsAll = true;
};
} // namespace terralux
