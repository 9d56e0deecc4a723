// vtkTerrainSource: georeferencing against independent GeographicLib computations,
// blanking, subsetting, the real Olinda and Luxembourg DEMs, pieces.
#include "terrain_source_checks.h"
#include "test_rasters.h"
#include "vtk_test_support.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkStructuredGrid.h"
#include "vtkTerrainReader.h"
#include "vtkTerrainSource.h"
#include "vtkUnsignedCharArray.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

using namespace terralux_test;

namespace
{
constexpr double millimetre = 1e-3;

MapToGeodetic utm(int zone, bool north)
{
  return [=](double x, double y, double& lat, double& lon) {
    GeographicLib::UTMUPS::Reverse(zone, north, x, y, lat, lon);
  };
}

// Every output point against GeographicLib: raster post (i, row) -> map (affine,
// by hand) -> geodetic (the given inverse projection) -> ENU about GeoOrigin.
// Also checks GeoOrigin itself: the grid centre at its ground height.
void expectPostsMatch(const RasterSpec& spec, vtkStructuredGrid* grid, const MapToGeodetic& toGeodetic,
  double tolerance)
{
  int dims[3];
  grid->GetDimensions(dims);
  ASSERT_EQ(dims[0], spec.width);
  ASSERT_EQ(dims[1], spec.height);
  ASSERT_EQ(dims[2], 1);
  const auto& g = spec.geoTransform;
  auto mapOf = [&](double col, double row, double& x, double& y) {
    x = g[0] + col * g[1] + row * g[2];
    y = g[3] + col * g[4] + row * g[5];
  };
  // Default origin: centre of the grid; for odd sizes a post.
  double x, y, lat0, lon0;
  mapOf(0.5 * spec.width, 0.5 * spec.height, x, y);
  toGeodetic(x, y, lat0, lon0);
  EXPECT_NEAR(fieldValue(grid, "GeoOrigin", 0), lat0, 1e-9);
  EXPECT_NEAR(fieldValue(grid, "GeoOrigin", 1), lon0, 1e-9);
  const double h0 = fieldValue(grid, "GeoOrigin", 2);
  if (spec.width % 2 == 1 && spec.height % 2 == 1)
  {
    EXPECT_NEAR(h0, spec.elevation(spec.width / 2, spec.height / 2), 1e-4);
  }
  const GeographicLib::LocalCartesian frame(fieldValue(grid, "GeoOrigin", 0),
    fieldValue(grid, "GeoOrigin", 1), fieldValue(grid, "GeoOrigin", 2));
  double worst = 0.0;
  for (int row = 0; row < spec.height; ++row)
  {
    for (int col = 0; col < spec.width; ++col)
    {
      double lat, lon, e, n, u;
      mapOf(col + 0.5, row + 0.5, x, y);
      toGeodetic(x, y, lat, lon);
      frame.Forward(lat, lon, spec.elevation(col, row), e, n, u);
      double p[3];
      grid->GetPoint(col + static_cast<vtkIdType>(spec.height - 1 - row) * spec.width, p);
      worst = std::max({ worst, std::abs(p[0] - e), std::abs(p[1] - n), std::abs(p[2] - u) });
    }
  }
  EXPECT_LT(worst, tolerance);
}
} // namespace

TEST(TerrainSource, UtmNorthPostsToAMillimetre)
{
  const RasterSpec spec = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  Terrain terrain;
  runDouble(terrain, writeRaster("utm32n.tif", spec));
  expectPostsMatch(spec, terrain.output(), utm(32, true), millimetre);
  EXPECT_EQ(terrain.output()->GetPointData()->GetArray("Elevation")->GetRange()[1],
    terrain.output()->GetPointData()->GetArray("Elevation")->GetRange()[1]);
}

TEST(TerrainSource, UtmSouthPostsToAMillimetre)
{
  const RasterSpec spec = utmSpec("EPSG:32725", 288776.25, 9120760.75);
  Terrain terrain;
  runDouble(terrain, writeRaster("utm25s.tif", spec));
  expectPostsMatch(spec, terrain.output(), utm(25, false), millimetre);
}

