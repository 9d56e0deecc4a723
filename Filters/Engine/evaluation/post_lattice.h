#pragma once
// A coarse lattice of a terrain's posts (every `step` posts each way), gathered before
// the others. What it learns serves the rest in two ways:
// - Light from surfaces: a ray's hit sends its reflectance times what it receives; the
//   light it receives from other surfaces is, from its leaf, the hierarchy's, which
//   misses the many small exchanges inside rough terrain (issue: about half of them on
//   a steep fractal DEM). Read between the lattice's gathered posts instead, a hit's
//   second bounce is as exact as their first. A post that reads its own light from
//   surfaces reads it by the parts of its view it sees terrain in (view_sectors.h).
// - Rays: a post's gather takes as many rays as a pilot of its own says are needed. The
//   lattice's posts tell their neighbours the spread of one ray's estimate instead (the
//   largest at a corner of the lattice cell: neighbours see much the same terrain),
//   from which each post sets its count against its own irradiance, with no pilot.
//   The count comes from other posts' rays, not from the post's own, so its estimate
//   stays unbiased.
// Its posts are gathered in two passes: every second one each way first (a cell of
// 2 step posts), then the others only in the cells whose corners disagree (refine):
// where terrain is smooth per post the first pass tells enough, and the 4097^2 fractal's
// lattice took a quarter of the rays. A post reads between the corners of the finest
// cell gathered around it.
// With a work split and a detail distance, a process holds the lattice posts of its
// window and its halo only (HeldPosts): gather rays read the lattice at hits within the
// detail distance, and refine decides the cells whose corners it holds.

