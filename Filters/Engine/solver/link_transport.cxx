#include "solver/link_transport.h"

#include "base/angles.h"
#include "hierarchy/cluster.h"
#include "evaluation/point_form_factor.h"
#include "hierarchy/polygon_element.h"
#include "emitters/external_source.h"
#include "visibility/visibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace terralux
{
namespace
{
// Clusters of up to this many input polygons send through their polygons' exact
// form factors rather than through the cluster model.
constexpr std::size_t exactClusterSurfaces = 8;

// A direction from `directionOf` above the surface with unit normal n: a sky patch
// straddling the surface's horizon is sampled where the surface sees it (its kernel
// counts only that part). False when a few draws all fall below.
template <typename DirectionOf>
bool directionAbove(const Vec3& n, DirectionOf& directionOf, int k, Vec3& d)
{
  for (int attempt = 0; attempt < 32; ++attempt)
  {
    d = directionOf(k);
    if (glm::dot(n, d) > 0.0)
      return true;
  }
  return false;
}

// Fraction of receiver samples that see a direction at infinity; samples on surfaces
// facing away do not count (their cosine is zero anyway).
template <typename DirectionOf>
double visibilityToward(HElement& receiver, const Visibility& visibility, int samples,
  SampleGenerator& random, DirectionOf directionOf)
{
  int counted = 0, visible = 0;
  for (int k = 0; k < samples; ++k)
  {
    const SurfaceSample s = receiver.sample(k, samples, random);
    Vec3 d;
    if (!directionAbove(s.normal, directionOf, k, d))
    {
      continue;
    }
    ++counted;
    visible += !visibility.occludedToward(s.position, s.normal, d);
  }
  return counted ? static_cast<double>(visible) / counted : 0.0;
}

// The centre twice (it weighs most) and the points halfway to three corners, or the
// centre and the points halfway to the four corners of a quad.
std::array<Vec3, 5> receiverPoints(const PolygonElement& p)
{
  const Vec3 c = p.centre();
  const Vec3* v = p.corners();
  if (p.cornerCount() == 3)
  {
    return { c, c, 0.5 * (c + v[0]), 0.5 * (c + v[1]), 0.5 * (c + v[2]) };
  }
  return { c, 0.5 * (c + v[0]), 0.5 * (c + v[1]), 0.5 * (c + v[2]), 0.5 * (c + v[3]) };
}

double visibilityBetween(HElement& receiver, HElement& sender, const Visibility& visibility,
  int samples, SampleGenerator& random)
{
  // Pairs of points that face each other, as many as `samples` asks; where none of
  // them did (a cluster of several faces of a box, whose samples all fell on faces
  // turned away), more rounds, up to four: visibility 0 drops the link, and in a closed
  // box of 4 samples such unlucky links left the leaves at one edge 20-37 % short.
  int counted = 0, visible = 0;
  for (int round = 0; round < 4 && counted == 0; ++round)
    for (int k = 0; k < samples; ++k)
    {
      const SurfaceSample x = receiver.sample(k, samples, random);
      const SurfaceSample y = sender.sample(k, samples, random);
      const Vec3 xy = y.position - x.position;
      if (glm::dot(x.normal, xy) <= 0.0 || glm::dot(y.normal, xy) >= 0.0)
      {
        continue; // the pair does not face each other
      }
      ++counted;
      visible += !visibility.occluded(x.position, x.normal, y.position, y.normal);
    }
  return counted ? static_cast<double>(visible) / counted : 0.0;
}

// Cluster sender seen from `distance` along `towardSender`: its projected area toward
// the receiver over pi r^2, regularised like a disc so the kernel stays below 1 at
// short range.
double clusterKernel(const HElement& sender, const Vec3& towardSender, double distance)
{
  const double projected = static_cast<const Cluster&>(sender).projectedArea(-towardSender);
  return projected / (pi * distance * distance + projected);
}
} // namespace

namespace
{
// A surface of approximate shape with a point within twice its bounding radius of its
// centre: there its coarse quad may pass far from the surface around the point (a
// point on a terrain patch's border can even lie under the quad).
bool nearApproximateShape(const Vec3& point, const HElement& sender)
{
  if (!sender.isSurface() || !static_cast<const PolygonElement&>(sender).approximateShape())
    return false;
  Vec3 low, high;
  static_cast<const PolygonElement&>(sender).bounds(low, high);
  return glm::length(point - sender.centre()) < glm::length(high - low);
}

// Form factor x visibility from a point to a surface's true shape, by its own samples:
// each carries area A / N, seen like a disc of that area (Wallace et al. 1989), which
// stays bounded as the point nears the surface.
double sampledFormFactor(const Vec3& point, const Vec3& n, const HElement& sender, const Visibility& visibility,
  int samples, SampleGenerator& random)
{
  const double share = sender.area() / samples;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k)
  {
    const SurfaceSample y = sender.sample(k, samples, random);
    const Vec3 d = y.position - point;
    const double r2 = glm::dot(d, d);
    const double cx = glm::dot(n, d), cy = -glm::dot(y.normal, d);
    if (!(cx > 0.0 && cy > 0.0) || visibility.occluded(point, n, y.position, y.normal))
      continue;
    sum += (cx * cy / r2) / (pi * r2 + share);
  }
  return sum * share;
}
} // namespace

