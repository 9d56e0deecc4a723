#include "sky/sky_hierarchy.h"

#include "base/angles.h"
#include "base/error.h"
#include "sky/sky_model.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace terralux
{
namespace
{
constexpr double halfPi = pi / 2.0;
} // namespace

double SkyTexture::sample(double compassAzimuthRad, double altitudeRad, int band) const
{
  double x = std::fmod(compassAzimuthRad / twoPi, 1.0);
  if (x < 0.0)
    x += 1.0;
  x *= (this->width - 1);
  const double y = std::clamp(altitudeRad / halfPi, 0.0, 1.0) * (this->height - 1);
  const int i0 = std::min(static_cast<int>(x), this->width - 2 < 0 ? 0 : this->width - 2);
  const int j0 = std::min(static_cast<int>(y), this->height - 2 < 0 ? 0 : this->height - 2);
  const int i1 = std::min(i0 + 1, this->width - 1);
  const int j1 = std::min(j0 + 1, this->height - 1);
  const double fx = x - i0, fy = y - j0;
  auto at = [&](int i, int j) {
    return this->values[(static_cast<std::size_t>(j) * this->width + i) * this->components + band];
  };
  return (1 - fy) * ((1 - fx) * at(i0, j0) + fx * at(i1, j0)) + fy * ((1 - fx) * at(i0, j1) + fx * at(i1, j1));
}

double SkyPatch::u0() const { return halfPi * this->iu / (1 << this->level); }
double SkyPatch::u1() const { return halfPi * (this->iu + 1) / (1 << this->level); }
double SkyPatch::v0() const { return twoPi * this->iv / (1 << this->level); }
double SkyPatch::v1() const { return twoPi * (this->iv + 1) / (1 << this->level); }

double SkyPatch::solidAngle() const
{
  return (this->v1() - this->v0()) * (std::sin(this->u1()) - std::sin(this->u0()));
}

Direction SkyPatch::vectorSolidAngle() const
{
  // Integral of (-sin v cos u, -cos v cos u, sin u) cos u du dv.
  const double u0 = this->u0(), u1 = this->u1(), v0 = this->v0(), v1 = this->v1();
  const double cosSquared = 0.5 * (u1 - u0) + 0.25 * (std::sin(2 * u1) - std::sin(2 * u0));
  const double sinCos = 0.5 * (std::sin(u1) * std::sin(u1) - std::sin(u0) * std::sin(u0));
  return { (std::cos(v1) - std::cos(v0)) * cosSquared, -(std::sin(v1) - std::sin(v0)) * cosSquared,
    (v1 - v0) * sinCos };
}

Direction SkyPatch::direction() const
{
  return directionFromSkyParameters(0.5 * (this->u0() + this->u1()), 0.5 * (this->v0() + this->v1()));
}

void SkyPatch::children(SkyPatch out[4]) const
{
  for (int k = 0; k < 4; ++k)
  {
    out[k] = { this->level + 1, 2 * this->iu + k / 2, 2 * this->iv + k % 2 };
  }
}

Direction directionFromSkyParameters(double u, double v)
{
  // Compass azimuth = v + pi: v = 0 is south, v = pi/2 west.
  return { -std::sin(v) * std::cos(u), -std::cos(v) * std::cos(u), std::sin(u) };
}

SkyHierarchy::SkyHierarchy(
  const SkyModel& model, double diffuseHorizontalWm2, int finestLevel, const SkyTexture* texture)
  : FinestLevel(finestLevel)
  , Bands(texture ? texture->components : 1)
{
  if (finestLevel < 1 || finestLevel > 10)
  {
    throw Error("sky hierarchy level " + std::to_string(finestLevel) + " is out of range 1..10");
  }
  if (!(diffuseHorizontalWm2 >= 0.0) || !std::isfinite(diffuseHorizontalWm2))
  {
    throw Error("the diffuse horizontal irradiance must be a finite value >= 0 W/m^2");
  }
  if (texture && (texture->components != 1 && texture->components != 3))
  {
    throw Error("a sky texture has 1 or 3 components");
  }
  if (texture && (texture->width < 1 || texture->height < 1 ||
                   texture->values.size() != static_cast<std::size_t>(texture->width) * texture->height * texture->components))
  {
    throw Error("the sky texture's size does not match its values");
  }

  // Finest cells: integrate over s = sin u (dOmega = ds dv) with 3x3 Gauss points, row
  // by row in parallel (the sky source's main cost: 147,456 points at level 7). Each
  // row keeps its own horizontal sums, added in row order: the same for any threads.
  const int side = cellsPerSide(finestLevel);
  const std::size_t bands = static_cast<std::size_t>(this->Bands);
  std::vector<double> modelIntegral(static_cast<std::size_t>(side) * side * bands);
  // Per row: the model's horizontal integral, then each band's.
  std::vector<double> rowHorizontal(static_cast<std::size_t>(side) * (bands + 1), 0.0);
  tbb::parallel_for(0, side, [&](int iu) {
    double* horizontal = &rowHorizontal[static_cast<std::size_t>(iu) * (bands + 1)];
    for (int iv = 0; iv < side; ++iv)
      forCellGaussPoints(SkyPatch{ finestLevel, iu, iv }, [&](const Direction& d, double weight, double s, double u,
                                                            double v) {
        const double relative = model.relativeRadiance(d);
        horizontal[0] += weight * relative * s;
        for (std::size_t band = 0; band < bands; ++band)
        {
          const double modulation = texture ? texture->sample(std::fmod(v + pi, twoPi), u, static_cast<int>(band)) : 1.0;
          modelIntegral[(static_cast<std::size_t>(iu) * side + iv) * bands + band] += weight * relative * modulation;
          horizontal[1 + band] += weight * relative * modulation * s;
        }
      });
  });
  double modelHorizontal = 0.0;
  std::vector<double> horizontalWeighted(bands, 0.0);
  for (int iu = 0; iu < side; ++iu)
  {
    const double* horizontal = &rowHorizontal[static_cast<std::size_t>(iu) * (bands + 1)];
    modelHorizontal += horizontal[0];
    for (std::size_t band = 0; band < bands; ++band)
      horizontalWeighted[band] += horizontal[1 + band];
  }
  if (!(modelHorizontal > 0.0) || !std::isfinite(modelHorizontal))
  {
    throw Error("the sky model gives no light on a horizontal plane; check its parameters");
  }
  this->Scale = diffuseHorizontalWm2 / modelHorizontal;
  this->Horizontal.resize(this->Bands);
  for (int band = 0; band < this->Bands; ++band)
  {
    this->Horizontal[band] = this->Scale * horizontalWeighted[band];
  }

  // Pyramid: finest averages, then solid-angle weighted averages upward, so every
  // level integrates to the same total.
  this->Pyramid.resize(finestLevel + 1);
  auto& finest = this->Pyramid[finestLevel];
  finest.resize(modelIntegral.size());
  for (int iu = 0; iu < side; ++iu)
  {
    const double omega = SkyPatch{ finestLevel, iu, 0 }.solidAngle();
    for (int iv = 0; iv < side; ++iv)
      for (int band = 0; band < this->Bands; ++band)
      {
        const std::size_t k = (static_cast<std::size_t>(iu) * side + iv) * this->Bands + band;
        finest[k] = this->Scale * modelIntegral[k] / omega;
      }
  }
  this->buildPyramid();
}

SkyHierarchy::SkyHierarchy(int finestLevel, int bands)
  : FinestLevel(finestLevel)
  , Bands(bands)
{
}

SkyHierarchy SkyHierarchy::fromCellAverages(int finestLevel, int bands, const std::vector<double>& averages)
{
  if (finestLevel < 1 || finestLevel > 10 || (bands != 1 && bands != 3))
  {
    throw Error("a sky map needs 2^k x 2^k cells (k in 1..10) and 1 or 3 bands");
  }
  const int side = cellsPerSide(finestLevel);
  if (averages.size() != static_cast<std::size_t>(side) * side * bands)
  {
    throw Error("the sky map's radiance array does not match its cells");
  }
  SkyHierarchy sky(finestLevel, bands);
  sky.Pyramid.resize(finestLevel + 1);
  sky.Pyramid[finestLevel] = averages;
  sky.Horizontal.assign(bands, 0.0);
  for (int iu = 0; iu < side; ++iu)
  {
    const SkyPatch row{ finestLevel, iu, 0 };
    const double weight = (row.v1() - row.v0()) * 0.5 *
      (std::pow(std::sin(row.u1()), 2) - std::pow(std::sin(row.u0()), 2));
    for (int iv = 0; iv < side; ++iv)
      for (int band = 0; band < bands; ++band)
      {
        const double value = averages[(static_cast<std::size_t>(iu) * side + iv) * bands + band];
        if (!(value >= 0.0) || !std::isfinite(value))
        {
          throw Error("the sky map holds a negative or non-finite radiance");
        }
        sky.Horizontal[band] += value * weight;
      }
  }
  sky.Scale = 1.0;
  sky.buildPyramid();
  return sky;
}

void SkyHierarchy::buildPyramid()
{
  const int finestLevel = this->FinestLevel;
  // Irradiance vectors: radiance x vector solid angle at the finest cells, sums above.
  this->VectorPyramid.assign(finestLevel + 1, {});
  {
    const int side = cellsPerSide(finestLevel);
    auto& finest = this->VectorPyramid[finestLevel];
    finest.resize(static_cast<std::size_t>(side) * side * this->Bands * 3);
    for (int iu = 0; iu < side; ++iu)
      for (int iv = 0; iv < side; ++iv)
      {
        const Direction vector = SkyPatch{ finestLevel, iu, iv }.vectorSolidAngle();
        for (int band = 0; band < this->Bands; ++band)
        {
          const std::size_t k = (static_cast<std::size_t>(iu) * side + iv) * this->Bands + band;
          for (int axis = 0; axis < 3; ++axis)
            finest[3 * k + axis] = this->Pyramid[finestLevel][k] * vector[axis];
        }
      }
    for (int level = finestLevel - 1; level >= 0; --level)
    {
      const int n = cellsPerSide(level);
      auto& cells = this->VectorPyramid[level];
      const auto& fine = this->VectorPyramid[level + 1];
      cells.assign(static_cast<std::size_t>(n) * n * this->Bands * 3, 0.0);
      for (int iu = 0; iu < n; ++iu)
        for (int iv = 0; iv < n; ++iv)
        {
          SkyPatch kids[4];
          SkyPatch{ level, iu, iv }.children(kids);
          for (const SkyPatch& kid : kids)
            for (int band = 0; band < this->Bands; ++band)
              for (int axis = 0; axis < 3; ++axis)
                cells[((static_cast<std::size_t>(iu) * n + iv) * this->Bands + band) * 3 + axis] +=
                  fine[((static_cast<std::size_t>(kid.iu) * 2 * n + kid.iv) * this->Bands + band) * 3 + axis];
        }
    }
  }
  for (int level = finestLevel - 1; level >= 0; --level)
  {
    const int n = cellsPerSide(level);
    auto& cells = this->Pyramid[level];
    const auto& fine = this->Pyramid[level + 1];
    cells.assign(static_cast<std::size_t>(n) * n * this->Bands, 0.0);
    for (int iu = 0; iu < n; ++iu)
      for (int iv = 0; iv < n; ++iv)
      {
        const SkyPatch parent{ level, iu, iv };
        SkyPatch kids[4];
        parent.children(kids);
        for (int band = 0; band < this->Bands; ++band)
        {
          double power = 0.0;
          for (const SkyPatch& kid : kids)
            power += kid.solidAngle() * fine[(static_cast<std::size_t>(kid.iu) * 2 * n + kid.iv) * this->Bands + band];
          cells[(static_cast<std::size_t>(iu) * n + iv) * this->Bands + band] = power / parent.solidAngle();
        }
      }
  }
}

double SkyHierarchy::finestAverage(int iu, int iv, int band) const
{
  const int side = cellsPerSide(this->FinestLevel);
  iu = std::clamp(iu, 0, side - 1);
  iv = ((iv % side) + side) % side; // azimuth wraps
  return this->Pyramid[this->FinestLevel][(static_cast<std::size_t>(iu) * side + iv) * this->Bands + band];
}

double SkyHierarchy::radiance(const SkyPatch& patch, int band) const
{
  if (patch.level <= this->FinestLevel)
  {
    const int n = cellsPerSide(patch.level);
    return this->Pyramid[patch.level][(static_cast<std::size_t>(patch.iu) * n + patch.iv) * this->Bands + band];
  }
  // Subsample: bilinear between finest-cell centres at the patch centre.
  const int side = cellsPerSide(this->FinestLevel);
  const double x = 0.5 * (patch.u0() + patch.u1()) / halfPi * side - 0.5;
  const double y = 0.5 * (patch.v0() + patch.v1()) / twoPi * side - 0.5;
  const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
  const double fx = std::clamp(x - i0, 0.0, 1.0), fy = y - j0;
  return (1 - fx) * ((1 - fy) * this->finestAverage(i0, j0, band) + fy * this->finestAverage(i0, j0 + 1, band)) +
    fx * ((1 - fy) * this->finestAverage(i0 + 1, j0, band) + fy * this->finestAverage(i0 + 1, j0 + 1, band));
}

Direction SkyHierarchy::irradianceVector(const SkyPatch& patch, int band) const
{
  if (patch.level <= this->FinestLevel)
  {
    const int n = cellsPerSide(patch.level);
    const double* v =
      &this->VectorPyramid[patch.level][((static_cast<std::size_t>(patch.iu) * n + patch.iv) * this->Bands + band) * 3];
    return { v[0], v[1], v[2] };
  }
  const double l = this->radiance(patch, band);
  const Direction vector = patch.vectorSolidAngle();
  return { l * vector[0], l * vector[1], l * vector[2] };
}

double SkyHierarchy::planeIrradiance(const Direction& normal, int level, int band) const
{
  const int n = cellsPerSide(level);
  double irradiance = 0.0;
  for (int iu = 0; iu < n; ++iu)
    for (int iv = 0; iv < n; ++iv)
    {
      const SkyPatch patch{ level, iu, iv };
      const Direction d = patch.direction();
      const double receiverFactor = std::max(0.0, normal[0] * d[0] + normal[1] * d[1] + normal[2] * d[2]);
      irradiance += skyIrradianceContribution(receiverFactor, 1.0, patch.solidAngle(), this->radiance(patch, band));
    }
  return irradiance;
}

SkyPatch skyMapCell(int level, int i, int j)
{
  const int n = 1 << level;
  return SkyPatch{ level, j, (i + n / 2) % n }; // compass 0 (north) is the pyramid's half turn from south
}

Direction skyMapCorner(int level, int i, int j)
{
  const int n = 1 << level;
  return directionFromZenithAzimuth(halfPi - halfPi * j / n, twoPi * i / n);
}
} // namespace terralux
