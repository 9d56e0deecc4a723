#pragma once
// What a scene's shape alone determines, built once and shared by every solve over it:
// the Embree scene of the rays (Visibility) and the horizons of a height-field terrain's
// posts (HorizonMap). Sources and materials are the solver's; a time series or a moving
// sun re-solves over the same SceneGeometry without rebuilding either (on the 1025^2
// fractal DEM the horizons alone take a fifth of an instant's time).

#include "horizons/horizon_map.h"
#include "terrain/far_terrain.h"
#include "hierarchy/radiosity_types.h"

#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace terralux
{
class WorkSplit;
class TerrainGrid;
class Visibility;

class SceneGeometry
{
public:
  /// The rays of `scene` (see Visibility). The scene's terrain grids must outlive
  /// this: the ray tracer shares their vertices. `far`: the terrain rays see beyond
  /// the detail distance of their origins (Visibility).
  SceneGeometry(const RadiosityScene& scene, const FarSight& far);
  ~SceneGeometry();
  SceneGeometry(const SceneGeometry&) = delete;
  SceneGeometry& operator=(const SceneGeometry&) = delete;

  /// The rays from the points the outputs read (their gathers, suns and skies): with
  /// the far sight, the far terrain beyond the detail distance.
  const Visibility& pointRays() const { return *this->Rays; }
  /// The hierarchy's rays, between points of its surfaces: with the far sight, the far
  /// terrain alone, on which the hierarchy is then solved (one count of rays with
  /// pointRays()); else the same as pointRays().
  const Visibility& hierarchyRays() const;

  /// The horizons of the posts of terrain `index` (a height field alone in its scene),
  /// built on the first call toward `density`'s azimuths (2 bytes a post and azimuth)
  /// and kept. A map of more azimuths, once built, also serves where fewer are asked
  /// for (it is more exact and proves more), unless `exactly` that density is asked
  /// (a map judged against its posts' targets, whatever was built before).
  /// `split`: the processes that build it together (HorizonMap), all calling this alike.
  const HorizonMap& horizons(std::size_t index, HorizonMap::Density density = HorizonMap::Density::Standard,
    const WorkSplit* split = nullptr, bool exactly = false);

  /// Whether rays see a given far terrain beyond the detail distance (a window's):
  /// its maps' horizons are each post's own, whatever window holds it.
  bool seesGivenFarTerrain() const { return this->GivenFar.grid && this->Far.detailDistance > 0.0; }

  /// Whether `scene` has this one's shape: the same polygons over the same points and
  /// terrains with the same posts and valid cells (materials may differ), seen from
  /// afar alike.
  bool sameShape(const RadiosityScene& scene, const FarSight& far) const;

private:
  std::vector<Vec3> Points;                 // the scene's polygon corners, to compare
  std::vector<ScenePolygon> Polygons;       // (their vertex indices count)
  std::vector<const TerrainGrid*> Terrains; // the grids rays and horizons are built on
  FarSight Far;
  GivenFarTerrain GivenFar; // its grid, like Terrains, outlives this
  std::unique_ptr<Visibility> Rays;
  // Per terrain, a map of each of HorizonMap::densities, built on demand.
  using MapsOfEachDensity = std::array<std::unique_ptr<HorizonMap>, HorizonMap::densities.size()>;
  std::vector<MapsOfEachDensity> Horizons;
  std::mutex HorizonsMutex;
};
} // namespace terralux