TEST(TerrainSource, GeographicDegreesPostsToAMillimetre)
{
  RasterSpec spec;
  spec.width = 35;
  spec.height = 29;
  spec.geoTransform = { 6.0, 0.001, 0.0, 49.9, 0.0, -0.001 };
  spec.crs = "EPSG:4326";
  spec.elevation = hills;
  Terrain terrain;
  runDouble(terrain, writeRaster("geographic.tif", spec));
  expectPostsMatch(spec, terrain.output(), geographic, millimetre);
}

TEST(TerrainSource, RotatedGeotransformPostsToAMillimetre)
{
  RasterSpec spec = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  const double angle = 20.0 * M_PI / 180.0;
  spec.geoTransform = { 380000.0, 30.0 * std::cos(angle), 30.0 * std::sin(angle), 5080000.0,
    30.0 * std::sin(angle), -30.0 * std::cos(angle) };
  Terrain terrain;
  runDouble(terrain, writeRaster("rotated.tif", spec));
  expectPostsMatch(spec, terrain.output(), utm(32, true), millimetre);
}

TEST(TerrainSource, SinglePrecisionPointsStayWithinTwoMillimetres)
{
  const RasterSpec spec = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("utm32n-single.tif", spec).c_str());
  ASSERT_EQ(terrain.run(), 1);
  EXPECT_EQ(terrain.output()->GetPoints()->GetDataType(), VTK_FLOAT);
  expectPostsMatch(spec, terrain.output(), utm(32, true), 2 * millimetre);
}

// Ground at constant ellipsoidal height 50 km north of the origin lies ~196 m
// below the tangent plane.
TEST(TerrainSource, EarthCurvatureIsKept)
{
  RasterSpec spec;
  spec.width = 5;
  spec.height = 181; // 0.005 deg posts: +-0.45 deg, ~ +-50 km around 45 N
  spec.geoTransform = { 9.9875, 0.005, 0.0, 45.4525, 0.0, -0.005 };
  spec.crs = "EPSG:4326";
  spec.elevation = [](int, int) { return 0.0; };
  Terrain terrain;
  runDouble(terrain, writeRaster("curvature.tif", spec));
  expectPostsMatch(spec, terrain.output(), geographic, millimetre);
  double north[3];
  terrain.output()->GetPoint(2 + 180 * 5, north); // top row, centre column
  EXPECT_NEAR(north[1], 50000.0, 200.0);
  const double drop = -north[2] * (50000.0 / north[1]) * (50000.0 / north[1]);
  EXPECT_NEAR(drop, 196.0, 1.0);
}

TEST(TerrainSource, NoDataPostsAreBlankedNotSpikes)
{
  RasterSpec spec = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  spec.noData = -32768.0;
  spec.elevation = [](int col, int row) {
    return (col >= 10 && col < 14 && row >= 5 && row < 8) ? NAN : hills(col, row);
  };
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("hole.tif", spec).c_str());
  ASSERT_EQ(terrain.run(), 1);
  vtkStructuredGrid* grid = terrain.output();
  vtkDataArray* elevation = grid->GetPointData()->GetArray("Elevation");
  vtkUnsignedCharArray* ghosts = grid->GetPointGhostArray();
  ASSERT_NE(ghosts, nullptr);
  EXPECT_TRUE(grid->HasAnyBlankPoints());
  int hidden = 0;
  double lowestValid = INFINITY, lowestZ = INFINITY, highestZ = -INFINITY;
  for (vtkIdType k = 0; k < grid->GetNumberOfPoints(); ++k)
  {
    const bool isHidden = ghosts->GetValue(k) & vtkDataSetAttributes::HIDDENPOINT;
    hidden += isHidden;
    EXPECT_EQ(isHidden, std::isnan(elevation->GetComponent(k, 0)));
    const double z = grid->GetPoint(k)[2];
    EXPECT_TRUE(std::isfinite(z));
    lowestZ = std::min(lowestZ, z);
    highestZ = std::max(highestZ, z);
    if (!isHidden)
      lowestValid = std::min(lowestValid, elevation->GetComponent(k, 0));
  }
  EXPECT_EQ(hidden, 12);
  // No -32768 m spike and no zero plane: hole points sit within the valid heights.
  EXPECT_GT(lowestZ, lowestValid - 1000.0 - 5.0);
  EXPECT_LT(highestZ, 2000.0);
  // Raster (col 10, row 5) -> grid (10, 30 - 5): hidden, and the cells around it too.
  const vtkIdType holePoint = 10 + (30 - 5) * 41;
  EXPECT_FALSE(grid->IsPointVisible(holePoint));
  EXPECT_FALSE(grid->IsCellVisible(10 + (30 - 5) * 40));
  EXPECT_FALSE(grid->IsCellVisible(9 + (30 - 5) * 40));
  EXPECT_TRUE(grid->IsCellVisible(0));
  EXPECT_DOUBLE_EQ(fieldValue(grid, "NoDataValue", 0), -32768.0);
}

