#pragma once
// The independent reference's own view of a scene (not part of TerraLux's API): every
// polygon and every valid terrain cell as triangles in an Embree scene of its own, with
// closest-hit queries that return the surface, its normal and its material. It shares
// with the engine only the scene description (RadiosityScene, TerrainGrid) and Embree;
// no form factor, link or visibility code of the solver.

#include "hierarchy/radiosity_types.h"

#include <embree3/rtcore.h>

#include <vector>

namespace terralux_reference
{
using terralux::Spectrum;
using terralux::Vec3;

struct Hit
{
  Vec3 position;
  Vec3 normal;          ///< unit, the side the triangle faces (right-handed corner order)
  Spectrum reflectance{};
  Spectrum emission{};  ///< emitted radiosity, W/m^2
};

class ReferenceScene
{
public:
  explicit ReferenceScene(const terralux::RadiosityScene& scene);
  ~ReferenceScene();
  ReferenceScene(const ReferenceScene&) = delete;
  ReferenceScene& operator=(const ReferenceScene&) = delete;

  /// Closest surface along a ray from `origin` (beyond tnear); false if none.
  bool intersect(const Vec3& origin, const Vec3& direction, double tnear, Hit& hit) const;
  /// Whether anything lies along the ray within (tnear, tfar).
  bool occluded(const Vec3& origin, const Vec3& direction, double tnear, double tfar) const;
  /// How far above a point its rays start, along its normal and again along the ray:
  /// "just above" as TerraLux defines it (documented in its README), 1e-5 of the
  /// scene's bounding diagonal, so that both judge shadows from the same place.
  double offsetAt(const Vec3& point) const;

private:
  struct Triangle
  {
    Vec3 normal;
    Spectrum reflectance;
    Spectrum emission;
  };
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  Vec3 Centre{ 0.0 };
  double Offset = 1e-4;
  std::vector<Triangle> Triangles;
};
} // namespace terralux_reference