namespace
{
// Elements whose kernels come from a far-field model: clusters (beyond a few surfaces)
// and surfaces of approximate shape (large terrain patches).
bool farFieldModel(const HElement& e)
{
  if (e.isCluster())
    return static_cast<const Cluster&>(e).surfaces().size() > exactClusterSurfaces;
  return e.isSurface() && static_cast<const PolygonElement&>(e).approximateShape();
}

// Receiver-averaged form factor from pairs of samples on both true surfaces, each with
// its own normal, disc-regularised (Wallace et al. 1989): F = mean A_s cx cy / (pi r^2 +
// A_s / N). Unoccluded: it bounds what the far-field model may leave out.
double sampledSurfaceKernel(const HElement& receiver, const HElement& sender, int samples, std::uint64_t seed)
{
  SampleGenerator random(seed);
  const double share = sender.area() / samples;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k)
  {
    const SurfaceSample x = receiver.sample(k, samples, random);
    const SurfaceSample y = sender.sample(k, samples, random);
    const Vec3 d = y.position - x.position;
    const double r2 = glm::dot(d, d);
    const double cx = glm::dot(x.normal, d), cy = -glm::dot(y.normal, d);
    if (cx > 0.0 && cy > 0.0 && r2 > 0.0)
      sum += sender.area() * (cx * cy / r2) / (pi * r2 + share);
  }
  return sum / samples;
}
} // namespace

double surfaceKernel(const PolygonElement& receiver, const HElement& sender, double* spread)
{
  if (!sender.isSurface())
  {
    const auto& cluster = static_cast<const Cluster&>(sender);
    if (cluster.surfaces().size() <= exactClusterSurfaces)
    {
      // Few surfaces: the sum of their exact form factors beats any cluster model.
      double sum = 0.0, spreadSum = 0.0;
      for (const PolygonElement* surface : cluster.surfaces())
      {
        double s = 0.0;
        sum += surfaceKernel(receiver, *surface, &s);
        spreadSum += s;
      }
      if (spread)
        *spread = spreadSum;
      return sum;
    }
    const Vec3 toSender = sender.centre() - receiver.centre();
    const double distance = glm::length(toSender);
    const Vec3 direction = distance > 0.0 ? toSender / distance : receiver.normal();
    if (spread)
      *spread = 0.0;
    return clusterKernel(sender, direction, distance) * receiver.receiverFactor(direction);
  }
  const auto& polygon = static_cast<const PolygonElement&>(sender);
  double low = 1.0, high = 0.0, sum = 0.0;
  for (const Vec3& x : receiverPoints(receiver))
  {
    const double f =
      polygon.formFactorFrom(x, receiver.normal());
    low = std::min(low, f);
    high = std::max(high, f);
    sum += f;
  }
  if (spread)
    *spread = high - low;
  return sum / 5.0;
}

double kernelAtSurface(const PolygonElement& receiver, HElement& sender)
{
  if (const ExternalSource* source = sender.asExternal())
    return source->kernelToward(receiver, receiver.normal());
  return surfaceKernel(receiver, sender);
}

double skyViewOf(const HElement& sender, const Vec3& normal, double transport)
{
  const ExternalSource* source = sender.asExternal();
  return source ? source->skyView(normal, transport) : 0.0;
}

Spectrum directSunlight(const Vec3& point, const Vec3& normal, const std::vector<HElement*>& suns,
  const Visibility& visibility, double* sunlitHours, const SunsProven& proven)
{
  Spectrum result{};
  for (std::size_t s = 0; s < suns.size(); ++s)
  {
    HElement& sun = *suns[s];
    const ExternalSource& source = *sun.asExternal();
    // A parallel sun in front of the surface is its kernel x 1 where its one ray finds
    // it open, else 0: transportToPoint's value, without its sampling machinery on this
    // hot path.
    double transport = 0.0;
    if (proven.hiddenAt(s))
      continue;
    if (!source.parallel())
      transport = transportToPoint(point, normal, sun, visibility, 1, 0);
    else if (const double kernel = source.kernel(normal); kernel > 0.0)
    {
      if (proven.seenAt(s) || !visibility.occludedToward(point, normal, source.direction()))
        transport = kernel;
    }
    addSunlight(transport, sun.emittance(), source.duration(), result, sunlitHours);
  }
  return result;
}

int lightCategoryOf(const HElement& sender)
{
  const ExternalSource* source = sender.asExternal();
  return source ? source->category() : ReflectedLight;
}

double sampledVisibility(HElement& receiver, HElement& sender, const Visibility& visibility, int samples)
{
  SampleGenerator random(linkSeed(receiver.id(), sender.id()));
  if (const ExternalSource* source = sender.asExternal())
    return visibilityToward(
      receiver, visibility, samples, random, [&](int) { return source->sampleDirection(random); });
  return visibilityBetween(receiver, sender, visibility, samples, random);
}

