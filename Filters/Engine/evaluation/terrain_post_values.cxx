// Per-post values of a terrain (see point_values.h).
#include "evaluation/point_values.h"

#include "terrain/far_terrain.h"
#include "evaluation/point_evaluator.h"
#include "terrain/terrain_grid.h"
#include "terrain/terrain_mesh.h"
#include "hierarchy/terrain_patch.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux
{
void terrainPostValues(const PointEvaluator& evaluator, const TerrainPatch& root, const int posts[4],
  const PointEvaluation& how, const std::function<void(std::size_t, const PointValues&)>& sink)
{
  // Posts of the scene's grid; the hierarchy's may be the far terrain's (its
  // parameters then mapped between the two).
  const TerrainGrid& grid = evaluator.solver().postGrid(root);
  const FarTerrain* far = evaluator.solver().hierarchyTerrain();
  const int nx = grid.postsX(), ny = grid.postsY();
  const int i0 = std::max(0, posts[0]), i1 = std::min(nx - 1, posts[1]);
  const int j0 = std::max(0, posts[2]), j1 = std::min(ny - 1, posts[3]);
  if (i1 < i0 || j1 < j0)
    return;
  auto index = [nx](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * nx; };
  if (how.atPoints)
  {
    // Every post evaluated at itself from its most lit leaf, with the normal of the cells
    // around it (a lattice of them was gathered first, see gatherPostLattice).
    tbb::parallel_for(j0, j1 + 1, [&](int j) {
      for (int i = i0; i <= i1; ++i)
      {
        const TerrainPatch* leaf = grid.postUsed(i, j) ? evaluator.solver().leafAtPost(root, i, j) : nullptr;
        if (leaf)
          sink(index(i, j),
            PointValues::atPoint(evaluator.irradianceAt(*leaf, grid.post(i, j), grid.normalAt(i, j, how.hornNormals)), *leaf));
      }
    });
    return;
  }
  // Sky and reflected light vary slowly: interpolated from the continuous leaf mesh.
  // Direct sun does not, and costs one ray: taken at each post with its own normal.
  const TerrainLeafMesh mesh(root);
  const std::vector<double> vertexValues =
    mesh.vertexValues(flatLeafValues(mesh.leaves()), PointValues::flatComponents);
  tbb::parallel_for(std::size_t(0), mesh.leaves().size(), [&](std::size_t k) {
    double flat[PointValues::flatComponents];
    const TerrainPatch& leaf = *mesh.leaves()[k];
    const ParameterRange& r = leaf.range();
    // The leaf's range in posts of the scene's grid.
    const double u0 = far ? far->fineU(r.u0) : r.u0, u1 = far ? far->fineU(r.u1) : r.u1;
    const double v0 = far ? far->fineV(r.v0) : r.v0, v1 = far ? far->fineV(r.v1) : r.v1;
    // A post on the range's border is written by the leaf that leafHolding finds for it,
    // so each post is written once (values agree anyway: the mesh is continuous).
    for (int j = std::max(j0, static_cast<int>(std::ceil(v0))); j <= std::min(j1, static_cast<int>(std::floor(v1))); ++j)
      for (int i = std::max(i0, static_cast<int>(std::ceil(u0))); i <= std::min(i1, static_cast<int>(std::floor(u1))); ++i)
      {
        const double leafU = far ? far->coarseU(i) : i, leafV = far ? far->coarseV(j) : j;
        const bool border = leafU <= r.u0 || leafU >= r.u1 || leafV <= r.v0 || leafV >= r.v1;
        if (!grid.postUsed(i, j) || (border && root.leafHolding(leafU, leafV) != &leaf))
          continue;
        mesh.interpolate(k, vertexValues, PointValues::flatComponents, leafU, leafV, flat);
        PointValues v = PointValues::unflatten(flat);
        v.irradiance[SunLight] = evaluator.directSunAt(grid.post(i, j), grid.normalAt(i, j, how.hornNormals), &v.sunlitHours);
        v.radiosity = radiosityOf(leaf.emission(), leaf.reflectance(), v.globalIrradiance());
        sink(index(i, j), v);
      }
  });
}
} // namespace terralux
