#pragma once
// Final gathers from a few points of each leaf: what LeafLight keeps for each leaf, and
// what measures how far the hierarchy's light from surfaces is off (HierarchyDeficit).

#include "evaluation/leaf_light.h"

#include <vector>

namespace terralux
{
class FinalGather;
class PolygonElement;
class Visibility;

class LeafGather
{
public:
  /// `raysPerLeaf` spread over each leaf's points; `surfacesSend`: whether any surface
  /// sends light (else the gathers take the sky alone); `randomSeed`:
  /// RadiosityOptions::randomSeed.
  LeafGather(std::vector<PolygonElement*> leaves, const Visibility& rays, int raysPerLeaf, bool surfacesSend,
    std::uint64_t randomSeed = 0);

  const std::vector<PolygonElement*>& leaves() const { return this->Leaves; }

  /// What the points of leaf k receive through `gather`, from points lifted clear of the
  /// leaf's surface; `pass` varies the points and rays. A point whose rays meet the backs
  /// of surfaces lies inside something (the part of a house's wall below the ground): it
  /// is left out, and a partly buried leaf is sought with more points. With `bounce`,
  /// the means over the points kept of GatheredLight::interreflected and
  /// GatheredLight::reflectanceSeen.
  struct Bounce
  {
    double interreflected = 0.0, reflectanceSeen = 0.0;
  };
  std::vector<LeafLight::Sample> at(
    std::size_t k, const FinalGather& gather, std::uint64_t pass, Bounce* bounce = nullptr) const;

private:
  std::vector<PolygonElement*> Leaves;
  std::vector<double> Lifts; // how far each leaf's points are lifted
  const Visibility& Rays;
  int RaysPerPoint;
  bool SurfacesSend;
  std::uint64_t RandomSeed;
};

/// How far the light from surfaces the hierarchy holds at its leaves is off, measured on
/// a sample of its leaves by gathers that read it: they find R1 where the leaves hold R0.
/// If the leaves are off by E0 (R = R0 + E0), a gathered bounce is off by s E0, s the
/// share of a change that a bounce brings back (the hits' reflectance times the share of
/// the view that is surfaces, GatheredLight::reflectanceSeen): R1 - R0 = (1 - s) E0.
/// Light read through b >= 1 gathered bounces is off by s^b E0, about R1 in size.
struct HierarchyDeficit
{
  double relative = 0.0;     ///< E0 / R0: the leaves' error over what they hold (d)
  double ofGathered = 0.0;   ///< E0 / R1: the same over what a gathered bounce finds (at most 1 / (1 - s))
  double bounceFactor = 0.0; ///< s
  /// The relative error of light from surfaces read through `bounces` gathered bounces
  /// above the hierarchy, over what is read: E0 / R0 for none, s^b E0 / R1 after b.
  double after(int bounces) const;
  /// Measured by gathering (through `gather`, which must read the hierarchy's values) at
  /// up to `sampled` leaves spread evenly over `leaves`.
  static HierarchyDeficit measure(const LeafGather& leaves, const FinalGather& gather, std::size_t sampled);
  /// The bound taken where it is not measured: the leaves wrong by their whole value or
  /// more, every bounce carrying it on.
  static HierarchyDeficit unknown() { return { maximumRelative, maximumRelative, 1.0 }; }
  static constexpr double maximumRelative = 4.0; ///< of `relative`: the leaves hold a fifth or more
  /// s at most: a bounce that brought back nearly all of a change would make E0 unbounded.
  static constexpr double largestBounceFactor = 0.95;
};
} // namespace terralux
