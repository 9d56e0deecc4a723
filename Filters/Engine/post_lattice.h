#pragma once
// A coarse lattice of a terrain's posts (every `step` posts each way), gathered before
// the others. What it learns serves the rest in two ways:
// - Light from surfaces: a ray's hit sends its reflectance times what it receives; the
//   light it receives from other surfaces is, from its leaf, the hierarchy's, which
//   misses the many small exchanges inside rough terrain (issue: about half of them on
//   a steep fractal DEM). Read between the lattice's gathered posts instead, a hit's
//   second bounce is as exact as their first.
// - Rays: a post's gather takes as many rays as a pilot of its own says are needed. The
//   lattice's posts tell their neighbours the spread of one ray's estimate instead (the
//   largest at a corner of the lattice cell: neighbours see much the same terrain),
//   from which each post sets its count against its own irradiance, with no pilot.
//   The count comes from other posts' rays, not from the post's own, so its estimate
//   stays unbiased.

#include "radiosity_types.h"
#include "work_split.h"

#include <array>
#include <vector>

namespace terralux
{
class PostLattice
{
public:
  static constexpr int defaultStep = 4;
  PostLattice(int postsX, int postsY, int step = defaultStep);

  int step() const { return this->Step; }
  bool onLattice(int i, int j) const { return i % this->Step == 0 && j % this->Step == 0; }
  /// What a lattice post's gather found beyond the sky of its horizons.
  struct Gathered
  {
    Spectrum reflected{};          ///< light from surfaces
    Spectrum skyCorrection{};      ///< sky its rays found where the interpolated horizon was wrong
    double skyViewCorrection = 0.0;
    double variance = 0.0;         ///< of one ray's estimate
    double terrainSeen = 0.0;      ///< 1 - its horizons' sky view factor
  };
  /// Records a lattice post's gather (from any thread, each post once).
  void set(int i, int j, const Gathered& gathered);
  /// With `split`, whether this process gathers lattice post (i, j): those of its
  /// window; and, once each has gathered its own, every window's received from its
  /// process.
  static bool gathers(int i, int j, const WorkSplit* split)
  {
    return !split || split->window(split->part()).holds(i, j);
  }
  void share(const WorkSplit& split);

  /// The largest variance at a corner of the lattice cell holding post (i, j); -1
  /// where none is known.
  double varianceAround(int i, int j) const { return this->around(i, j).variance; }
  /// What the gathered corners of the lattice cell holding post (i, j) found: the
  /// largest variance (-1 where none was gathered), and the largest and least light
  /// beyond their horizons' sky per terrain seen (largest band; see perTerrainSeenAt).
  struct Around
  {
    double variance = -1.0;
    double largestPerTerrainSeen = 0.0;
    double leastPerTerrainSeen = 0.0;
  };
  Around around(int i, int j) const;
  /// Light from surfaces at grid parameters (u, v), bilinear between the lattice's
  /// posts; false where none around holds a value.
  bool reflectedAt(double u, double v, Spectrum& reflected) const;
  /// What the lattice's posts found beyond their horizons' sky (light from surfaces,
  /// the sky's corrections), each over the part of their hemisphere that is terrain (1 -
  /// sky view factor), bilinear between them at grid parameters (u, v): a post there
  /// that sees terrainSeen of terrain receives about terrainSeen times this. False where
  /// none around holds a value.
  struct PerTerrainSeen
  {
    Spectrum reflected{};
    Spectrum skyCorrection{};
    double skyViewCorrection = 0.0;
  };
  bool perTerrainSeenAt(double u, double v, PerTerrainSeen& value) const;

private:
  std::size_t index(int li, int lj) const { return static_cast<std::size_t>(lj) * this->Nx + li; }
  // Per lattice post, over terrain seen: reflected, sky correction (maxBands each), sky
  // view correction.
  using Scaled = std::array<double, 2 * maxBands + 1>;

  int Step, Nx, Ny; // lattice posts each way
  std::vector<Spectrum> Reflected;
  std::vector<double> Variance; // -1: not gathered (no data there)
  std::vector<Scaled> PerTerrain;
};
} // namespace terralux
