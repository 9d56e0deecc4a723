#pragma once
// Visibility queries against the full-resolution scene with Embree 3: occlusion
// rays between two points or from a point toward infinity. Ray ends are pulled in
// by an offset that scales with the scene, never a fixed epsilon.

#include "radiosity_types.h"

#include <cstdint>
#include <memory>

struct RTCDeviceTy;
struct RTCSceneTy;

namespace terralux
{
class TerrainGrid;

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
  /// Offset (metres) of ray ends: 1e-5 of the scene's bounding diagonal.
  double offset() const { return this->Offset; }
  /// A seed for samples that belong to a point: its position relative to the scene,
  /// quantised to a thousandth of offset(), so moving the whole scene (by 1e7 m, say)
  /// draws the same samples.
  std::uint64_t seedOf(const Vec3& p) const;
  /// Rays cast so far, over all threads.
  std::uint64_t raysCast() const;

private:
  void addTerrain(const TerrainGrid& terrain);
  void addPolygons(const RadiosityScene& scene);

  RTCDeviceTy* Device = nullptr;
  RTCSceneTy* Scene = nullptr;
  double Offset = 1e-6;
  Vec3 Centre{ 0.0 }; // Embree's float vertices are stored relative to it
  // One counter per thread: a shared atomic would bounce between cores on every ray.
  struct RayCounters;
  std::unique_ptr<RayCounters> Rays;
};
} // namespace terralux