TEST(TerrainSource, WindowStrideAndGeoBoundsSubsetTheSamePosts)
{
  const RasterSpec spec = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  const std::string path = writeRaster("subset.tif", spec);
  Terrain full;
  full.source->SetFileName(path.c_str());
  full.source->SetGeoOrigin(45.8, 7.4, 500.0);
  full.source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  ASSERT_EQ(full.run(), 1);
  EXPECT_NEAR(fieldValue(full.output(), "GeoOrigin", 0), 45.8, 0.0);

  Terrain part;
  part.source->SetFileName(path.c_str());
  part.source->SetGeoOrigin(45.8, 7.4, 500.0);
  part.source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  part.source->SetPixelWindow(5, 3, 30, 20);
  part.source->SetStride(3);
  ASSERT_EQ(part.run(), 1);
  int dims[3];
  part.output()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 10); // posts 0, 3, ..., 27 of the window
  EXPECT_EQ(dims[1], 7);  // posts 0, 3, ..., 18
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      const int col = 5 + 3 * i, row = 3 + 3 * (dims[1] - 1 - j);
      double p[3], q[3];
      part.output()->GetPoint(i + j * dims[0], p);
      full.output()->GetPoint(col + (30 - row) * 41, q);
      // (A subsampled grid places its posts between nodes of its own, 8 of its pixels
      // apart: within the placement's interpolation, a few nm, of the full grid's.)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(p[k], q[k], 1e-8);
    }
  }
  // The window's geotransform puts its pixel centres on the kept posts.
  EXPECT_DOUBLE_EQ(fieldValue(part.output(), "GeoTransform", 0), 380000.0 + 5 * 30.0 + 15.0 - 45.0);
  EXPECT_DOUBLE_EQ(fieldValue(part.output(), "GeoTransform", 1), 90.0);
  EXPECT_DOUBLE_EQ(fieldValue(part.output(), "GeoTransform", 5), -90.0);
  EXPECT_EQ(vtkIntArray::SafeDownCast(part.output()->GetFieldData()->GetArray("RasterSize"))->GetValue(0), 10);

  // A geographic box around the raster's centre reads only the pixels it overlaps.
  Terrain box;
  box.source->SetFileName(path.c_str());
  double lat, lon;
  GeographicLib::UTMUPS::Reverse(32, true, 380000.0 + 20.5 * 30.0, 5080000.0 - 15.5 * 30.0, lat, lon);
  box.source->SetGeoBounds(lat - 0.001, lat + 0.001, lon - 0.001, lon + 0.001);
  box.source->UseGeoBoundsOn();
  ASSERT_EQ(box.run(), 1) << box.messages->Errors;
  box.output()->GetDimensions(dims);
  EXPECT_GE(dims[0], 6); // ~ 157 m of longitude / 30 m
  EXPECT_LE(dims[0], 8);
  EXPECT_GE(dims[1], 8); // ~ 222 m of latitude / 30 m
  EXPECT_LE(dims[1], 10);

  // UseGeoBoundsOff returns to the whole raster, saying the box is set but unused; a
  // box of zeros in use is refused as no box (zeros are no sentinel).
  box.source->UseGeoBoundsOff();
  ASSERT_EQ(box.run(), 1) << box.messages->Errors;
  EXPECT_EQ(box.output()->GetNumberOfPoints(), full.output()->GetNumberOfPoints());
  EXPECT_NE(box.messages->Warnings.find("UseGeoBounds is off"), std::string::npos);
  box.source->SetGeoBounds(0.0, 0.0, 0.0, 0.0);
  box.source->UseGeoBoundsOn();
  EXPECT_EQ(box.run(), 0);
  EXPECT_NE(box.messages->Errors.find("not a geographic box"), std::string::npos);
}

