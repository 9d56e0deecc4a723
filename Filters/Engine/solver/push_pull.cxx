#include "solver/solver.h"

#include "hierarchy/cluster.h"
#include "solver/link_transport.h"
#include "hierarchy/polygon_element.h"
#include "emitters/external_source.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/visibility.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

// Solving on a fixed set of links: gather (sun and sky links held by surfaces), then
// push-pull, which evaluates the deferred links at each leaf and pulls radiosity up.
namespace terralux
{
void HierarchicalRadiosity::gather()
{
  // Sun and sky links stored on surfaces: their irradiance holds for every descendant
  // (same normal). Everything else is evaluated at the leaves during push.
  const auto& all = this->Store->all();
  tbb::parallel_for(std::size_t(0), all.size(), [&](std::size_t k) {
    HElement& element = *all[k];
    element.Gathered = {};
    element.GatheredPartial = 0.0;
    element.GatheredSkyView = 0.0;
    if (!element.isSurface() || !static_cast<PolygonElement&>(element).childrenShareNormal())
    {
      return; // evaluated at the leaves during push instead
    }
    for (const Link& link : element.Incoming)
    {
      const int category = lightCategoryOf(*link.sender);
      if (category == ReflectedLight)
      {
        continue;
      }
      const Spectrum emittance = link.sender->emittance();
      for (int band = 0; band < maxBands; ++band)
        element.Gathered[category][band] += link.kernel * link.visibility * emittance[band];
      if (link.visibility < 1.0)
      {
        element.GatheredPartial +=
          link.kernel * link.visibility * largestBand(emittance);
      }
      element.GatheredSkyView +=
        skyViewOf(*link.sender, static_cast<PolygonElement&>(element).normal(), link.kernel * link.visibility);
    }
  });
}

namespace
{
// A link waiting to be evaluated at the leaves below the element that stores it.
struct DeferredLink
{
  const Link* link;
  const HElement* owner;
};

// What push hands to one leaf: irradiance that holds for it as is, and the links to
// evaluate with its own geometry (a slice of a shared array).
// What a surface passes down unchanged: irradiance, its partially visible part, and
// its sky view.
struct Inherited
{
  std::array<Spectrum, lightCategories> irradiance{};
  double partial = 0.0;
  double skyView = 0.0;
};

struct LeafTask
{
  PolygonElement* leaf;
  Inherited inherited;
  std::size_t first;
  std::size_t count;
};

struct LeafResult
{
  Spectrum radiosity{}; // applied after every leaf is done (Jacobi), so no leaf reads
                        // a value another thread is writing
  double change = 0.0;
  double largestRadiosity = 0.0;
  double incidentPower = 0.0;
};

// Push, first half: walk down, collecting for each leaf the irradiance that passes
// unchanged (sun and sky gathered on a surface hold for its children, which share its
// normal) and the links to evaluate at the leaf (links stored on clusters, whose
// irradiance each contained surface takes by its own orientation, and links from other
// surfaces, evaluated with the leaf's own points at whatever level they live).
void collectLeafTasks(HElement& element, const Inherited& inherited, std::vector<DeferredLink>& deferred,
  std::vector<DeferredLink>& flat, std::vector<LeafTask>& tasks)
{
  const std::size_t mark = deferred.size();
  // Terrain patches pass nothing down as is: their children have normals of their own.
  const bool shareNormal = element.isSurface() && static_cast<PolygonElement&>(element).childrenShareNormal();
  for (const Link& link : element.Incoming)
  {
    if (!shareNormal || lightCategoryOf(*link.sender) == ReflectedLight)
      deferred.push_back({ &link, &element });
  }
  if (element.isSurface())
  {
    auto& polygon = static_cast<PolygonElement&>(element);
    Inherited passed = inherited;
    for (int c = 0; c < lightCategories; ++c)
      for (int band = 0; band < maxBands; ++band)
        passed.irradiance[c][band] += polygon.Gathered[c][band];
    passed.partial += polygon.GatheredPartial;
    passed.skyView += polygon.GatheredSkyView;
    if (!polygon.hasChildren())
    {
      tasks.push_back({ &polygon, passed, flat.size(), deferred.size() });
      flat.insert(flat.end(), deferred.begin(), deferred.end());
    }
    else
    {
      for (HElement* child : polygon.children())
        collectLeafTasks(*child, passed, deferred, flat, tasks);
    }
  }
  else
  {
    for (HElement* child : element.children())
      collectLeafTasks(*child, Inherited{}, deferred, flat, tasks);
  }
  deferred.resize(mark);
}

// Push, second half, for one leaf: its irradiance and radiosity. A partially visible
// link from above is re-sampled at the leaf, so shadow boundaries are resolved by the
// leaves even where no single link is worth refining.
LeafResult solveLeaf(const LeafTask& task, const DeferredLink* deferred, const Visibility& rays, int samples,
  double extrapolation)
{
  PolygonElement& polygon = *task.leaf;
  std::array<Spectrum, lightCategories> irradiance = task.inherited.irradiance;
  double skyView = task.inherited.skyView;
  // A kernel depends only on the link that reaches the leaf (sender, owner, the link's
  // own kernel and visibility): each is kept under that key and recomputed only for
  // links that refinement changed, not for every link of a leaf whose set changed.
  std::vector<std::uint64_t> keys(task.count);
  std::uint64_t signature = 1469598103934665603ull;
  for (std::size_t k = 0; k < task.count; ++k)
  {
    std::uint64_t key = 1469598103934665603ull, kernelBits, visibilityBits;
    std::memcpy(&kernelBits, &deferred[k].link->kernel, sizeof kernelBits);
    std::memcpy(&visibilityBits, &deferred[k].link->visibility, sizeof visibilityBits);
    for (std::uint64_t value : { deferred[k].link->sender->id(), deferred[k].owner->id(), kernelBits, visibilityBits })
      key = (key ^ value) * 1099511628211ull;
    keys[k] = key;
    signature = (signature ^ key) * 1099511628211ull;
  }
  if (polygon.LeafKernels.size() != task.count || polygon.LeafKernelSignature != signature)
  {
    std::unordered_map<std::uint64_t, std::pair<double, bool>> previous;
    for (std::size_t k = 0; k < polygon.LeafKernelKeys.size(); ++k)
      previous.emplace(polygon.LeafKernelKeys[k], std::make_pair(polygon.LeafKernels[k], polygon.LeafKernelPartial[k] != 0));
    polygon.LeafKernelSignature = signature;
    polygon.LeafKernels.resize(task.count);
    polygon.LeafKernelPartial.assign(task.count, 0);
    polygon.DeferredPartial = 0.0;
    polygon.DeferredSkyView = 0.0;
    for (std::size_t k = 0; k < task.count; ++k)
    {
      const DeferredLink& item = deferred[k];
      const Link& link = *item.link;
      const auto known = previous.find(keys[k]);
      bool partial;
      if (known != previous.end())
      {
        polygon.LeafKernels[k] = known->second.first;
        partial = known->second.second;
      }
      else if (item.owner == &polygon)
      {
        polygon.LeafKernels[k] = link.kernel * link.visibility;
        partial = link.visibility > 0.0 && link.visibility < 1.0;
      }
      else
      {
        const double visibility = link.visibility < 1.0 ? sampledVisibility(polygon, *link.sender, rays, samples) : 1.0;
        polygon.LeafKernels[k] = kernelAtSurface(polygon, *link.sender) * visibility;
        partial = visibility > 0.0 && visibility < 1.0;
      }
      polygon.LeafKernelPartial[k] = partial;
      if (partial)
        polygon.DeferredPartial += polygon.LeafKernels[k] * largestBand(link.sender->emittance());
      polygon.DeferredSkyView += skyViewOf(*link.sender, polygon.normal(), polygon.LeafKernels[k]);
    }
    polygon.LeafKernelKeys = std::move(keys);
  }
  for (std::size_t k = 0; k < task.count; ++k)
  {
    const Link& link = *deferred[k].link;
    const double transport = polygon.LeafKernels[k]; // kernel x visibility
    const Spectrum e = link.sender->emittance();
    const int category = lightCategoryOf(*link.sender);
    for (int band = 0; band < maxBands; ++band)
      irradiance[category][band] += transport * e[band];
  }
  skyView += polygon.DeferredSkyView;
  polygon.Irradiance = irradiance;
  polygon.SkyViewFactor = skyView;
  polygon.PartialIrradiance = task.inherited.partial + polygon.DeferredPartial;
  LeafResult result;
  const Spectrum total = totalIrradiance(irradiance[SunLight], irradiance[SkyLight], irradiance[ReflectedLight]);
  result.radiosity = radiosityOf(polygon.emission(), polygon.reflectance(), total);
  const double incident = largestBand(total);
  for (int band = 0; band < maxBands; ++band)
  {
    if (extrapolation > 0.0)
    {
      result.radiosity[band] = std::max(polygon.emission()[band],
        result.radiosity[band] + extrapolation * (result.radiosity[band] - polygon.Radiosity[band]));
    }
    result.change = std::max(result.change, std::abs(result.radiosity[band] - polygon.Radiosity[band]));
    result.largestRadiosity = std::max(result.largestRadiosity, result.radiosity[band]);
  }
  result.incidentPower = incident * polygon.area();
  return result;
}

// Pull: area-weighted radiosity up the hierarchy.
Spectrum pullRadiosity(HElement& element)
{
  if (element.isSurface() && !static_cast<PolygonElement&>(element).hasChildren())
  {
    return element.Radiosity;
  }
  Spectrum radiosity{};
  double area = 0.0;
  for (HElement* child : element.children())
  {
    const Spectrum b = pullRadiosity(*child);
    for (int band = 0; band < maxBands; ++band)
      radiosity[band] += b[band] * child->area();
    area += child->area();
  }
  for (double& value : radiosity)
    value /= area;
  element.Radiosity = radiosity;
  return radiosity;
}
} // namespace

double HierarchicalRadiosity::pushPull(double extrapolation)
{
  std::vector<DeferredLink> deferred, flat;
  std::vector<LeafTask> tasks;
  collectLeafTasks(*this->RootCluster, Inherited{}, deferred, flat, tasks);

  std::vector<LeafResult> results(tasks.size());
  tbb::parallel_for(std::size_t(0), tasks.size(), [&](std::size_t k) {
    results[k] = solveLeaf(tasks[k], flat.data() + tasks[k].first, *this->Rays,
      this->Options.visibilitySamples, extrapolation);
  });
  double change = 0.0, radiosity = 0.0, incident = 0.0;
  for (std::size_t k = 0; k < tasks.size(); ++k) // in leaf order: the same for any thread count
  {
    const LeafResult& r = results[k];
    tasks[k].leaf->Radiosity = r.radiosity;
    change = std::max(change, r.change);
    radiosity = std::max(radiosity, r.largestRadiosity);
    incident += r.incidentPower;
  }
  pullRadiosity(*this->RootCluster);
  // The oracle's tolerance is relative to the power the scene receives, which
  // interreflection raises above the direct estimate.
  this->Stats.referencePowerW = std::max(this->Stats.referencePowerW, incident);
  this->LargestRadiosity = radiosity;
  return change;
}

} // namespace terralux
