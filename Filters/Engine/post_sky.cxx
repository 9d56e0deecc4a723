#include "post_sky.h"

#include "angles.h"
#include "grid_interpolation.h"
#include "horizon_sky.h"
#include "open_sky.h"
#include "terrain_grid.h"
#include "work_split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux
{
PostSky::PostSky(
  const TerrainGrid& terrain, const HorizonSky& horizons, const OpenSky& sky, bool hornNormals, const WorkSplit* split)
  : Terrain(terrain)
  , HornNormals(hornNormals)
{
  const int nx = terrain.postsX(), ny = terrain.postsY();
  const std::size_t posts = static_cast<std::size_t>(nx) * ny;
  // With a split, each process finds the skies of its window's posts (whose horizons
  // it holds), and gets the others' (gather rays read them wherever they land).
  const WorkSplit::Window own = WorkSplit::ownWindow(split, nx, ny);
  WorkSplit::partThenShare(
    split,
    [&]() {
      this->Values.resize(posts);
      this->Used.assign(posts, 0);
      tbb::parallel_for(own.j0, own.j1 + 1, [&](int j) {
        for (int i = own.i0; i <= own.i1; ++i)
        {
          HorizonMap::Post post;
          post.found = true;
          post.index = static_cast<std::size_t>(j) * nx + i;
          this->Values[post.index] = {};
          if (!terrain.postUsed(i, j))
            continue;
          const Value value = at(post, terrain.normalAt(i, j, hornNormals), horizons, sky);
          for (int band = 0; band < maxBands; ++band)
            this->Values[post.index][band] = static_cast<float>(value.irradiance[band]);
          this->Values[post.index][maxBands] = static_cast<float>(value.skyViewFactor);
          this->Used[post.index] = 1;
        }
      });
    },
    [&]() {
      split->shareWindows(this->Values, nx, ny);
      split->shareWindows(this->Used, nx, ny);
    });
}

PostSky::Value PostSky::at(const HorizonMap::Post& post, const Vec3& normal, const HorizonSky& horizons, const OpenSky& sky)
{
  Value result;
  Spectrum open{};
  double openOmega = 0.0;
  sky.irradiance(normal, open, openOmega);
  const HiddenSky hidden = horizons.hiddenAt(post, normal);
  for (int band = 0; band < maxBands; ++band)
    result.irradiance[band] = std::max(0.0, open[band] - hidden.irradiance[band]);
  result.skyViewFactor = std::max(0.0, openOmega - hidden.projectedSolidAngle) / pi;
  return result;
}

bool PostSky::found(const HorizonMap::Post& post, const Vec3& normal, Value& value) const
{
  if (!post || post.index >= this->Used.size() || !this->Used[post.index])
    return false;
  const int nx = this->Terrain.postsX();
  const int i = static_cast<int>(post.index % nx), j = static_cast<int>(post.index / nx);
  // Stored as floats: the same normal to 1e-6 gives the same sky to about 1e-6.
  if (glm::length(this->Terrain.normalAt(i, j, this->HornNormals) - normal) > 1e-6)
    return false;
  for (int band = 0; band < maxBands; ++band)
    value.irradiance[band] = this->Values[post.index][band];
  value.skyViewFactor = this->Values[post.index][maxBands];
  return true;
}

bool PostSky::interpolate(double u, double v, Spectrum& irradiance) const
{
  const int nx = this->Terrain.postsX();
  return interpolateNodes(u, v, nx, this->Terrain.postsY(),
    [&](int i, int j, Spectrum& value) {
      const std::size_t index = static_cast<std::size_t>(j) * nx + i;
      if (!this->Used[index])
        return false;
      for (int band = 0; band < maxBands; ++band)
        value[band] = this->Values[index][band];
      return true;
    },
    irradiance);
}
} // namespace terralux
