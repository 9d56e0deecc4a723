// Engine tests of the hierarchical terrain mesh (paper section 4): the grid's surface,
// patch splitting and holes, generic-edge neighbour finding and T-vertices on
// hand-built refinement patterns, leaf-mesh continuity, and solutions on planes, a
// hill, a vertical step and a terrain with a hole against closed forms.
#include "sky/sky_hierarchy.h"
#include "base/angles.h"
#include "solver/solver.h"
#include "hierarchy/terrain_edges.h"
#include "terrain_grids.h"
#include "terrain/terrain_mesh.h"
#include "hierarchy/terrain_patch.h"

#include "sky/cie_sky.h"
#include "radiosity_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <iterator>
#include <random>

using namespace terralux;
using namespace terralux_test;

namespace
{

TerrainPatch* child(TerrainPatch* patch, double u0, double v0)
{
  for (HElement* c : patch->children())
  {
    auto* p = static_cast<TerrainPatch*>(c);
    if (p->range().u0 == u0 && p->range().v0 == v0)
      return p;
  }
  return nullptr;
}

std::vector<std::array<double, 4>> rangesOf(const std::vector<const TerrainPatch*>& patches)
{
  std::vector<std::array<double, 4>> r;
  for (const TerrainPatch* p : patches)
    r.push_back({ p->range().u0, p->range().v0, p->range().u1, p->range().v1 });
  return r;
}

// The refinement pattern of the neighbour tests on an 8 x 8-cell flat grid: the root
// split once; its low corner child again; that one's high corner child again (single
// cells); and optionally one of those cells below cell size.
struct Pattern
{
  ElementStore store;
  std::unique_ptr<TerrainGrid> grid = makeGrid(9, 9, 10.0, [](double, double) { return 0.0; });
  TerrainPatch* root = nullptr;
  TerrainPatch *east = nullptr, *cell33 = nullptr;

  explicit Pattern(bool subCell)
  {
    std::vector<TerrainPatch*> complete;
    this->root = TerrainPatch::buildTree(this->store, *this->grid, 0, complete);
    TerrainPatch* low = child(this->root, 0, 0);
    this->east = child(this->root, 4, 0);
    TerrainPatch* corner = child(low, 2, 2);
    corner->children();
    this->cell33 = child(corner, 3, 3);
    if (subCell)
      this->cell33->children();
  }
};
} // namespace

TEST(TerrainGrid, SurfaceOfATiltedPlane)
{
  const double a = 0.3, b = -0.2, spacing = 10.0;
  const auto grid = makeGrid(6, 5, spacing, [&](double x, double y) { return a * x + b * y; });
  const Vec3 normal = glm::normalize(Vec3(-a, -b, 1.0));
  const TerrainRangeSummary all = grid->summarize(0, 0, 5, 4);
  EXPECT_NEAR(all.area, 50.0 * 40.0 * std::sqrt(1.0 + a * a + b * b), 1e-6);
  EXPECT_NEAR(glm::dot(glm::normalize(all.areaVector), normal), 1.0, 1e-12);
  EXPECT_EQ(all.validCells, 20u);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 5.0), v(0.0, 4.0);
  for (int k = 0; k < 100; ++k)
  {
    const double pu = u(random), pv = v(random);
    const TerrainPoint p = grid->surfacePoint(pu, pv);
    EXPECT_NEAR(p.position.x, spacing * pu, 1e-4);
    EXPECT_NEAR(p.position.y, spacing * pv, 1e-4);
    EXPECT_NEAR(p.position.z, a * p.position.x + b * p.position.y, 1e-4);
    EXPECT_NEAR(glm::dot(p.normal, normal), 1.0, 1e-6);
  }
  EXPECT_EQ(grid->surfacePoint(3.0, 2.0).position, grid->post(3, 2)); // posts exactly
  EXPECT_NEAR(glm::dot(grid->postNormal(0, 0), normal), 1.0, 1e-6);
  EXPECT_NEAR(glm::dot(grid->postNormal(3, 2), normal), 1.0, 1e-6);
}

