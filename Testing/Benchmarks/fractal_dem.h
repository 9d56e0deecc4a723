#pragma once
// Generated test terrain: fractal heights (fractional Brownian motion of gradient
// noise) with a fixed seed, so scale benchmarks run on the same "real-looking" DEM
// every time.

#include <cstdint>
#include <string>
#include <vector>

namespace terralux_bench
{
/// The relief of the benchmarks' DEMs (make_fractal_dem, roughness 0.55): the gentle
/// one's (1025^2 at 30 m: mean slope 8.0 deg, p95 15 deg) and the steep one's (mean 15
/// deg, p95 28 deg, as real mountain DEMs).
constexpr double gentleReliefM = 1500.0;
constexpr double steepReliefM = 3000.0;

/// n = 2^k + 1 posts per side; roughness in (0, 1) (0.5 ~ natural terrain): each
/// octave's amplitude over the one of twice its wavelength, from the grid's side down
/// to 2 posts; heights in metres, reliefM from lowest to highest.
std::vector<float> fractalHeights(int n, std::uint32_t seed, double roughness, double reliefM);

/// Writes heights as a float32 GeoTIFF in UTM zone 32N (EPSG:32632) with the given
/// post spacing, its upper-left corner at (easting, northing).
void writeGeoTiff(const std::string& path, int n, const std::vector<float>& heights, double spacingM,
  double easting, double northing);
} // namespace terralux_bench
