#pragma once
// Sky patch H-element (paper section 5.1): a range of altitude and azimuth at
// infinity with the cell-averaged radiance of the sky pyramid (subsampled below its
// finest level). It computes its own transport: dE = R S Omega L (eq. 1).
// The sun, the other external source, is in sun_element.h.

#include "emitters/external_source.h"
#include "base/angles.h"
#include "sky/sky_hierarchy.h"

#include <array>

namespace terralux
{
class SkyPatchElement : public ExternalSource
{
public:
  SkyPatchElement(std::uint64_t id, int level, ElementStore* store, const SkyHierarchy* sky, SkyPatch patch);

  Kind kind() const override { return Kind::SkyPatch; }
  Spectrum emittance() const override { return this->Radiance; }
  const std::vector<HElement*>& children() override;
  bool canSplit() const override { return this->Patch.level < this->Store->MaximumSkyLevel; }

  double solidAngle() const { return this->SolidAngle; }
  const Vec3& direction() const override { return this->Direction; }
  double kernelToward(const HElement&, const Vec3& normal) const override { return this->kernel(normal); }
  double directionalKernel() const override { return this->SolidAngle; }
  bool parallel() const override { return false; }
  LightCategory category() const override { return SkyLight; }
  double hemisphereShare() const override { return this->SolidAngle / twoPi; }
  double skyView(const Vec3& normal, double transport) const override
  {
    return transport * this->geometricShare(normal) / pi;
  }
  const SkyPatch& patch() const { return this->Patch; }

  /// Integral of max(0, n . d) dOmega over the patch for a unit normal n: in closed form
  /// (n . the patch's vector solid angle) when the whole patch is in front of n, 0 when
  /// it is wholly behind, else exactly along azimuth and by Gauss-Legendre over sin u. Geometric: what the
  /// sky view factor counts.
  double projectedSolidAngle(const Vec3& normal) const;
  /// The transport kernel toward a surface of unit normal n, per unit of the patch's
  /// mean radiance: exact (n . the patch's irradiance vector / mean radiance) when the
  /// whole patch is in front of n, whatever its level, so an open plane receives exactly
  /// what the radiance map gives it; projectedSolidAngle(n) where the surface's horizon
  /// crosses the patch (the refinement splits such links while they matter).
  double kernel(const Vec3& normal) const override;
  /// What sideOf and the projection need of a unit normal whatever the patch: one
  /// plane's terms, found once for all the patches it is tested against (OpenSky).
  struct PlaneTerms
  {
    explicit PlaneTerms(const Vec3& normal);
    double horizontal; ///< |(n_x, n_y)|
    double phi;        ///< atan2(n_x, n_y): the azimuth v where n . d is least
  };
  /// kernel(n) and projectedSolidAngle(n) at once.
  void kernelAndProjection(const Vec3& normal, double& kernel, double& projected) const;
  /// The same for a side already known (sideOf).
  void kernelAndProjection(
    const Vec3& normal, const PlaneTerms& plane, int side, double& kernel, double& projected) const;
  /// A direction in the patch for sampled visibility, distributed like the irradiance
  /// the patch gives a horizontal plane (radiance x sin u over dOmega): a bright part
  /// of the patch (the circumsolar sky) that an obstacle hides weighs as much as it
  /// lights, instead of as much as it spans. Below the sky map's finest level (constant
  /// radiance), by sin u alone.
  Vec3 sampleDirection(SampleGenerator& random) const override;
  /// projectedSolidAngle(n) / kernel(n) (1 where they agree or kernel is 0): turns
  /// transport into the geometric share the sky view factor counts.
  double geometricShare(const Vec3& normal) const;

  /// Whether the patch lies wholly in front of (+1), wholly behind (-1) a plane of unit
  /// normal n through the receiver, or straddles its horizon (0): the exact extremes of
  /// n . d over the patch.
  int sideOf(const Vec3& normal) const { return this->sideOf(normal, PlaneTerms(normal)); }
  int sideOf(const Vec3& normal, const PlaneTerms& plane) const;

private:
  ElementStore* Store;
  const SkyHierarchy* Sky;
  SkyPatch Patch;
  Spectrum Radiance{};
  double SolidAngle;
  Vec3 Direction;
  /// Integral of max(0, n . d) dOmega over a patch that straddles the plane's horizon.
  double straddlingProjection(const Vec3& normal, const PlaneTerms& plane) const;
  /// The patch's bounds in altitude u and azimuth v, and their sines and cosines, which
  /// every side test and projection reads (the exact open sky of a point takes a few
  /// hundred of them).
  struct Bounds
  {
    double u0, u1, v0, v1;
    double sinU0, cosU0, sinU1, cosU1, sinV0, cosV0, sinV1, cosV1;
  };
  Bounds Range;

  /// Sin u-weighted sampling of (sin u, v) over a range of the patch.
  static Vec3 uniformDirection(double u0, double u1, double v0, double v1, SampleGenerator& random);

  Vec3 VectorSolidAngle{ 0.0 };       // integral of d dOmega over the patch
  /// Over the finest map cells inside the patch (row by row in altitude): cumulative
  /// horizontal irradiance, normalised; empty below the finest level or for a dark patch.
  std::vector<float> CellCdf;
  int CellsPerSide = 1;
  Vec3 RadianceVector{ 0.0 };         // integral of L d dOmega / mean L (bands summed)
  std::vector<HElement*> Children;
};
} // namespace terralux