TEST(TerrainSource, RasterWithoutCrsIsLocalMetresWithAWarning)
{
  RasterSpec spec = utmSpec("", 1000.0, 2000.0);
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("nocrs.tif", spec).c_str());
  ASSERT_EQ(terrain.run(), 1);
  EXPECT_NE(terrain.messages->Warnings.find("no coordinate reference system"), std::string::npos);
  EXPECT_EQ(terrain.output()->GetFieldData()->GetArray("GeoOrigin"), nullptr);
  double p[3];
  terrain.output()->GetPoint(0, p); // raster (0, 30): map (1015, 2000 - 30.5 * 30)
  EXPECT_NEAR(p[0], 1015.0 - fieldValue(terrain.output(), "LocalOrigin", 0), 1e-3);
  EXPECT_NEAR(p[1], 2000.0 - 30.5 * 30.0 - fieldValue(terrain.output(), "LocalOrigin", 1), 1e-3);
  EXPECT_NEAR(p[2], hills(0, 30) - hills(20, 15), 1e-3);
}

TEST(TerrainSource, AsciiGridAndSrtmHgtAreRead)
{
  RasterSpec ascii = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  ascii.noData = -9999.0;
  Terrain a;
  runDouble(a, writeRaster("grid.asc", ascii, "AAIGrid"));
  expectPostsMatch(ascii, a.output(), utm(32, true), millimetre);

  // SRTM 3" tile N45E007: 1201 x 1201 posts at 1/1200 deg, integer metres.
  RasterSpec hgt;
  hgt.width = hgt.height = 1201;
  hgt.geoTransform = { 7.0 - 0.5 / 1200, 1.0 / 1200, 0.0, 46.0 + 0.5 / 1200, 0.0, -1.0 / 1200 };
  hgt.crs = "EPSG:4326";
  hgt.elevation = [](int col, int row) { return std::round(hills(col / 10, row / 10)); };
  Terrain h;
  h.source->SetStride(100);
  runDouble(h, writeRaster("N45E007.hgt", hgt, "SRTMHGT"));
  int dims[3];
  h.output()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 13);
  EXPECT_EQ(dims[1], 13);
  EXPECT_NEAR(fieldValue(h.output(), "GeoOrigin", 0), 45.5, 1e-9);
  EXPECT_NEAR(fieldValue(h.output(), "GeoOrigin", 1), 7.5, 1e-9);
}

