#include "evaluation/point_values.h"

#include "hierarchy/polygon_element.h"
#include "solver/solver.h"

namespace terralux
{
PointValues PointValues::ofLeaf(const PolygonElement& leaf)
{
  PointValues v;
  v.irradiance = leaf.Irradiance;
  v.radiosity = leaf.Radiosity;
  v.skyViewFactor = leaf.SkyViewFactor;
  return v;
}

PointValues PointValues::atPoint(const PointIrradiance& received, const PolygonElement& leaf)
{
  PointValues v;
  v.irradiance = received.irradiance;
  v.radiosity = radiosityOf(leaf.emission(), leaf.reflectance(), v.globalIrradiance());
  v.skyViewFactor = received.skyViewFactor;
  v.sunlitHours = received.sunlitHours;
  v.irradianceError = received.irradianceError;
  return v;
}

Spectrum PointValues::globalIrradiance() const
{
  return totalIrradiance(this->irradiance[SunLight], this->irradiance[SkyLight], this->irradiance[ReflectedLight]);
}

void PointValues::accumulate(const PointValues& v, double weight)
{
  for (int band = 0; band < maxBands; ++band)
  {
    for (int c = 0; c < lightCategories; ++c)
      this->irradiance[c][band] += weight * v.irradiance[c][band];
    this->radiosity[band] += weight * v.radiosity[band];
  }
  this->skyViewFactor += weight * v.skyViewFactor;
  this->sunlitHours += weight * v.sunlitHours;
  this->irradianceError += weight * v.irradianceError;
}

void PointValues::flatten(double* out) const
{
  for (int c = 0; c < lightCategories; ++c)
    for (int band = 0; band < maxBands; ++band)
      *out++ = this->irradiance[c][band];
  for (int band = 0; band < maxBands; ++band)
    *out++ = this->radiosity[band];
  *out = this->skyViewFactor;
}

PointValues PointValues::unflatten(const double* flat)
{
  PointValues v;
  for (int c = 0; c < lightCategories; ++c)
    for (int band = 0; band < maxBands; ++band)
      v.irradiance[c][band] = *flat++;
  for (int band = 0; band < maxBands; ++band)
    v.radiosity[band] = *flat++;
  v.skyViewFactor = *flat;
  return v;
}
} // namespace terralux
