#include "solver.h"

#include "bf_oracle.h"
#include "cluster.h"
#include "error.h"
#include "final_gather.h"
#include "open_sky.h"
#include "link_transport.h"
#include "polygon_element.h"
#include "sky_hierarchy.h"
#include "sky_patch_element.h"
#include "terrain_mesh.h"
#include "terrain_patch.h"
#include "visibility.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace terralux
{
namespace
{
constexpr double pi = 3.14159265358979323846;

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

HierarchicalRadiosity::HierarchicalRadiosity(const RadiosityScene& scene, const RadiosityOptions& options)
  : Options(options)
  , Store(std::make_unique<ElementStore>())
{
  if (options.visibilitySamples < 1 || options.maximumIterations < 1 || !(options.errorTolerance > 0.0) ||
    options.gatherSamples < 0 || !(options.gatherError > 0.0))
  {
    throw Error("radiosity options: VisibilitySamples and MaximumIterations must be >= 1, "
                "ErrorTolerance > 0, MaximumGatherRays >= 0 and GatherError > 0");
  }
  std::vector<PolygonElement*>& polygons = this->TopSurfaces;
  this->Roots.assign(scene.polygons.size(), nullptr);
  for (std::size_t k = 0; k < scene.polygons.size(); ++k)
  {
    const ScenePolygon& input = scene.polygons[k];
    Vec3 corners[4];
    bool finite = true;
    for (int c = 0; c < input.vertexCount; ++c)
    {
      corners[c] = scene.points[input.vertices[c]];
      finite = finite && std::isfinite(corners[c].x) && std::isfinite(corners[c].y) && std::isfinite(corners[c].z);
    }
    Vec3 normal;
    const double area = finite ? PolygonElement::areaAndNormal(corners, input.vertexCount, normal) : 0.0;
    if (!(area > 0.0))
    {
      ++this->Degenerate;
      continue;
    }
    PolygonElement* element = this->Store->make<PolygonElement>(
      0, this->Store.get(), corners, input.vertexCount, input.reflectance, input.emission, static_cast<int>(k));
    this->Roots[k] = element;
    polygons.push_back(element);
    this->SceneArea += area;
  }
  for (std::size_t k = 0; k < scene.terrains.size(); ++k)
  {
    std::vector<TerrainPatch*> complete;
    this->TerrainRoots.push_back(
      TerrainPatch::buildTree(*this->Store, *scene.terrains[k], static_cast<int>(k), complete));
    for (TerrainPatch* patch : complete)
    {
      polygons.push_back(patch);
      this->SceneArea += patch->area();
    }
  }
  if (polygons.empty())
  {
    throw Error("the scene has no polygon or terrain cell with a non-zero area");
  }
  this->Store->MinimumArea =
    options.minimumElementArea > 0.0 ? options.minimumElementArea : 1e-6 * this->SceneArea;
  this->Store->MaximumSkyLevel = options.maximumSkyLevel;
  this->RootCluster = Cluster::build(*this->Store, polygons, 0);

  const auto start = std::chrono::steady_clock::now();
  this->Rays = std::make_unique<Visibility>(scene);
  this->PointCount = scene.points.size();
  for (const TerrainGrid* terrain : scene.terrains)
    this->PointCount += static_cast<std::size_t>(terrain->postsX()) * terrain->postsY();
  this->Gather = std::make_unique<FinalGather>(*this->Rays, this->Roots, this->TerrainRoots, this->Suns);
  this->Stats.secondsVisibilityBuild = secondsSince(start);
}

HierarchicalRadiosity::~HierarchicalRadiosity() = default;

std::uint64_t HierarchicalRadiosity::raysCast() const
{
  return this->Rays->raysCast();
}

void HierarchicalRadiosity::addSun(const Vec3& directionTowardSun, const Spectrum& normalIrradiance, double duration)
{
  // A sun at or below the horizon lights nothing: beyond the scene's edge the ground
  // would hide it, and inside the scene steep slopes that face it are shadowed anyway;
  // it gets no element and no links (they would only refine toward edge slopes).
  if (largestBand(normalIrradiance) > 0.0 && glm::length(directionTowardSun) > 0.0 && directionTowardSun.z > 0.0)
    this->PointSuns.push_back(this->Store->make<SunElement>(0, directionTowardSun, normalIrradiance, duration));
}

void HierarchicalRadiosity::setSky(const SkyHierarchy* sky)
{
  this->Sky = sky;
  this->SkyAtPoints = sky ? std::make_unique<OpenSky>(*sky) : nullptr;
  this->Gather->setSky(this->SkyAtPoints.get());
  this->SkyRoot = sky ? this->Store->make<SkyPatchElement>(0, this->Store.get(), sky, SkyPatch{ 0, 0, 0 }) : nullptr;
}

OracleSettings HierarchicalRadiosity::oracleSettings() const
{
  OracleSettings oracle;
  oracle.powerThreshold = this->Options.errorTolerance * this->Stats.referencePowerW;
  oracle.sceneArea = this->SceneArea;
  oracle.meanIrradiance = this->SceneArea > 0.0 ? this->Stats.referencePowerW / this->SceneArea : 0.0;
  oracle.irradianceThreshold = 5.0 * this->Options.errorTolerance * oracle.meanIrradiance;
  return oracle;
}

double HierarchicalRadiosity::referencePower() const
{
  // Direct light on every polygon without occlusion, plus emission: the scale of the
  // oracle's tolerance.
  double total = 0.0;
  for (const PolygonElement* polygon : this->TopSurfaces)
  {
    double incident = 0.0;
    for (int band = 0; band < maxBands; ++band)
    {
      double e = polygon->emission()[band];
      for (const HElement* sun : this->Suns)
        e += sun->emittance()[band] *
          std::max(0.0, glm::dot(polygon->normal(), static_cast<const SunElement*>(sun)->direction()));
      if (this->Sky)
      {
        e += this->Sky->horizontalIrradiance(std::min(band, this->Sky->bands() - 1)) *
          0.5 * (1.0 + polygon->normal().z);
      }
      incident = std::max(incident, e);
    }
    total += incident * polygon->area();
  }
  return total;
}

bool HierarchicalRadiosity::mayGrow()
{
  // Links count too: at tight tolerances every pair of small elements wants a link, so
  // links can grow as the square of the elements while hardly any element is added.
  if (this->Store->size() < this->Options.maximumElements &&
    this->StoredLinks + this->PendingLinks < 4 * this->Options.maximumElements)
    return true;
  this->Stats.elementBudgetReached = true;
  return false;
}

std::size_t HierarchicalRadiosity::refine(std::vector<std::pair<HElement*, Link>>& pending, bool evaluated)
{
  std::size_t splits = 0;
  OracleSettings oracle = this->oracleSettings();
  std::vector<std::pair<HElement*, Link>> next;
  // New, not yet evaluated links from every child of `split` to / from `other`.
  auto addChildLinks = [&next](HElement* receiver, HElement* sender, bool splitReceiver) {
    for (HElement* child : (splitReceiver ? receiver : sender)->children())
    {
      Link sub;
      sub.sender = splitReceiver ? sender : child;
      next.emplace_back(splitReceiver ? child : receiver, sub);
    }
  };
  while (!pending.empty())
  {
    if (!evaluated)
    {
      tbb::parallel_for(std::size_t(0), pending.size(), [&](std::size_t k) {
        HElement* receiver = pending[k].first;
        HElement* sender = pending[k].second.sender;
        if (receiver != sender)
        {
          pending[k].second = evaluateLink(*receiver, *sender, *this->Rays, this->Options.visibilitySamples);
        }
      });
    }
    next.clear();
    for (auto& [receiver, link] : pending)
    {
      this->PendingLinks = pending.size() + next.size();
      HElement* sender = link.sender;
      if (receiver == sender)
      {
        // A cluster's self-link becomes links between all pairs of its members;
        // a planar surface does not light itself.
        if (receiver->isCluster())
        {
          for (HElement* member : receiver->children())
            addChildLinks(receiver, member, true);
        }
        else if (lightsItself(*receiver, oracle) && this->mayGrow() && !receiver->children().empty())
        {
          ++splits;
          for (HElement* part : receiver->children())
            addChildLinks(receiver, part, true);
        }
        continue;
      }
      if (!(link.kernel > 0.0 && link.visibility > 0.0) &&
        (clusterMayCarryMore(*receiver, link, oracle) || modelMissesExchange(*receiver, link, oracle)))
      {
        // A cluster's centre direction or its few samples saw nothing, but its members
        // may: split (the side decideRefinement picks) rather than drop.
        const Refinement decision = this->mayGrow() ? decideRefinement(*receiver, link, oracle) : Refinement::Keep;
        if (decision != Refinement::Keep)
        {
          ++splits;
          addChildLinks(receiver, sender, decision == Refinement::SplitReceiver);
        }
        continue;
      }
      if (!(link.kernel > 0.0))
      {
        // Carries nothing, now or later; but a rough terrain patch facing away from a
        // sky patch on average may hold slopes facing it: split while those could matter.
        Link rough = link;
        rough.kernel = link.kernelSpread;
        rough.visibility = 1.0;
        if (receiver->canSplit() && linkPower(*receiver, rough) > oracle.partialVisibilityFactor * oracle.powerThreshold &&
          this->mayGrow())
        {
          ++splits;
          addChildLinks(receiver, sender, true);
        }
        continue;
      }
      if (!(link.visibility > 0.0))
      {
        // No sample saw the sender; parts of a large receiver still may. Split the
        // receiver while the unoccluded transport would matter, else drop the link.
        Link unoccluded = link;
        unoccluded.visibility = 1.0;
        if (receiver->canSplit() &&
          linkPower(*receiver, unoccluded) > oracle.partialVisibilityFactor * oracle.powerThreshold && this->mayGrow())
        {
          ++splits;
          addChildLinks(receiver, sender, true);
        }
        continue;
      }
      const Refinement decision = decideRefinement(*receiver, link, oracle);
      if (decision != Refinement::Keep && !this->mayGrow())
      {
        receiver->Incoming.push_back(link); // over budget: the link stays as it is
        ++this->StoredLinks;
        continue;
      }
      switch (decision)
      {
        case Refinement::Keep:
          receiver->Incoming.push_back(link);
          ++this->StoredLinks;
          break;
        case Refinement::SplitReceiver:
          ++splits;
          addChildLinks(receiver, sender, true);
          break;
        case Refinement::SplitSender:
          ++splits;
          addChildLinks(receiver, sender, false);
          break;
      }
    }
    pending.swap(next);
    evaluated = false;
  }
  this->PendingLinks = 0;
  return splits;
}

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
  double incident = 0.0;
  for (int band = 0; band < maxBands; ++band)
  {
    const double total = irradiance[0][band] + irradiance[1][band] + irradiance[2][band];
    incident = std::max(incident, total);
    result.radiosity[band] = polygon.emission()[band] + polygon.reflectance()[band] * total;
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

std::size_t HierarchicalRadiosity::splitLeaves(const std::vector<PolygonElement*>& leaves)
{
  if (leaves.empty() || !this->mayGrow())
    return 0;
  // The leaves' links move to their children, evaluated and refined there.
  std::vector<std::pair<HElement*, Link>> pending;
  for (PolygonElement* polygon : leaves)
  {
    for (HElement* child : polygon->children())
      for (const Link& link : polygon->Incoming)
      {
        Link sub;
        sub.sender = link.sender;
        pending.emplace_back(child, sub);
      }
    this->StoredLinks -= polygon->Incoming.size();
    polygon->Incoming.clear();
  }
  if (!pending.empty())
  {
    this->refine(pending, false);
  }
  return leaves.size();
}

std::size_t HierarchicalRadiosity::splitShadowedLeaves()
{
  // A leaf lit through many partially visible links, none worth refining alone, still
  // averages a shadow over its area: split it when that light carries enough power.
  const double threshold = this->Options.errorTolerance * this->Stats.referencePowerW;
  std::vector<PolygonElement*> leaves;
  for (const auto& element : this->Store->all())
  {
    if (!element->isSurface())
      continue;
    auto* polygon = static_cast<PolygonElement*>(element.get());
    if (!polygon->hasChildren() && polygon->canSplit() && polygon->PartialIrradiance * polygon->area() > threshold)
      leaves.push_back(polygon);
  }
  return this->splitLeaves(leaves);
}

std::size_t HierarchicalRadiosity::restrictTerrainMeshes()
{
  // Restricted subdivision (paper section 4.2): no leaf has a neighbour more than one
  // level finer, i.e. more than one T-vertex on an edge, so shading varies gradually
  // from coarse to fine leaves. Splits cascade outward until none is needed.
  std::size_t splits = 0;
  for (;;)
  {
    std::vector<PolygonElement*> leaves;
    for (const TerrainPatch* root : this->TerrainRoots)
    {
      if (!root)
        continue;
      const TerrainLeafMesh mesh(*root);
      for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
      {
        // Ids are positions in the store, which owns the (mutable) element.
        auto* leaf = static_cast<PolygonElement*>(this->Store->all()[mesh.leaves()[k]->id()].get());
        if (mesh.mostTVerticesOnAnEdge(k) > 1 && leaf->canSplit())
          leaves.push_back(leaf);
      }
    }
    const std::size_t split = leaves.empty() ? 0 : this->splitLeaves(leaves);
    if (split == 0)
      return splits; // done, or over the element budget
    splits += split;
  }
}

void HierarchicalRadiosity::mergeSuns()
{
  this->Suns = this->PointSuns;
  if (this->PointSuns.size() <= maximumSolveSuns)
    return;
  constexpr double degree = 3.14159265358979323846 / 180.0;
  struct Merged
  {
    Spectrum flux{};
    Vec3 direction{ 0.0 };
    double duration = 0.0;
  };
  std::map<std::pair<int, int>, Merged> bins; // ordered: the same suns in the same order every run
  for (const HElement* element : this->PointSuns)
  {
    const auto& sun = static_cast<const SunElement&>(*element);
    const Vec3& d = sun.direction();
    const double altitude = std::asin(std::min(1.0, d.z));
    const double azimuth = std::atan2(d.x, d.y) + 3.14159265358979323846;
    const double azimuthWidth = mergedSunDegrees * degree / std::max(std::cos(altitude), 0.05);
    Merged& bin = bins[{ static_cast<int>(altitude / (mergedSunDegrees * degree)),
      static_cast<int>(azimuth / azimuthWidth) }];
    const Spectrum flux = sun.emittance();
    for (int band = 0; band < maxBands; ++band)
      bin.flux[band] += flux[band];
    bin.direction += largestBand(flux) * d;
    bin.duration += sun.duration();
  }
  this->Suns.clear();
  for (const auto& entry : bins)
    this->Suns.push_back(this->Store->make<SunElement>(
      0, glm::normalize(entry.second.direction), entry.second.flux, entry.second.duration));
}

bool HierarchicalRadiosity::solve(RadiosityProgress* progress)
{
  this->mergeSuns();
  // Many points to evaluate: the open sky of each point's plane from a table over
  // normals (16,641 exact evaluations) rather than one exact evaluation per point.
  if (this->SkyAtPoints && this->Options.gatherSamples > 0 && this->PointCount > openSkyTablePoints)
    this->SkyAtPoints->tabulate(128);
  this->Stats.referencePowerW = this->referencePower();
  this->Gather->prepareSuns();
  std::vector<std::pair<HElement*, Link>> pending;
  auto addInitial = [&](HElement* sender) {
    if (sender)
    {
      Link link;
      link.sender = sender;
      pending.emplace_back(this->RootCluster, link);
    }
  };
  addInitial(this->RootCluster); // the self-link (paper Fig. 3)
  for (HElement* sun : this->Suns)
    addInitial(sun);
  addInitial(this->SkyRoot);

  // Clusters start with the area-weighted emission of their surfaces, so the oracle
  // sees emitters before the first gather.
  this->pushPull();
  auto start = std::chrono::steady_clock::now();
  std::uint64_t rays = this->Rays->raysCast();
  // Rays cast since the last call, for the phase that cast them.
  auto raysSince = [&]() {
    const std::uint64_t now = this->Rays->raysCast(), since = now - rays;
    rays = now;
    return since;
  };
  this->refine(pending, false);
  this->Stats.secondsRefine += secondsSince(start);
  this->Stats.raysRefine += raysSince();

  // Gathering is a Jacobi iteration: its change shrinks by about the scene's
  // reflectance each time. The remaining change is estimated from that ratio, and where
  // it is high (bright closed scenes) and steady, B jumps ahead by the geometric sum.
  double previousChange = 0.0, previousRatio = -1.0, knownRatio = 0.0;
  int steadyIterations = 0; // iterations since the structure or an extrapolation changed
  double extrapolation = 0.0;
  for (int iteration = 0; iteration < this->Options.maximumIterations; ++iteration)
  {
    start = std::chrono::steady_clock::now();
    this->gather();
    this->Stats.secondsGather += secondsSince(start);
    start = std::chrono::steady_clock::now();
    const double absoluteChange = this->pushPull(extrapolation);
    const double change = this->LargestRadiosity > 0.0 ? absoluteChange / this->LargestRadiosity : 0.0;
    this->Stats.secondsPushPull += secondsSince(start);
    this->Stats.raysPushPull += raysSince();
    this->Stats.iterations = iteration + 1;
    if (progress && !progress->report(static_cast<double>(iteration + 1) / this->Options.maximumIterations))
    {
      return false;
    }
    const bool extrapolated = extrapolation > 0.0;
    extrapolation = 0.0;
    // The ratio of absolute changes (relative ones shrink also because B grows).
    const double ratio = steadyIterations > 0 && previousChange > 0.0 ? absoluteChange / previousChange : -1.0;
    if (ratio >= 0.0)
      knownRatio = ratio; // else (just after a change of structure) the last one measured
    this->Stats.residual =
      knownRatio < 1.0 ? change / (1.0 - knownRatio) : std::numeric_limits<double>::infinity();
    const bool converged = change == 0.0 || (!extrapolated && this->Stats.residual < this->Options.convergenceTolerance);
    // Leaves split now get their irradiance in the next iteration, so the last one
    // splits nothing.
    const bool last = iteration + 1 == this->Options.maximumIterations;
    const std::size_t splits = last ? 0 : this->splitShadowedLeaves() + this->restrictTerrainMeshes();
    if ((converged && splits == 0) || last)
    {
      this->Stats.converged = converged;
      break;
    }
    // Radiosity changed: links that now carry too much power are refined further;
    // the others stay where they are.
    start = std::chrono::steady_clock::now();
    const OracleSettings oracle = this->oracleSettings();
    pending.clear();
    const std::size_t count = this->Store->size(); // refinement appends elements
    for (std::size_t k = 0; k < count; ++k)
    {
      HElement* element = this->Store->all()[k].get();
      auto& links = element->Incoming;
      auto keep = std::stable_partition(links.begin(), links.end(),
        [&](const Link& link) { return decideRefinement(*element, link, oracle) == Refinement::Keep; });
      for (auto it = keep; it != links.end(); ++it)
        pending.emplace_back(element, *it);
      this->StoredLinks -= static_cast<std::size_t>(links.end() - keep);
      links.erase(keep, links.end());
    }
    if (!pending.empty())
    {
      this->refine(pending, true);
    }
    this->Stats.secondsRefine += secondsSince(start);
    this->Stats.raysRefine += raysSince(); // with the leaf splits of the iteration

    const bool structureChanged = splits > 0 || !pending.empty();
    steadyIterations = structureChanged || extrapolated ? 0 : steadyIterations + 1;
    // Two equal ratios in a row, and a slow one: extrapolate in the next push.
    if (steadyIterations >= 2 && ratio > 0.5 && ratio < 1.0 && std::abs(ratio - previousRatio) < 0.01 * ratio)
    {
      extrapolation = std::min(1e6, ratio / (1.0 - ratio));
      steadyIterations = 0;
    }
    previousRatio = ratio;
    previousChange = absoluteChange;
  }

  this->Stats.elements = this->Store->size();
  this->Stats.links = 0;
  for (const auto& element : this->Store->all())
    this->Stats.links += element->Incoming.size();
  this->Stats.rays = this->Rays->raysCast();
  if (progress)
  {
    progress->report(1.0);
  }
  return true;
}
} // namespace terralux