#include "parallel/held_posts.h"
#include "hierarchy/radiosity_types.h"
#include "parallel/work_split.h"
#include "terrain/view_sectors.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace terralux
{
class PostLattice
{
public:
  static constexpr int defaultStep = 4;
  /// How far from a post, in posts, the lattice posts its reads weigh can lie: the 4 x
  /// 4 around it (widerCornersAt) on the coarse lattice, two of its cells.
  static constexpr int readReach = 4 * defaultStep;
  /// With `split` and a `postsHalo` >= 0 (HeldPosts::haloFor a detail distance), the
  /// lattice posts within that many posts of this process's window, and the margin its
  /// cells read; every lattice post otherwise.
  PostLattice(int postsX, int postsY, int step = defaultStep, const WorkSplit* split = nullptr, int postsHalo = -1);

  int step() const { return this->Step; }
  bool onLattice(int i, int j) const { return i % this->Step == 0 && j % this->Step == 0; }
  /// Whether lattice post (i, j) is gathered in the first pass (`first`), or in the
  /// second, after refine: a corner of a cell of a refined coarse cell, not gathered
  /// in the first.
  bool gatheredInPass(int i, int j, bool first) const;
  /// After the first pass (and its share): the coarse cells to refine, those where a
  /// corner's spread of what the corners found per terrain seen exceeds
  /// `allowedSpread` x what that corner receives (at least `allowedFloor`, W/m^2), or
  /// where a corner has no data; and the cells at the lattice's far edges, which have no
  /// coarse corners there. Cells with a corner this process does not hold stay
  /// undecided (a read there throws).
  void refine(double allowedSpread, double allowedFloor = 0.0);
  /// What a lattice post's gather found: the light from surfaces below its horizons.
  struct Gathered
  {
    Spectrum reflected{};          ///< light from surfaces
    double variance = 0.0;         ///< of one ray's estimate
    double terrainSeen = 0.0;      ///< PostSky::Value::terrainSeen(), from its horizons
    double voidSeen = 0.0;         ///< PostSky::Value::voidViewFactor
    /// The light from surfaces by the part of the view it comes from
    /// (GatheredLight::surfacesByPart), and the view factor of the terrain its rays met
    /// there (GatheredLight::surfacesSeenByPart): their ratio is the mean radiosity its
    /// rays met in that part, bounded whatever its horizons show there.
    PerViewPart<Spectrum> reflectedByPart{};
    PerViewPart<double> terrainByPart{};
    double received = 0.0;         ///< from the sun and its horizons' sky (largest bands)
    bool edge = false;             ///< on the terrain's edge (see Around::edgeCorner)
  };
  /// Records a lattice post's gather (from any thread, each post once).
  void set(int i, int j, const Gathered& gathered);
  /// With `split`, whether this process gathers lattice post (i, j): those of its
  /// window; and, once each has gathered its own, share receives those it holds of the
  /// others' windows from their processes.
  static bool gathers(int i, int j, const WorkSplit* split)
  {
    return !split || split->window(split->part()).holds(i, j);
  }
  void share();

  /// The largest variance at a corner of the lattice cell holding post (i, j) (the
  /// finest gathered there, as for every reading below); -1 where none is known.
  double varianceAround(int i, int j) const { return this->around(i, j).variance; }
  /// What the gathered corners of the lattice cell holding post (i, j) found: the
  /// largest variance (-1 where none was gathered), and the largest and least light
  /// from surfaces per terrain seen (largest band; see perTerrainSeenAt), over the
  /// corners that see terrain (both 0 where none does); and whether a gathered corner
  /// lies on the terrain's edge (the grid's border, or beside missing data): it sees
  /// terrain on one side only, so per terrain seen it tells little of the posts inside.
  struct Around
  {
    double variance = -1.0;
    double largestPerTerrainSeen = 0.0;
    double leastPerTerrainSeen = 0.0;
    /// The width of the corners' light per terrain seen (largest band) across the
    /// parts of their views they met terrain in: a post's read by part (readByPart)
    /// and its whole's differ by at most its terrain seen times this.
    double partWidth = 0.0;
    /// The same across the sectors of their views (both parts of each together): how
    /// much which way a post sees its terrain can matter.
    double sectorWidth = 0.0;
    /// The largest difference between a corner's near and far parts of a sector (where
    /// it met terrain in both): how much how far a post sees its terrain can matter. A
    /// read by sector and by part differ by at most the post's terrain seen times this.
    double distanceWidth = 0.0;
    bool edgeCorner = false;
  };
  Around around(int i, int j) const;
  /// Light from surfaces at grid parameters (u, v), bilinear between the lattice's
  /// posts; false where none around holds a value.
  bool reflectedAt(double u, double v, Spectrum& reflected) const;
  /// How much more terrain a post at grid parameters (u, v) that sees `terrainSeen`
  /// and `voidSeen` by its horizons (PostSky::Value) sees by them than rays meet. The
  /// lattice's light per terrain seen is per terrain its rays met, and the map counts a
  /// little more, most of it per unit of void: a read would spread the light over that
  /// excess too, most where a post sees little terrain and much void (a ridge's). The
  /// lattice's posts around (4 x 4, as far parts) tell their excess per unit of their
  /// own terrain seen and void, the void weighing excessVoidWeight times as much.
  /// False where no lattice post around holds a value.
  bool mapExcessAt(double u, double v, double terrainSeen, double voidSeen, double& excess) const;
  /// How much more of the map's excess over the rays a unit of void holds than a unit
  /// of terrain seen (fitted over the report's terrain scenes, docs/tuning.md).
  static constexpr double excessVoidWeight = 4.0;
  /// The light from surfaces the lattice's posts found over the terrain their rays
  /// met, both bilinear between them at grid parameters (u, v): a post there that sees
  /// terrainSeen of terrain receives about terrainSeen times this. False where none
  /// around holds a value or sees terrain.
  bool perTerrainSeenAt(double u, double v, Spectrum& reflected) const;
  /// What a post that sees `shares` of its terrain in each part of its view (summing
  /// to 1; HorizonSky::terrainByPart) reads: each part's light per terrain seen (the
  /// corners' sums of light over their sums of terrain met there, the far parts' over
  /// 4 x 4 lattice posts; a part where none met terrain takes its sector's, else the
  /// whole's) weighed by its share; without `byDistance`, each sector's (both parts
  /// together) by its share of both. Also the whole's, as perTerrainSeenAt; and what
  /// the first may err by, as Around's spread for the whole: in each part (or sector)
  /// the spread of the corners' light per terrain seen there (largest band), weighed
  /// by its share. False where perTerrainSeenAt is.
  struct PartRead
  {
    Spectrum perTerrainSeen{}, whole{};
    double spread = 0.0;
  };
  bool readByPart(double u, double v, const PerViewPart<double>& shares, bool byDistance, PartRead& read) const;

private:
  /// Where lattice post (li, lj) is in the held values; throws unless held.
  std::size_t index(int li, int lj) const
  {
    this->Held.requireHeld(li, lj, "lattice's light");
    return this->Held.index(li, lj);
  }
  /// The coarse cell (2 x 2 lattice cells) holding lattice cell (li, lj), in Refined;
  /// throws unless held.
  std::size_t coarseCell(int li, int lj) const;
  enum : std::uint8_t
  {
    CellCoarse = 0,
    CellRefined = 1,
    CellUndecided = 2 // a corner is not held here
  };
  /// The cell that grid parameters (u, v) read from: its lowest corner and its side, in
  /// lattice posts (1 in a refined coarse cell, else 2).
  struct Cell
  {
    int li, lj, side;
  };
  Cell cellAt(double u, double v) const;
  /// Calls corner(k) for each corner of `cell` on the lattice (k: its index).
  template <class Corner>
  void forEachCorner(const Cell& cell, const Corner& corner) const;
  /// What the gathered corners of `cell` found (see around).
  Around aroundCell(const Cell& cell) const;
  /// The gathered corners of the cell that grid parameters (u, v) read from, with
  /// their bilinear weights (`total`: their sum); how many (0: none).
  struct WeightedCorner
  {
    std::size_t k;
    double weight;
  };
  int cornersAt(double u, double v, std::array<WeightedCorner, 4>& corners, double& total) const;
  /// The same over the gathered lattice posts within two of its node spacings, with
  /// tent weights (1 - d / 2 each way): 4 x 4 of them.
  int widerCornersAt(double u, double v, std::array<WeightedCorner, 16>& corners, double& total) const;
  /// The lattice grid that grid parameters (u, v) read from (its posts `side` lattice
  /// posts apart) and where they lie in it.
  struct NodeGrid
  {
    int side;
    double x, y;
    int nodesX, nodesY;
  };
  NodeGrid nodeGridAt(double u, double v) const;
  template <class Value, class NodeValue>
  bool interpolate(double u, double v, const NodeValue& nodeValue, Value& result) const;
  double terrainSeen(std::size_t k) const { return this->Found[k][terrainSeenSlot]; }
  /// Whether lattice post k sees enough terrain to tell what terrain sends.
  bool seesTerrain(std::size_t k) const;
  /// Finds Ranges[k] from Found[k].
  void findRanges(std::size_t k);
  // Per lattice post: the light from surfaces it found (maxBands), then the terrain it
  // sees; then the same for each sector of the view (both parts), then for each
  // sector's far part (its near part is the sector's less that): a read by sector
  // touches what it did before the parts.
  static constexpr std::size_t slots = maxBands + 1;
  using Slots = std::array<double, slots>;
  using Beyond = std::array<double, slots * (1 + 2 * viewSectors)>;
  static constexpr std::size_t terrainSeenSlot = maxBands;
  static constexpr std::size_t sectorStart(int q) { return slots * (1 + q); }
  static constexpr std::size_t farStart(int q) { return slots * (1 + viewSectors + q); }
  static constexpr double minimumTerrainSeen = 1e-6;
  /// Light per terrain seen (largest band) of a part's slots, where it saw terrain.
  static double perTerrainSeenIn(const double* part);
  /// Lattice post k's slots of part `part` (view_sectors.h's numbering).
  Slots partOf(std::size_t k, int part) const;
  /// A sector's near part: its slots less its far part's (none where only the far's
  /// rounding is left).
  static Slots nearSlots(const double* sector, const double* far);
  /// The weighted mean of `count` lattice posts' slots from `start`.
  Slots meanOver(const WeightedCorner* corners, int count, double total, std::size_t start) const;

  int Step, Nx, Ny; // lattice posts each way
  int CoarseX, CoarseY; // coarse cells each way
  HeldPosts Held; // the lattice posts this process holds
  WorkSplit::Window HeldCells; // the coarse cells over them
  // Per held lattice post. Variance -1: not gathered (no data there, or not asked for).
  std::vector<double> Variance;
  std::vector<Beyond> Found;
  // The least and largest light per terrain seen (largest band) over the parts of its
  // view where the post met terrain, then over the sectors; then Around::distanceWidth's.
  std::vector<std::array<double, 5>> Ranges;
  std::vector<double> Received;
  // Gathered::terrainSeen less the terrain its rays met; its terrain seen and void as
  // mapExcessAt weighs them.
  std::vector<double> MapExcess, ExcessBasis;
  static double excessBasisOf(double terrainSeen, double voidSeen)
  {
    return std::max(0.0, terrainSeen) + excessVoidWeight * std::max(0.0, voidSeen);
  }
  std::vector<std::uint8_t> Edge; // Gathered::edge
  std::vector<std::uint8_t> Refined; // per coarse cell of HeldCells
};
} // namespace terralux
