#pragma once
// Cluster H-element (Sillion 1995): a group of elements in a bounding box. R = 1 and
// S = 1/4 estimate the power it receives (for the oracle); the irradiance itself is
// evaluated for each contained surface by that surface's own orientation during push.
// As a sender it shows its projected area (see projectedArea).

#include "hierarchy/helement.h"

namespace terralux
{
class PolygonElement;

class Cluster : public HElement
{
public:
  Cluster(std::uint64_t id, int level, std::vector<HElement*> members,
    std::vector<PolygonElement*> surfaces);

  Kind kind() const override { return Kind::Cluster; }
  double area() const override { return this->Area; }
  Vec3 centre() const override { return 0.5 * (this->Low + this->High); }
  const Vec3& low() const { return this->Low; }
  const Vec3& high() const { return this->High; }
  /// Largest reflectance and emission (any band) among its surfaces: what it could send.
  double largestReflectance() const { return this->LargestReflectance; }
  double largestEmission() const { return this->LargestEmission; }
  /// Area of its smallest surface.
  double smallestSurfaceArea() const { return this->SmallestSurfaceArea; }
  /// Sum of A_i n_i over its surfaces (length A when they all face one way).
  const Vec3& weightedNormal() const { return this->WeightedNormal; }
  /// Every input polygon inside, for sampling.
  const std::vector<PolygonElement*>& surfaces() const { return this->Surfaces; }

  const std::vector<HElement*>& children() override { return this->Members; }
  bool canSplit() const override { return !this->Members.empty(); }
  SurfaceSample sample(int k, int n, SampleGenerator& random) const override;
  double receiverFactor(const Vec3&) const override { return 1.0; }
  double scaleFactor() const override { return 0.25; }

  /// Area the cluster's surfaces show toward unit direction w: max(0, N . w) for the
  /// aligned part N = sum A_i n_i, plus (A - |N|)/4 for the rest, which is treated as
  /// isotropic (S = 1/4). Exact for a flat cluster, Sillion's isotropic model for one
  /// with random orientations.
  double projectedArea(const Vec3& w) const;

  /// Top-down spatial split of polygons: median along the longest box axis until at
  /// most `leafSize` polygons remain, which become the members.
  static Cluster* build(ElementStore& store, std::vector<PolygonElement*> polygons, int level,
    std::size_t leafSize = 4);

private:
  std::vector<HElement*> Members;
  std::vector<PolygonElement*> Surfaces;
  std::vector<double> CumulativeArea;
  double Area = 0.0;
  double SmallestSurfaceArea = 0.0;
  double LargestReflectance = 0.0;
  double LargestEmission = 0.0;
  Vec3 WeightedNormal{ 0.0 };
  Vec3 Low{ 0.0 }, High{ 0.0 };
};
} // namespace terralux
