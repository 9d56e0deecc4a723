#pragma once
// What a source at infinity tells the transport (paper section 5.3: "external sources
// compute their own transport"), in the manner of pbrt-v4's lights: the kernel toward
// a receiver's normal, directions for sampled visibility, and the category of light
// it adds. The sun (sun_element.h) and sky patches (sky_patch_element.h) implement it;
// link_transport.cxx and point evaluation ask it instead of switching on kinds.

#include "hierarchy/helement.h"

namespace terralux
{
class ExternalSource : public HElement
{
public:
  ExternalSource* asExternal() override { return this; }
  const ExternalSource* asExternal() const override { return this; }

  /// Unit vector toward the source's centre.
  virtual const Vec3& direction() const = 0;
  /// Transport toward a surface of unit normal n per unit emittance: R S for the sun
  /// (the cosine), R S Omega for a sky patch (its projected solid angle, radiance-weighted).
  virtual double kernel(const Vec3& normal) const = 0;
  /// Transport toward a surface element of unit normal n: kernel(n) for a source with
  /// extent; for a parallel one the receiver's own factor, which for a coarse terrain
  /// patch is its cells' mean cosine, not the cosine of its mean normal.
  virtual double kernelToward(const HElement& receiver, const Vec3& normal) const = 0;
  /// Transport toward a cluster, whose surfaces weigh their own cosines later (paper
  /// section 5.1): 1 for the sun, the solid angle for a sky patch.
  virtual double directionalKernel() const = 0;
  /// A direction toward the source for a visibility ray (consumes `random` only when the
  /// source has extent).
  virtual Vec3 sampleDirection(SampleGenerator& random) const = 0;
  /// Whether every direction toward the source is the same (a parallel source): one ray
  /// then decides its visibility from a point.
  virtual bool parallel() const = 0;
  /// SunLight or SkyLight.
  virtual LightCategory category() const = 0;
  /// The share of the hemisphere the source spans (solid angle over 2 pi): its size on
  /// the refinement oracle's common scale.
  virtual double hemisphereShare() const = 0;
  /// What transport (kernel x visibility) toward a surface of unit normal n adds to its
  /// sky view factor: the geometric share of it over pi for the sky, 0 for the sun.
  virtual double skyView(const Vec3& normal, double transport) const = 0;
  /// Hours this source stands for (a time series' step), 0 for an instant.
  virtual double duration() const { return 0.0; }

  // Sources at infinity have no surface and never receive.
  double receiverFactor(const Vec3&) const override { return 0.0; }
  SurfaceSample sample(int, int, SampleGenerator&) const override { return { Vec3(0.0), this->direction() }; }

protected:
  using HElement::HElement;
};
} // namespace terralux
