#pragma once
// What the terrain patch, edge, grid and mesh tests share.

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

namespace terralux_test
{

using namespace terralux;
using namespace terralux_test;

inline TerrainPatch* child(TerrainPatch* patch, double u0, double v0)
{
  for (HElement* c : patch->children())
  {
    auto* p = static_cast<TerrainPatch*>(c);
    if (p->range().u0 == u0 && p->range().v0 == v0)
      return p;
  }
  return nullptr;
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
} // namespace terralux_test
