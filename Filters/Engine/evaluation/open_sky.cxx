#include "evaluation/open_sky.h"

#include "base/angles.h"
#include "emitters/sky_patch_element.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace terralux
{
OpenSky::OpenSky(const SkyHierarchy& sky)
  : Deepest(std::min(sky.finestLevel(), 5))
  , Side(SkyHierarchy::cellsPerSide(sky.finestLevel()))
  , Bands(std::clamp(sky.bands(), 1, maxBands))
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
        // Largest distance from the centre direction to the patch (padded): at a corner.
        // Along an edge of constant altitude the cosine to the centre falls with the
        // azimuth's distance from the centre's (at most pi), and along an edge of
        // constant azimuth it is a cosine of the altitude whose minimum lies outside
        // [0, pi / 2].
        const Vec3& c = patches.back()->direction();
        double radius = 0.0;
        for (const double u : { cell.u0(), cell.u1() })
          for (const double v : { cell.v0(), cell.v1() })
          {
            const Direction d = directionFromSkyParameters(u, v);
            radius = std::max(radius, glm::length(Vec3(d[0], d[1], d[2]) - c));
          }
        radii.push_back(1.01 * radius + 1e-9);
      }
    this->Levels.push_back(std::move(patches));
    this->Radii.push_back(std::move(radii));
  }
  // The finest cells' radiance, read per ray and per cell by the gather's samplers.
  const int side = this->cellsPerSide();
  this->Finest.resize(static_cast<std::size_t>(side) * side);
  for (int iu = 0; iu < side; ++iu)
    for (int iv = 0; iv < side; ++iv)
    {
      Spectrum& l = this->Finest[static_cast<std::size_t>(iu) * side + iv];
      for (int band = 0; band < maxBands; ++band)
        l[band] = sky.radiance(SkyPatch{ sky.finestLevel(), iu, iv }, sky.bands() == 1 ? 0 : std::min(band, sky.bands() - 1));
    }
}

OpenSky::~OpenSky() = default;

void OpenSky::accumulate(
  int level, int iu, int iv, const Vec3& n, const SkyPatchElement::PlaneTerms& plane, Spectrum& e, double& omega) const
{
  const std::size_t index = static_cast<std::size_t>(iu) * SkyHierarchy::cellsPerSide(level) + iv;
  const SkyPatchElement& patch = *this->Levels[level][index];
  // Cheap side test first: n . d >= n . c - |d - c| for unit n, and |d - c| <= the
  // patch's radius about its centre direction c; the exact test only where it is close.
  const double towardCentre = glm::dot(n, patch.direction()), radius = this->Radii[level][index];
  const int side = towardCentre > radius ? 1 : (towardCentre < -radius ? -1 : patch.sideOf(n, plane));
  if (side < 0)
    return;
  // The plane's horizon crosses the patch: split it while it gives anything (from level
  // 3, as its projection tells), since its radiance is taken as its mean where
  // splitting stops.
  double kernel = 0.0, projected = 0.0;
  const bool measured = side == 0 && level >= 3;
  if (measured)
    patch.kernelAndProjection(n, plane, side, kernel, projected);
  if (side == 0 && level < this->Deepest && (!measured || projected * largestBand(patch.emittance()) > 0.0))
  {
    for (int k = 0; k < 4; ++k)
      this->accumulate(level + 1, 2 * iu + k / 2, 2 * iv + k % 2, n, plane, e, omega);
    return;
  }
  // Exact in front (the irradiance vector); exact in solid angle where the horizon
  // crosses a deepest patch, whose radiance is then taken as its mean.
  if (!measured)
    patch.kernelAndProjection(n, plane, side, kernel, projected);
  const Spectrum l = patch.emittance();
  for (int band = 0; band < maxBands; ++band)
    e[band] += kernel * l[band];
  omega += projected;
}

void OpenSky::exactIrradiance(const Vec3& n, Spectrum& irradiance, double& projectedSolidAngle) const
{
  irradiance = {};
  projectedSolidAngle = 0.0;
  this->accumulate(0, 0, 0, n, SkyPatchElement::PlaneTerms(n), irradiance, projectedSolidAngle);
}

