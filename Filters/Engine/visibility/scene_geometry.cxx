#include "visibility/scene_geometry.h"

#include "horizons/horizon_map.h"
#include "terrain/terrain_grid.h"
#include "visibility/visibility.h"

#include <algorithm>

namespace terralux
{
SceneGeometry::SceneGeometry(const RadiosityScene& scene, const FarSight& far)
  : Points(scene.points)
  , Polygons(scene.polygons)
  , Terrains(scene.terrains)
  , Far(far)
  , GivenFar(scene.farTerrain)
  , Rays(std::make_unique<Visibility>(scene, far))
  , Horizons(scene.terrains.size())
{
}

SceneGeometry::~SceneGeometry() = default;

const Visibility& SceneGeometry::hierarchyRays() const
{
  return this->Rays->farRays();
}

const HorizonMap& SceneGeometry::horizons(
  std::size_t index, HorizonMap::Density density, const WorkSplit* split, bool exactly)
{
  const std::lock_guard<std::mutex> lock(this->HorizonsMutex);
  const auto& densities = HorizonMap::densities;
  MapsOfEachDensity& maps = this->Horizons[index];
  const std::size_t asked = std::find(densities.begin(), densities.end(), density) - densities.begin();
  for (std::size_t k = exactly ? asked + 1 : densities.size(); k-- > asked;)
    if (maps[k])
      return *maps[k];
  // A map already built lends its sweeps toward the azimuths both hold: the finest,
  // which holds every coarser one's.
  const HorizonMap* lender = nullptr;
  for (std::size_t k = 0; k < densities.size(); ++k)
    if (maps[k])
      lender = maps[k].get();
  // A window with its far terrain given sees that terrain beyond the detail distance.
  if (this->seesGivenFarTerrain())
    maps[asked] = std::make_unique<HorizonMap>(
      *this->Terrains[index], this->GivenFar, this->Far.detailDistance, density, lender);
  else
    maps[asked] = std::make_unique<HorizonMap>(*this->Terrains[index], density, split, lender);
  return *maps[asked];
}

bool SceneGeometry::sameShape(const RadiosityScene& scene, const FarSight& far) const
{
  if (!(far == this->Far) || scene.points != this->Points || scene.polygons.size() != this->Polygons.size() ||
    scene.terrains.size() != this->Terrains.size())
    return false;
  for (std::size_t k = 0; k < scene.polygons.size(); ++k)
  {
    const ScenePolygon &a = scene.polygons[k], &b = this->Polygons[k];
    if (a.vertexCount != b.vertexCount || a.vertices != b.vertices)
      return false;
  }
  for (std::size_t k = 0; k < scene.terrains.size(); ++k)
    if (!scene.terrains[k]->sameSurface(*this->Terrains[k]))
      return false;
  const GivenFarTerrain &a = scene.farTerrain, &b = this->GivenFar;
  if (!a.grid || !b.grid)
    return !a.grid && !b.grid;
  return a.stride == b.stride && a.i0 == b.i0 && a.j0 == b.j0 && a.grid->sameSurface(*b.grid);
}
} // namespace terralux