// A post's normal is that of the triangles that have it as a corner, area-weighted:
// checked against their area vectors found one by one from the cells' triangles, on
// rough terrain, at inner posts, at edges and corners, and next to a missing cell.
TEST(TerrainGrid, PostNormalsAreTheAreaWeightedNormalsOfTheirTriangles)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> rough(-15.0, 15.0);
  std::vector<double> heights(7 * 6);
  for (double& h : heights)
    h = rough(random);
  const auto grid = makeGrid(
    7, 6, 10.0, [&](double x, double y) { return heights[static_cast<std::size_t>(std::lround(y / 10.0) * 7 + std::lround(x / 10.0))]; },
    [](int i, int j) { return !(i == 4 && j == 3); });
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 7; ++i)
    {
      Vec3 sum(0.0);
      for (int cj = std::max(0, j - 1); cj <= std::min(j, 4); ++cj)
        for (int ci = std::max(0, i - 1); ci <= std::min(i, 5); ++ci)
          if (grid->cellValid(ci, cj))
            for (const TerrainGrid::Triangle& t : grid->cellTriangles(ci, cj))
              if (std::find(t.begin(), t.end(), grid->post(i, j)) != t.end())
                sum += TerrainGrid::areaVector(t);
      const Vec3 expected = glm::normalize(sum), normal = grid->postNormal(i, j);
      EXPECT_NEAR(glm::length(normal - expected), 0.0, 1e-12) << "post " << i << ", " << j;
    }
}

TEST(TerrainPatch, SplitRanges)
{
  using R = std::array<double, 4>;
  auto split = [](const ParameterRange& r) {
    std::vector<R> out;
    for (const ParameterRange& c : TerrainPatch::splitRange(r))
      out.push_back({ c.u0, c.v0, c.u1, c.v1 });
    return out;
  };
  EXPECT_EQ(split({ 0, 0, 5, 3 }), (std::vector<R>{ { 0, 0, 2, 1 }, { 2, 0, 5, 1 }, { 2, 1, 5, 3 }, { 0, 1, 2, 3 } }));
  EXPECT_EQ(split({ 4, 0, 5, 3 }), (std::vector<R>{ { 4, 0, 5, 1 }, { 4, 1, 5, 3 } }));
  EXPECT_EQ(split({ 2, 2, 3, 3 }),
    (std::vector<R>{ { 2, 2, 2.5, 2.5 }, { 2.5, 2, 3, 2.5 }, { 2.5, 2.5, 3, 3 }, { 2, 2.5, 2.5, 3 } }));
}

TEST(TerrainPatch, TrueAreaNormalAndBoundsOfAHill)
{
  const auto grid = makeGrid(17, 17, 10.0, [](double x, double y) {
    return 60.0 * std::exp(-((x - 80) * (x - 80) + (y - 80) * (y - 80)) / (2 * 30.0 * 30.0));
  });
  ElementStore store;
  std::vector<TerrainPatch*> complete;
  TerrainPatch* root = TerrainPatch::buildTree(store, *grid, 0, complete);
  ASSERT_EQ(complete.size(), 1u);
  ASSERT_EQ(complete[0], root);
  // The coarse quad is the flat square of the corner posts; the patch keeps the hill's area and height.
  EXPECT_GT(root->area(), 160.0 * 160.0 * 1.02);
  EXPECT_NEAR(root->normal().z, 1.0, 1e-9); // symmetric hill: the mean normal is up
  EXPECT_GT(root->unalignedArea(), 0.01 * root->area());
  Vec3 low, high;
  root->bounds(low, high);
  EXPECT_NEAR(high.z, 60.0, 1e-3);
  // Samples lie on the hill, not on the coarse quad.
  SampleGenerator random(7);
  for (int k = 0; k < 16; ++k)
  {
    const SurfaceSample s = root->sample(k, 16, random);
    const double u = s.position.x / 10.0, v = s.position.y / 10.0;
    EXPECT_NEAR(s.position.z, grid->surfacePoint(u, v).position.z, 1e-3);
  }
  // Children: the four quadrants, whose areas add up to the parent's.
  double sum = 0.0;
  for (HElement* c : root->children())
    sum += c->area();
  EXPECT_NEAR(sum, root->area(), 1e-6 * root->area());
}

