#include "open_sky.h"

#include "sky_patch_element.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
OpenSky::OpenSky(const SkyHierarchy& sky)
  : Sky(sky)
  , Deepest(std::min(sky.finestLevel(), 4))
{
  for (int level = 0; level <= this->Deepest; ++level)
  {
    const int side = SkyHierarchy::cellsPerSide(level);
    std::vector<std::unique_ptr<SkyPatchElement>> patches;
    std::vector<double> radii;
    for (int iu = 0; iu < side; ++iu)
      for (int iv = 0; iv < side; ++iv) // never split: they need no element store
      {
        const SkyPatch cell{ level, iu, iv };
        patches.push_back(std::make_unique<SkyPatchElement>(0, level, nullptr, &sky, cell));
        // Largest distance from the centre direction to the patch's boundary (where the
        // farthest point of a patch below a hemisphere lies), sampled densely, padded.
        const Vec3& c = patches.back()->direction();
        double radius = 0.0;
        constexpr int steps = 32;
        for (int k = 0; k <= steps; ++k)
        {
          const double f = static_cast<double>(k) / steps;
          const double us[4] = { cell.u0(), cell.u1(), cell.u0() + f * (cell.u1() - cell.u0()),
            cell.u0() + f * (cell.u1() - cell.u0()) };
          const double vs[4] = { cell.v0() + f * (cell.v1() - cell.v0()), cell.v0() + f * (cell.v1() - cell.v0()),
            cell.v0(), cell.v1() };
          for (int e = 0; e < 4; ++e)
          {
            const Direction d = directionFromSkyParameters(us[e], vs[e]);
            radius = std::max(radius, glm::length(Vec3(d[0], d[1], d[2]) - c));
          }
        }
        radii.push_back(1.01 * radius + 1e-9);
      }
    this->Levels.push_back(std::move(patches));
    this->Radii.push_back(std::move(radii));
  }
}

OpenSky::~OpenSky() = default;

void OpenSky::accumulate(int level, int iu, int iv, const Vec3& n, Spectrum& e, double& omega) const
{
  const std::size_t index = static_cast<std::size_t>(iu) * SkyHierarchy::cellsPerSide(level) + iv;
  const SkyPatchElement& patch = *this->Levels[level][index];
  // Cheap side test first: n . d >= n . c - |d - c| for unit n, and |d - c| <= the
  // patch's radius about its centre direction c; the exact test only where it is close.
  const double towardCentre = glm::dot(n, patch.direction()), radius = this->Radii[level][index];
  const int side = towardCentre > radius ? 1 : (towardCentre < -radius ? -1 : patch.sideOf(n));
  if (side < 0)
    return;
  // The plane's horizon crosses the patch: split it while what it gives could matter,
  // since its radiance is taken as its mean where splitting stops.
  if (side == 0 && level < this->Deepest &&
    (level < 3 || patch.projectedSolidAngle(n) * largestBand(patch.emittance()) > 1e-4 * this->Brightest))
  {
    for (int k = 0; k < 4; ++k)
      this->accumulate(level + 1, 2 * iu + k / 2, 2 * iv + k % 2, n, e, omega);
    return;
  }
  // Exact in front (the irradiance vector); exact in solid angle where the horizon
  // crosses a deepest patch, whose radiance is then taken as its mean.
  double kernel, projected;
  patch.kernelAndProjection(n, side, kernel, projected);
  const Spectrum l = patch.emittance();
  for (int band = 0; band < maxBands; ++band)
    e[band] += kernel * l[band];
  omega += projected;
}

void OpenSky::irradiance(const Vec3& n, Spectrum& irradiance, double& projectedSolidAngle) const
{
  irradiance = {};
  projectedSolidAngle = 0.0;
  this->accumulate(0, 0, 0, n, irradiance, projectedSolidAngle);
}

Spectrum OpenSky::radiance(const Vec3& d) const
{
  Spectrum result{};
  if (!(d.z > 0.0))
    return result;
  // Inverse of directionFromSkyParameters: d = (-sin v cos u, -cos v cos u, sin u).
  constexpr double pi = 3.14159265358979323846;
  const double u = std::asin(std::min(1.0, d.z));
  double v = std::atan2(-d.x, -d.y);
  if (v < 0.0)
    v += 2.0 * pi;
  const int level = this->Sky.finestLevel(), side = SkyHierarchy::cellsPerSide(level);
  const SkyPatch cell{ level, std::min(side - 1, static_cast<int>(u / (0.5 * pi) * side)),
    std::min(side - 1, static_cast<int>(v / (2.0 * pi) * side)) };
  for (int band = 0; band < maxBands; ++band)
    result[band] = this->Sky.radiance(cell, this->Sky.bands() == 1 ? 0 : std::min(band, this->Sky.bands() - 1));
  return result;
}
} // namespace terralux
