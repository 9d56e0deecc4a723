// Generic edges of terrain patches (terrain_edges.h, paper section 4.2): neighbours
// and T-vertices at every level.
#include "terrain_patch_checks.h"
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
std::vector<std::array<double, 4>> rangesOf(const std::vector<const TerrainPatch*>& patches)
{
  std::vector<std::array<double, 4>> r;
  for (const TerrainPatch* p : patches)
    r.push_back({ p->range().u0, p->range().v0, p->range().u1, p->range().v1 });
  return r;
}
} // namespace

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
