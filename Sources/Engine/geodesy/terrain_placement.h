#pragma once
// Places the posts of a DEM grid in the scene's local Cartesian frame.
// Georeferenced rasters go map CRS -> WGS84 (GDAL/OSR) -> ECEF -> ENU
// (GeographicLib), keeping Earth curvature; rasters without a CRS are taken
// as local metres relative to a map origin.
//
// Post order: grid point (i, j) is raster post (i, row) with j = gridRow(row)
// (GeoTransform::gridRow): for a north-up raster, whose rows run north to south,
// j = ny - 1 - row grows northward; a raster whose transform keeps orientation
// (south-up, or negative pixel width) keeps its row order. Either way the grid is
// right-handed in ENU and its cell normals point up.

#include "geodesy/geo_transform.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_projection.h"

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace terralux
{
/// The posts of a (windowed, subsampled) DEM grid and where they are.
struct GridGeoreference
{
  int nx = 0;
  int ny = 0;
  /// Pixel (col0 + i, row0 + row) of this transform is centred on post (i, row),
  /// raster order.
  GeoTransform geoTransform;
  /// Where the posts start in geoTransform's pixels: a piece of a larger grid keeps
  /// the whole grid's transform, so its posts are placed bit for bit as there.
  int col0 = 0;
  int row0 = 0;
};

/// Fractional raster position of the grid centre and the ground height there.
struct GridCentre
{
  double col = 0.0; ///< pixel-corner convention: the centre post of a 3-wide grid is 1.5
  double row = 0.0;
  double heightM = 0.0;
};

/// Centre of the grid and its ground height: bilinear between the four posts around
/// it when all are valid, else the nearest valid post (only then are other posts
/// asked for). heightAt(i, row) is raster order, NaN for no data; throws Error
/// when no post is valid.
GridCentre findGridCentre(int nx, int ny, const std::function<double(int, int)>& heightAt);
/// The same over nx x ny heights in raster order.
template <typename HeightT>
GridCentre findGridCentre(int nx, int ny, const HeightT* heights)
{
  return findGridCentre(nx, ny, [&](int i, int row) {
    return static_cast<double>(heights[static_cast<std::size_t>(row) * nx + i]);
  });
}

/// Geodetic position of a fractional raster position (pixel-corner convention).
GeodeticPoint geodeticOfPixel(
  const GeoTransform& geoTransform, MapProjection& projection, double col, double row, double heightM);

class TerrainPlacement
{
public:
  /// Georeferenced placement about a geodetic frame.
  TerrainPlacement(const GridGeoreference& grid, const MapProjection& projection, const LocalFrame& frame);
  /// Local metres: x = X - mapOrigin[0], y = Y - mapOrigin[1], z = h - mapOrigin[2].
  TerrainPlacement(const GridGeoreference& grid, const LocalPoint& mapOrigin);
  ~TerrainPlacement();

  /// Writes 3 * nx * ny coordinates in VTK order (see above). No-data posts (NaN)
  /// are put at holeHeightM so that no spike or NaN reaches the geometry; callers
  /// blank them. Throws Error when a post maps beyond latitude +-90 (a geotransform
  /// that reaches past a pole). Runs in parallel; results do not depend on the
  /// thread count.
  template <typename HeightT, typename PointT>
  void place(const HeightT* heights, double holeHeightM, PointT* xyz) const;

  /// Posts are placed between nodes transformed every this many pixels (each post
  /// transformed itself where a node falls outside the CRS's domain or past a pole).
  static constexpr int nodeSpacing = 8;

private:
  /// Each node's local place on the ellipsoid and the local direction of its height;
  /// false where a node cannot be placed.
  bool placeNodes(std::vector<std::array<double, 6>>& nodes, int& firstColumn, int& firstRow, int& columns) const;

  GridGeoreference Grid;
  std::unique_ptr<MapProjection> Projection; // null for local metres
  std::unique_ptr<LocalFrame> Frame;
  LocalPoint MapOrigin{ 0.0, 0.0, 0.0 };
};
} // namespace terralux
