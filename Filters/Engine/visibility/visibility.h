#pragma once
// Visibility queries against the full-resolution scene with Embree 3: occlusion
// rays between two points or from a point toward infinity. Ray ends are pulled in
// by an offset that scales with the scene, never a fixed epsilon. Beyond the detail
// distance of its origin, a ray may see the terrain at a coarser resolution
// (far_terrain.h).

#include "terrain/far_terrain.h"
#include "hierarchy/radiosity_types.h"

#include <cstdint>
#include <memory>
#include <utility>

struct RTCDeviceTy;
struct RTCSceneTy;

namespace terralux
{
class TerrainGrid;

/// The surface a ray meets first: a terrain (its index in RadiosityScene::terrains and
/// the grid parameter of the hit, in post units) or an input polygon (its index).
struct SurfaceHit
{
  int terrain = -1;
  int polygon = -1;
  double u = 0.0, v = 0.0;
  Vec3 point{ 0.0 };
  Vec3 normal{ 0.0, 0.0, 1.0 }; ///< unit normal of the triangle met, either side
  /// On the far terrain (u, v still the full grid's): rays from it take farRays().
  bool far = false;
};

class Visibility
{
public:
  /// Builds the Embree scene of every polygon (quads as two triangles) and of every
  /// terrain grid (Embree grid geometry over its valid cells, sharing the grid's own
  /// vertices: no triangle mesh of the terrain is ever made). Throws Error when Embree
  /// fails.
  /// With `far` active, in a scene of one terrain alone, a ray that leaves the vertical
  /// cylinder of radius far.detailDistance around its origin meets, beyond it, the
  /// terrain's every far.stride-th post (FarTerrain) instead. A ray that leaves the
  /// cylinder below the coarse surface (which spans hollows and valleys) stops there,
  /// at the surface above it: it is inside the far terrain. Each ray's answer then
  /// depends on its origin alone, not on who traces it.
  explicit Visibility(const RadiosityScene& scene, const FarSight& far = {});
  ~Visibility();
  Visibility(const Visibility&) = delete;
  Visibility& operator=(const Visibility&) = delete;

  /// True when the segment between surface points a and b (with their surfaces' unit
  /// normals, facing the segment) is blocked. Ends are lifted off their surfaces by
  /// offset() along the normals, so grazing rays do not hit their own polygons.
  bool occluded(const Vec3& a, const Vec3& aNormal, const Vec3& b, const Vec3& bNormal) const;
  /// True when the ray from surface point a (unit normal aNormal) along unit direction
  /// d hits anything.
  bool occludedToward(const Vec3& a, const Vec3& aNormal, const Vec3& d) const;
  /// The first surface the ray from surface point a (unit normal aNormal) along unit
  /// direction d meets, from a lifted by offset() along aNormal; false when it escapes.
  bool firstHit(const Vec3& a, const Vec3& aNormal, const Vec3& d, SurfaceHit& hit) const;
  /// The rays from a point on the far terrain (a far hit's shadow rays, and the
  /// hierarchy's, which is solved on it): that terrain alone, whose coarse surface the
  /// point lies on; one count of rays with these. Without one, these rays.
  const Visibility& farRays() const { return this->Far ? *this->Far : *this; }
  /// What the far terrain is, or none.
  const FarTerrain* farTerrain() const { return this->Coarse.get(); }
  /// Offset (metres) of ray ends: 1e-5 of the scene's bounding diagonal.
  double offset() const { return this->Offset; }
  /// A seed for samples that belong to a point: its position relative to the scene,
  /// quantised to a thousandth of offset(), so moving the whole scene (by 1e7 m, say)
  /// draws the same samples.
  std::uint64_t seedOf(const Vec3& p) const;
  /// Rays cast so far, over all threads.
  std::uint64_t raysCast() const;

private:
  struct RayCounters;
  /// The far terrain's own rays: its grid alone, hits mapped to the fine grid's
  /// parameters.
  Visibility(const FarTerrain& far, double sceneOffset, std::shared_ptr<RayCounters> counters);
  void build(const RadiosityScene& scene);
  /// Where a ray along unit d leaves its origin's cylinder of detail (infinity
  /// without a far terrain, or straight up or down).
  double detailEnd(const Vec3& d) const;
  // One stretch [tnear, tfar] of a ray from `origin` (absolute), uncounted.
  bool intersect(const Vec3& origin, const Vec3& d, double tnear, double tfar, SurfaceHit& hit) const;
  bool blocked(const Vec3& origin, const Vec3& d, double tnear, double tfar) const;
  /// In the far terrain's rays: whether `point` lies under its surface, and the
  /// surface above it.
  bool under(const Vec3& point, SurfaceHit& above) const;
  // A ray's stretch beyond its detail distance, on the far terrain.
  bool farBlocked(const Vec3& origin, const Vec3& d, double detail, double tfar) const;
  bool farHit(const Vec3& origin, const Vec3& d, double detail, SurfaceHit& hit) const;
  void addTerrain(const TerrainGrid& terrain, int terrainIndex);
  void addPolygons(const RadiosityScene& scene);

  // What each Embree geometry id stands for: a terrain's index and the first post of
  // each of its grids, or (terrain -1) the polygons, with the polygon of each triangle.
  struct GeometryOrigin
  {
    int terrain = -1;
    std::vector<std::pair<int, int>> gridStarts; // (i0, j0) per grid
    std::vector<std::pair<int, int>> gridSizes;  // (cells in u, cells in v) per grid
  };
  std::vector<GeometryOrigin> Origins;
  std::vector<const TerrainGrid*> Grids; // the terrains, by index (hits' parameters are found on them)
  std::vector<int> TrianglePolygon;

  RTCDeviceTy* Device = nullptr;
  RTCSceneTy* Scene = nullptr;
  double Offset = 1e-6;
  std::unique_ptr<FarTerrain> Coarse;  // the far terrain (with a far sight)
  std::unique_ptr<Visibility> Far;     // and its rays
  double DetailDistance = 0.0;
  const FarTerrain* MapsTo = nullptr;  // in the far terrain's rays: the map of its hits
  Vec3 Centre{ 0.0 }; // Embree's float vertices are stored relative to it
  // One counter per thread: a shared atomic would bounce between cores on every ray.
  // Shared with the far terrain's rays: one count of all.
  std::shared_ptr<RayCounters> Rays;
};
} // namespace terralux
