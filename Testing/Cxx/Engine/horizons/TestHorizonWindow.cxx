// A window's horizons (an MPI process's piece and halo, its far terrain given): what
// its rays see, the window's triangles within the detail distance and the far terrain
// beyond, checked with those rays; the same at a post from any window that holds the
// detail distance around it, bit for bit, with the bounds its proofs take; and what
// they prove of a sun, rays find so.
#include "terrain/far_terrain.h"
#include "horizon_checks.h"
#include "horizons/horizon_map.h"
#include "terrain_grids.h"
#include "visibility/visibility.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

using namespace terralux;
using namespace terralux_test;

namespace
{
/// Ridges 30 m apart, and a mountain 1.2 km high in the east: from most posts it
/// stands beyond the detail distance, where only the far terrain shows it.
std::unique_ptr<TerrainGrid> ridgesAndMountain()
{
  return makeGrid(193, 161, 30.0, [](double x, double y) {
    const double mountain = 1200.0 * std::exp(-(std::pow(x - 5200.0, 2) + std::pow(y - 2400.0, 2)) / (2.0 * 500.0 * 500.0));
    return 150.0 * std::sin(x / 700.0) * std::cos(y / 1100.0) + 60.0 * std::sin((x + 2.0 * y) / 400.0) +
      12.0 * std::sin(x / 90.0 + 1.3) * std::sin(y / 110.0) + mountain;
  });
}

constexpr double detail = 450.0; // 15 posts
constexpr int stride = 4;

/// A window of the terrain, with the far terrain given, and its rays.
struct Window
{
  std::unique_ptr<TerrainGrid> grid;
  GivenFarTerrain given;
  std::unique_ptr<Visibility> rays;
};
Window windowWithRays(const TerrainGrid& grid, const FarTerrain& far, int i0, int j0, int nx, int ny)
{
  Window window{ windowOf(grid, i0, j0, nx, ny), GivenFarTerrain{ &far.grid(), stride, i0, j0 }, nullptr };
  RadiosityScene scene = sceneOf({ window.grid.get() });
  scene.farTerrain = window.given;
  window.rays = std::make_unique<Visibility>(scene, FarSight{ stride, detail });
  return window;
}
} // namespace

TEST(HorizonWindow, AWindowsHorizonsAreThoseItsRaysSee)
{
  const auto grid = ridgesAndMountain();
  const FarTerrain far(*grid, stride);
  const int i0 = 24, j0 = 8;
  const Window part = windowWithRays(*grid, far, i0, j0, 121, 121);
  const TerrainGrid* window = part.grid.get();
  const Visibility& rays = *part.rays;
  const HorizonMap map(*window, part.given, detail);
  ASSERT_TRUE(rays.farTerrain());
  // Posts at least the detail distance inside the window's edges.
  int blocked = 0, checked = 0;
  for (int j = 15; j <= 105; j += 6)
    for (int i = 15; i <= 105; i += 7)
    {
      blocked += checkAgainstRays(map, rays, *window, i, j, 0.3 * degree);
      checked += map.azimuthCount();
    }
  EXPECT_GT(blocked, checked / 2);
  // Toward the mountain (east) from a post 2 km west of it, the far terrain alone
  // makes the horizon: the window's triangles within 450 m rise less.
  const HorizonMap::Post post = map.find(window->post(105 - i0, 80 - j0));
  ASSERT_TRUE(post);
  const double mountainTop = std::atan((grid->post(173, 80).z - grid->post(105, 80).z) / 2040.0);
  EXPECT_GT(map.elevation(post, 0), 0.9 * mountainTop);
}

TEST(HorizonWindow, TerrainFallingAwayKeepsItsHorizonBelowTheHorizontal)
{
  // A plane falling at 0.2 toward +x, its far terrain the same plane: from a window's
  // post, toward azimuth phi the terrain lies at atan(-0.2 cos phi), within the detail
  // distance and beyond it; past the far terrain's +x edge nothing lies (the nadir).
  const auto grid = makeGrid(121, 101, 30.0, [](double x, double) { return -0.2 * x; });
  const FarTerrain far(*grid, stride);
  const auto window = windowOf(*grid, 40, 20, 41, 41);
  const HorizonMap map(*window, GivenFarTerrain{ &far.grid(), stride, 40, 20 }, detail);
  const HorizonMap::Post post = map.find(window->post(20, 20));
  ASSERT_TRUE(post);
  for (int a = 0; a < map.azimuthCount(); ++a)
    EXPECT_NEAR(map.trueElevation(post, a), std::atan(-0.2 * std::cos(map.azimuths()[a])), 5e-5)
      << map.azimuths()[a] / degree;
  const auto edgeWindow = windowOf(*grid, 80, 20, 41, 41);
  const HorizonMap edgeMap(*edgeWindow, GivenFarTerrain{ &far.grid(), stride, 80, 20 }, detail);
  const HorizonMap::Post edge = edgeMap.find(edgeWindow->post(40, 20));
  ASSERT_TRUE(edge);
  EXPECT_EQ(edgeMap.trueElevation(edge, 0), -0.5 * pi);
}

