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
  /// sends light (else the gathers take the sky alone).
  LeafGather(std::vector<PolygonElement*> leaves, const Visibility& rays, int raysPerLeaf, bool surfacesSend);

  const std::vector<PolygonElement*>& leaves() const { return this->Leaves; }

  /// What the points of leaf k receive through `gather`, from points lifted clear of the
  /// leaf's surface; `pass` varies the points and rays. A point whose rays meet the backs
  /// of surfaces lies inside something (the part of a house's wall below the ground): it
  /// is left out, and a partly buried leaf is sought with more points. With
  /// `interreflected`, the mean over the points kept of GatheredLight::interreflected.
  std::vector<LeafLight::Sample> at(
    std::size_t k, const FinalGather& gather, std::uint64_t pass, double* interreflected = nullptr) const;

private:
  std::vector<PolygonElement*> Leaves;
  std::vector<double> Lifts; // how far each leaf's points are lifted
  const Visibility& Rays;
  int RaysPerPoint;
  bool SurfacesSend;
};

/// How far the light from surfaces the hierarchy holds at its leaves is off, measured on
/// a sample of its leaves by gathers that read it: they find R1 where the leaves hold R0,
/// while R1 itself reads R0 through its hits' reflectances (its interreflected part M1).
/// If the leaves err by a fraction d, R1 errs by d M1, so d (R0 - M1) = R1 - R0 over the
/// sample. Each gathered bounce carries the error on scaled by s = M1 / R0 (the
/// reflectance times the share of the view that is lit surfaces; in a closed uniform
/// room, the reflectance).
struct HierarchyDeficit
{
  double relative = 0.0; ///< d, the leaves' relative error (its size)
  double bounceFactor = 0.0; ///< s
  /// The relative error, against what the hierarchy holds, of light from surfaces read
  /// through `bounces` gathered bounces above it: d s^bounces.
  double after(int bounces) const;
  /// Measured by gathering (through `gather`, which must read the hierarchy's values) at
  /// up to `sampled` leaves spread evenly over `leaves`.
  static HierarchyDeficit measure(const LeafGather& leaves, const FinalGather& gather, std::size_t sampled);
  /// The bound taken where it is not measured: the leaves wrong by their whole value or
  /// more, every bounce carrying it on.
  static HierarchyDeficit unknown() { return { maximumRelative, 1.0 }; }
  static constexpr double maximumRelative = 4.0; ///< of d: the leaves hold a fifth or more
};
} // namespace terralux
