#pragma once
// The radiosity engine's tuned constants, in one place. What each one trades, and the
// measurement behind its value, is in docs/tuning.md: change both together.

#include <cstddef>

namespace terralux
{
struct Tuning
{
  // Direct sun at posts (PointEvaluator::findSunHorizons).
  /// Suns from which the horizon map is built to prove suns seen or hidden (~20 rays a post).
  static constexpr std::size_t sunsForHorizonMap = 48;
  /// Suns from which the horizon map is dense: 64 azimuths instead of 32.
  static constexpr std::size_t sunsForDenseHorizons = 1000;
  /// TargetError from which the map is coarse (16 azimuths; fewer suns than above).
  static constexpr double coarseHorizonsTarget = 0.03;

  // The hierarchy at the knob's coarse end.
  /// From coarseHorizonsTarget on, with values evaluated at points, the hierarchy refines
  /// to this times ErrorTolerance: the points gather over the leaves at full resolution,
  /// and a coarse target does not need the finer hierarchy.
  static constexpr double coarseHierarchyFactor = 3.0;
  /// The refinement tolerance of a solve whose values are evaluated at points
  /// (`atPoints`) to `targetError`, for a user's `errorTolerance`.
  static double hierarchyTolerance(double errorTolerance, double targetError, bool atPoints)
  {
    return atPoints && targetError >= coarseHorizonsTarget ? coarseHierarchyFactor * errorTolerance : errorTolerance;
  }

  // The hierarchy's suns (HierarchicalRadiosity::mergeSuns).
  /// Suns beyond which those within mergedSunDegrees of each other are merged into one.
  static constexpr std::size_t maximumSolveSuns = 64;
  static constexpr double mergedSunDegrees = 2.0;

  // The open sky of a point's plane (OpenSky::tabulate).
  /// Points from which its table over normals is 128 a side instead of 64.
  static constexpr std::size_t openSkyTablePoints = 200000;
  /// Points from which the table (64 a side) serves rather than an exact evaluation per
  /// point: about its vertices over the upper hemisphere, so that the table, filled where
  /// it is read, evaluates no more often than the points would.
  static constexpr std::size_t openSkyTableFewestPoints = 65 * 65 / 2;

  // The leaves' own gather (LeafLight): rays per leaf and passes (bounces).
  static constexpr int leafGatherRays = 256;
  static constexpr int leafGatherPasses = 3;
  /// Leaves sampled to measure how far the hierarchy's light from surfaces is off.
  static constexpr std::size_t deficitProbeLeaves = 512;
  /// Rays per sampled leaf: the leaves' own gather's up to this TargetError, fewer in
  /// proportion beyond it, to a floor. A coarser target needs the deficit (a term of
  /// each point's estimate) less exactly, and on small terrains the probe was a third
  /// of the coarse end's rays.
  static constexpr double deficitProbeTarget = 0.008;
  static constexpr int deficitProbeFewestRays = 32;
  static int deficitProbeRays(double targetError)
  {
    const double scaled = targetError > deficitProbeTarget ? leafGatherRays * deficitProbeTarget / targetError
                                                           : leafGatherRays;
    return scaled > deficitProbeFewestRays ? static_cast<int>(scaled) : deficitProbeFewestRays;
  }
  /// The share of the sky a post's horizons hide that its error estimate takes: the
  /// horizons are interpolated between the map's azimuths, and no ray corrects them.
  static constexpr double horizonSkyError = 0.1;
  /// The same from a coarse map (16 azimuths), where a post's band between azimuths is
  /// not known (a plane other than its own).
  static constexpr double coarseHorizonSkyError = 0.25;
  /// A coarse map's post errs by up to this many times its band between azimuths
  /// (HiddenSky::betweenAzimuths: the sky between its horizon interpolated linearly and
  /// by a cubic).
  static constexpr double betweenAzimuthsError = 4.0;
  /// Below coarseHorizonsTarget a coarse map serves where that share is within every
  /// post's target; every this many posts each way judge first (a 16th of them).
  static constexpr int coarseSkySampleStride = 4;
  /// Where the coarse sky misses at most this share of the posts' targets, the coarse
  /// map is refined at those posts alone (walked toward the other 16 azimuths); beyond
  /// it, the standard map's 16 sweeps cost less.
  static constexpr double refinedPostsShare = 0.2;
  /// The open sky's own relative error (OpenSky: patches split to level 5 where a
  /// plane's horizon crosses them), which every point's error estimate takes of its sky.
  static constexpr double openSkyError = 2e-3;

  // A post's final gather, below its horizon (TerrainDirections).
  /// Its rays are capped at the gather's maximum over this.
  static constexpr int postGatherDivisor = 4;
  /// Its pilot where no lattice tells the spread, and its rays where one does.
  static constexpr int postPilotRays = 16;
  static constexpr int latticeKnownRays = 9;
  /// Visibility samples from a point, per link sample, where the link saw its sender in part.
  static constexpr int partialVisibilityFactor = 8;

  // The lattice of posts gathered first (PostLattice).
  /// A post reading light from surfaces between lattice posts errs, beyond their
  /// spread, by up to this share of it (reading ignores how its own slope faces the
  /// terrain it sees): its error estimate takes it, and it gathers where that misses its
  /// target.
  static constexpr double latticeReadBias = 0.1;
  /// A post reads by the sectors of its view only where the corners' light per terrain
  /// seen differs, across their sectors, by more than this share of its target; below
  /// it the whole's read errs by no more than that width (docs/tuning.md).
  static constexpr double latticeSectorWidthShare = 0.25;
  /// A post reads its sectors' near and far parts apart where the corners' two parts
  /// of a sector differ by more than this share of its target (times its terrain
  /// seen), or where its read by sector, erring by that difference too, would miss
  /// the target. Their cost falls mostly on posts that see little terrain, whose reads
  /// they hardly move (docs/tuning.md, "Near and far terrain").
  static constexpr double latticeDistanceWidthShare = 1.0;
  /// A lattice cell is refined where its corners spread more than this share of their
  /// target.
  static constexpr double latticeRefineShare = 0.5;
};
} // namespace terralux
