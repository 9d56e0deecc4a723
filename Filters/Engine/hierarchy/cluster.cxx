#include "hierarchy/cluster.h"

#include "hierarchy/polygon_element.h"

#include <algorithm>
#include <limits>

namespace terralux
{
Cluster::Cluster(
  std::uint64_t id, int level, std::vector<HElement*> members, std::vector<PolygonElement*> surfaces)
  : HElement(id, level)
  , Members(std::move(members))
  , Surfaces(std::move(surfaces))
{
  this->Low = Vec3(std::numeric_limits<double>::max());
  this->High = Vec3(-std::numeric_limits<double>::max());
  this->CumulativeArea.reserve(this->Surfaces.size());
  for (PolygonElement* surface : this->Surfaces)
  {
    this->Area += surface->area();
    this->WeightedNormal += surface->area() * surface->normal();
    this->CumulativeArea.push_back(this->Area);
    this->SmallestSurfaceArea = this->SmallestSurfaceArea > 0.0 ? std::min(this->SmallestSurfaceArea, surface->area())
                                                                : surface->area();
    for (int band = 0; band < maxBands; ++band)
    {
      this->LargestReflectance = std::max(this->LargestReflectance, surface->reflectance()[band]);
      this->LargestEmission = std::max(this->LargestEmission, surface->emission()[band]);
    }
    Vec3 low, high;
    surface->bounds(low, high);
    this->Low = glm::min(this->Low, low);
    this->High = glm::max(this->High, high);
  }
}

SurfaceSample Cluster::sample(int k, int n, SampleGenerator& random) const
{
  // Stratified in cumulative area: each sample picks a surface in proportion to area.
  const double target = (k + random.uniform()) / n * this->Area;
  const std::size_t index = std::min<std::size_t>(
    std::lower_bound(this->CumulativeArea.begin(), this->CumulativeArea.end(), target) -
      this->CumulativeArea.begin(),
    this->Surfaces.size() - 1);
  return this->Surfaces[index]->sample(0, 1, random);
}

double Cluster::projectedArea(const Vec3& w) const
{
  return std::max(0.0, glm::dot(this->WeightedNormal, w)) + 0.25 * (this->Area - glm::length(this->WeightedNormal));
}

Cluster* Cluster::build(
  ElementStore& store, std::vector<PolygonElement*> polygons, int level, std::size_t leafSize)
{
  std::vector<HElement*> members;
  if (polygons.size() <= leafSize)
  {
    members.assign(polygons.begin(), polygons.end());
  }
  else
  {
    Vec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
    for (PolygonElement* p : polygons)
    {
      low = glm::min(low, p->centre());
      high = glm::max(high, p->centre());
    }
    const Vec3 extent = high - low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t half = polygons.size() / 2;
    std::nth_element(polygons.begin(), polygons.begin() + half, polygons.end(),
      [axis](const PolygonElement* a, const PolygonElement* b) {
        return a->centre()[axis] < b->centre()[axis] || (a->centre()[axis] == b->centre()[axis] && a->id() < b->id());
      });
    std::vector<PolygonElement*> left(polygons.begin(), polygons.begin() + half);
    std::vector<PolygonElement*> right(polygons.begin() + half, polygons.end());
    members.push_back(build(store, std::move(left), level + 1, leafSize));
    members.push_back(build(store, std::move(right), level + 1, leafSize));
  }
  Cluster* cluster = store.make<Cluster>(level, members, std::move(polygons));
  for (HElement* member : members)
  {
    member->Parent = cluster;
  }
  return cluster;
}
} // namespace terralux
