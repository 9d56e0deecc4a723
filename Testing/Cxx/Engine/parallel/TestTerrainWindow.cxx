// A window of a terrain (an MPI process's piece and its halo) solved with the whole
// grid's far terrain given (GivenFarTerrain): its piece's posts take the values the
// whole grid gives them with the same far terrain, to 1e-6, while it holds a fraction
// of the posts at full resolution. This is what lets memory follow the piece.
#include "base/angles.h"
#include "sky/cie_sky.h"
#include "base/error.h"
#include "terrain/far_terrain.h"
#include "evaluation/point_values.h"
#include "sky/sky_hierarchy.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "terrain_grids.h"
#include "hierarchy/terrain_patch.h"
#include "parallel/terrain_window.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace terralux;
using namespace terralux_test;

TEST(TerrainWindow, AWindowHoldsThreeDetailDistancesAndTheLatticeFromACellOfIt)
{
  // 300 m at 30 m posts: 30 posts, the lattice posts a read weighs (16 posts) and a
  // margin of 3.
  EXPECT_EQ(TerrainWindow::haloPosts(300.0, 30.0), 49);
  EXPECT_EQ(TerrainWindow::haloPosts(300.0, 0.0), -1);
  EXPECT_EQ(TerrainWindow::haloPosts(1e12, 1e-3), -1);
  // The piece [40, 59]^2 of a 100^2 grid grown by 10, its low ends moved down to a
  // multiple of the lattice's cell (8) from the whole grid's: [24, 69]^2.
  const TerrainWindow::Extent window = TerrainWindow::requested({ 0, 99, 0, 99 }, { 40, 59, 40, 59 }, 10);
  EXPECT_EQ(window.i0, 24);
  EXPECT_EQ(window.i1, 69);
  EXPECT_EQ(window.j0, 24);
  EXPECT_EQ(window.j1, 69);
  EXPECT_EQ(TerrainWindow::requested({ 0, 99, 0, 99 }, { 0, 9, 90, 99 }, 10).j1, 99); // clamped to the whole

  // What a piece's values need, checked on the posts given: the whole grid, or a
  // window with room enough, passes; one cut short, or not on the lattice, does not.
  const auto grid = makeGrid(100, 100, 30.0, [](double x, double y) { return 0.01 * x + 0.02 * y; });
  EXPECT_NO_THROW(TerrainWindow::checkHeld(*grid, 90.0, { 0, 99, 0, 99 }, { 0, 99, 0, 99 }, { 40, 59, 40, 59 }));
  EXPECT_NO_THROW(TerrainWindow::checkHeld(*grid, 90.0, { 0, 99, 0, 99 }, { 8, 91, 8, 91 }, { 40, 59, 40, 59 }));
  EXPECT_THROW(TerrainWindow::checkHeld(*grid, 90.0, { 0, 99, 0, 99 }, { 16, 83, 16, 83 }, { 40, 59, 40, 59 }), Error);
  EXPECT_THROW(TerrainWindow::checkHeld(*grid, 90.0, { 0, 99, 0, 99 }, { 17, 83, 16, 83 }, { 40, 59, 40, 59 }), Error);
}

