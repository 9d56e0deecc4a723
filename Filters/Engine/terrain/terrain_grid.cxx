#include "terrain/terrain_grid.h"

#include "base/error.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace terralux
{
TerrainGrid::TerrainGrid(int nx, int ny, const Vec3& origin)
  : Nx(nx)
  , Ny(ny)
  , Origin(origin)
{
  if (nx < 2 || ny < 2)
  {
    throw Error("a terrain grid needs at least 2 x 2 posts");
  }
  // 4 floats of padding: Embree reads vertices with 16-byte loads.
  this->Xyz.assign(3 * static_cast<std::size_t>(nx) * ny + 4, 0.0f);
  this->Valid.assign(static_cast<std::size_t>(nx - 1) * (ny - 1), 1);
}

void TerrainGrid::setPost(int i, int j, const Vec3& position)
{
  float* p = &this->Xyz[3 * this->postIndex(i, j)];
  for (int c = 0; c < 3; ++c)
    p[c] = static_cast<float>(position[c] - this->Origin[c]);
}

Vec3 TerrainGrid::post(int i, int j) const
{
  const float* p = &this->Xyz[3 * this->postIndex(i, j)];
  return this->Origin + Vec3(p[0], p[1], p[2]);
}

void TerrainGrid::setUniformMaterial(const Spectrum& reflectance, const Spectrum& emission)
{
  this->UniformReflectance = reflectance;
  this->UniformEmission = emission;
}

void TerrainGrid::setCellMaterial(int i, int j, const Spectrum& reflectance, const Spectrum& emission)
{
  if (this->CellReflectance.empty())
  {
    this->CellReflectance.assign(this->Valid.size(), this->UniformReflectance);
    this->CellEmission.assign(this->Valid.size(), this->UniformEmission);
  }
  this->CellReflectance[this->cellIndex(i, j)] = reflectance;
  this->CellEmission[this->cellIndex(i, j)] = emission;
}

Spectrum TerrainGrid::cellReflectance(int i, int j) const
{
  return this->CellReflectance.empty() ? this->UniformReflectance : this->CellReflectance[this->cellIndex(i, j)];
}

Spectrum TerrainGrid::cellEmission(int i, int j) const
{
  return this->CellEmission.empty() ? this->UniformEmission : this->CellEmission[this->cellIndex(i, j)];
}

std::array<TerrainGrid::Triangle, 2> TerrainGrid::cellTriangles(int i, int j) const
{
  return cellTriangles(this->post(i, j), this->post(i + 1, j), this->post(i, j + 1), this->post(i + 1, j + 1));
}

TerrainPoint TerrainGrid::surfacePoint(double u, double v) const
{
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, this->Nx - 2);
  const int j = std::clamp(static_cast<int>(std::floor(v)), 0, this->Ny - 2);
  const double s = std::clamp(u - i, 0.0, 1.0), t = std::clamp(v - j, 0.0, 1.0);
  const bool lower = s + t <= 1.0;
  const Triangle tri = this->cellTriangles(i, j)[lower ? 0 : 1];
  // Coordinates along the triangle's two edges from its first corner.
  const double a = lower ? s : 1.0 - s, b = lower ? t : 1.0 - t;
  const Vec3 n = areaVector(tri);
  const double length = glm::length(n);
  const Vec3 normal = length > 0.0 ? n / length : Vec3(0.0, 0.0, 1.0);
  if ((a == 0.0 || a == 1.0) && (b == 0.0 || b == 1.0))
  {
    return { a == 1.0 ? tri[1] : (b == 1.0 ? tri[2] : tri[0]), normal }; // a post, exactly
  }
  return { tri[0] + a * (tri[1] - tri[0]) + b * (tri[2] - tri[0]), normal };
}

Vec3 TerrainGrid::cellAreaVector(int i, int j) const
{
  const auto cell = this->cellTriangles(i, j);
  return areaVector(cell[0]) + areaVector(cell[1]);
}

