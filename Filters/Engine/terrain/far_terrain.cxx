#include "terrain/far_terrain.h"

#include "base/error.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
std::vector<int> FarTerrain::coarsePosts(int finePosts, int stride)
{
  std::vector<int> posts;
  for (int i = 0; i < finePosts - 1; i += stride)
    posts.push_back(i);
  posts.push_back(finePosts - 1);
  return posts;
}

double FarTerrain::fineParameter(const std::vector<int>& posts, double coarse)
{
  const int cells = static_cast<int>(posts.size()) - 1;
  const int k = std::clamp(static_cast<int>(std::floor(coarse)), 0, cells - 1);
  const double along = std::clamp(coarse - k, 0.0, 1.0);
  return posts[k] + along * (posts[k + 1] - posts[k]);
}

double FarTerrain::coarseParameter(const std::vector<int>& posts, double fine)
{
  // Every cell but the last spans posts[1] - posts[0] fine cells.
  const int cells = static_cast<int>(posts.size()) - 1;
  const int k = std::clamp(static_cast<int>(std::floor((fine - posts[0]) / (posts[1] - posts[0]))), 0, cells - 1);
  return k + std::clamp((fine - posts[k]) / (posts[k + 1] - posts[k]), 0.0, 1.0);
}

namespace
{
std::vector<int> givenPosts(int coarsePosts, int stride, int firstFine)
{
  std::vector<int> posts(static_cast<std::size_t>(coarsePosts));
  for (int k = 0; k < coarsePosts; ++k)
    posts[static_cast<std::size_t>(k)] = k * stride - firstFine;
  return posts;
}
} // namespace

FarTerrain::FarTerrain(const GivenFarTerrain& given)
  : ColumnPosts(givenPosts(given.grid->postsX(), given.stride, given.i0))
  , RowPosts(givenPosts(given.grid->postsY(), given.stride, given.j0))
  , Coarse(*given.grid)
{
  if (given.stride < 2 || given.grid->postsX() < 2 || given.grid->postsY() < 2)
    throw Error("a given far terrain needs a stride of at least 2 and at least 2 x 2 posts");
}

std::unique_ptr<FarTerrain> FarTerrain::of(const RadiosityScene& scene, const FarSight& sight)
{
  if (!sight.appliesTo(scene))
    return nullptr;
  if (scene.farTerrain.grid)
    return std::make_unique<FarTerrain>(scene.farTerrain);
  return std::make_unique<FarTerrain>(*scene.terrains.front(), sight.stride);
}

FarTerrain::FarTerrain(const TerrainGrid& fine, int stride)
  : ColumnPosts(coarsePosts(fine.postsX(), std::max(stride, 1)))
  , RowPosts(coarsePosts(fine.postsY(), std::max(stride, 1)))
  , Coarse(static_cast<int>(ColumnPosts.size()), static_cast<int>(RowPosts.size()), fine.origin())
{
  if (stride < 2)
    throw Error("a far terrain keeps every stride-th post: stride must be at least 2");
  const int nx = this->Coarse.postsX(), ny = this->Coarse.postsY();
  for (int l = 0; l < ny; ++l)
    for (int k = 0; k < nx; ++k)
      this->Coarse.setPost(k, l, fine.post(this->ColumnPosts[k], this->RowPosts[l]));
  const bool uniform = !fine.hasCellMaterials();
  if (uniform)
    this->Coarse.setUniformMaterial(fine.cellReflectance(0, 0), fine.cellEmission(0, 0));
  for (int l = 0; l + 1 < ny; ++l)
    for (int k = 0; k + 1 < nx; ++k)
    {
      bool valid = true;
      Spectrum reflectance{}, emission{};
      for (int j = this->RowPosts[l]; j < this->RowPosts[l + 1]; ++j)
        for (int i = this->ColumnPosts[k]; i < this->ColumnPosts[k + 1]; ++i)
        {
          valid = valid && fine.cellValid(i, j);
          if (!uniform)
          {
            const Spectrum r = fine.cellReflectance(i, j), e = fine.cellEmission(i, j);
            for (int band = 0; band < maxBands; ++band)
            {
              reflectance[band] += r[band];
              emission[band] += e[band];
            }
          }
        }
      this->Coarse.setCellValid(k, l, valid);
      if (!uniform)
      {
        const double cells = static_cast<double>(this->RowPosts[l + 1] - this->RowPosts[l]) *
          (this->ColumnPosts[k + 1] - this->ColumnPosts[k]);
        for (int band = 0; band < maxBands; ++band)
        {
          reflectance[band] /= cells;
          emission[band] /= cells;
        }
        this->Coarse.setCellMaterial(k, l, reflectance, emission);
      }
    }
}
} // namespace terralux
