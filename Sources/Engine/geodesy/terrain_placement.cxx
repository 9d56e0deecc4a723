#include "geodesy/terrain_placement.h"

#include "base/error.h"
#include "base/floor_divide.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace terralux
{
GridCentre findGridCentre(int nx, int ny, const std::function<double(int, int)>& at)
{
  GridCentre centre;
  const double ci = 0.5 * (nx - 1);
  const double cj = 0.5 * (ny - 1);
  centre.col = ci + 0.5;
  centre.row = cj + 0.5;

  const int i0 = static_cast<int>(std::floor(ci));
  const int j0 = static_cast<int>(std::floor(cj));
  const int i1 = std::min(i0 + 1, nx - 1);
  const int j1 = std::min(j0 + 1, ny - 1);
  const double fi = ci - i0;
  const double fj = cj - j0;
  const double h00 = at(i0, j0), h10 = at(i1, j0), h01 = at(i0, j1), h11 = at(i1, j1);
  if (std::isfinite(h00) && std::isfinite(h10) && std::isfinite(h01) && std::isfinite(h11))
  {
    centre.heightM = (1 - fj) * ((1 - fi) * h00 + fi * h10) + fj * ((1 - fi) * h01 + fi * h11);
    return centre;
  }
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const double h = at(i, j);
      const double distance = (i - ci) * (i - ci) + (j - cj) * (j - cj);
      if (std::isfinite(h) && distance < bestDistance)
      {
        bestDistance = distance;
        centre.heightM = h;
      }
    }
  }
  if (!std::isfinite(bestDistance))
  {
    throw Error("the DEM window holds no valid post (all no data): choose another window or band");
  }
  return centre;
}


TerrainPlacement::TerrainPlacement(
  const GridGeoreference& grid, const MapProjection& projection, const LocalFrame& frame)
  : Grid(grid)
  , Projection(projection.clone())
  , Frame(std::make_unique<LocalFrame>(frame))
{
}

TerrainPlacement::TerrainPlacement(const GridGeoreference& grid, const LocalPoint& mapOrigin)
  : Grid(grid)
  , MapOrigin(mapOrigin)
{
}

TerrainPlacement::~TerrainPlacement() = default;

GeodeticPoint geodeticOfPixel(
  const GeoTransform& geoTransform, MapProjection& projection, double col, double row, double heightM)
{
  double x, y;
  geoTransform.pixelToMap(col, row, x, y);
  projection.toGeographic(1, &x, &y);
  return { y, x, heightM };
}