namespace
{
// The upper hemisphere on the diamond |a| + |b| <= 1 of the square [-1, 1]^2 (the
// octahedral map): n / (|x| + |y| + z). The map folds along a = 0 and b = 0, lines of
// the table's grid, so no cell straddles a fold; cells that reach past the diamond's
// border (the horizon) are not read.
void toSquare(const Vec3& n, double& a, double& b)
{
  const double scale = 1.0 / (std::abs(n.x) + std::abs(n.y) + n.z);
  a = n.x * scale;
  b = n.y * scale;
}

Vec3 fromSquare(double a, double b)
{
  return glm::normalize(Vec3(a, b, std::max(0.0, 1.0 - std::abs(a) - std::abs(b))));
}

constexpr int tableValues = maxBands + 1;
} // namespace

void OpenSky::tabulate(int side)
{
  const int vertices = side + 1;
  const std::size_t count = static_cast<std::size_t>(vertices) * vertices;
  this->Table.assign(count * tableValues, 0.0);
  this->TableState = std::make_unique<std::atomic<std::uint8_t>[]>(count);
  for (std::size_t v = 0; v < count; ++v)
    this->TableState[v].store(0, std::memory_order_relaxed);
  this->TableSide = side;
}

const double* OpenSky::tableVertex(int row, int column) const
{
  // 0: not computed; 1: one thread computes it; 2: ready. A thread that finds another
  // computing it waits the few tens of microseconds that takes.
  constexpr std::uint8_t computing = 1, ready = 2;
  const int side = this->TableSide;
  const std::size_t index = static_cast<std::size_t>(row) * (side + 1) + column;
  double* values = &this->Table[index * tableValues];
  std::atomic<std::uint8_t>& state = this->TableState[index];
  if (state.load(std::memory_order_acquire) == ready)
    return values;
  std::uint8_t expected = 0;
  if (state.compare_exchange_strong(expected, computing, std::memory_order_acq_rel))
  {
    Spectrum e;
    double omega;
    this->exactIrradiance(fromSquare(-1.0 + 2.0 * column / side, -1.0 + 2.0 * row / side), e, omega);
    for (int band = 0; band < maxBands; ++band)
      values[band] = e[band];
    values[maxBands] = omega;
    state.store(ready, std::memory_order_release);
    return values;
  }
  while (state.load(std::memory_order_acquire) != ready)
    std::this_thread::yield();
  return values;
}

void OpenSky::irradiance(const Vec3& n, Spectrum& irradiance, double& projectedSolidAngle) const
{
  // Normals whose cell reaches the horizon, and those below it, are computed exactly.
  double a = 0.0, b = 0.0;
  if (n.z > 0.0)
    toSquare(n, a, b);
  const int side = this->TableSide;
  if (side == 0 || !(n.z > 0.0) || std::abs(a) + std::abs(b) > 1.0 - 6.0 / std::max(side, 1))
  {
    this->exactIrradiance(n, irradiance, projectedSolidAngle);
    return;
  }
  const double x = std::clamp(0.5 * (a + 1.0) * side, 0.0, static_cast<double>(side));
  const double y = std::clamp(0.5 * (b + 1.0) * side, 0.0, static_cast<double>(side));
  const int column = std::min(static_cast<int>(x), side - 1), row = std::min(static_cast<int>(y), side - 1);
  const double fx = x - column, fy = y - row;
  const double* v00 = this->tableVertex(row, column);
  const double* v10 = this->tableVertex(row, column + 1);
  const double* v01 = this->tableVertex(row + 1, column);
  const double* v11 = this->tableVertex(row + 1, column + 1);
  double values[tableValues];
  for (int k = 0; k < tableValues; ++k)
    values[k] = (1.0 - fy) * ((1.0 - fx) * v00[k] + fx * v10[k]) + fy * ((1.0 - fx) * v01[k] + fx * v11[k]);
  for (int band = 0; band < maxBands; ++band)
    irradiance[band] = values[band];
  projectedSolidAngle = values[maxBands];
}

Spectrum OpenSky::radiance(const Vec3& d) const
{
  Spectrum result{};
  if (!(d.z > 0.0))
    return result;
  // Inverse of directionFromSkyParameters: d = (-sin v cos u, -cos v cos u, sin u).
  const double u = std::asin(std::min(1.0, d.z));
  double v = std::atan2(-d.x, -d.y);
  if (v < 0.0)
    v += 2.0 * pi;
  const int side = this->cellsPerSide();
  return this->cellRadiance(
    std::min(side - 1, static_cast<int>(u / (0.5 * pi) * side)), std::min(side - 1, static_cast<int>(v / (2.0 * pi) * side)));
}
} // namespace terralux
