#include "fractal_dem.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>

namespace terralux_bench
{
namespace
{
// A well-mixed 64-bit hash (splitmix64's finaliser).
std::uint64_t mix(std::uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Gradient noise (Perlin's, with a quintic fade) at (x, y) on the unit lattice of one
// octave, its gradients drawn from `key`: 0 at lattice points, within about +-0.7.
double gradientNoise(double x, double y, std::uint64_t key)
{
  const double fx = std::floor(x), fy = std::floor(y);
  const double u = x - fx, v = y - fy;
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  auto corner = [&](std::int64_t dx, std::int64_t dy) {
    const std::uint64_t h =
      mix(key ^ mix(static_cast<std::uint64_t>(ix + dx) * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(iy + dy)));
    const double angle = static_cast<double>(h >> 11) * (6.283185307179586 / 9007199254740992.0);
    return std::cos(angle) * (u - dx) + std::sin(angle) * (v - dy);
  };
  auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
  const double c00 = corner(0, 0), c10 = corner(1, 0), c01 = corner(0, 1), c11 = corner(1, 1);
  const double fu = fade(u);
  const double a = c00 + fu * (c10 - c00);
  const double b = c01 + fu * (c11 - c01);
  return a + fade(v) * (b - a);
}
} // namespace

std::vector<float> fractalHeights(int n, std::uint32_t seed, double roughness, double reliefM)
{
  if (n < 3 || ((n - 1) & (n - 2)) != 0)
  {
    throw std::invalid_argument("fractal DEM size must be 2^k + 1");
  }
  // Octaves from the grid's side down to 2 posts, each `roughness` times the one
  // before, each on its own lattice turned and shifted at random, so that no scale of
  // the relief lines up with the posts (diamond-square's did, which biased anything
  // that samples every 4th post: docs/benchmarks.md).
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  struct Octave
  {
    double cosine, sine, scale, offsetX, offsetY, amplitude;
    std::uint64_t key;
  };
  std::vector<Octave> octaves;
  double amplitude = 1.0;
  for (int wavelength = n - 1; wavelength >= 2; wavelength /= 2, amplitude *= roughness)
  {
    // Drawn one statement at a time: the order of draws within one expression is
    // unspecified, and a seed must give one DEM whatever order a compiler picks.
    const double angle = 6.283185307179586 * uniform(random);
    const double offsetX = 1024.0 * uniform(random);
    const double offsetY = 1024.0 * uniform(random);
    const std::uint64_t high = random();
    const std::uint64_t low = random();
    octaves.push_back({ std::cos(angle), std::sin(angle), 1.0 / wavelength, offsetX, offsetY, amplitude, (high << 32) | low });
  }
  std::vector<float> h(static_cast<std::size_t>(n) * n, 0.0f);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      double sum = 0.0;
      for (const Octave& o : octaves)
        sum += o.amplitude *
          gradientNoise(o.scale * (o.cosine * i - o.sine * j) + o.offsetX, o.scale * (o.sine * i + o.cosine * j) + o.offsetY, o.key);
      h[static_cast<std::size_t>(j) * n + i] = static_cast<float>(sum);
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