TEST(TerrainSource, OlindaDem)
{
  Terrain terrain;
  const std::string path = terralux_test::externalDataDir() + "/olinda_dem_utm25s.tif";
  ASSERT_TRUE(std::ifstream(path).good()) << path << " missing: run cmake/install-dependencies.sh";
  runDouble(terrain, path);
  vtkStructuredGrid* grid = terrain.output();
  int dims[3];
  grid->GetDimensions(dims);
  EXPECT_EQ(dims[0], 111);
  EXPECT_EQ(dims[1], 111);
  double range[2];
  grid->GetPointData()->GetArray("Elevation")->GetRange(range);
  EXPECT_EQ(range[0], -1.0); // gdalinfo -stats: Minimum=-1.000, Maximum=88.000
  EXPECT_EQ(range[1], 88.0);
  EXPECT_FALSE(grid->HasAnyBlankPoints());
  EXPECT_NE(vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("CRS"))
              ->GetValue(0)
              .find("UTM Zone 25, Southern Hemisphere"),
    std::string::npos);
  EXPECT_NEAR(fieldValue(grid, "GeoTransform", 0), 288776.250000803, 1e-6);
  EXPECT_NEAR(fieldValue(grid, "GeoTransform", 3), 9120760.75002874, 1e-6);

  // Corners as gdalinfo reports them (pixel corners, DMS to 0.01"), from the posts:
  // extrapolate half a post outward in geodetic coordinates.
  const GeographicLib::LocalCartesian frame(fieldValue(grid, "GeoOrigin", 0),
    fieldValue(grid, "GeoOrigin", 1), fieldValue(grid, "GeoOrigin", 2));
  auto geodetic = [&](int i, int j, double& lat, double& lon) {
    double p[3], h;
    grid->GetPoint(i + j * 111, p);
    frame.Reverse(p[0], p[1], p[2], lat, lon, h);
  };
  auto corner = [&](int i, int j, int di, int dj, double& lat, double& lon) {
    double lat0, lon0, lat1, lon1, lat2, lon2;
    geodetic(i, j, lat0, lon0);
    geodetic(i + di, j, lat1, lon1);
    geodetic(i, j + dj, lat2, lon2);
    lat = lat0 - 0.5 * (lat1 - lat0) - 0.5 * (lat2 - lat0);
    lon = lon0 - 0.5 * (lon1 - lon0) - 0.5 * (lon2 - lon0);
  };
  auto dms = [](double d, double m, double s) { return -(d + m / 60.0 + s / 3600.0); };
  const double tolerance = 0.01 / 3600.0; // gdalinfo's rounding
  double lat, lon;
  corner(0, 110, 1, -1, lat, lon); // upper left: raster (0, 0)
  EXPECT_NEAR(lat, dms(7, 56, 59.36), tolerance);
  EXPECT_NEAR(lon, dms(34, 54, 58.20), tolerance);
  corner(0, 0, 1, 1, lat, lon); // lower left
  EXPECT_NEAR(lat, dms(8, 2, 24.47), tolerance);
  EXPECT_NEAR(lon, dms(34, 54, 59.71), tolerance);
  corner(110, 110, -1, -1, lat, lon); // upper right
  EXPECT_NEAR(lat, dms(7, 57, 0.83), tolerance);
  EXPECT_NEAR(lon, dms(34, 49, 32.08), tolerance);
  corner(110, 0, -1, 1, lat, lon); // lower right
  EXPECT_NEAR(lat, dms(8, 2, 25.96), tolerance);
  EXPECT_NEAR(lon, dms(34, 49, 33.52), tolerance);
  // The bottom row of posts spans 110 pixels of map distance divided by the UTM
  // scale factor, turned from east by the meridian convergence (GeographicLib).
  double latMid, lonMid, convergence, scale, p0[3], p1[3];
  GeographicLib::UTMUPS::Reverse(25, false, 288776.25 + 55.5 * 89.994067, 9120760.75 - 110.5 * 89.994067,
    latMid, lonMid, convergence, scale);
  grid->GetPoint(0, p0);
  grid->GetPoint(110, p1);
  EXPECT_NEAR(std::hypot(p1[0] - p0[0], p1[1] - p0[1]), 110 * 89.994067 / scale, 0.5);
  // gamma is the bearing of grid north, so grid east turns by -gamma from true east.
  EXPECT_NEAR(std::atan2(p1[1] - p0[1], p1[0] - p0[0]) * 180 / M_PI, -convergence, 0.005);
}

