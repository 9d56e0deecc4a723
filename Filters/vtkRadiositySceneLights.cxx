// vtkRadiosityScene's lights: vtkSunSource outputs become suns, vtkSkySource radiance
// maps are summed into one hierarchical sky.
#include "vtkRadiosityScene.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkTerraLuxFieldData.h"

#include "base/error.h"

#include <algorithm>
#include <cmath>

void vtkRadiosityScene::AddLight(vtkDataObject* light)
{
  if (auto* map = vtkImageData::SafeDownCast(light))
  {
    vtkDataArray* radiance = map->GetCellData()->GetArray(vtkTerraLuxFieldData::RadianceName());
    int dims[3];
    map->GetDimensions(dims);
    const int n = dims[0] - 1;
    int level = 0;
    while ((1 << level) < n)
      ++level;
    if (!radiance || n < 2 || dims[1] - 1 != n || (1 << level) != n)
    {
      throw terralux::Error("a sky on input port 1 must be vtkSkySource's radiance map: 2^k x 2^k "
                            "cells over (azimuth, altitude) with cell data 'Radiance'");
    }
    const int bands = radiance->GetNumberOfComponents();
    std::vector<double> averages(static_cast<std::size_t>(n) * n * bands);
    // Map cell (i compass azimuth, j altitude) -> pyramid cell (iu = j, iv = i + n/2).
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int band = 0; band < bands; ++band)
          averages[(static_cast<std::size_t>(j) * n + (i + n / 2) % n) * bands + band] =
            radiance->GetComponent(i + static_cast<vtkIdType>(j) * n, band);
    this->AddSky(level, bands, std::move(averages));
    return;
  }
  vtkFieldData* fieldData = light ? light->GetFieldData() : nullptr;
  vtkDataArray* direction = fieldData ? fieldData->GetArray(vtkTerraLuxFieldData::SunDirectionName()) : nullptr;
  vtkDataArray* irradiance = fieldData ? fieldData->GetArray(vtkTerraLuxFieldData::SunNormalIrradianceName()) : nullptr;
  if (!direction || !irradiance || direction->GetNumberOfValues() != 3)
  {
    throw terralux::Error("input port 1 takes vtkSkySource's radiance map and vtkSunSource's "
                          "output; this input is neither");
  }
  // Three values, as three tuples (vtkSunSource) or one tuple of three components.
  const int components = direction->GetNumberOfComponents();
  terralux::Vec3 toward(0.0);
  for (int k = 0; k < 3; ++k)
    toward[k] = direction->GetComponent(k / components, k % components);
  const double flux = irradiance->GetNumberOfValues() > 0 ? irradiance->GetComponent(0, 0) : NAN;
  if (!(glm::length(toward) > 0.0) || !std::isfinite(glm::length(toward)) || !(flux >= 0.0) ||
    !std::isfinite(flux))
  {
    throw terralux::Error("the sun on input port 1 needs a finite, non-zero SunDirection and a finite "
                          "SunNormalIrradiance >= 0 (W/m^2)");
  }
  this->Suns.push_back({ toward, terralux::uniformSpectrum(flux), 0.0 });
}

void vtkRadiosityScene::AddSky(int level, int bands, std::vector<double> averages)
{
  for (double value : averages)
    if (!(value >= 0.0) || !std::isfinite(value))
    {
      throw terralux::Error("the sky's Radiance array holds a negative, NaN or infinite value: "
                            "give radiances >= 0 (W/m^2/sr)");
    }
  // Resamples cell averages of a (level, bands) map to the finer (toLevel, toBands) one:
  // each fine cell takes its coarse cell's average, which keeps every integral.
  auto resampled = [](const std::vector<double>& values, int level, int bands, int toLevel, int toBands) {
    const int side = 1 << level, toSide = 1 << toLevel, ratio = toSide / side;
    std::vector<double> result(static_cast<std::size_t>(toSide) * toSide * toBands);
    for (int iu = 0; iu < toSide; ++iu)
      for (int iv = 0; iv < toSide; ++iv)
        for (int band = 0; band < toBands; ++band)
          result[(static_cast<std::size_t>(iu) * toSide + iv) * toBands + band] =
            values[(static_cast<std::size_t>(iu / ratio) * side + iv / ratio) * bands + std::min(band, bands - 1)];
    return result;
  };
  if (this->SkyAverages.empty())
  {
    this->SkyLevel = level;
    this->SkyBands = bands;
    this->SkyAverages = std::move(averages);
  }
  else
  {
    const int toLevel = std::max(level, this->SkyLevel), toBands = std::max(bands, this->SkyBands);
    std::vector<double> sum = resampled(this->SkyAverages, this->SkyLevel, this->SkyBands, toLevel, toBands);
    const std::vector<double> added = resampled(averages, level, bands, toLevel, toBands);
    for (std::size_t k = 0; k < sum.size(); ++k)
      sum[k] += added[k];
    this->SkyLevel = toLevel;
    this->SkyBands = toBands;
    this->SkyAverages = std::move(sum);
  }
  this->Sky = std::make_unique<terralux::SkyHierarchy>(
    terralux::SkyHierarchy::fromCellAverages(this->SkyLevel, this->SkyBands, this->SkyAverages));
}
