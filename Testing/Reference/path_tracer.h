#pragma once
// An independent Monte Carlo reference for TerraLux's per-point irradiance (not part of
// its API): Lambertian scenes under suns and a sky, estimated by path tracing. Direct
// sun is one shadow ray from just above the point; sky and reflected light come from
// stratified cosine-weighted directions, from just above the point along its normal on
// (not one offset further along the ray: at the foot of a wall the wall's front is
// seen, the limit from the open side): one that hits a surface's front brings that
// surface's radiosity, estimated recursively (its own sun ray, one cosine-weighted
// continuation, Russian roulette after the second bounce). The sky term uses the
// unoccluded sky as a control variate: its irradiance on the point's plane is summed
// over the sky map's cells, and the rays estimate only what the scene hides of it, so
// an open point has no sky noise at all. Each component comes with its standard error.

#include "reference_scene.h"

#include "sky/sky_hierarchy.h"

#include <array>
#include <cstdint>
#include <vector>

namespace terralux_reference
{
struct ReferenceSun
{
  Vec3 direction; ///< unit, toward the sun
  double normalIrradiance = 0.0;
};

/// The suns of a scene's lights (anything with a `direction` toward the sun and an
/// `irradiance` by band) as the reference takes them: as TerraLux defines it, a sun at
/// or below the horizon lights nothing; the first band.
template <typename Suns>
std::vector<ReferenceSun> referenceSuns(const Suns& suns)
{
  std::vector<ReferenceSun> result;
  for (const auto& sun : suns)
    if (sun.direction.z > 0.0)
      result.push_back({ glm::normalize(sun.direction), sun.irradiance[0] });
  return result;
}

/// Mean and standard error of one component, W/m^2.
struct Estimate
{
  double mean = 0.0;
  double standardError = 0.0;
};

struct ReferenceIrradiance
{
  Estimate sun, sky, reflected, global;
};

class PathTracer
{
public:
  /// The sky may be null; it and the scene must outlive the tracer. Band 0 is traced.
  PathTracer(const ReferenceScene& scene, const terralux::SkyHierarchy* sky, std::vector<ReferenceSun> suns);

  /// Irradiance on a surface point with unit normal n, from `samples` directions
  /// (rounded up to a square for stratification); deterministic for a seed.
  ReferenceIrradiance irradianceAt(const Vec3& point, const Vec3& normal, int samples, std::uint64_t seed) const;

  /// Many points in parallel, point k seeded by firstSeed + k (seeds far apart give
  /// independent estimates: a seed's stream is the next seed's one draw behind).
  std::vector<ReferenceIrradiance> irradianceAt(
    const std::vector<Vec3>& points, const std::vector<Vec3>& normals, int samples, std::uint64_t firstSeed = 1) const;

  /// Sky radiance toward a unit direction above the horizon (0 below, or without sky).
  double skyRadiance(const Vec3& direction) const;
  /// Irradiance the whole sky map gives a plane of unit normal n with nothing in the
  /// way: cells in front by their vector solid angle, cells across the plane's horizon
  /// by 4 x 4 sub-cells.
  double unoccludedSky(const Vec3& normal) const;
  /// Direct sun on a point with normal n: shadow rays from just above it.
  double directSun(const Vec3& point, const Vec3& normal) const;

private:
  class Random;
  double radiosityAt(const Hit& hit, int depth, Random& random) const;
  double incidentAt(const Vec3& point, const Vec3& normal, int depth, Random& random) const;
  /// Where a point's sky and reflected light are estimated from: the point itself, or,
  /// where it lies on the line a surface meets another (a post at the foot of a wall,
  /// possibly inside the wall's plane), the most open of four points two offsets away
  /// along its tangent diagonals: the limit from the open side.
  Vec3 openSideOf(const Vec3& point, const Vec3& normal, Random& random) const;

  const ReferenceScene& Scene;
  const terralux::SkyHierarchy* Sky;
  std::vector<ReferenceSun> Suns;
  struct SkyCell
  {
    double radiance;
    Vec3 vectorSolidAngle;
    double u0, u1, v0, v1;
    std::array<Vec3, 6> edges; ///< directions at (u0, u1) x (v0, mid v, v1): extremes of n . d
  };
  std::vector<SkyCell> Cells;
};
} // namespace terralux_reference
