#include "height_field_horizon.h"

#include "terrain_grid.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace terralux
{
namespace
{
constexpr float noTerrain = -std::numeric_limits<float>::infinity();

/// How the grid's parameters (u, v) move the horizontal position: d(x, y) = U du + V dv.
struct PlaneJacobian
{
  double ux, uy, vx, vy;

  double determinant() const { return this->ux * this->vy - this->vx * this->uy; }
  /// The least stretch of a parameter step: |d(x, y)| >= smallestStretch() |(du, dv)|.
  double smallestStretch() const
  {
    // The smaller singular value of [U V].
    const double a = this->ux * this->ux + this->uy * this->uy, c = this->vx * this->vx + this->vy * this->vy;
    const double b = this->ux * this->vx + this->uy * this->vy;
    const double half = 0.5 * (a + c), root = std::sqrt(std::max(0.0, 0.25 * (a - c) * (a - c) + b * b));
    return std::sqrt(std::max(0.0, half - root));
  }
  /// (du, dv) for the horizontal step (dx, dy); false where the map is singular.
  bool solve(double dx, double dy, double& du, double& dv) const
  {
    const double det = this->determinant();
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
      return false;
    du = (this->vy * dx - this->vx * dy) / det;
    dv = (this->ux * dy - this->uy * dx) / det;
    return std::isfinite(du) && std::isfinite(dv);
  }
};
} // namespace

struct HeightFieldHorizon::Pyramid
{
  const TerrainGrid* Grid = nullptr;
  const float* Xyz = nullptr;
  int Nx = 0, CellsX = 0, CellsY = 0;
  /// Level l >= 1 (index l - 1) has blocks of 2^l x 2^l cells, row by row, each the
  /// highest post of its valid cells (noTerrain: none). Heights only, so that a walk's
  /// scattered reads stay in cache; how far a block is comes from the mean map.
  std::vector<std::vector<float>> Levels;
  std::vector<int> Widths;
  /// The grid's mean affine map from parameters to xy (relative to the grid origin),
  /// how far any valid post strays from it (m), and its least stretch (m per cell).
  PlaneJacobian Mean{ 1.0, 0.0, 0.0, 1.0 };
  double MeanX0 = 0.0, MeanY0 = 0.0;
  double Stray = 0.0, Stretch = 1.0;

  Vec3 post(int i, int j) const
  {
    const float* p = this->Xyz + 3 * (static_cast<std::size_t>(j) * this->Nx + i);
    return Vec3(p[0], p[1], p[2]);
  }
  bool valid(int i, int j) const { return this->Grid->cellValid(i, j); }

  explicit Pyramid(const TerrainGrid* grid)
    : Grid(grid)
    , Xyz(grid->vertices())
    , Nx(grid->postsX())
    , CellsX(grid->cellsX())
    , CellsY(grid->cellsY())
  {
    this->fitMeanMap();
    // Level 1 from the cells, each further level from the one below.
    for (int w = CellsX, h = CellsY; w > 1 || h > 1 || this->Levels.empty();)
    {
      const int width = (w + 1) / 2, height = (h + 1) / 2;
      std::vector<float> tops(static_cast<std::size_t>(width) * height, noTerrain);
      const std::vector<float>* below = this->Levels.empty() ? nullptr : &this->Levels.back();
      const int belowWidth = w, belowHeight = h;
      tbb::parallel_for(0, height, [&](int J) {
        for (int I = 0; I < width; ++I)
        {
          float& top = tops[static_cast<std::size_t>(J) * width + I];
          for (int j = 2 * J; j < std::min(2 * J + 2, belowHeight); ++j)
            for (int i = 2 * I; i < std::min(2 * I + 2, belowWidth); ++i)
              top = std::max(top, below ? (*below)[static_cast<std::size_t>(j) * belowWidth + i] : this->cellTop(i, j));
        }
      });
      this->Levels.push_back(std::move(tops));
      this->Widths.push_back(width);
      w = width;
      h = height;
    }
  }

  float cellTop(int i, int j) const
  {
    if (!this->valid(i, j))
      return noTerrain;
    const std::size_t row = static_cast<std::size_t>(j) * this->Nx + i, next = row + this->Nx;
    return std::max(std::max(this->Xyz[3 * row + 2], this->Xyz[3 * row + 5]),
      std::max(this->Xyz[3 * next + 2], this->Xyz[3 * next + 5]));
  }

  void fitMeanMap()
  {
    // Mean steps along u and v over the valid cells, and the mean offset.
    double sx = 0, sy = 0, ux = 0, uy = 0, vx = 0, vy = 0, x0 = 0, y0 = 0;
    std::size_t count = 0;
    for (int j = 0; j < this->CellsY; ++j)
      for (int i = 0; i < this->CellsX; ++i)
        if (this->valid(i, j))
        {
          const Vec3 p00 = this->post(i, j), p10 = this->post(i + 1, j), p01 = this->post(i, j + 1);
          ux += p10.x - p00.x, uy += p10.y - p00.y, vx += p01.x - p00.x, vy += p01.y - p00.y;
          sx += p00.x, sy += p00.y, x0 += i, y0 += j;
          ++count;
        }
    if (count == 0)
      return;
    const double n = static_cast<double>(count);
    this->Mean = { ux / n, uy / n, vx / n, vy / n };
    this->MeanX0 = sx / n - (this->Mean.ux * x0 + this->Mean.vx * y0) / n;
    this->MeanY0 = sy / n - (this->Mean.uy * x0 + this->Mean.vy * y0) / n;
    this->Stretch = this->Mean.smallestStretch();
    for (int j = 0; j < this->CellsY; ++j)
      for (int i = 0; i < this->CellsX; ++i)
        if (this->valid(i, j))
          for (int c = 0; c < 4; ++c)
          {
            const int pi = i + c % 2, pj = j + c / 2;
            const Vec3 p = this->post(pi, pj);
            const double ex = p.x - (this->MeanX0 + this->Mean.ux * pi + this->Mean.vx * pj);
            const double ey = p.y - (this->MeanY0 + this->Mean.uy * pi + this->Mean.vy * pj);
            this->Stray = std::max(this->Stray, std::sqrt(ex * ex + ey * ey));
          }
  }

  /// The surface point of parameter (u, v) inside valid cell (i, j), and the
  /// parameters' Jacobian there (of the triangle it lies on).
  Vec3 surface(int i, int j, double u, double v, PlaneJacobian* jacobian = nullptr) const
  {
    const double fu = std::clamp(u - i, 0.0, 1.0), fv = std::clamp(v - j, 0.0, 1.0);
    if (fu + fv <= 1.0)
    {
      const Vec3 p00 = this->post(i, j), eu = this->post(i + 1, j) - p00, ev = this->post(i, j + 1) - p00;
      if (jacobian)
        *jacobian = { eu.x, eu.y, ev.x, ev.y };
      return p00 + fu * eu + fv * ev;
    }
    const Vec3 p11 = this->post(i + 1, j + 1), eu = p11 - this->post(i, j + 1), ev = p11 - this->post(i + 1, j);
    if (jacobian)
      *jacobian = { eu.x, eu.y, ev.x, ev.y };
    return p11 - (1.0 - fu) * eu - (1.0 - fv) * ev;
  }

  /// Parameters of the horizontal position (x, y) and the Jacobian there: Newton's
  /// steps over the triangles from the mean map's guess (a few for a bent grid).
  void locate(double x, double y, double& u, double& v, PlaneJacobian& jacobian) const
  {
    jacobian = this->Mean;
    if (!this->Mean.solve(x - this->MeanX0, y - this->MeanY0, u, v))
      u = v = 0.0;
    for (int step = 0; step < 8; ++step)
    {
      const int i = std::clamp(static_cast<int>(std::floor(u)), 0, this->CellsX - 1);
      const int j = std::clamp(static_cast<int>(std::floor(v)), 0, this->CellsY - 1);
      if (!this->valid(i, j))
        return; // over no data: the mean map's guess and Jacobian
      PlaneJacobian local;
      // Beyond the grid the border triangle's plane continues.
      const double cu = std::clamp(u, static_cast<double>(i), i + 1.0);
      const double cv = std::clamp(v, static_cast<double>(j), j + 1.0);
      const Vec3 p = this->surface(i, j, cu, cv, &local);
      double du, dv;
      if (!local.solve(x - p.x - local.ux * (u - cu) - local.vx * (v - cv),
            y - p.y - local.uy * (u - cu) - local.vy * (v - cv), du, dv))
        return;
      jacobian = local;
      u += du;
      v += dv;
      if (std::abs(du) + std::abs(dv) < 1e-9)
        return;
    }
  }

  /// The largest tangent of elevation from o (relative to the grid origin) toward
  /// (dx, dy) over this grid, or `best` if none is larger.
  double walk(const Vec3& o, double dx, double dy, double best) const;
};

double HeightFieldHorizon::Pyramid::walk(const Vec3& o, double dx, double dy, double best) const
{
  double u, v, du, dv;
  PlaneJacobian jacobian;
  this->locate(o.x, o.y, u, v, jacobian);
  if (!jacobian.solve(dx, dy, du, dv))
    return best;
  // s: horizontal metres along the azimuth (to first order); clipped to the grid.
  double sIn = 0.0, sOut = std::numeric_limits<double>::infinity();
  auto clip = [&](double start, double step, double high) {
    if (step == 0.0)
    {
      if (start < 0.0 || start > high)
        sOut = -1.0;
      return;
    }
    const double a = -start / step, b = (high - start) / step;
    sIn = std::max(sIn, std::min(a, b));
    sOut = std::min(sOut, std::max(a, b));
  };
  clip(u, du, this->CellsX);
  clip(v, dv, this->CellsY);
  if (!(sIn < sOut))
    return best;

  // Where the line leaves the parameter box [i0, i1] x [j0, j1].
  const double inverseDu = 1.0 / du, inverseDv = 1.0 / dv; // infinite along an axis
  auto exitOf = [&](int i0, int i1, int j0, int j1) {
    const double eu = du > 0.0 ? (i1 - u) * inverseDu : du < 0.0 ? (i0 - u) * inverseDu : sOut;
    const double ev = dv > 0.0 ? (j1 - v) * inverseDv : dv < 0.0 ? (j0 - v) * inverseDv : sOut;
    return std::min(eu, ev);
  };
  // A surface point q (relative to o) raises the horizon when its rise over its
  // distance is larger; compared squared, so most points cost no root or division.
  auto consider = [&](const Vec3& q) {
    const double distance2 = q.x * q.x + q.y * q.y;
    if (q.z > 0.0 && q.z * q.z > best * best * distance2 && distance2 > 0.0)
      best = q.z / std::sqrt(distance2);
  };
  // A block cannot hold the horizon when even its highest post at its nearest
  // horizontal distance is seen no higher than the horizon found so far. That
  // distance is at least the mean map's least stretch times the parameter distance,
  // less how far the point and the block's posts may stray from the mean map.
  const double slack = 2.0 * this->Stray;
  auto hidden = [&](float top, int i0, int i1, int j0, int j1) {
    const double rise = top - o.z; // -inf where the block has no terrain
    if (rise <= 0.0)
      return true; // best >= 0
    const double eu = std::max(std::max(i0 - u, u - i1), 0.0), ev = std::max(std::max(j0 - v, v - j1), 0.0);
    const double distance = this->Stretch * std::sqrt(eu * eu + ev * ev) - slack;
    return distance > 0.0 && rise <= best * distance;
  };

  // A nudge of a millionth of a cell decides which cell a boundary point is in.
  const double nudge = 1e-6 / std::max(std::abs(du), std::abs(dv));
  const int top = static_cast<int>(this->Levels.size());
  int level = 0;
  // The block last found to hold possible horizon at each level, and the horizon then:
  // while both stay, the walk goes down past it without testing it again.
  struct Refused
  {
    std::size_t block = ~std::size_t{ 0 };
    double best = -1.0;
  };
  std::array<Refused, 32> refused;
  bool first = true; // the line's first point in the grid is nobody's exit
  for (double s = sIn; s < sOut;)
  {
    const double inside = s + nudge;
    const int i = std::clamp(static_cast<int>(std::floor(u + inside * du)), 0, this->CellsX - 1);
    const int j = std::clamp(static_cast<int>(std::floor(v + inside * dv)), 0, this->CellsY - 1);
    double next;
    // Up a level after each step, down while the block may hold the horizon.
    for (level = std::min(level + 1, top);; --level)
    {
      if (level == 0)
      {
        const double eu = du > 0.0 ? (i + 1 - u) * inverseDu : du < 0.0 ? (i - u) * inverseDu : sOut;
        const double ev = dv > 0.0 ? (j + 1 - v) * inverseDv : dv < 0.0 ? (j - v) * inverseDv : sOut;
        next = std::min(std::min(eu, ev), sOut);
        if (this->valid(i, j))
        {
          // The crossings: where the line enters the cell (the previous cell's exit,
          // or a block's boundary that bounded it), leaves it through a side, and
          // crosses the diagonal from (i + 1, j) to (i, j + 1); each on its edge.
          auto onEdge = [&](int ia, int ja, int ib, int jb, double f) {
            const Vec3 a = this->post(ia, ja);
            return a + std::clamp(f, 0.0, 1.0) * (this->post(ib, jb) - a) - o;
          };
          if (first)
            consider(this->surface(i, j, u + s * du, v + s * dv) - o);
          if (eu <= ev)
          {
            const int side = du > 0.0 ? i + 1 : i;
            consider(onEdge(side, j, side, j + 1, v + next * dv - j));
          }
          else
          {
            const int side = dv > 0.0 ? j + 1 : j;
            consider(onEdge(i, side, i + 1, side, u + next * du - i));
          }
          const double diagonal = (1.0 + i + j - u - v) / (du + dv);
          if (diagonal > s && diagonal < next)
            consider(onEdge(i + 1, j, i, j + 1, v + diagonal * dv - j));
        }
        break;
      }
      const int I = i >> level, J = j >> level;
      const std::size_t block = static_cast<std::size_t>(J) * this->Widths[level - 1] + I;
      if (refused[level].block == block && refused[level].best == best)
        continue;
      const int i0 = I << level, i1 = (I + 1) << level, j0 = J << level, j1 = (J + 1) << level;
      if (hidden(this->Levels[level - 1][block], i0, i1, j0, j1))
      {
        next = exitOf(i0, i1, j0, j1);
        break;
      }
      refused[level] = { block, best };
    }
    first = false;
    s = std::max(next, inside);
  }
  return best;
}

HeightFieldHorizon::HeightFieldHorizon(const std::vector<const TerrainGrid*>& grids)
{
  for (const TerrainGrid* grid : grids)
    this->Pyramids.emplace_back(grid);
}

HeightFieldHorizon::~HeightFieldHorizon() = default;

double HeightFieldHorizon::tangentToward(const Vec3& from, double dx, double dy, double floorTangent) const
{
  double best = std::max(0.0, floorTangent);
  for (const Pyramid& pyramid : this->Pyramids)
    best = pyramid.walk(from - pyramid.Grid->origin(), dx, dy, best);
  return best;
}

std::size_t HeightFieldHorizon::memoryBytes() const
{
  std::size_t bytes = 0;
  for (const Pyramid& pyramid : this->Pyramids)
    for (const std::vector<float>& level : pyramid.Levels)
      bytes += level.size() * sizeof(float);
  return bytes;
}
} // namespace terralux
