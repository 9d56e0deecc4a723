#include "far_terrain.h"

#include "error.h"

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
  // Every cell but the last spans posts[1] fine cells.
  const int cells = static_cast<int>(posts.size()) - 1;
  const int k = std::clamp(static_cast<int>(std::floor(fine / posts[1])), 0, cells - 1);
  return k + std::clamp((fine - posts[k]) / (posts[k + 1] - posts[k]), 0.0, 1.0);
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