bool TerrainGrid::facesUp() const
{
  std::atomic<bool> up{ true };
  tbb::parallel_for(0, this->cellsY(), [&](int j) {
    for (int i = 0; i < this->cellsX() && up.load(std::memory_order_relaxed); ++i)
      if (this->cellValid(i, j))
        for (const Triangle& t : this->cellTriangles(i, j))
          if (!(areaVector(t).z > 0.0))
            up = false;
  });
  return up;
}

TerrainRangeSummary TerrainGrid::emptySum()
{
  TerrainRangeSummary empty;
  empty.low = Vec3(std::numeric_limits<double>::max());
  empty.high = Vec3(-std::numeric_limits<double>::max());
  return empty;
}

TerrainRangeSummary TerrainGrid::sumCells(int i0, int j0, int i1, int j1) const
{
  const TerrainRangeSummary empty = emptySum();
  if (!(i0 < i1 && j0 < j1))
    return empty;
  auto add = [this](const tbb::blocked_range2d<int>& r, TerrainRangeSummary sum) {
    for (int j = r.rows().begin(); j < r.rows().end(); ++j)
      for (int i = r.cols().begin(); i < r.cols().end(); ++i)
      {
        ++sum.cells;
        if (!this->cellValid(i, j))
          continue;
        const auto cell = this->cellTriangles(i, j);
        const Vec3 a = areaVector(cell[0]), b = areaVector(cell[1]);
        const double area = glm::length(a) + glm::length(b);
        sum.area += area;
        sum.areaVector += a + b;
        for (const Vec3& p : { cell[0][0], cell[0][1], cell[0][2], cell[1][0] }) // the four posts
        {
          sum.low = glm::min(sum.low, p);
          sum.high = glm::max(sum.high, p);
        }
        ++sum.validCells;
        const Spectrum rho = this->cellReflectance(i, j), e = this->cellEmission(i, j);
        for (int band = 0; band < maxBands; ++band)
        {
          sum.reflectance[band] += area * rho[band];
          sum.emission[band] += area * e[band];
        }
      }
    return sum;
  };
  const tbb::blocked_range2d<int> range(j0, j1, 64, i0, i1, 64);
  return static_cast<std::size_t>(i1 - i0) * (j1 - j0) > 16384 ? tbb::parallel_reduce(range, empty, add, joined)
                                                               : add(range, empty);
}

TerrainRangeSummary TerrainGrid::joined(TerrainRangeSummary a, const TerrainRangeSummary& b)
{
  a.area += b.area;
  a.areaVector += b.areaVector;
  a.low = glm::min(a.low, b.low);
  a.high = glm::max(a.high, b.high);
  a.validCells += b.validCells;
  a.cells += b.cells;
  for (int band = 0; band < maxBands; ++band)
  {
    a.reflectance[band] += b.reflectance[band];
    a.emission[band] += b.emission[band];
  }
  return a;
}

TerrainRangeSummary TerrainGrid::finished(TerrainRangeSummary sum)
{
  if (sum.area > 0.0)
  {
    for (int band = 0; band < maxBands; ++band)
    {
      sum.reflectance[band] /= sum.area;
      sum.emission[band] /= sum.area;
    }
  }
  return sum;
}

bool TerrainGrid::validBounds(Vec3& low, Vec3& high) const
{
  using Box = std::array<Vec3, 2>;
  const Box none{ Vec3(std::numeric_limits<double>::max()), Vec3(-std::numeric_limits<double>::max()) };
  const Box box = tbb::parallel_reduce(
    tbb::blocked_range<int>(0, this->cellsY()), none,
    [this](const tbb::blocked_range<int>& rows, Box b) {
      for (int j = rows.begin(); j < rows.end(); ++j)
        for (int i = 0; i < this->cellsX(); ++i)
          if (this->cellValid(i, j))
            for (const Vec3& p : { this->post(i, j), this->post(i + 1, j), this->post(i, j + 1), this->post(i + 1, j + 1) })
            {
              b[0] = glm::min(b[0], p);
              b[1] = glm::max(b[1], p);
            }
      return b;
    },
    [](const Box& a, const Box& b) { return Box{ glm::min(a[0], b[0]), glm::max(a[1], b[1]) }; });
  if (!(box[0].x <= box[1].x))
    return false;
  low = box[0], high = box[1];
  return true;
}