TEST(TerrainPatch, HolesSplitUntilTheValidPartIsRepresented)
{
  // 8 x 8 cells without the 2 x 3 cells [3, 5) x [2, 5).
  auto hole = [](int i, int j) { return i >= 3 && i < 5 && j >= 2 && j < 5; };
  const auto grid = makeGrid(9, 9, 10.0, [](double x, double) { return 0.1 * x; }, [&](int i, int j) { return !hole(i, j); });
  ElementStore store;
  std::vector<TerrainPatch*> complete;
  TerrainPatch* root = TerrainPatch::buildTree(store, *grid, 0, complete);
  ASSERT_NE(root, nullptr);
  EXPECT_FALSE(root->complete());
  double area = 0.0;
  for (TerrainPatch* p : complete)
  {
    EXPECT_TRUE(p->complete());
    area += p->area();
    const ParameterRange& r = p->range();
    for (int j = static_cast<int>(r.v0); j < r.v1; ++j)
      for (int i = static_cast<int>(r.u0); i < r.u1; ++i)
        EXPECT_FALSE(hole(i, j)) << "patch over the hole at " << i << ", " << j;
  }
  EXPECT_NEAR(area, 58 * 100.0 * std::sqrt(1.01), 1e-6);
  // A grid with no valid cell has no tree.
  const auto empty = makeGrid(3, 3, 1.0, [](double, double) { return 0.0; }, [](int, int) { return false; });
  complete.clear();
  EXPECT_EQ(TerrainPatch::buildTree(store, *empty, 1, complete), nullptr);
  EXPECT_TRUE(complete.empty());
}

TEST(TerrainEdges, NeighboursAcrossLevels)
{
  Pattern p(false);
  using R = std::array<double, 4>;
  // The coarse east patch sees, across u = 4, one 2 x 2 patch and two single cells.
  const GenericEdge west = edgeOf(*p.east, Side::LowU);
  EXPECT_EQ(west.line, 4.0);
  EXPECT_EQ(rangesOf(neighbourLeaves(west)), (std::vector<R>{ { 2, 0, 4, 2 }, { 3, 2, 4, 3 }, { 3, 3, 4, 4 } }));
  EXPECT_EQ(tVertices(west), (std::vector<double>{ 2.0, 3.0 }));
  // A single cell looks up to the root (its edge's full support), across, and finds the coarse patch.
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*p.cell33, Side::HighU))), (std::vector<R>{ { 4, 0, 8, 4 } }));
  EXPECT_TRUE(tVertices(edgeOf(*p.cell33, Side::HighU)).empty());
  // Across v = 4 it finds the root's upper-left quadrant.
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*p.cell33, Side::HighV))), (std::vector<R>{ { 0, 4, 4, 8 } }));
  // Its siblings, at the same level.
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*p.cell33, Side::LowU))), (std::vector<R>{ { 2, 3, 3, 4 } }));
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*p.cell33, Side::LowV))), (std::vector<R>{ { 3, 2, 4, 3 } }));
  // The grid's border has no neighbours.
  EXPECT_TRUE(neighbourLeaves(edgeOf(*p.east, Side::HighU)).empty());
  EXPECT_TRUE(neighbourLeaves(edgeOf(*p.east, Side::LowV)).empty());
  // The upper-left quadrant sees, across v = 4, the east half of the split corner.
  const TerrainPatch* upperLeft = child(p.root, 0, 4);
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*upperLeft, Side::LowV))),
    (std::vector<R>{ { 0, 2, 2, 4 }, { 2, 3, 3, 4 }, { 3, 3, 4, 4 } }));
  EXPECT_EQ(tVertices(edgeOf(*upperLeft, Side::LowV)), (std::vector<double>{ 2.0, 3.0 }));
}

