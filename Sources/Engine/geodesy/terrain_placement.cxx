#include "geodesy/terrain_placement.h"

#include "base/error.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

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

template <typename HeightT, typename PointT>
void TerrainPlacement::place(const HeightT* heights, double holeHeightM, PointT* xyz) const
{
  const int nx = this->Grid.nx;
  const int ny = this->Grid.ny;
  // Transforms keep state, so each thread converts with its own copy.
  tbb::enumerable_thread_specific<std::unique_ptr<MapProjection>> projections([this]() {
    return this->Projection ? this->Projection->clone() : std::unique_ptr<MapProjection>();
  });

  std::atomic<bool> pastPole{ false }, nonFinite{ false };
  tbb::parallel_for(tbb::blocked_range<int>(0, ny, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<double> x(nx), y(nx);
    MapProjection* projection = projections.local().get();
    for (int row = rows.begin(); row != rows.end(); ++row)
    {
      for (int i = 0; i < nx; ++i)
      {
        this->Grid.geoTransform.pixelToMap(this->Grid.col0 + i + 0.5, this->Grid.row0 + row + 0.5, x[i], y[i]);
      }
      if (projection)
      {
        projection->toGeographic(static_cast<std::size_t>(nx), x.data(), y.data());
      }
      const HeightT* rowHeights = heights + static_cast<std::size_t>(row) * nx;
      PointT* out = xyz + 3 * static_cast<std::size_t>(this->Grid.geoTransform.gridRow(row, ny)) * nx;
      for (int i = 0; i < nx; ++i)
      {
        const double h = std::isfinite(rowHeights[i]) ? static_cast<double>(rowHeights[i]) : holeHeightM;
        LocalPoint local;
        if (projection)
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
