#include "fractal_dem.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace terralux_bench
{
std::vector<float> fractalHeights(int n, std::uint32_t seed, double roughness, double reliefM)
{
  if (n < 3 || ((n - 1) & (n - 2)) != 0)
  {
    throw std::invalid_argument("fractal DEM size must be 2^k + 1");
  }
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<float> h(static_cast<std::size_t>(n) * n, 0.0f);
  auto at = [&](int i, int j) -> float& { return h[static_cast<std::size_t>(j) * n + i]; };
  double amplitude = 1.0;
  for (int step = n - 1; step > 1; step /= 2, amplitude *= roughness)
  {
    const int half = step / 2;
    for (int j = half; j < n; j += step) // diamond: centres of squares
      for (int i = half; i < n; i += step)
        at(i, j) = 0.25f * (at(i - half, j - half) + at(i + half, j - half) + at(i - half, j + half) +
                     at(i + half, j + half)) +
          static_cast<float>(amplitude) * uniform(random);
    for (int j = 0; j < n; j += half) // square: edge midpoints
      for (int i = (j / half) % 2 == 0 ? half : 0; i < n; i += step)
      {
        float sum = 0.0f;
        int count = 0;
        if (i >= half) { sum += at(i - half, j); ++count; }
        if (i + half < n) { sum += at(i + half, j); ++count; }
        if (j >= half) { sum += at(i, j - half); ++count; }
        if (j + half < n) { sum += at(i, j + half); ++count; }
        at(i, j) = sum / count + static_cast<float>(amplitude) * uniform(random);
      }
  }
  const auto [low, high] = std::minmax_element(h.begin(), h.end());
  const float lowest = *low, scale = static_cast<float>(reliefM / std::max(1e-6f, *high - *low));
  for (float& value : h)
    value = 200.0f + (value - lowest) * scale;
  return h;
}

void writeGeoTiff(const std::string& path, int n, const std::vector<float>& heights, double spacingM,
  double easting, double northing)
{
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  const char* options[] = { "TILED=YES", nullptr };
  std::unique_ptr<GDALDataset> dataset(
    driver->Create(path.c_str(), n, n, 1, GDT_Float32, const_cast<char**>(options)));
  if (!dataset)
    throw std::runtime_error("cannot create " + path);
  double geoTransform[6] = { easting, spacingM, 0.0, northing, 0.0, -spacingM };
  dataset->SetGeoTransform(geoTransform);
  OGRSpatialReference crs;
  crs.importFromEPSG(32632);
  dataset->SetSpatialRef(&crs);
  if (dataset->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, n, n, const_cast<float*>(heights.data()), n,
        n, GDT_Float32, 0, 0, nullptr) != CE_None)
    throw std::runtime_error("cannot write " + path);
}
} // namespace terralux_bench
