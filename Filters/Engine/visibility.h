#pragma once
// Visibility queries against the full-resolution scene with Embree 3: occlusion
// rays between two points or from a point toward infinity. Ray ends are pulled in
// by an offset that scales with the scene, never a fixed epsilon.

#include "radiosity_types.h"

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
};

class Visibility
{
public:
  /// Builds the Embree scene of every polygon (quads as two triangles) and of every
  /// terrain grid (Embree grid geometry over its valid cells, sharing the grid's own
  /// vertices: no triangle mesh of the terrain is ever made). Throws Error when Embree
  /// fails.
  explicit Visibility(const RadiosityScene& scene);
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
  /// Offset (metres) of ray ends: 1e-5 of the scene's bounding diagonal.
  double offset() const { return this->Offset; }
  /// A seed for samples that belong to a point: its position relative to the scene,
  /// quantised to a thousandth of offset(), so moving the whole scene (by 1e7 m, say)
  /// draws the same samples.
  std::uint64_t seedOf(const Vec3& p) const;
  /// Rays cast so far, over all threads.
  std::uint64_t raysCast() const;

private:
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
  std::vector<int> TrianglePolygon;

  RTCDeviceTy* Device = nullptr;
  RTCSceneTy* Scene = nullptr;
  double Offset = 1e-6;
  Vec3 Centre{ 0.0 }; // Embree's float vertices are stored relative to it
  // One counter per thread: a shared atomic would bounce between cores on every ray.
  struct RayCounters;
  std::unique_ptr<RayCounters> Rays;
};
} // namespace terralux