namespace
{
// Cubic Lagrange weights at t in [0, 1) of the nodes at -1, 0, 1 and 2.
std::array<double, 4> cubicWeights(double t)
{
  return { -t * (t - 1.0) * (t - 2.0) / 6.0, (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0,
    -(t + 1.0) * t * (t - 2.0) / 2.0, (t + 1.0) * t * (t - 1.0) / 6.0 };
}

// A node's place on the ellipsoid and the local direction of its height: a geodetic
// point's local position is the first plus its height times the second (ECEF is linear
// in the height along the ellipsoid's normal, ENU a rotation of it).
using NodePlace = std::array<double, 6>;
} // namespace

bool TerrainPlacement::placeNodes(std::vector<NodePlace>& nodes, int& firstColumn, int& firstRow, int& columns) const
{
  // Nodes every nodeSpacing pixels of the transform, counted from its origin (a piece
  // of the grid finds the same nodes as the whole), two beyond each end of the grid.
  const int i0 = floorDivide(this->Grid.col0, nodeSpacing) - 1;
  const int i1 = floorDivide(this->Grid.col0 + this->Grid.nx - 1, nodeSpacing) + 2;
  const int j0 = floorDivide(this->Grid.row0, nodeSpacing) - 1;
  const int j1 = floorDivide(this->Grid.row0 + this->Grid.ny - 1, nodeSpacing) + 2;
  firstColumn = i0, firstRow = j0, columns = i1 - i0 + 1;
  nodes.assign(static_cast<std::size_t>(columns) * (j1 - j0 + 1), NodePlace{});
  std::atomic<bool> placed{ true };
  tbb::enumerable_thread_specific<std::unique_ptr<MapProjection>> projections(
    [this]() { return this->Projection->clone(); });
  tbb::parallel_for(j0, j1 + 1, [&](int j) {
    std::vector<double> x(columns), y(columns);
    for (int i = i0; i <= i1; ++i)
      this->Grid.geoTransform.pixelToMap(nodeSpacing * i + 0.5, nodeSpacing * j + 0.5, x[i - i0], y[i - i0]);
    try
    {
      projections.local()->toGeographic(static_cast<std::size_t>(columns), x.data(), y.data());
    }
    catch (const Error&)
    {
      placed = false; // a node outside the CRS's domain: the posts are placed one by one
      return;
    }
    for (int i = 0; i < columns; ++i)
    {
      if (!(std::abs(y[i]) <= 90.0))
      {
        placed = false;
        return;
      }
      // The height's direction over 10 km: the local frame rounds to about 1e-9 m, which
      // a 1 m difference would take times every post's height.
      constexpr double rise = 1e4;
      const LocalPoint ground = this->Frame->toLocal({ y[i], x[i], 0.0 });
      const LocalPoint above = this->Frame->toLocal({ y[i], x[i], rise });
      NodePlace& node = nodes[static_cast<std::size_t>(j - j0) * columns + i];
      for (int c = 0; c < 3; ++c)
        node[c] = ground[c], node[3 + c] = (above[c] - ground[c]) / rise;
      for (const double value : node)
        if (!std::isfinite(value))
          placed = false;
    }
  });
  return placed;
}

template <typename HeightT, typename PointT>
void TerrainPlacement::place(const HeightT* heights, double holeHeightM, PointT* xyz) const
{
  const int nx = this->Grid.nx;
  const int ny = this->Grid.ny;
  std::vector<NodePlace> nodes;
  int firstColumn = 0, firstRow = 0, columns = 0;
  const bool byNodes = this->Projection && this->placeNodes(nodes, firstColumn, firstRow, columns);
  // Without nodes each post is transformed itself; transforms keep state, so each
  // thread converts with its own copy.
  tbb::enumerable_thread_specific<std::unique_ptr<MapProjection>> projections([this, byNodes]() {
    return this->Projection && !byNodes ? this->Projection->clone() : std::unique_ptr<MapProjection>();
  });

  std::atomic<bool> pastPole{ false }, nonFinite{ false };
  tbb::parallel_for(tbb::blocked_range<int>(0, ny, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<double> x(nx), y(nx);
    std::vector<NodePlace> nodeRow(columns);
    MapProjection* projection = projections.local().get();
    for (int row = rows.begin(); row != rows.end(); ++row)
    {
      if (byNodes)
      {
        // Between the node rows around this one, then between the columns at each post
        // (cubic both ways: within 1e-9 m of the posts' own transforms at 30 m posts).
        const int r = this->Grid.row0 + row, below = floorDivide(r, nodeSpacing);
        const std::array<double, 4> w = cubicWeights(static_cast<double>(r - below * nodeSpacing) / nodeSpacing);
        for (int i = 0; i < columns; ++i)
        {
          NodePlace& value = nodeRow[i];
          value.fill(0.0);
          for (int k = 0; k < 4; ++k)
          {
            const NodePlace& node = nodes[static_cast<std::size_t>(below - 1 + k - firstRow) * columns + i];
            for (int c = 0; c < 6; ++c)
              value[c] += w[k] * node[c];
          }
        }
      }
      else
      {
        for (int i = 0; i < nx; ++i)
          this->Grid.geoTransform.pixelToMap(this->Grid.col0 + i + 0.5, this->Grid.row0 + row + 0.5, x[i], y[i]);
        if (projection)
          projection->toGeographic(static_cast<std::size_t>(nx), x.data(), y.data());
      }
      const HeightT* rowHeights = heights + static_cast<std::size_t>(row) * nx;
      PointT* out = xyz + 3 * static_cast<std::size_t>(this->Grid.geoTransform.gridRow(row, ny)) * nx;
      for (int i = 0; i < nx; ++i)
      {
        const double h = std::isfinite(rowHeights[i]) ? static_cast<double>(rowHeights[i]) : holeHeightM;
        LocalPoint local;
        if (byNodes)
        {
          const int column = this->Grid.col0 + i, left = floorDivide(column, nodeSpacing);
          const std::array<double, 4> w =
            cubicWeights(static_cast<double>(column - left * nodeSpacing) / nodeSpacing);
          const NodePlace* node = &nodeRow[static_cast<std::size_t>(left - 1 - firstColumn)];
          for (int c = 0; c < 3; ++c)
            local[c] = w[0] * (node[0][c] + h * node[0][3 + c]) + w[1] * (node[1][c] + h * node[1][3 + c]) +
              w[2] * (node[2][c] + h * node[2][3 + c]) + w[3] * (node[3][c] + h * node[3][3 + c]);
        }
        else if (projection)
        {
          if (!(std::abs(y[i]) <= 90.0))
          {
            pastPole = true;
            y[i] = 0.0;
          }
          local = this->Frame->toLocal({ y[i], x[i], h });
        }
        else
        {
          local = { x[i] - this->MapOrigin[0], y[i] - this->MapOrigin[1], h - this->MapOrigin[2] };
        }
        // Checked as stored: a finite double may still overflow a float.
        for (int c = 0; c < 3; ++c)
          if (!std::isfinite(static_cast<PointT>(local[c])))
            nonFinite = true;
        out[3 * i + 0] = static_cast<PointT>(local[0]);
        out[3 * i + 1] = static_cast<PointT>(local[1]);
        out[3 * i + 2] = static_cast<PointT>(local[2]);
      }
    }
  });
  if (nonFinite && !pastPole)
  {
    throw Error("the raster's geotransform puts posts at infinite or NaN coordinates (a pixel size or "
                "origin out of range): check its geotransform (gdalinfo)");
  }
  if (pastPole)
  {
    throw Error("the raster's geotransform puts posts beyond latitude 90 degrees (or where no "
                "latitude exists): check its geotransform and CRS (gdalinfo), or read a window "
                "inside the valid range (SetGeoBounds, SetPixelWindow)");
  }
}

template void TerrainPlacement::place<float, float>(const float*, double, float*) const;
template void TerrainPlacement::place<float, double>(const float*, double, double*) const;
template void TerrainPlacement::place<double, float>(const double*, double, float*) const;
template void TerrainPlacement::place<double, double>(const double*, double, double*) const;
} // namespace terralux