double transportToPoint(const Vec3& point, const Vec3& normal, HElement& sender,
  const Visibility& visibility, int samples, std::uint64_t seed)
{
  SampleGenerator random(seed);
  const Vec3& n = normal;
  auto seen = [&](std::function<Vec3(int)> directionOf) {
    if (samples == 0)
      return 1.0; // the caller knows the sender is unoccluded
    int counted = 0, visible = 0;
    for (int k = 0; k < samples; ++k)
    {
      Vec3 d;
      if (!directionAbove(n, directionOf, k, d))
        continue;
      ++counted;
      visible += !visibility.occludedToward(point, n, d);
    }
    // No draw fell above the surface: the patch shows it only a sliver, which its kernel
    // already counts alone; with no ray to say otherwise it is taken as seen.
    return counted ? static_cast<double>(visible) / counted : 1.0;
  };
  if (const ExternalSource* source = sender.asExternal())
  {
    const double kernel = source->kernel(n);
    if (!(kernel > 0.0))
      return 0.0;
    if (source->parallel())
      samples = std::min(samples, 1); // one direction: one ray decides
    return kernel * seen([&](int) { return source->sampleDirection(random); });
  }
  if (samples > 0 && nearApproximateShape(point, sender))
  {
    return sampledFormFactor(point, n, sender, visibility, samples, random);
  }
  double kernel = 0.0;
  auto formFactor = [&](const PolygonElement& polygon) {
    return polygon.formFactorFrom(point, n);
  };
  if (sender.isSurface())
  {
    kernel = formFactor(static_cast<const PolygonElement&>(sender));
  }
  else
  {
    const auto& cluster = static_cast<const Cluster&>(sender);
    if (cluster.surfaces().size() <= exactClusterSurfaces)
    {
      for (const PolygonElement* surface : cluster.surfaces())
        kernel += formFactor(*surface);
    }
    else
    {
      const Vec3 toSender = cluster.centre() - point;
      const double distance = glm::length(toSender);
      const Vec3 direction = distance > 0.0 ? toSender / distance : n;
      kernel = clusterKernel(cluster, direction, distance) * std::max(0.0, glm::dot(n, direction));
    }
  }
  if (!(kernel > 0.0))
    return 0.0;
  if (samples == 0)
    return kernel;
  int counted = 0, visible = 0;
  for (int k = 0; k < samples; ++k)
  {
    const SurfaceSample y = sender.sample(k, samples, random);
    if (glm::dot(n, y.position - point) <= 0.0 || glm::dot(y.normal, point - y.position) <= 0.0)
      continue;
    ++counted;
    visible += !visibility.occluded(point, n, y.position, y.normal);
  }
  return counted ? kernel * visible / counted : 0.0;
}

namespace
{
// How much the cosine toward a source at infinity varies over a surface receiver, per
// unit kernel: the share of its area not aligned with its mean normal (0 for planar
// polygons, whose cosine is the same everywhere).
double cosineSpread(const HElement& receiver)
{
  if (!receiver.isSurface() || !(receiver.area() > 0.0))
    return 0.0;
  return static_cast<const PolygonElement&>(receiver).unalignedArea() / receiver.area();
}
} // namespace

Link evaluateLink(HElement& receiver, HElement& sender, const Visibility& visibility, int samples)
{
  Link link;
  link.sender = &sender;
  link.directional = receiver.isCluster();

  if (const ExternalSource* source = sender.asExternal())
  {
    link.direction = source->direction();
    // R S Omega for a sky patch toward a surface counts only the part of the patch above
    // the surface's horizon; a cluster weighs its surfaces' cosines later.
    link.kernel = link.directional ? source->directionalKernel()
                                   : source->kernelToward(receiver, static_cast<PolygonElement&>(receiver).normal());
    link.kernelSpread = cosineSpread(receiver) * source->directionalKernel();
    if (link.kernel > 0.0)
      link.visibility = sampledVisibility(receiver, sender, visibility, samples);
    return link;
  }

  // Surface or cluster sender.
  const Vec3 toSender = sender.centre() - receiver.centre();
  const double distance = glm::length(toSender);
  link.direction = distance > 0.0 ? toSender / distance : Vec3(0.0, 0.0, 1.0);
  if (receiver.isSurface())
  {
    link.kernel = surfaceKernel(static_cast<PolygonElement&>(receiver), sender, &link.kernelSpread);
    if (farFieldModel(receiver) || farFieldModel(sender))
      link.sampledKernel = sampledSurfaceKernel(receiver, sender, 8, linkSeed(sender.id(), receiver.id()));
  }
  else if (sender.isSurface())
  {
    // Cluster receiver: the form factor onto a surface facing the sender.
    auto& polygon = static_cast<PolygonElement&>(sender);
    link.kernel = polygon.formFactorFrom(receiver.centre(), link.direction);
  }
  else
  {
    link.kernel = clusterKernel(sender, link.direction, distance);
  }
  if (link.kernel > 0.0)
  {
    link.visibility = sampledVisibility(receiver, sender, visibility, samples);
  }
  return link;
}
} // namespace terralux