TEST(TerrainSource, LuxembourgDemWithNoData)
{
  Terrain terrain;
  const std::string path = terralux_test::externalDataDir() + "/elev.tif";
  ASSERT_TRUE(std::ifstream(path).good()) << path << " missing: run cmake/install-dependencies.sh";
  terrain.source->SetFileName(path.c_str());
  ASSERT_EQ(terrain.run(), 1);
  vtkStructuredGrid* grid = terrain.output();
  int dims[3];
  grid->GetDimensions(dims);
  EXPECT_EQ(dims[0], 95);
  EXPECT_EQ(dims[1], 90);
  double range[2];
  grid->GetPointData()->GetArray("Elevation")->GetRange(range);
  EXPECT_EQ(range[0], 141.0); // gdalinfo: Min=141.000 Max=547.000
  EXPECT_EQ(range[1], 547.0);

  // Independent count of no-data posts straight from GDAL.
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  std::vector<short> raw(95 * 90);
  ASSERT_EQ(dataset->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 95, 90, raw.data(), 95, 90, GDT_Int16, 0, 0, nullptr),
    CE_None);
  const auto expectedHidden = std::count(raw.begin(), raw.end(), short(-32768));
  EXPECT_GT(expectedHidden, 1000);
  vtkIdType hidden = 0;
  for (vtkIdType k = 0; k < grid->GetNumberOfPoints(); ++k)
    hidden += !grid->IsPointVisible(k);
  EXPECT_EQ(hidden, expectedHidden);

  // Corners (gdalinfo): 5d44'30"E .. 6d32'E, 49d26'30"N .. 50d11'30"N.
  EXPECT_NEAR(fieldValue(grid, "GeoTransform", 0), 5.7416667, 1e-7);
  EXPECT_NEAR(fieldValue(grid, "GeoTransform", 3), 50.1916667, 1e-7);
  const GeographicLib::LocalCartesian frame(fieldValue(grid, "GeoOrigin", 0),
    fieldValue(grid, "GeoOrigin", 1), fieldValue(grid, "GeoOrigin", 2));
  double p[3], lat, lon, h;
  grid->GetPoint(0, p); // lower-left post: half a pixel inside the corner
  frame.Reverse(p[0], p[1], p[2], lat, lon, h);
  EXPECT_NEAR(lat, 49.4416667 + 0.5 / 120, 1e-7);
  EXPECT_NEAR(lon, 5.7416667 + 0.5 / 120, 1e-7);
  EXPECT_NEAR(fieldValue(grid, "GeoOrigin", 0), 49.8166667, 1e-6); // gdalinfo centre
  EXPECT_NEAR(fieldValue(grid, "GeoOrigin", 1), 6.1375, 1e-6);
}

TEST(TerrainSource, HeightFieldImageInput)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(6, 4, 1);
  image->SetSpacing(25.0, 30.0, 1.0);
  image->SetOrigin(100.0, 200.0, 0.0);
  vtkNew<vtkFloatArray> heights;
  heights->SetName("h");
  heights->SetNumberOfTuples(24);
  for (int k = 0; k < 24; ++k)
    heights->SetValue(k, 10.0f * k);
  heights->SetValue(7, NAN);
  image->GetPointData()->SetScalars(heights);
  const unsigned long imageTime = image->GetMTime();

  Terrain terrain;
  terrain.source->SetInputData(image);
  ASSERT_EQ(terrain.run(), 1);
  vtkStructuredGrid* grid = terrain.output();
  EXPECT_EQ(grid->GetNumberOfPoints(), 24);
  double p[3];
  grid->GetPoint(9, p); // (3, 1)
  EXPECT_DOUBLE_EQ(p[0], 175.0);
  EXPECT_DOUBLE_EQ(p[1], 230.0);
  EXPECT_DOUBLE_EQ(p[2], 90.0);
  EXPECT_FALSE(grid->IsPointVisible(7));
  EXPECT_TRUE(std::isnan(grid->GetPointData()->GetArray("Elevation")->GetComponent(7, 0)));
  EXPECT_DOUBLE_EQ(grid->GetPoint(7)[2], 0.0); // the lowest valid height
  // The input is left as it was.
  EXPECT_EQ(image->GetMTime(), imageTime);
  EXPECT_TRUE(std::isnan(heights->GetValue(7)));
  EXPECT_EQ(image->GetPointGhostArray(), nullptr);

  terrain.source->SetGeoOrigin(-8.0, -34.9, 10.0);
  ASSERT_EQ(terrain.run(), 1);
  EXPECT_DOUBLE_EQ(fieldValue(terrain.output(), "GeoOrigin", 1), -34.9);

  vtkNew<vtkImageData> volume;
  volume->SetDimensions(3, 3, 3);
  volume->AllocateScalars(VTK_FLOAT, 1);
  terrain.source->SetInputData(volume);
  EXPECT_EQ(terrain.run(), 0);
  EXPECT_NE(terrain.messages->Errors.find("2-D height field"), std::string::npos);
  EXPECT_EQ(terrain.output()->GetNumberOfPoints(), 0);
}