TEST(TerrainEdges, NeighboursBelowCellSize)
{
  Pattern p(true);
  using R = std::array<double, 4>;
  const GenericEdge west = edgeOf(*p.east, Side::LowU);
  EXPECT_EQ(rangesOf(neighbourLeaves(west)),
    (std::vector<R>{ { 2, 0, 4, 2 }, { 3, 2, 4, 3 }, { 3.5, 3, 4, 3.5 }, { 3.5, 3.5, 4, 4 } }));
  EXPECT_EQ(tVertices(west), (std::vector<double>{ 2.0, 3.0, 3.5 }));
  // From the quarter cell back to the coarse patch, up three levels of the hierarchy.
  TerrainPatch* quarter = child(p.cell33, 3.5, 3.5);
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*quarter, Side::HighU))), (std::vector<R>{ { 4, 0, 8, 4 } }));
  EXPECT_EQ(rangesOf(neighbourLeaves(edgeOf(*quarter, Side::LowU))), (std::vector<R>{ { 3, 3.5, 3.5, 4 } }));
}

TEST(TerrainEdges, HolesHaveNoNeighbours)
{
  auto hole = [](int i, int j) { return i >= 4 && j < 4; }; // the low-v east quadrant is missing
  const auto grid = makeGrid(9, 9, 10.0, [](double, double) { return 0.0; }, [&](int i, int j) { return !hole(i, j); });
  ElementStore store;
  std::vector<TerrainPatch*> complete;
  TerrainPatch* root = TerrainPatch::buildTree(store, *grid, 0, complete);
  ASSERT_EQ(complete.size(), 3u);
  const TerrainPatch* low = child(root, 0, 0);
  EXPECT_TRUE(neighbourLeaves(edgeOf(*low, Side::HighU)).empty());
  EXPECT_EQ(neighbourLeaves(edgeOf(*low, Side::HighV)).size(), 1u);
}

TEST(TerrainLeafMesh, ContinuousAcrossLevels)
{
  Pattern p(true);
  const TerrainLeafMesh mesh(*p.root);
  ASSERT_EQ(mesh.leaves().size(), 3u + 3u + 3u + 4u); // 3 quadrants, 3 of the corner, 3 cells, 4 quarters
  // (4,2) (4,3) (4,3.5) on the east patch, (2,4) (3,4) (3.5,4) on the upper-left one,
  // (3,2) (2,3) on the 2 x 2 patches, (3,3.5) (3.5,3) on the cells next to the quarters.
  EXPECT_EQ(mesh.tVertexCount(), 10u);
  // The coarse east patch's boundary: 4 corners and the 3 T-vertices on its west side.
  for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
    if (mesh.leaves()[k] == p.east)
    {
      EXPECT_EQ(mesh.boundary(k).size(), 7u);
      EXPECT_EQ(mesh.mostTVerticesOnAnEdge(k), 3); // not restricted: neighbours 3 levels finer
    }
  // Arbitrary values per leaf (3 components); along every edge, both sides agree at the
  // neighbours' corners and in between.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(0.0, 100.0);
  std::vector<double> leafValues(3 * mesh.leaves().size());
  for (double& v : leafValues)
    v = value(random);
  const std::vector<double> vertexValues = mesh.vertexValues(leafValues, 3);
  auto indexOf = [&](const TerrainPatch* leaf) {
    return static_cast<std::size_t>(std::find(mesh.leaves().begin(), mesh.leaves().end(), leaf) - mesh.leaves().begin());
  };
  int checked = 0;
  for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
    for (int side = 0; side < 4; ++side)
    {
      const GenericEdge edge = edgeOf(*mesh.leaves()[k], static_cast<Side>(side));
      for (const TerrainPatch* other : neighbourLeaves(edge))
      {
        const double from = std::max(edge.from, edge.alongU() ? other->range().u0 : other->range().v0);
        const double to = std::min(edge.to, edge.alongU() ? other->range().u1 : other->range().v1);
        for (double t : { from, 0.3 * from + 0.7 * to, to })
        {
          const double u = edge.alongU() ? t : edge.line, v = edge.alongU() ? edge.line : t;
          double mine[3], theirs[3];
          mesh.interpolate(k, vertexValues, 3, u, v, mine);
          mesh.interpolate(indexOf(other), vertexValues, 3, u, v, theirs);
          for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(mine[c], theirs[c], 1e-9) << "leaf " << k << " side " << side << " at " << u << ", " << v;
          ++checked;
        }
      }
    }
  EXPECT_GT(checked, 40);
}