TEST(HorizonWindow, WindowsAgreeOnThePostsTheyShare)
{
  const auto grid = ridgesAndMountain();
  const FarTerrain far(*grid, stride);
  std::unique_ptr<HorizonMap> coarser;
  for (const HorizonMap::Density density : HorizonMap::densities)
  {
  SCOPED_TRACE(std::to_string(static_cast<int>(density)) + " azimuths");
  auto wholeMap = std::make_unique<HorizonMap>(*grid, GivenFarTerrain{ &far.grid(), stride, 0, 0 }, detail, density);
  const HorizonMap& whole = *wholeMap;
  // The same map from a coarser one's sweeps (every other azimuth), bit for bit.
  if (coarser)
  {
    const HorizonMap copying(*grid, GivenFarTerrain{ &far.grid(), stride, 0, 0 }, detail, density, coarser.get());
    for (int j = 0; j < grid->postsY(); j += 3)
      for (int i = 0; i < grid->postsX(); i += 3)
      {
        const HorizonMap::Post post = whole.find(grid->post(i, j));
        for (int a = 0; a < whole.azimuthCount(); ++a)
          ASSERT_EQ(copying.trueElevation(post, a), whole.trueElevation(post, a)) << i << " " << j << " azimuth " << a;
      }
  }
  // Two windows of different extents, neither a multiple of the stride from the grid's
  // first post.
  for (const auto& [i0, j0, nx, ny] : { std::array<int, 4>{ 24, 8, 121, 121 }, std::array<int, 4>{ 61, 37, 90, 100 } })
  {
    const auto window = windowOf(*grid, i0, j0, nx, ny);
    const HorizonMap map(*window, GivenFarTerrain{ &far.grid(), stride, i0, j0 }, detail, density);
    ASSERT_EQ(map.azimuthCount(), whole.azimuthCount());
    for (int a = 0; a < map.azimuthCount(); ++a)
      ASSERT_EQ(map.azimuths()[a], whole.azimuths()[a]);
    int compared = 0;
    for (int j = 16; j < ny - 16; ++j)
      for (int i = 16; i < nx - 16; ++i)
      {
        const HorizonMap::Post here = map.find(window->post(i, j)), there = whole.find(grid->post(i0 + i, j0 + j));
        ASSERT_TRUE(here && there);
        for (int a = 0; a < map.azimuthCount(); ++a)
          ASSERT_EQ(map.trueElevation(here, a), whole.trueElevation(there, a)) << i << " " << j << " azimuth " << a;
        // And what the proofs bound the sights with.
        ASSERT_EQ(map.slopeAt(i, j), whole.slopeAt(i0 + i, j0 + j)) << i << " " << j;
        ASSERT_EQ(map.highestAt(i, j), whole.highestAt(i0 + i, j0 + j)) << i << " " << j;
        ++compared;
      }
    EXPECT_EQ(compared, (nx - 32) * (ny - 32));
  }
  coarser = std::move(wholeMap);
  }
}

TEST(HorizonWindow, WhatAWindowsHorizonsProveRaysFindSo)
{
  const auto grid = ridgesAndMountain();
  const FarTerrain far(*grid, stride);
  const Window window = windowWithRays(*grid, far, 40, 16, 113, 129);
  for (const HorizonMap::Density density : HorizonMap::densities)
  {
    const HorizonMap map(*window.grid, window.given, detail, density);
    const Proven share = checkProofs(map, *window.rays, *window.grid, 15, 97, 15, 113, 4);
    EXPECT_GT(share.open, 0.4) << "share " << share.open;
    // A coarse map's sectors are twice as wide: its proofs bound less.
    EXPECT_GT(share.shadowed, density == HorizonMap::Density::Coarse ? 0.1 : 0.2) << "share " << share.shadowed;
  }
}
