#include "solver/solver.h"

#include "base/angles.h"
#include "base/elapsed.h"
#include "solver/bf_oracle.h"
#include "hierarchy/cluster.h"
#include "base/error.h"
#include "visibility/scene_geometry.h"
#include "solver/link_transport.h"
#include "hierarchy/polygon_element.h"
#include "sky/sky_hierarchy.h"
#include "emitters/sky_patch_element.h"
#include "emitters/sun_element.h"
#include "terrain/terrain_mesh.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/visibility.h"

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
HierarchicalRadiosity::HierarchicalRadiosity(
  const RadiosityScene& scene, const RadiosityOptions& options, std::shared_ptr<SceneGeometry> geometry)
  : Options(options)
  , Store(std::make_unique<ElementStore>())
  , Sources(std::make_unique<ElementStore>(firstSourceId))
{
  if (options.visibilitySamples < 1 || options.maximumIterations < 1 || !(options.errorTolerance > 0.0) ||
    options.gatherSamples < 0 || !(options.targetError > 0.0) ||
    !(options.targetErrorFloor >= 0.0 && options.targetErrorFloor <= std::numeric_limits<double>::max()) || options.farTerrainStride < 1 ||
    !(options.gatherDetailDistance >= 0.0 && options.gatherDetailDistance <= std::numeric_limits<double>::max()))
  {
    throw Error("radiosity options: VisibilitySamples and MaximumIterations must be >= 1, "
                "ErrorTolerance > 0, MaximumGatherRays >= 0, TargetError > 0, TargetErrorFloor >= 0, FarTerrainStride >= 1 and "
                "DetailDistance finite and >= 0");
  }
  const auto hierarchyStart = std::chrono::steady_clock::now();
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
  // With a far sight, the hierarchy is solved on the far terrain: light from surfaces
  // varies slowly, and points gather near them at the full resolution.
  this->PostGrids = scene.terrains;
  this->HierarchyTerrain = FarTerrain::of(scene, options.farSight());
  this->Window = this->HierarchyTerrain && scene.farTerrain.grid;
  for (std::size_t k = 0; k < scene.terrains.size(); ++k)
  {
    std::vector<TerrainPatch*> complete;
    const TerrainGrid& grid = this->HierarchyTerrain ? this->HierarchyTerrain->grid() : *scene.terrains[k];
    this->TerrainRoots.push_back(TerrainPatch::buildTree(*this->Store, grid, static_cast<int>(k), complete));
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
  this->Sources->MaximumSkyLevel = options.maximumSkyLevel;
  this->RootCluster = Cluster::build(*this->Store, polygons, 0);
  this->InitialElements = this->Store->size();
  this->Stats.secondsHierarchyBuild = secondsSince(hierarchyStart);

  const auto start = std::chrono::steady_clock::now();
  const bool reused = geometry && geometry->sameShape(scene, options.farSight());
  this->Geometry = reused ? std::move(geometry) : std::make_shared<SceneGeometry>(scene, options.farSight());
  this->Rays = &this->Geometry->hierarchyRays();
  this->RaysBefore = this->Rays->raysCast();
  this->PointCount = scene.points.size();
  for (const TerrainGrid* terrain : scene.terrains)
    this->PointCount += static_cast<std::size_t>(terrain->postsX()) * terrain->postsY();
  // A window counts the whole grid's posts (from its far terrain's): what it decides
  // (the open sky's table) must be the same on every process.
  if (this->Window)
  {
    const TerrainGrid& far = this->HierarchyTerrain->grid();
    const auto stride = static_cast<std::size_t>(scene.farTerrain.stride);
    this->PointCount = static_cast<std::size_t>(far.postsX()) * far.postsY() * stride * stride;
  }
  // A window decides by the far terrain, the same on every process.
  this->HeightField = options.skyFromHorizons && scene.polygons.empty() &&
    (this->Window ? this->HierarchyTerrain->grid().facesUp()
                  : std::all_of(scene.terrains.begin(), scene.terrains.end(),
                      [](const TerrainGrid* t) { return t->facesUp(); }));
  if (this->HeightField && scene.terrains.size() == 1)
    this->HeightFieldGrid = scene.terrains.front();
  this->Stats.secondsVisibilityBuild = reused ? 0.0 : secondsSince(start);
}

HierarchicalRadiosity::~HierarchicalRadiosity() = default;

const TerrainGrid& HierarchicalRadiosity::postGrid(const TerrainPatch& root) const
{
  return *this->PostGrids[static_cast<std::size_t>(root.terrain())];
}

const TerrainPatch* HierarchicalRadiosity::leafAtPost(const TerrainPatch& root, int i, int j) const
{
  if (!this->HierarchyTerrain)
    return root.mostLitLeafAt(i, j);
  // A post of the far terrain's takes the most lit leaf around it, as there; others
  // lie inside one of its cells.
  const double u = this->HierarchyTerrain->coarseU(i), v = this->HierarchyTerrain->coarseV(j);
  if (u == std::floor(u) && v == std::floor(v))
    return root.mostLitLeafAt(static_cast<int>(u), static_cast<int>(v));
  return root.leafHolding(u, v);
}

bool operator==(const RadiosityOptions& a, const RadiosityOptions& b)
{
  static_assert(sizeof(RadiosityOptions) == 104, "an option was added: compare it here");
  return a.errorTolerance == b.errorTolerance && a.minimumElementArea == b.minimumElementArea &&
    a.visibilitySamples == b.visibilitySamples && a.maximumIterations == b.maximumIterations &&
    a.convergenceTolerance == b.convergenceTolerance && a.maximumSkyLevel == b.maximumSkyLevel &&
    a.maximumElements == b.maximumElements && a.gatherSamples == b.gatherSamples &&
    a.targetError == b.targetError && a.targetErrorFloor == b.targetErrorFloor && a.skyFromHorizons == b.skyFromHorizons &&
    a.gatherDetailDistance == b.gatherDetailDistance && a.farTerrainStride == b.farTerrainStride &&
    a.randomSeed == b.randomSeed;
}

bool HierarchicalRadiosity::serves(const RadiosityScene& scene, const RadiosityOptions& options) const
{
  // The cheap comparisons first: the shape's reads every post.
  if (options != this->Options || scene.polygons.size() != this->Roots.size() ||
    scene.terrains.size() != this->TerrainRoots.size())
    return false;
  for (std::size_t k = 0; k < scene.polygons.size(); ++k)
  {
    const PolygonElement* root = this->Roots[k]; // null for degenerate ones, in both
    if (root &&
      (root->reflectance() != scene.polygons[k].reflectance || root->emission() != scene.polygons[k].emission))
      return false;
  }
  for (std::size_t k = 0; k < scene.terrains.size(); ++k)
    if (!this->PostGrids[k]->sameMaterials(*scene.terrains[k]))
      return false;
  return this->Geometry->sameShape(scene, options.farSight());
}

std::size_t HierarchicalRadiosity::elementCount() const
{
  return this->Store->size() + this->Sources->size() + (this->MergedSuns ? this->MergedSuns->size() : 0);
}

bool HierarchicalRadiosity::seesFarTerrain() const
{
  return this->Geometry->pointRays().farTerrain() != nullptr;
}

std::vector<PolygonElement*> HierarchicalRadiosity::surfaceLeaves()
{
  std::vector<PolygonElement*> leaves;
  for (const auto& element : this->Store->all())
    if (element->isSurface() && !static_cast<PolygonElement&>(*element).hasChildren())
      leaves.push_back(static_cast<PolygonElement*>(element.get()));
  return leaves;
}

std::uint64_t HierarchicalRadiosity::raysCast() const
{
  return this->Rays->raysCast() - this->RaysBefore;
}

void HierarchicalRadiosity::addSun(const Vec3& directionTowardSun, const Spectrum& normalIrradiance, double duration)
{
  // A sun at or below the horizon lights nothing: beyond the scene's edge the ground
  // would hide it, and inside the scene steep slopes that face it are shadowed anyway;
  // it gets no element and no links (they would only refine toward edge slopes).
  if (largestBand(normalIrradiance) > 0.0 && glm::length(directionTowardSun) > 0.0 && directionTowardSun.z > 0.0)
    this->PointSuns.push_back(this->Sources->make<SunElement>(0, directionTowardSun, normalIrradiance, duration));
}

void HierarchicalRadiosity::setSky(const SkyHierarchy* sky)
{
  this->Sky = sky;
  this->SkyRoot =
    sky ? this->Sources->make<SkyPatchElement>(0, this->Sources.get(), sky, SkyPatch{ 0, 0, 0 }) : nullptr;
}

void HierarchicalRadiosity::clearSources()
{
  this->restart();
  this->PointSuns.clear();
  this->SkyRoot = nullptr;
  this->Sky = nullptr;
  this->Sources = std::make_unique<ElementStore>(firstSourceId);
  this->Sources->MaximumSkyLevel = this->Options.maximumSkyLevel;
}

void HierarchicalRadiosity::restart()
{
  this->Store->restore(this->InitialElements);
  this->StoredLinks = 0;
  this->PendingLinks = 0;
  this->LargestRadiosity = 0.0;
  this->Suns.clear();
  this->MergedSuns.reset();
  // The hierarchy and the geometry were built for the first solve only.
  const RadiosityStatistics built = this->Stats;
  this->Stats = RadiosityStatistics();
  this->Stats.secondsHierarchyBuild = this->Solved ? 0.0 : built.secondsHierarchyBuild;
  this->Stats.secondsVisibilityBuild = this->Solved ? 0.0 : built.secondsVisibilityBuild;
  this->RaysBefore = this->Rays->raysCast();
  this->Solved = true;
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
          sun->asExternal()->kernel(polygon->normal());
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

void HierarchicalRadiosity::mergeSuns()
{
  this->Suns = this->PointSuns;
  if (this->PointSuns.size() <= Tuning::maximumSolveSuns)
    return;
  struct Merged
  {
    Spectrum flux{};
    Vec3 direction{ 0.0 };
  };
  std::map<std::pair<int, int>, Merged> bins; // ordered: the same suns in the same order every run
  for (const HElement* element : this->PointSuns)
  {
    const ExternalSource& sun = *element->asExternal();
    const Vec3& d = sun.direction();
    const double altitude = std::asin(std::min(1.0, d.z));
    const double azimuth = std::atan2(d.x, d.y) + pi;
    const double azimuthWidth = Tuning::mergedSunDegrees * degree / std::max(std::cos(altitude), 0.05);
    Merged& bin = bins[{ static_cast<int>(altitude / (Tuning::mergedSunDegrees * degree)),
      static_cast<int>(azimuth / azimuthWidth) }];
    const Spectrum flux = sun.emittance();
    for (int band = 0; band < maxBands; ++band)
      bin.flux[band] += flux[band];
    bin.direction += largestBand(flux) * d;
  }
  this->Suns.clear();
  this->MergedSuns = std::make_unique<ElementStore>(firstMergedSunId);
  for (const auto& entry : bins)
    this->Suns.push_back(
      this->MergedSuns->make<SunElement>(0, glm::normalize(entry.second.direction), entry.second.flux));
}

bool HierarchicalRadiosity::solve(RadiosityProgress* progress)
{
  this->restart();
  this->mergeSuns();
  this->Stats.referencePowerW = this->referencePower();
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

  this->Stats.elements = this->elementCount();
  this->Stats.links = 0;
  for (const auto& element : this->Store->all())
    this->Stats.links += element->Incoming.size();
  this->Stats.rays = this->raysCast();
  if (progress)
  {
    progress->report(1.0);
  }
  return true;
}
} // namespace terralux