double TerrainGrid::meanCosine(int i0, int j0, int i1, int j1, const Vec3& d) const
{
  const int stepI = std::max(1, (i1 - i0) / 64), stepJ = std::max(1, (j1 - j0) / 64);
  double weighted = 0.0, area = 0.0;
  for (int j = j0 + stepJ / 2; j < j1; j += stepJ)
    for (int i = i0 + stepI / 2; i < i1; i += stepI)
    {
      if (!this->cellValid(i, j))
        continue;
      for (const Triangle& triangle : this->cellTriangles(i, j))
      {
        const Vec3 a = areaVector(triangle);
        weighted += std::max(0.0, glm::dot(a, d)); // |a| max(0, n . d)
        area += glm::length(a);
      }
    }
  return area > 0.0 ? weighted / area : 0.0;
}

bool TerrainGrid::surroundedByCells(int i, int j) const
{
  return i > 0 && j > 0 && i + 1 < this->Nx && j + 1 < this->Ny && this->cellValid(i - 1, j - 1) &&
    this->cellValid(i, j - 1) && this->cellValid(i - 1, j) && this->cellValid(i, j);
}

Vec3 TerrainGrid::postNormal(int i, int j) const
{
  // The triangles that have the post as a corner (six with this diagonal), as a
  // triangle mesh's vertex normal: the cell to the upper right contributes its lower
  // triangle, the lower-left one its upper triangle, the other two both.
  if (this->surroundedByCells(i, j))
  {
    // Inside the grid the six triangles close a fan: their area vectors sum to half
    // the cross products of neighbouring spokes, read once each (a post's normal is
    // asked for several times a solve).
    const Vec3 p = this->post(i, j);
    const Vec3 spokes[6] = { this->post(i + 1, j) - p, this->post(i, j + 1) - p, this->post(i - 1, j + 1) - p,
      this->post(i - 1, j) - p, this->post(i, j - 1) - p, this->post(i + 1, j - 1) - p };
    Vec3 fan(0.0);
    for (int k = 0; k < 6; ++k)
      fan += glm::cross(spokes[k], spokes[(k + 1) % 6]);
    const double length = glm::length(fan);
    return length > 0.0 ? fan / length : Vec3(0.0, 0.0, 1.0);
  }
  Vec3 sum(0.0);
  for (int cj = std::max(0, j - 1); cj <= std::min(j, this->Ny - 2); ++cj)
    for (int ci = std::max(0, i - 1); ci <= std::min(i, this->Nx - 2); ++ci)
    {
      if (!this->cellValid(ci, cj))
        continue;
      const auto cell = this->cellTriangles(ci, cj);
      const bool lowerLeft = ci == i && cj == j, upperRight = ci < i && cj < j;
      if (!upperRight)
        sum += areaVector(cell[0]);
      if (!lowerLeft)
        sum += areaVector(cell[1]);
    }
  const double length = glm::length(sum);
  return length > 0.0 ? sum / length : Vec3(0.0, 0.0, 1.0);
}

Vec3 TerrainGrid::hornNormal(int i, int j) const
{
  if (!this->surroundedByCells(i, j))
    return this->postNormal(i, j);
  auto p = [this](int a, int b) { return this->post(a, b); };
  const Vec3 alongI = (p(i + 1, j - 1) + 2.0 * p(i + 1, j) + p(i + 1, j + 1)) - (p(i - 1, j - 1) + 2.0 * p(i - 1, j) + p(i - 1, j + 1));
  const Vec3 alongJ = (p(i - 1, j + 1) + 2.0 * p(i, j + 1) + p(i + 1, j + 1)) - (p(i - 1, j - 1) + 2.0 * p(i, j - 1) + p(i + 1, j - 1));
  const Vec3 n = glm::cross(alongI, alongJ);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : this->postNormal(i, j);
}

bool TerrainGrid::postUsed(int i, int j) const
{
  for (int cj = std::max(0, j - 1); cj <= std::min(j, this->Ny - 2); ++cj)
    for (int ci = std::max(0, i - 1); ci <= std::min(i, this->Nx - 2); ++ci)
      if (this->cellValid(ci, cj))
        return true;
  return false;
}
} // namespace terralux
