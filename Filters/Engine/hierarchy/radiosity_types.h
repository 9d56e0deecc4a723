#pragma once
// Shared value types of the radiosity engine: vectors (GLM), spectra of up to three
// bands, and the scene as the VTK adapter hands it over.

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace terralux
{
using Vec3 = glm::dvec3;
constexpr int maxBands = 3;
using Spectrum = std::array<double, maxBands>;

inline Spectrum uniformSpectrum(double value)
{
  return { value, value, value };
}

/// Two unit tangents u, v of a unit normal n, with u x v = n: the one frame the
/// engine's directions and in-plane coordinates are built in.
inline void tangentsOf(const Vec3& n, Vec3& u, Vec3& v)
{
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  u = glm::normalize(glm::cross(a, n));
  v = glm::cross(n, u);
}

/// The largest band of a spectrum: what the oracle and the samplers measure by.
inline double largestBand(const Spectrum& s)
{
  return std::max({ s[0], s[1], s[2] });
}

/// Sun + sky + reflected irradiance, in that order everywhere, so that every place that
/// totals them agrees to the last bit.
inline Spectrum totalIrradiance(const Spectrum& sun, const Spectrum& sky, const Spectrum& reflected)
{
  Spectrum total;
  for (std::size_t band = 0; band < total.size(); ++band)
    total[band] = sun[band] + sky[band] + reflected[band];
  return total;
}

/// Radiosity B = Be + rho E (paper eq. 1's emitted plus reflected light) of a surface of
/// emission Be and reflectance rho under irradiance E: the one place it is computed.
inline Spectrum radiosityOf(const Spectrum& emission, const Spectrum& reflectance, const Spectrum& irradiance)
{
  Spectrum radiosity;
  for (std::size_t band = 0; band < radiosity.size(); ++band)
    radiosity[band] = emission[band] + reflectance[band] * irradiance[band];
  return radiosity;
}

/// FNV-1a over the bits of a position (-0 and +0 alike): for hash maps keyed by exact
/// positions and for seeds that belong to a point.
inline std::uint64_t hashPosition(const Vec3& p)
{
  std::uint64_t h = 1469598103934665603ull;
  for (int k = 0; k < 3; ++k)
  {
    std::uint64_t bits;
    const double value = p[k] == 0.0 ? 0.0 : p[k];
    std::memcpy(&bits, &value, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  }
  return h;
}

/// Where irradiance comes from, kept apart for the outputs.
enum LightCategory
{
  SunLight = 0,
  SkyLight = 1,
  ReflectedLight = 2,
  lightCategories = 3
};

/// One planar input polygon (triangle or quad) with its material.
struct ScenePolygon
{
  int vertexCount = 3;           ///< 3 or 4
  std::array<int, 4> vertices{}; ///< indices into RadiosityScene::points
  Spectrum reflectance{};        ///< in [0, 1) per band
  Spectrum emission{};           ///< emitted radiosity, W/m^2
  int owner = 0;                 ///< which input data set
  std::int64_t cell = 0;         ///< cell id in that data set
};

class TerrainGrid;

/// A terrain's far terrain given whole, for a scene whose one terrain is a window of
/// the full-resolution grid (an MPI process's piece and its halo): the far terrain's
/// post (k, l) is the full grid's post (k stride, l stride), the window's post (0, 0)
/// the full grid's (i0, j0). Rays beyond the detail distance and the hierarchy then
/// see the same terrain on every process, whatever window it holds.
struct GivenFarTerrain
{
  const TerrainGrid* grid = nullptr;
  int stride = 1;
  int i0 = 0, j0 = 0;
};

/// Everything the engine needs about the geometry: polygons, and terrain grids that
/// enter the hierarchy as terrain patches (owned by the caller, who keeps them alive
/// while the solver exists).
struct RadiosityScene
{
  std::vector<Vec3> points;
  std::vector<ScenePolygon> polygons;
  std::vector<const TerrainGrid*> terrains;
  GivenFarTerrain farTerrain; ///< optional: with a detail distance, see FarSight
};
} // namespace terralux
