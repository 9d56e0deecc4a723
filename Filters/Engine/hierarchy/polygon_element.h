#pragma once
// Surface H-element: a planar triangle or quad, split regularly into four children
// (triangles at edge midpoints, quads at edge midpoints and centre).

#include "hierarchy/helement.h"

namespace terralux
{
class PolygonElement : public HElement
{
public:
  /// rootPolygon: index of the input polygon this element subdivides.
  PolygonElement(std::uint64_t id, int level, ElementStore* store, const Vec3* corners, int count,
    const Spectrum& reflectance, const Spectrum& emission, int rootPolygon);

  Kind kind() const override { return Kind::Polygon; }
  double area() const override { return this->Area; }
  Vec3 centre() const override { return this->Centre; }
  const Vec3& normal() const { return this->Normal; }
  int cornerCount() const { return this->Count; }
  const Vec3* corners() const { return this->Corners; }
  const Spectrum& reflectance() const { return this->Reflectance; }
  const Spectrum& emission() const { return this->Emission; }
  int rootPolygon() const { return this->RootPolygon; }

  const std::vector<HElement*>& children() override;
  bool canSplit() const override { return this->Area >= 4.0 * this->Store->MinimumArea; }
  bool hasChildren() const { return !this->Children.empty(); }
  void resetSolution() override;
  void forgetChildrenFrom(std::uint64_t firstId) override;
  /// The leaf below this element that holds point p of its plane: at each level the
  /// child p lies deepest inside (so a point on a shared edge, or just off the
  /// polygon by rounding, still finds one).
  const PolygonElement* leafHolding(const Vec3& p) const;
  SurfaceSample sample(int k, int n, SampleGenerator& random) const override;
  double receiverFactor(const Vec3& towardSender) const override;
  /// Form factor from a differential area at x with unit normal n to this surface
  /// (exact, without occlusion).
  virtual double formFactorFrom(const Vec3& x, const Vec3& n) const;
  /// Bounding box of the surface this element stands for.
  virtual void bounds(Vec3& low, Vec3& high) const;
  /// Whether every descendant has this element's normal, so irradiance from sources at
  /// infinity gathered here holds for them as is (planar polygons; not terrain patches).
  virtual bool childrenShareNormal() const { return true; }
  /// Whether formFactorFrom is a far-field approximation of the surface (a large
  /// terrain patch's coarse quad): near the element, links are refined and points
  /// sample its true surface instead.
  virtual bool approximateShape() const { return false; }
  /// Whether its children follow finer geometry than itself (a terrain patch of more
  /// than one cell), so that what it sends onto itself is worth refining at the scale
  /// of the irradiance it receives, not only of the scene's power.
  virtual bool refinesGeometry() const { return false; }
  /// Area not aligned with the mean normal, A - |sum A_i n_i|: 0 for a planar polygon.
  /// It bounds both how much the surface lights itself and how far its parts' cosines
  /// toward a source differ from the mean one.
  double unalignedArea() const { return this->UnalignedArea; }

  /// Area of a planar polygon and its unit normal (right-handed corner order);
  /// returns 0 area for degenerate input.
  static double areaAndNormal(const Vec3* corners, int count, Vec3& normal);

  /// Irradiance by category once push-pull has run (leaves only).
  std::array<Spectrum, lightCategories> Irradiance{};
  /// All of it, each category by its largest band.
  double receivedIrradiance() const;
  /// Cosine-weighted fraction of the sky the leaf sees, once push-pull has run (0
  /// without a sky).
  double SkyViewFactor = 0.0;
  /// Kernels of the links evaluated at this leaf during push, kept while the links
  /// that reach it (their signature) do not change.
  std::vector<double> LeafKernels;
  std::vector<std::uint64_t> LeafKernelKeys;   ///< the link each kernel belongs to
  std::vector<std::uint8_t> LeafKernelPartial; ///< whether the leaf saw its sender in part
  std::uint64_t LeafKernelSignature = 0;
  /// Irradiance (largest band) this leaf receives through partially visible links;
  /// where it is large the leaf is split so shadows are resolved in space.
  double PartialIrradiance = 0.0;
  double DeferredPartial = 0.0; ///< the part from links evaluated at this leaf (cached)
  /// Sky view factor from the sky links evaluated at this leaf (cached with LeafKernels).
  double DeferredSkyView = 0.0;

protected:
  ElementStore* Store;
  Vec3 Corners[4];
  int Count;
  Vec3 Normal{ 0.0, 0.0, 1.0 };
  Vec3 Centre{ 0.0 };
  double Area = 0.0;
  double UnalignedArea = 0.0;
  Spectrum Reflectance;
  Spectrum Emission;
  int RootPolygon;
  std::vector<HElement*> Children;
};
} // namespace terralux
