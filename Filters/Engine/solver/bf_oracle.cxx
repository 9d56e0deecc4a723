#include "solver/bf_oracle.h"

#include "base/angles.h"
#include "hierarchy/cluster.h"
#include "emitters/external_source.h"
#include "hierarchy/polygon_element.h"

#include <algorithm>
#include <limits>

namespace terralux
{
namespace
{

// Size on a common scale: fraction of the scene's area, or of the hemisphere.
double relativeSize(const HElement& element, double sceneArea)
{
  if (const ExternalSource* source = element.asExternal())
    return source->hemisphereShare();
  return element.area() / sceneArea;
}

// Bounding box of a surface or cluster.
void elementBounds(const HElement& e, Vec3& low, Vec3& high)
{
  if (e.isCluster())
  {
    low = static_cast<const Cluster&>(e).low();
    high = static_cast<const Cluster&>(e).high();
  }
  else
  {
    static_cast<const PolygonElement&>(e).bounds(low, high);
  }
}
} // namespace

// Whether the element's kernels come from a far-field model: clusters, and surfaces
// whose form factors use an approximate shape (large terrain patches).
bool approximated(const HElement& e)
{
  return e.isCluster() || (e.isSurface() && static_cast<const PolygonElement&>(e).approximateShape());
}

// Bounding radius of the approximated element(s) of a link over the distance between centres.
double approximatedSizeOverDistance(const HElement& receiver, const HElement& sender)
{
  auto radius = [](const HElement& e) {
    if (!approximated(e))
      return 0.0;
    Vec3 low, high;
    elementBounds(e, low, high);
    return 0.5 * glm::length(high - low);
  };
  const double distance = glm::length(sender.centre() - receiver.centre());
  const double size = std::max(radius(receiver), radius(sender));
  return distance > 0.0 ? size / distance : std::numeric_limits<double>::infinity();
}

namespace
{
// The one direction all of an element's surfaces face, if they do (planar polygons,
// flat clusters); false for rough terrain patches and clusters of several orientations.
bool facingDirection(const HElement& e, Vec3& n)
{
  if (e.isCluster())
  {
    const auto& cluster = static_cast<const Cluster&>(e);
    const double length = glm::length(cluster.weightedNormal());
    n = length > 0.0 ? cluster.weightedNormal() / length : Vec3(0.0);
    return length >= (1.0 - 1e-9) * cluster.area();
  }
  const auto& surface = static_cast<const PolygonElement&>(e);
  n = surface.normal();
  return surface.unalignedArea() <= 1e-9 * surface.area();
}

// Largest and smallest n . x over a box.
double boxSupport(const Vec3& low, const Vec3& high, const Vec3& n, bool largest)
{
  double value = 0.0;
  for (int k = 0; k < 3; ++k)
    value += n[k] * ((n[k] > 0.0) == largest ? high[k] : low[k]);
  return value;
}

// Upper bound of the form factor from a cluster at one end of a link to the other
// end: the sender's whole area A seen from the closest distance d between their
// boxes, A / (pi d^2), at most 1; 0 when a side whose surfaces all face one way has
// the other wholly behind or in its plane (coplanar parts of a flat ground).
double clusterKernelBound(const HElement& receiver, const HElement& sender)
{
  Vec3 rLow, rHigh, sLow, sHigh;
  elementBounds(receiver, rLow, rHigh);
  elementBounds(sender, sLow, sHigh);
  const double slack = 1e-9 * glm::length(glm::max(rHigh, sHigh) - glm::min(rLow, sLow));
  Vec3 n;
  if (facingDirection(sender, n) && boxSupport(rLow, rHigh, n, true) <= boxSupport(sLow, sHigh, n, false) + slack)
    return 0.0;
  if (facingDirection(receiver, n) && boxSupport(sLow, sHigh, n, true) <= boxSupport(rLow, rHigh, n, false) + slack)
    return 0.0;
  const Vec3 gap = glm::max(Vec3(0.0), glm::max(sLow - rHigh, rLow - sHigh));
  const double d2 = glm::dot(gap, gap);
  return d2 > 0.0 ? std::min(1.0, sender.area() / (pi * d2)) : 1.0;
}

// What a surface or cluster sends now, or could once lit at the scene's mean irradiance.
double potentialEmittance(const HElement& sender, const OracleSettings& settings)
{
  double emittance = 0.0;
  for (double b : sender.emittance())
    emittance = std::max(emittance, b);
  if (sender.isCluster())
  {
    const auto& cluster = static_cast<const Cluster&>(sender);
    return std::max(emittance, cluster.largestEmission() + cluster.largestReflectance() * settings.meanIrradiance);
  }
  if (!sender.isSurface())
    return emittance; // a source outside the scene (sun, sky patch) reflects nothing
  const auto& surface = static_cast<const PolygonElement&>(sender);
  for (int band = 0; band < maxBands; ++band)
    emittance = std::max(emittance, surface.emission()[band] + surface.reflectance()[band] * settings.meanIrradiance);
  return emittance;
}
} // namespace

bool clusterMayCarryMore(const HElement& receiver, const Link& link, const OracleSettings& settings)
{
  const HElement& sender = *link.sender;
  // Only where the receiver (or a surface in it) is small beside the sender: between
  // elements of like size the near-field rule of decideRefinement refines, and the
  // bound, loose where boxes touch, would refine every pair of neighbouring clusters on
  // a curved surface.
  if (sender.isExternal() || !(receiver.isCluster() || sender.isCluster()) || !(settings.irradianceThreshold > 0.0) ||
    (receiver.isCluster() ? static_cast<const Cluster&>(receiver).smallestSurfaceArea() : receiver.area()) >
      0.01 * sender.area())
    return false;
  const double emittance = potentialEmittance(sender, settings);
  const double estimate = link.kernel * link.visibility * (link.directional ? receiver.scaleFactor() : 1.0);
  return emittance * (clusterKernelBound(receiver, sender) - estimate) > settings.irradianceThreshold;
}

bool modelMissesExchange(const HElement&, const Link& link, const OracleSettings& settings)
{
  if (!(link.sampledKernel > link.kernel) || !(settings.irradianceThreshold > 0.0))
    return false;
  return potentialEmittance(*link.sender, settings) * (link.sampledKernel - link.kernel) > settings.irradianceThreshold;
}

double linkPower(const HElement& receiver, const Link& link)
{
  const Spectrum e = link.sender->emittance();
  const double emittance = largestBand(e);
  // A cluster receiver's links carry normal irradiance; its surfaces take on average
  // S = 1/4 of it (Sillion's isotropic receiver, paper eq. 1).
  return emittance * link.kernel * link.visibility * receiver.area() * (link.directional ? receiver.scaleFactor() : 1.0);
}

bool lightsItself(const HElement& element, const OracleSettings& settings)
{
  if (!element.isSurface())
  {
    return false;
  }
  const auto& surface = static_cast<const PolygonElement&>(element);
  double radiosity = 0.0;
  for (int band = 0; band < maxBands; ++band)
  {
    radiosity = std::max({ radiosity, surface.Radiosity[band],
      surface.emission()[band] + surface.reflectance()[band] * settings.meanIrradiance });
  }
  // Scene-relative power, or, for patches whose children follow finer terrain, the
  // irradiance it can send onto itself (B (A - |N|) / A) against the receiver-relative
  // bound: the many small exchanges of a rough terrain each fall below the first.
  return radiosity * surface.unalignedArea() > settings.powerThreshold ||
    (surface.refinesGeometry() && settings.irradianceThreshold > 0.0 &&
      radiosity * surface.unalignedArea() > settings.irradianceThreshold * surface.area());
}

Refinement decideRefinement(HElement& receiver, const Link& link, const OracleSettings& settings)
{
  const double power = linkPower(receiver, link);
  const bool partial = link.visibility > 0.0 && link.visibility < 1.0;
  // Besides BF, the kernel's variation over the receiver bounds the error of using one
  // value for the whole element (the bounds-based refinement the paper cites [10, 5]).
  const Spectrum e = link.sender->emittance();
  const double variation = largestBand(e) * link.kernelSpread * link.visibility * receiver.area();
  // Cluster kernels and coarse terrain quads are far-field estimates: near the other
  // element they are refined while they carry any noticeable power.
  const bool nearApproximation = !link.sender->isExternal() && (approximated(receiver) || approximated(*link.sender)) &&
    approximatedSizeOverDistance(receiver, *link.sender) > 0.25 && power > 0.01 * settings.powerThreshold;
  const bool refine = nearApproximation || clusterMayCarryMore(receiver, link, settings) ||
    modelMissesExchange(receiver, link, settings) ||
    power > settings.powerThreshold ||
    variation > settings.powerThreshold * settings.partialVisibilityFactor ||
    (partial && power > settings.partialVisibilityFactor * settings.powerThreshold);
  if (!refine)
  {
    return Refinement::Keep;
  }
  HElement& sender = *link.sender;
  const bool receiverSplits = receiver.canSplit();
  const bool senderSplits = sender.canSplit();
  if (!receiverSplits && !senderSplits)
  {
    return Refinement::Keep;
  }
  if (receiverSplits && senderSplits)
  {
    // Partial visibility is an error in space: the receiver splits unless the sender
    // is much the larger.
    const double bias = partial ? 4.0 : 1.0;
    return bias * relativeSize(receiver, settings.sceneArea) >= relativeSize(sender, settings.sceneArea)
      ? Refinement::SplitReceiver
      : Refinement::SplitSender;
  }
  return receiverSplits ? Refinement::SplitReceiver : Refinement::SplitSender;
}
} // namespace terralux
