#include "evaluation/leaf_gather.h"

#include "evaluation/final_gather.h"
#include "hierarchy/polygon_element.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/sampling.h"
#include "visibility/visibility.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
constexpr int points = 4, morePoints = 16; // of each leaf; of a partly buried one
}

LeafGather::LeafGather(std::vector<PolygonElement*> leaves, const Visibility& rays, int raysPerLeaf, bool surfacesSend,
  std::uint64_t randomSeed)
  : Leaves(std::move(leaves))
  , Lifts(this->Leaves.size(), 3.0 * rays.offset())
  , Rays(rays)
  , RaysPerPoint(std::max(1, raysPerLeaf / points))
  , SurfacesSend(surfacesSend)
  , RandomSeed(randomSeed)
{
  // Points are lifted as points users read are (three ray offsets), above a rough
  // patch's crease; a non-planar quad's points (on its bilinear surface) also by how far
  // the input quad's corners leave its plane, above both triangles rays meet (else, on a
  // displaced vtkPlaneSource, points under them saw backs and nearly every leaf looked
  // buried, at four times the rays).
  for (std::size_t k = 0; k < this->Leaves.size(); ++k)
  {
    if (dynamic_cast<const TerrainPatch*>(this->Leaves[k]))
      continue;
    const PolygonElement* root = this->Leaves[k];
    while (root->Parent && root->Parent->isSurface())
      root = static_cast<const PolygonElement*>(root->Parent);
    for (int c = 0; c < root->cornerCount(); ++c)
      this->Lifts[k] = std::max(this->Lifts[k],
        3.0 * rays.offset() + std::abs(glm::dot(root->corners()[c] - root->centre(), root->normal())));
  }
}

std::vector<LeafLight::Sample> LeafGather::at(
  std::size_t k, const FinalGather& gather, std::uint64_t pass, Bounce* bounce) const
{
  // A few rays from each point, no pilot: a point's rays meet many leaves, whose noise
  // averages out.
  GatherBudget budget;
  budget.pilot = 0;
  budget.minimum = budget.maximum = this->RaysPerPoint;
  const PolygonElement& leaf = *this->Leaves[k];
  SampleGenerator random(reseeded((leaf.id() * 0xD1342543DE82EF95ull + 1) ^ (pass * 0x9E3779B97F4A7C15ull), this->RandomSeed));
  std::vector<LeafLight::Sample> seen;
  Bounce sum;
  int buried = 0;
  auto gatherAt = [&](int p, int n) {
    const SurfaceSample at = leaf.sample(p, n, random);
    const Vec3 from = at.position + this->Lifts[k] * at.normal;
    const GatheredLight received =
      gather.irradianceAt(
        from, at.normal, budget, reseeded(this->Rays.seedOf(from), this->RandomSeed) ^ pass, 0.0, this->SurfacesSend);
    if (4 * received.backRays > received.count)
      ++buried;
    else
    {
      seen.push_back({ at.position, received.sky, received.surfaces });
      sum.interreflected += received.interreflected;
      sum.reflectanceSeen += received.reflectanceSeen;
    }
  };
  for (int p = 0; p < points; ++p)
    gatherAt(p, points);
  // A partly buried leaf: its open part may be a thin strip (a wall's foot above sloping
  // ground), which hits meet most from nearby.
  if (buried > 0)
  {
    seen.clear();
    sum = Bounce{};
    for (int p = 0; p < morePoints; ++p)
      gatherAt(p, morePoints);
  }
  if (bounce && !seen.empty())
    *bounce = { sum.interreflected / static_cast<double>(seen.size()), sum.reflectanceSeen / static_cast<double>(seen.size()) };
  return seen;
}

double HierarchyDeficit::after(int bounces) const
{
  return bounces == 0 ? this->relative : this->ofGathered * std::pow(this->bounceFactor, bounces);
}

HierarchyDeficit HierarchyDeficit::measure(const LeafGather& leaves, const FinalGather& gather, std::size_t sampled)
{
  const std::size_t count = leaves.leaves().size(), stride = std::max<std::size_t>(1, count / std::max<std::size_t>(1, sampled));
  const std::size_t taken = (count + stride - 1) / stride;
  // Per sampled leaf, by its area: R0, R1 and what its hits bring back of a change.
  std::vector<double> held(taken), gathered(taken), seenReflectance(taken), seenArea(taken);
  constexpr std::uint64_t probe = 0x5EED; // points and rays of their own
  tbb::parallel_for(std::size_t(0), taken, [&](std::size_t s) {
    const std::size_t k = s * stride;
    const PolygonElement& leaf = *leaves.leaves()[k];
    LeafGather::Bounce bounce;
    const std::vector<LeafLight::Sample> seen = leaves.at(k, gather, probe, &bounce);
    if (seen.empty())
      return;
    double reflected = 0.0;
    for (const LeafLight::Sample& sample : seen)
      reflected += largestBand(sample.reflected) / static_cast<double>(seen.size());
    held[s] = leaf.area() * largestBand(leaf.Irradiance[ReflectedLight]);
    gathered[s] = leaf.area() * reflected;
    seenReflectance[s] = leaf.area() * bounce.reflectanceSeen;
    seenArea[s] = leaf.area();
  });
  double r0 = 0.0, r1 = 0.0, reflectance = 0.0, area = 0.0;
  for (std::size_t s = 0; s < taken; ++s)
    r0 += held[s], r1 += gathered[s], reflectance += seenReflectance[s], area += seenArea[s];
  HierarchyDeficit deficit;
  if (!(r1 > 0.0) || !(area > 0.0))
    return deficit;
  deficit.bounceFactor = std::clamp(reflectance / area, 0.0, largestBounceFactor);
  const double e0 = std::abs(r1 - r0) / (1.0 - deficit.bounceFactor);
  // Where the leaves hold next to nothing (or noise) the quotient over R0 means
  // nothing: they are then taken as wrong by their whole value or more.
  deficit.relative = r0 > 0.05 * r1 ? std::min(maximumRelative, e0 / r0) : maximumRelative;
  deficit.ofGathered = std::min(1.0 / (1.0 - largestBounceFactor), e0 / r1);
  return deficit;
}
} // namespace terralux
