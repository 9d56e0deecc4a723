// Terrain placement (terrain_placement.h): posts placed between transformed nodes
// against each post's own transform, a piece of a grid placed as the whole, and the
// error past a pole.
#include "base/error.h"
#include "geodesy/geo_transform.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_projection.h"
#include "geodesy/terrain_placement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace terralux;

namespace
{
// Rough heights from 0 to 3000 m (no data at one post), as a DEM's.
std::vector<float> roughHeights(int nx, int ny)
{
  std::vector<float> heights(static_cast<std::size_t>(nx) * ny);
  for (int row = 0; row < ny; ++row)
    for (int i = 0; i < nx; ++i)
      heights[static_cast<std::size_t>(row) * nx + i] =
        static_cast<float>(1500.0 + 1500.0 * std::sin(0.37 * i) * std::cos(0.23 * row + 0.011 * i * row));
  heights[static_cast<std::size_t>(ny / 2) * nx + nx / 3] = std::nanf("");
  return heights;
}

// The largest distance (m) between the placement's posts and each post's own
// transform (map -> WGS84 -> local), in double precision.
double largestDeparture(const GridGeoreference& grid, const std::string& crs, const GeodeticPoint& origin)
{
  const MapProjection projection(crs);
  const LocalFrame frame(origin);
  const std::vector<float> heights = roughHeights(grid.nx, grid.ny);
  const double hole = -10.0;
  std::vector<double> xyz(3 * heights.size());
  TerrainPlacement(grid, projection, frame).place(heights.data(), hole, xyz.data());
  std::unique_ptr<MapProjection> own = projection.clone();
  double largest = 0.0;
  for (int row = 0; row < grid.ny; ++row)
    for (int i = 0; i < grid.nx; ++i)
    {
      const float h = heights[static_cast<std::size_t>(row) * grid.nx + i];
      GeodeticPoint point = geodeticOfPixel(grid.geoTransform, *own, grid.col0 + i + 0.5, grid.row0 + row + 0.5,
        std::isfinite(h) ? h : hole);
      const LocalPoint exact = frame.toLocal(point);
      const double* placed = &xyz[3 * (static_cast<std::size_t>(grid.geoTransform.gridRow(row, grid.ny)) * grid.nx + i)];
      largest = std::max(largest,
        std::hypot(placed[0] - exact[0], placed[1] - exact[1], placed[2] - exact[2]));
    }
  return largest;
}
} // namespace

TEST(TerrainPlacement, PostsBetweenNodesLieWhereTheirOwnTransformsPutThem)
{
  // 30 m UTM posts over 15 km (Olinda's zone), a window starting off the nodes.
  GridGeoreference utm;
  utm.nx = 517, utm.ny = 389, utm.col0 = 13, utm.row0 = 5;
  utm.geoTransform.coefficients = { 280000.0, 30.0, 0.0, 9130000.0, 0.0, -30.0 };
  EXPECT_LT(largestDeparture(utm, "EPSG:32725", { -8.0, -35.0, 0.0 }), 1e-7);
  // 3 arc-second posts at 60 N, far from the frame's origin (curvature and the
  // meridians' convergence at their largest over the grid).
  GridGeoreference geographic;
  geographic.nx = 301, geographic.ny = 257;
  geographic.geoTransform.coefficients = { 10.0, 1.0 / 1200.0, 0.0, 60.2, 0.0, -1.0 / 1200.0 };
  EXPECT_LT(largestDeparture(geographic, "EPSG:4326", { 60.0, 10.2, 100.0 }), 1e-7);
}

TEST(TerrainPlacement, APieceIsPlacedBitForBitAsTheWhole)
{
  GridGeoreference whole;
  whole.nx = 203, whole.ny = 151;
  whole.geoTransform.coefficients = { 280000.0, 30.0, 0.0, 9130000.0, 0.0, -30.0 };
  const MapProjection projection("EPSG:32725");
  const LocalFrame frame({ -8.0, -35.0, 0.0 });
  const std::vector<float> heights = roughHeights(whole.nx, whole.ny);
  std::vector<float> all(3 * heights.size());
  TerrainPlacement(whole, projection, frame).place(heights.data(), 0.0, all.data());
  // Raster columns 37..136 and rows 21..110 (north-up: grid rows reversed).
  GridGeoreference piece = whole;
  piece.nx = 100, piece.ny = 90, piece.col0 = 37, piece.row0 = 21;
  std::vector<float> pieceHeights;
  for (int row = 0; row < piece.ny; ++row)
    for (int i = 0; i < piece.nx; ++i)
      pieceHeights.push_back(heights[static_cast<std::size_t>(piece.row0 + row) * whole.nx + piece.col0 + i]);
  std::vector<float> part(3 * pieceHeights.size());
  TerrainPlacement(piece, projection, frame).place(pieceHeights.data(), 0.0, part.data());
  for (int row = 0; row < piece.ny; ++row)
    for (int i = 0; i < piece.nx; ++i)
      for (int c = 0; c < 3; ++c)
      {
        const std::size_t inPiece = 3 * (static_cast<std::size_t>(piece.geoTransform.gridRow(row, piece.ny)) * piece.nx + i) + c;
        const std::size_t inWhole =
          3 * (static_cast<std::size_t>(whole.geoTransform.gridRow(piece.row0 + row, whole.ny)) * whole.nx + piece.col0 + i) + c;
        ASSERT_EQ(part[inPiece], all[inWhole]) << "post " << i << ", " << row;
      }
}

TEST(TerrainPlacement, PostsPastAPoleThrowWhateverTheNodes)
{
  // Nodes beyond 90 degrees fall back to each post's own transform, which names the
  // problem.
  GridGeoreference grid;
  grid.nx = 40, grid.ny = 40;
  grid.geoTransform.coefficients = { 10.0, 0.01, 0.0, 90.2, 0.0, -0.01 };
  const MapProjection projection("EPSG:4326");
  const LocalFrame frame({ 89.9, 10.2, 0.0 });
  const std::vector<float> heights(1600, 100.0f);
  std::vector<float> xyz(3 * heights.size());
  try
  {
    TerrainPlacement(grid, projection, frame).place(heights.data(), 0.0, xyz.data());
    FAIL() << "no error past the pole";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("beyond latitude 90"), std::string::npos) << error.what();
  }
  // Just below the pole, the nodes beyond it fail and each post is placed itself.
  grid.geoTransform.coefficients = { 10.0, 0.001, 0.0, 89.99, 0.0, -0.001 };
  EXPECT_NO_THROW(TerrainPlacement(grid, projection, frame).place(heights.data(), 0.0, xyz.data()));
}
