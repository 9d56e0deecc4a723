#include "horizons/post_sky.h"

#include "base/angles.h"
#include "terrain/grid_interpolation.h"
#include "horizons/horizon_sky.h"
#include "evaluation/open_sky.h"
#include "terrain/terrain_grid.h"
#include "parallel/work_split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
constexpr int skyTag = 900; // apart from the horizons' hand-off (a tag per azimuth)
}

PostSky::PostSky(const TerrainGrid& terrain, const HorizonSky& horizons, const OpenSky& sky, bool hornNormals,
  const WorkSplit* split, int halo)
  : Terrain(terrain)
  , Held(terrain.postsX(), terrain.postsY(), split, halo)
{
  this->findOwn(horizons, sky, hornNormals, split, nullptr);
}

void PostSky::findAgain(const std::vector<std::uint8_t>& again, const HorizonSky& horizons, const OpenSky& sky,
  bool hornNormals, const WorkSplit* split)
{
  this->findOwn(horizons, sky, hornNormals, split, &again);
}

void PostSky::findOwn(const HorizonSky& horizons, const OpenSky& sky, bool hornNormals, const WorkSplit* split,
  const std::vector<std::uint8_t>* again)
{
  const TerrainGrid& terrain = this->Terrain;
  const int nx = terrain.postsX(), ny = terrain.postsY();
  // With a split, each process finds the skies of its window's posts (whose horizons
  // it holds), and gets the others' (gather rays read them wherever they land).
  const WorkSplit::Window own = WorkSplit::ownWindow(split, nx, ny);
  const std::size_t ownX = own.empty() ? 0 : static_cast<std::size_t>(own.i1 - own.i0 + 1);
  WorkSplit::partThenShare(
    split,
    [&]() {
      if (!again)
      {
        this->Values.resize(this->Held.count());
        this->Used.assign(this->Held.count(), 0);
      }
      tbb::parallel_for(own.j0, own.j1 + 1, [&](int j) {
        for (int i = own.i0; i <= own.i1; ++i)
        {
          if (again && !(*again)[static_cast<std::size_t>(j - own.j0) * ownX + (i - own.i0)])
            continue;
          HorizonMap::Post post;
          post.found = true;
          post.index = static_cast<std::size_t>(j) * nx + i;
          const std::size_t index = this->Held.index(i, j);
          this->Values[index] = {};
          if (!terrain.postUsed(i, j))
            continue;
          const Vec3 normal = terrain.normalAt(i, j, hornNormals);
          const Value value = at(post, normal, horizons, sky);
          std::array<float, valueSize>& held = this->Values[index];
          for (int band = 0; band < maxBands; ++band)
            held[band] = static_cast<float>(value.irradiance[band]);
          held[skyViewSlot] = static_cast<float>(value.skyViewFactor);
          held[openBandSlot] = static_cast<float>(value.openLargestBand);
          held[openSolidAngleSlot] = static_cast<float>(value.openProjectedSolidAngle);
          held[voidSlot] = static_cast<float>(value.voidViewFactor);
          for (int axis = 0; axis < 3; ++axis)
            held[normalSlot + axis] = static_cast<float>(normal[axis]);
          this->Used[index] = 1;
        }
      });
    },
    [&]() {
      this->Held.share(this->Values, skyTag);
      this->Held.share(this->Used, skyTag + 1);
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
  result.openLargestBand = largestBand(open);
  result.openProjectedSolidAngle = openOmega;
  result.voidViewFactor = hidden.voidSolidAngle / pi;
  return result;
}

bool PostSky::found(const HorizonMap::Post& post, const Vec3& normal, Value& value) const
{
  const int nx = this->Terrain.postsX();
  if (!post || nx < 1)
    return false;
  const auto* held = this->heldAt(static_cast<int>(post.index % nx), static_cast<int>(post.index / nx));
  // Stored as floats: the same normal to 1e-6 gives the same sky to about 1e-6 (the
  // normal the sky was found on, kept to 6e-8, need not be found again).
  if (!held || glm::length(normalOf(*held) - normal) > 1e-6)
    return false;
  value = valueOf(*held);
  return true;
}

bool PostSky::foundAt(int i, int j, Value& value, Vec3& normal) const
{
  const auto* held = this->heldAt(i, j);
  if (!held)
    return false;
  value = valueOf(*held);
  normal = normalOf(*held);
  return true;
}

const std::array<float, PostSky::valueSize>* PostSky::heldAt(int i, int j) const
{
  if (!this->Held.holds(i, j) || !this->Used[this->Held.index(i, j)])
    return nullptr;
  return &this->Values[this->Held.index(i, j)];
}

PostSky::Value PostSky::valueOf(const std::array<float, valueSize>& held)
{
  Value value;
  for (int band = 0; band < maxBands; ++band)
    value.irradiance[band] = held[band];
  value.skyViewFactor = held[skyViewSlot];
  value.openLargestBand = held[openBandSlot];
  value.openProjectedSolidAngle = held[openSolidAngleSlot];
  value.voidViewFactor = held[voidSlot];
  return value;
}

Vec3 PostSky::normalOf(const std::array<float, valueSize>& held)
{
  return Vec3(held[normalSlot], held[normalSlot + 1], held[normalSlot + 2]);
}

bool PostSky::interpolate(double u, double v, Spectrum& irradiance) const
{
  const int nx = this->Terrain.postsX();
  return interpolateNodes(u, v, nx, this->Terrain.postsY(),
    [&](int i, int j, Spectrum& value) {
      this->Held.requireHeld(i, j, "sky");
      const std::size_t index = this->Held.index(i, j);
      if (!this->Used[index])
        return false;
      for (int band = 0; band < maxBands; ++band)
        value[band] = this->Values[index][band];
      return true;
    },
    irradiance);
}
} // namespace terralux