namespace
{
RadiosityOptions terrainOptions(double tolerance)
{
  RadiosityOptions options;
  options.errorTolerance = tolerance;
  options.visibilitySamples = 4;
  return options;
}

// Sun and uniform sky at every post of `grid` selected by `where`, through irradianceAt.
template <typename Check>
void forEachPost(const HierarchicalRadiosity& solver, const TerrainGrid& grid, Check check)
{
  const TerrainPatch* root = solver.terrainRoots()[0];
  for (int j = 0; j < grid.postsY(); ++j)
    for (int i = 0; i < grid.postsX(); ++i)
    {
      const TerrainPatch* leaf = root->leafHolding(i, j);
      ASSERT_NE(leaf, nullptr) << i << ", " << j;
      check(i, j, solver.irradianceAt(*leaf, grid.post(i, j), grid.postNormal(i, j)));
    }
}
} // namespace

TEST(TerrainHierarchy, FlatAndTiltedPlanesAgainstClosedForms)
{
  const double radiance = 30.0, sunFlux = 900.0;
  const SkyHierarchy sky(UniformSky(), pi * radiance, 7);
  const Vec3 sun = glm::normalize(Vec3(0.2, -0.4, 0.7));
  for (double slope : { 0.0, 30.0 })
  {
    const double t = std::tan(slope * degree);
    const auto grid = makeGrid(33, 33, 10.0, [&](double, double y) { return t * y; });
    RadiosityScene scene;
    scene.terrains.push_back(grid.get());
    HierarchicalRadiosity solver(scene, terrainOptions(2e-4));
    solver.addSun(sun, uniformSpectrum(sunFlux));
    solver.setSky(&sky);
    ASSERT_TRUE(solver.solve());
    // Lazy: at a coarse tolerance a plane's patches stay far larger than its cells; all
    // elements (sky patches and clusters too) are fewer than a quarter of the 2048
    // triangles the plain path starts from.
    HierarchicalRadiosity coarse(scene, terrainOptions(1e-2));
    coarse.addSun(sun, uniformSpectrum(sunFlux));
    ASSERT_TRUE(coarse.solve());
    EXPECT_LT(coarse.statistics().elements, 2048u / 4u);
    const Vec3 normal = glm::normalize(Vec3(0.0, -t, 1.0));
    const double expectedSun = sunFlux * glm::dot(normal, sun);
    const double expectedSky = pi * radiance * (1.0 + std::cos(slope * degree)) / 2.0;
    forEachPost(solver, *grid, [&](int i, int j, const PointIrradiance& e) {
      // A plane neither shadows nor lights itself, however coarse its patches.
      EXPECT_NEAR(e.irradiance[SunLight][0], expectedSun, 1e-6 * sunFlux) << slope << " at " << i << ", " << j;
      EXPECT_NEAR(e.irradiance[SkyLight][0] / expectedSky, 1.0, 0.01) << slope << " at " << i << ", " << j;
      EXPECT_NEAR(e.irradiance[ReflectedLight][0], 0.0, 1e-9);
    });
    // The leaves' own sky view factor (what interpolated outputs use).
    const TerrainLeafMesh leaves(*solver.terrainRoots()[0]);
    for (const TerrainPatch* leaf : leaves.leaves())
      EXPECT_NEAR(leaf->SkyViewFactor, (1.0 + std::cos(slope * degree)) / 2.0, 0.01) << slope;
  }
}

