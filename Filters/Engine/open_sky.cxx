#include "open_sky.h"

#include "sky_patch_element.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
double largestOf(const Spectrum& s)
{
  return std::max({ s[0], s[1], s[2] });
}
} // namespace

OpenSky::OpenSky(const SkyHierarchy& sky)
  : Sky(sky)
  , Deepest(std::min(sky.finestLevel(), 4))
{
  for (int level = 0; level <= this->Deepest; ++level)
  {
    const int side = SkyHierarchy::cellsPerSide(level);
    std::vector<std::unique_ptr<SkyPatchElement>> patches;
    for (int iu = 0; iu < side; ++iu)
      for (int iv = 0; iv < side; ++iv) // never split: they need no element store
        patches.push_back(std::make_unique<SkyPatchElement>(0, level, nullptr, &sky, SkyPatch{ level, iu, iv }));
    this->Levels.push_back(std::move(patches));
  }
}

OpenSky::~OpenSky() = default;

void OpenSky::accumulate(int level, int iu, int iv, const Vec3& n, Spectrum& e, double& omega) const
{
  const SkyPatchElement& patch =
    *this->Levels[level][static_cast<std::size_t>(iu) * SkyHierarchy::cellsPerSide(level) + iv];
  const int side = patch.sideOf(n);
  if (side < 0)
    return;
  // The plane's horizon crosses the patch: split it while what it gives could matter,
  // since its radiance is taken as its mean where splitting stops.
  if (side == 0 && level < this->Deepest &&
    (level < 3 || patch.kernel(n) * largestOf(patch.emittance()) > 1e-4 * this->Brightest))
  {
    for (int k = 0; k < 4; ++k)
      this->accumulate(level + 1, 2 * iu + k / 2, 2 * iv + k % 2, n, e, omega);
    return;
  }
  // Exact in front (the irradiance vector); exact in solid angle where the horizon
  // crosses a deepest patch, whose radiance is then taken as its mean.
  const double kernel = patch.kernel(n);
  const Spectrum l = patch.emittance();
  for (int band = 0; band < maxBands; ++band)
    e[band] += kernel * l[band];
  omega += patch.projectedSolidAngle(n);
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
