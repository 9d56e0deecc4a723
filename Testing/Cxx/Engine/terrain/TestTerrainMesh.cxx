// The leaf mesh of a terrain tree (terrain_mesh.h): continuous across levels, no cracks.
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