TEST(TerrainHierarchy, GaussianHillAgainstClosedFormsOnItsConvexTop)
{
  // sigma 60 m, 40 m high: slopes below 21 degrees, so a sun 60 degrees high casts no
  // shadow, and the top (r < sigma / 2) lies below its tangent planes: it sees the
  // whole sky above them.
  const double sigma = 60.0, radiance = 30.0, sunFlux = 900.0;
  auto height = [&](double x, double y) {
    return 40.0 * std::exp(-((x - 160) * (x - 160) + (y - 160) * (y - 160)) / (2 * sigma * sigma));
  };
  const auto grid = makeGrid(65, 65, 5.0, height);
  RadiosityScene scene;
  scene.terrains.push_back(grid.get());
  const SkyHierarchy sky(UniformSky(), pi * radiance, 7);
  const Vec3 sun = glm::normalize(Vec3(std::cos(60 * degree), 0.0, std::sin(60 * degree)));
  // The foot's view of the slopes carries little of the scene's power: a fine tolerance
  // keeps those links.
  HierarchicalRadiosity solver(scene, terrainOptions(1e-4));
  solver.addSun(sun, uniformSpectrum(sunFlux));
  solver.setSky(&sky);
  ASSERT_TRUE(solver.solve());
  int top = 0;
  double reflectedAtFoot = 0.0;
  forEachPost(solver, *grid, [&](int i, int j, const PointIrradiance& e) {
    const Vec3 n = grid->postNormal(i, j);
    EXPECT_NEAR(e.irradiance[SunLight][0], sunFlux * glm::dot(n, sun), 1e-6 * sunFlux);
    const double r = std::hypot(5.0 * i - 160, 5.0 * j - 160);
    if (r < 0.5 * sigma)
    {
      ++top;
      EXPECT_NEAR(e.irradiance[SkyLight][0] / (pi * radiance * (1.0 + n.z) / 2.0), 1.0, 0.01);
      EXPECT_NEAR(e.skyViewFactor, (1.0 + n.z) / 2.0, 0.01);
    }
    if (std::abs(r - 2.0 * sigma) < 5.0)
      reflectedAtFoot = std::max(reflectedAtFoot, e.irradiance[ReflectedLight][0]);
  });
  EXPECT_GT(top, 100);
  EXPECT_GT(reflectedAtFoot, 0.0); // the concave foot sees the lit hill
}

