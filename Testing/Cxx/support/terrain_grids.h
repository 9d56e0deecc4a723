#pragma once
// Terrain grids for engine tests, built in code: planes, hills, steps, holes.

#include "hierarchy/radiosity_types.h"
#include "terrain/terrain_grid.h"

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace terralux_test
{
/// nx x ny posts at `spacing` metres, post (i, j) at (x(i), y(j), height(x, y)); cells
/// for which `valid` is false are missing.
inline std::unique_ptr<terralux::TerrainGrid> makeGrid(int nx, int ny, double spacing,
  const std::function<double(double, double)>& height,
  const std::function<bool(int, int)>& valid = [](int, int) { return true; },
  const std::function<double(int)>& xOf = nullptr)
{
  auto grid = std::make_unique<terralux::TerrainGrid>(nx, ny, terralux::Vec3(0.5 * spacing * (nx - 1), 0.5 * spacing * (ny - 1), 0.0));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
      const double x = xOf ? xOf(i) : spacing * i, y = spacing * j;
      grid->setPost(i, j, terralux::Vec3(x, y, height(x, y)));
    }
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i)
      grid->setCellValid(i, j, valid(i, j));
  grid->setUniformMaterial(terralux::uniformSpectrum(0.2), terralux::uniformSpectrum(0.0));
  return grid;
}

/// Rolling hills: crossed waves of `height` metres over `lengthX` x `lengthY` (metres
/// per radian) plus a diagonal ridge of `ridge` metres every `ridgeLength` radians.
struct Hills
{
  double height, lengthX, lengthY, ridge, ridgeLength;
  double operator()(double x, double y) const
  {
    return this->height * std::sin(x / this->lengthX) * std::cos(y / this->lengthY) +
      this->ridge * std::sin((x + 2.0 * y) / this->ridgeLength);
  }
};
/// The hills the engine's larger tests share: 260 m of relief over kilometres.
inline constexpr Hills rollingHills{ 200.0, 900.0, 1300.0, 60.0, 500.0 };

/// Posts [i0, i0 + nx) x [j0, j0 + ny) of `grid`, bit for bit, with its cells' validity
/// and its material; its origin kept (a window of it, as an MPI process holds).
inline std::unique_ptr<terralux::TerrainGrid> windowOf(const terralux::TerrainGrid& grid, int i0, int j0, int nx, int ny)
{
  auto window = std::make_unique<terralux::TerrainGrid>(nx, ny, grid.origin());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      window->setPost(i, j, grid.post(i0 + i, j0 + j));
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i)
      window->setCellValid(i, j, grid.cellValid(i0 + i, j0 + j));
  window->setUniformMaterial(grid.cellReflectance(0, 0), grid.cellEmission(0, 0));
  return window;
}

/// A scene of terrains alone.
inline terralux::RadiosityScene sceneOf(const std::vector<const terralux::TerrainGrid*>& grids)
{
  terralux::RadiosityScene scene;
  scene.terrains = grids;
  return scene;
}
inline terralux::RadiosityScene sceneOf(const terralux::TerrainGrid& grid)
{
  return sceneOf(std::vector<const terralux::TerrainGrid*>{ &grid });
}
} // namespace terralux_test
