// Writes a fractal DEM GeoTIFF: make_fractal_dem OUT.tif [N=4097] [SEED=1] [SPACING=30] [RELIEF=1500]
#include "fractal_dem.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace
{
const char* const usage =
  "usage: make_fractal_dem OUT.tif [N=4097] [SEED=1] [SPACING_M=30] [RELIEF_M=1500]\n"
  "  an N x N fractal DEM (N = 2^k + 1; UTM 32N), seeded, as a float32 GeoTIFF; relief 1500 m is the\n"
  "  gentle benchmark DEM (1025^2: mean slope 8.0 deg), 3000 m the steep one (mean 15 deg, p95 28 deg)\n";

// The whole argument as a number, or false.
bool parse(const char* text, double& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && errno == 0;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0))
  {
    std::cout << usage; // and no file
    return 0;
  }
  if (argc < 2 || argc > 6)
  {
    std::cerr << usage;
    return 2;
  }
  if (argv[1][0] == '-')
  {
    std::cerr << "make_fractal_dem: unknown option " << argv[1] << "\n" << usage;
    return 2;
  }
  double n = 4097, seed = 1, spacing = 30.0, relief = terralux_bench::gentleReliefM;
  if ((argc > 2 && !parse(argv[2], n)) || (argc > 3 && !parse(argv[3], seed)) ||
    (argc > 4 && !parse(argv[4], spacing)) || (argc > 5 && !parse(argv[5], relief)) ||
    !(n >= 3 && n <= 32767 && n == static_cast<int>(n)) || !(seed >= 0 && seed <= 4294967295.0) ||
    !(spacing > 0 && spacing < 1e6) || !(relief >= 0 && relief < 1e5))
  {
    std::cerr << "make_fractal_dem: N must be a whole number in 3..32767, SEED in 0..2^32-1, SPACING_M in (0, 1e6), "
                 "RELIEF_M in [0, 1e5)\n"
              << usage;
    return 2;
  }
  try
  {
    const auto heights = terralux_bench::fractalHeights(static_cast<int>(n), static_cast<unsigned>(seed), 0.55, relief);
    terralux_bench::writeGeoTiff(argv[1], static_cast<int>(n), heights, spacing, 300000.0, 5200000.0);
  }
  catch (const std::exception& error)
  {
    std::cerr << "make_fractal_dem: " << error.what() << "\n";
    return 1;
  }
  std::cout << "wrote " << argv[1] << ": " << n << " x " << n << " float32 posts at " << spacing << " m, seed "
            << seed << "\n";
  return 0;
}