TEST(TerrainHierarchy, VerticalStepCastsItsShadowAndNoLightLeaks)
{
  // Posts 0..10 at x = 0..100 m, height 0; posts 11..20 at x = 100..190 m, height 100:
  // cells of column 10 form a vertical wall facing -x. Sun from +x, 60 degrees high:
  // the wall shades the low ground for 100 / tan 60 = 57.7 m, to x = 42.3 m.
  auto xOf = [](int i) { return i <= 10 ? 10.0 * i : 10.0 * (i - 1); };
  const auto grid = makeGrid(21, 9, 10.0, [](double, double) { return 0.0; }, [](int, int) { return true; }, xOf);
  for (int j = 0; j < 9; ++j)
    for (int i = 11; i < 21; ++i)
      grid->setPost(i, j, Vec3(xOf(i), 10.0 * j, 100.0));
  RadiosityScene scene;
  scene.terrains.push_back(grid.get());
  const Vec3 sun = glm::normalize(Vec3(std::cos(60 * degree), 0.0, std::sin(60 * degree)));
  HierarchicalRadiosity solver(scene, terrainOptions(1e-3));
  solver.addSun(sun, uniformSpectrum(1000.0));
  ASSERT_TRUE(solver.solve());
  const double lit = 1000.0 * std::sin(60 * degree);
  for (int j = 1; j < 8; ++j) // away from the open ends of the wall
  {
    for (int i = 0; i <= 9; ++i)
    {
      const double x = xOf(i);
      const Spectrum e = solver.directSunAt(grid->post(i, j), grid->postNormal(i, j));
      EXPECT_NEAR(e[0], x < 42.3 ? lit : 0.0, 1e-6) << "x " << x;
    }
    for (int i = 12; i < 21; ++i) // the plateau is lit
      EXPECT_NEAR(solver.directSunAt(grid->post(i, j), grid->postNormal(i, j))[0], lit, 1e-6);
  }
  // Uneven refinement along the shadow, yet restricted: no leaf has a neighbour two
  // levels finer (more than one T-vertex on an edge).
  const TerrainLeafMesh mesh(*solver.terrainRoots()[0]);
  int levels[64] = {};
  for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
  {
    ++levels[std::min(63, mesh.leaves()[k]->level())];
    if (mesh.leaves()[k]->canSplit())
      EXPECT_LE(mesh.mostTVerticesOnAnEdge(k), 1) << "leaf " << k;
  }
  EXPECT_GE(std::count_if(std::begin(levels), std::end(levels), [](int n) { return n > 0; }), 3);
  // The wall element faces away from the sun; the low ground in its shadow still gets
  // light reflected by the lit ground in front (not through the wall).
  forEachPost(solver, *grid, [&](int i, int j, const PointIrradiance& e) {
    if (j >= 1 && j < 8 && i >= 6 && i <= 9)
    {
      EXPECT_EQ(e.irradiance[SunLight][0], 0.0) << i << ", " << j;
    }
  });
}

TEST(TerrainHierarchy, LightPassesThroughAHoleOnlyWhereItIs)
{
  // A 16 x 16-cell terrain at z = 50 with a 4 x 4-cell hole over a floor at z = 0; sun
  // straight down: the floor is lit exactly below the hole.
  auto hole = [](int i, int j) { return i >= 6 && i < 10 && j >= 6 && j < 10; };
  const auto grid = makeGrid(17, 17, 10.0, [](double, double) { return 50.0; }, [&](int i, int j) { return !hole(i, j); });
  RadiosityScene scene;
  scene.terrains.push_back(grid.get());
  addPolygon(scene, { { 0, 0, 0 }, { 160, 0, 0 }, { 160, 160, 0 }, { 0, 160, 0 } }, 0.0);
  HierarchicalRadiosity solver(scene, terrainOptions(1e-3));
  solver.addSun(Vec3(0.0, 0.0, 1.0), uniformSpectrum(1000.0));
  ASSERT_TRUE(solver.solve());
  for (double x = 5.0; x < 160.0; x += 10.0)
    for (double y = 5.0; y < 160.0; y += 10.0)
    {
      const bool below = x > 60.0 && x < 100.0 && y > 60.0 && y < 100.0;
      EXPECT_NEAR(solver.directSunAt(Vec3(x, y, 0.0), Vec3(0, 0, 1))[0], below ? 1000.0 : 0.0, 1e-6) << x << ", " << y;
    }
  // The terrain itself is lit everywhere it exists, and nothing comes from the hole.
  for (int j = 0; j < 17; ++j)
    for (int i = 0; i < 17; ++i)
      if (grid->postUsed(i, j))
        EXPECT_NEAR(solver.directSunAt(grid->post(i, j), grid->postNormal(i, j))[0], 1000.0, 1e-6);
}
