#pragma once
// The abstract hierarchical element of paper section 3.1: radiosity, reflectance,
// area, incoming links, lazy split, sample points, and the receiver and scale
// factors of section 5.1. Subclasses: PolygonElement (surfaces), Cluster (groups),
// and the external sources of section 5 (ExternalSource: SkyPatchElement, SunElement).

#include "hierarchy/radiosity_types.h"
#include "visibility/sampling.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace terralux
{
class HElement;
class ExternalSource;

/// Light transport from `sender` to the element that stores the link. Geometry is
/// cached at creation: irradiance = kernel * visibility * sender->emittance().
struct Link
{
  HElement* sender = nullptr;
  double kernel = 0.0;     ///< form factor, R S Omega, or R S, per unit sender emittance
  double kernelSpread = 0.0; ///< max - min of the kernel over the receiver's sample points
  /// For a surface receiver whose link's kernel comes from a far-field model (a coarse
  /// terrain quad or a cluster at either end): the unoccluded kernel estimated from
  /// samples of both true surfaces with their own normals, which sees the exchange
  /// inside concave terrain that the model misses. 0 elsewhere.
  double sampledKernel = 0.0;
  double visibility = 1.0; ///< fraction in [0, 1]
  Vec3 direction{ 0.0 };   ///< unit vector toward the sender (receiver centre to sender)
  bool directional = false; ///< received by a cluster: evaluated for each contained surface
};

/// A point on an element's surface with the surface's normal.
struct SurfaceSample
{
  Vec3 position;
  Vec3 normal;
};

class HElement
{
public:
  enum class Kind
  {
    Polygon,
    Cluster,
    SkyPatch,
    Sun
  };

  virtual ~HElement() = default;
  virtual Kind kind() const = 0;
  bool isSurface() const { return this->kind() == Kind::Polygon; }
  bool isCluster() const { return this->kind() == Kind::Cluster; }
  bool isExternal() const { return this->asExternal() != nullptr; }
  /// This element as a source at infinity, or null for surfaces and clusters.
  virtual ExternalSource* asExternal() { return nullptr; }
  virtual const ExternalSource* asExternal() const { return nullptr; }

  /// Deterministic id (creation order), used to seed the link's samples.
  std::uint64_t id() const { return this->Id; }
  int level() const { return this->Level; }

  /// Surface area in m^2 (clusters: the sum of their surfaces; sources: 0).
  virtual double area() const { return 0.0; }
  /// Centre used for directions and distances.
  virtual Vec3 centre() const { return Vec3(0.0); }
  /// What this element sends per unit kernel: radiosity B (W/m^2) for surfaces and
  /// clusters, radiance (W/m^2/sr) for sky patches, flux density (W/m^2) for the sun.
  virtual Spectrum emittance() const { return this->Radiosity; }

  /// Children, created on the first call; empty when the element cannot split.
  virtual const std::vector<HElement*>& children() = 0;
  /// Whether children() would return anything (without creating them).
  virtual bool canSplit() const = 0;

  /// The k-th of n stratified points on the element's surfaces.
  virtual SurfaceSample sample(int k, int n, SampleGenerator& random) const = 0;

  // Receiver and scale factors (paper eq. 1): cosine and 1 for surfaces, 1 and 1/4
  // for clusters.
  virtual double receiverFactor(const Vec3& towardSender) const = 0;
  virtual double scaleFactor() const { return 1.0; }

  /// The element whose children() holds this one (null for roots and sources' roots).
  HElement* Parent = nullptr;

  /// Back to the state of a new element: no links, no values (surfaces keep their
  /// emission as radiosity).
  virtual void resetSolution();
  /// Forgets children with ids from `firstId` on (made by refinement after the element
  /// store held that many), which the store is about to drop.
  virtual void forgetChildrenFrom(std::uint64_t) {}

  // State of the solution.
  Spectrum Radiosity{};
  std::array<Spectrum, lightCategories> Gathered{}; ///< irradiance gathered at this level
  double GatheredPartial = 0.0; ///< the part of it from partially visible links (largest band)
  double GatheredSkyView = 0.0; ///< sky kernels x visibility gathered here, over pi
  std::vector<Link> Incoming;

protected:
  HElement(std::uint64_t id, int level)
    : Id(id)
    , Level(level)
  {
  }

private:
  std::uint64_t Id;
  int Level;
};

/// Owns every element and hands out ids in creation order; refinement creates
/// elements sequentially, so ids (and the samples seeded by them) are deterministic.
/// Ids start at `firstId`: stores of different elements (surfaces, sources) never
/// share one, so no two links share a seed.
class ElementStore
{
public:
  explicit ElementStore(std::uint64_t firstId = 0)
    : FirstId(firstId)
  {
  }
  template <typename T, typename... Args>
  T* make(int level, Args&&... args)
  {
    auto element =
      std::unique_ptr<T>(new T(this->FirstId + this->Elements.size(), level, std::forward<Args>(args)...));
    T* raw = element.get();
    this->Elements.push_back(std::move(element));
    return raw;
  }
  std::size_t size() const { return this->Elements.size(); }
  /// Element k has id firstId() + k.
  std::uint64_t firstId() const { return this->FirstId; }
  const std::vector<std::unique_ptr<HElement>>& all() const { return this->Elements; }
  /// Back to the first `count` elements, each as new (resetSolution): the elements made
  /// later (by refinement) are dropped, so the next ones get the ids they had.
  void restore(std::size_t count);

  /// Smallest area a polygon may be split into (its children's area), m^2.
  double MinimumArea = 0.0;
  /// Deepest sky-patch level.
  int MaximumSkyLevel = 10;

private:
  std::uint64_t FirstId;
  std::vector<std::unique_ptr<HElement>> Elements;
};
} // namespace terralux
