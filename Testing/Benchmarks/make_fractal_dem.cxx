// Writes a fractal DEM GeoTIFF: make_fractal_dem OUT.tif [N=4097] [SEED=1] [SPACING=30]
#include "fractal_dem.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: make_fractal_dem OUT.tif [N=4097] [SEED=1] [SPACING_M=30]\n";
    return 2;
  }
  const int n = argc > 2 ? std::atoi(argv[2]) : 4097;
  const unsigned seed = argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 1u;
  const double spacing = argc > 4 ? std::atof(argv[4]) : 30.0;
  try
  {
    const auto heights = terralux_bench::fractalHeights(n, seed, 0.55, 1500.0);
    terralux_bench::writeGeoTiff(argv[1], n, heights, spacing, 300000.0, 5200000.0);
  }
  catch (const std::exception& error)
  {
    std::cerr << "make_fractal_dem: " << error.what() << "\n";
    return 1;
  }
  std::cout << "wrote " << argv[1] << ": " << n << " x " << n << " float32 posts at " << spacing
            << " m, seed " << seed << "\n";
  return 0;
}