TEST(TerrainWindow, APiecesPostsTakeTheWholeGridsValuesFromAWindowAndTheFarTerrain)
{
  // Ridges and a hole, 193 x 161 posts 30 m apart, under a sun and a clear sky.
  const auto grid = makeGrid(
    193, 161, 30.0,
    [](double x, double y) {
      return 250.0 * std::sin(x / 700.0) * std::cos(y / 1100.0) + 80.0 * std::sin((x + 2.0 * y) / 400.0);
    },
    [](int i, int j) { return !(i >= 150 && i < 156 && j >= 30 && j < 34); });
  grid->setUniformMaterial(uniformSpectrum(0.25), Spectrum{});
  const FarTerrain far(*grid, 4);
  const Direction sun = directionFromZenithAzimuth(60.0 * degree, 2.5);
  const SkyHierarchy sky(CieGeneralSky(12, sun), 120.0, 6);
  const double detail = 450.0;
  auto solve = [&](const TerrainGrid& terrain, int i0, int j0) {
    RadiosityScene scene = sceneOf(terrain);
    scene.farTerrain = GivenFarTerrain{ &far.grid(), 4, i0, j0 };
    RadiosityOptions options;
    options.gatherDetailDistance = detail;
    auto solver = std::make_unique<HierarchicalRadiosity>(scene, options);
    solver->addSun(Vec3(sun[0], sun[1], sun[2]), uniformSpectrum(800.0));
    solver->setSky(&sky);
    EXPECT_TRUE(solver->solve());
    auto points = std::make_unique<PointEvaluator>(*solver, EvaluationPlan{});
    return std::make_pair(std::move(solver), std::move(points));
  };
  // The piece: posts [80, 112] x [40, 80]. Its window reaches three detail distances
  // (45 posts) and the lattice's 8 posts plus 2 beyond it, from a multiple of 8.
  const int piece[4] = { 80, 112, 40, 80 };
  const int i0 = 24, j0 = 0, i1 = 168, j1 = 136;
  const auto window = windowOf(*grid, i0, j0, i1 - i0 + 1, j1 - j0 + 1);
  const auto wholeLit = solve(*grid, 0, 0);
  const auto partLit = solve(*window, i0, j0);
  const HierarchicalRadiosity *whole = wholeLit.first.get(), *part = partLit.first.get();
  EXPECT_EQ(part->hierarchyTerrain()->grid().postsX(), 49);
  // One hierarchy, on the far terrain, whichever grid the posts are in.
  EXPECT_EQ(part->statistics().elements, whole->statistics().elements);
  EXPECT_EQ(part->statistics().links, whole->statistics().links);

  for (const bool atPoints : { true, false })
  {
    SCOPED_TRACE(atPoints ? "at points" : "averaged");
    PointEvaluation how;
    how.atPoints = atPoints;
    std::vector<double> global[2], flat[2];
    constexpr std::size_t components = PointValues::flatComponents;
    for (int k = 0; k < 2; ++k)
    {
      const PointEvaluator& points = *(k == 0 ? wholeLit : partLit).second;
      const HierarchicalRadiosity& solver = points.solver();
      const int di = k == 0 ? 0 : i0, dj = k == 0 ? 0 : j0;
      const int posts[4] = { piece[0] - di, piece[1] - di, piece[2] - dj, piece[3] - dj };
      const int nx = solver.postGrid(*solver.terrainRoots()[0]).postsX();
      global[k].assign(grid->postsX() * grid->postsY(), std::nan(""));
      flat[k].assign(global[k].size() * components, std::nan(""));
      terrainPostValues(points, *solver.terrainRoots()[0], posts, how, [&](std::size_t post, const PointValues& v) {
        const std::size_t i = post % nx + di, j = post / nx + dj;
        global[k][j * grid->postsX() + i] = v.globalIrradiance()[0];
        v.flatten(&flat[k][(j * grid->postsX() + i) * components]);
      });
    }
    int compared = 0;
    double largest = 0.0;
    for (int j = piece[2]; j <= piece[3]; ++j)
      for (int i = piece[0]; i <= piece[1]; ++i)
      {
        const std::size_t p = static_cast<std::size_t>(j) * grid->postsX() + i;
        ASSERT_TRUE(std::isfinite(global[0][p]) && std::isfinite(global[1][p])) << i << ", " << j;
        largest = std::max(largest, std::abs(global[1][p] - global[0][p]) / global[0][p]);
        // Every value a post has (each category of light, each band, sky view,
        // radiosity), against the post's global irradiance where it is near zero.
        for (std::size_t c = 0; c < components; ++c)
        {
          const double a = flat[0][p * components + c], b = flat[1][p * components + c];
          largest = std::max(largest, std::abs(b - a) / std::max(std::abs(a), 1e-3 * global[0][p]));
        }
        ++compared;
      }
    EXPECT_EQ(compared, 33 * 41);
    EXPECT_LE(largest, 1e-6);
  }
}

TEST(TerrainWindow, AGivenFarTerrainMapsTheWindowsPostsToItsOwn)
{
  const auto grid = makeGrid(41, 33, 10.0, [](double x, double y) { return 0.1 * x + 0.05 * y; });
  const FarTerrain far(*grid, 4);
  // A window from post (8, 16) of the full grid: its post (0, 0) is the far terrain's
  // (2, 4); its post (6, 3), the full grid's (14, 19), lies at (3.5, 4.75).
  const FarTerrain given(GivenFarTerrain{ &far.grid(), 4, 8, 16 });
  EXPECT_DOUBLE_EQ(given.coarseU(0.0), 2.0);
  EXPECT_DOUBLE_EQ(given.coarseV(0.0), 4.0);
  EXPECT_DOUBLE_EQ(given.coarseU(6.0), 3.5);
  EXPECT_DOUBLE_EQ(given.coarseV(3.0), 4.75);
  EXPECT_DOUBLE_EQ(given.fineU(3.5), 6.0);
  EXPECT_DOUBLE_EQ(given.fineV(0.0), -16.0);
  EXPECT_TRUE(given.grid().sameSurface(far.grid()));
  EXPECT_THROW(FarTerrain(GivenFarTerrain{ &far.grid(), 1, 0, 0 }), Error);
}
