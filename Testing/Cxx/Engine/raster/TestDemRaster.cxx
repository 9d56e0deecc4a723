// Engine tests: reading DEM rasters through GDAL (windows, stride, no data, errors).
#include "raster/dem_raster.h"
#include "base/error.h"
#include "geodesy/terrain_placement.h"
#include "test_rasters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <vector>

using namespace terralux;
using terralux_test::RasterSpec;
using terralux_test::writeRaster;

namespace
{
RasterSpec rampSpec()
{
  RasterSpec spec;
  spec.width = 23;
  spec.height = 17;
  spec.geoTransform = { 400000.0, 30.0, 0.0, 5000000.0, 0.0, -30.0 };
  spec.crs = "EPSG:32632";
  spec.noData = -9999.0;
  spec.elevation = [](int col, int row) { return 100.0 * row + col; };
  return spec;
}
} // namespace

TEST(DemRaster, ReadsInfo)
{
  DemRaster raster(writeRaster("ramp.tif", rampSpec()), 1);
  const RasterInfo& info = raster.info();
  EXPECT_EQ(info.driver, "GTiff");
  EXPECT_EQ(info.width, 23);
  EXPECT_EQ(info.height, 17);
  EXPECT_TRUE(info.hasNoData);
  EXPECT_EQ(info.noData, -9999.0);
  EXPECT_FALSE(info.needsDoublePrecision);
  EXPECT_NE(info.crsWkt.find("32632"), std::string::npos);
  EXPECT_DOUBLE_EQ(info.geoTransform.coefficients[1], 30.0);
}

TEST(DemRaster, WindowAndStrideReadTheRightPosts)
{
  DemRaster raster(writeRaster("ramp.tif", rampSpec()), 1);
  const PixelWindow window{ 3, 2, 15, 11 };
  for (int stride : { 1, 2, 4 })
  {
    const int nx = PixelWindow::postCount(window.width, stride);
    const int ny = PixelWindow::postCount(window.height, stride);
    std::vector<float> heights(static_cast<std::size_t>(nx) * ny);
    EXPECT_EQ(raster.read(window, stride, heights.data()), heights.size());
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        EXPECT_EQ(heights[j * nx + i], 100.0f * (2 + j * stride) + (3 + i * stride));
      }
    }
  }
  EXPECT_EQ(PixelWindow::postCount(15, 4), 4); // posts 0, 4, 8, 12
}

TEST(DemRaster, NoDataBecomesNaN)
{
  RasterSpec spec = rampSpec();
  spec.elevation = [](int col, int row) { return (col == 5 && row == 4) ? NAN : 1.0; };
  DemRaster raster(writeRaster("hole.tif", spec), 1);
  std::vector<double> heights(23 * 17);
  EXPECT_EQ(raster.read(raster.fullWindow(), 1, heights.data()), heights.size() - 1);
  EXPECT_TRUE(std::isnan(heights[4 * 23 + 5]));
  EXPECT_EQ(heights[4 * 23 + 6], 1.0);
}

TEST(DemRaster, MaskedPostsBecomeNaN)
{
  // A per-dataset mask (no no-data value): masked posts are blanked, with and without stride.
  RasterSpec spec = rampSpec();
  spec.elevation = [](int, int) { return 5.0; };
  spec.masked = [](int col, int row) { return col >= 8 && col < 12 && row >= 4 && row < 8; };
  DemRaster raster(writeRaster("masked.tif", spec), 1);
  std::vector<float> heights(23 * 17);
  EXPECT_EQ(raster.read(raster.fullWindow(), 1, heights.data()), heights.size() - 16);
  EXPECT_TRUE(std::isnan(heights[5 * 23 + 9]));
  EXPECT_EQ(heights[5 * 23 + 7], 5.0f);
  std::vector<float> strided(PixelWindow::postCount(23, 2) * PixelWindow::postCount(17, 2));
  EXPECT_EQ(raster.read(raster.fullWindow(), 2, strided.data()), strided.size() - 4); // cols 8, 10 x rows 4, 6
  EXPECT_TRUE(std::isnan(strided[2 * 12 + 4]));
}

TEST(DemRaster, WindowCoveringMapBounds)
{
  DemRaster raster(writeRaster("ramp.tif", rampSpec()), 1);
  // Pixels 2..4 in x (400060..400150) and rows 1..2 in y (4999970..4999910).
  const PixelWindow w = raster.windowCovering(400065.0, 4999915.0, 400145.0, 4999965.0);
  EXPECT_EQ(w.col0, 2);
  EXPECT_EQ(w.row0, 1);
  EXPECT_EQ(w.width, 3);
  EXPECT_EQ(w.height, 2);
  EXPECT_TRUE(raster.windowCovering(0.0, 0.0, 10.0, 10.0).isEmpty());
}

TEST(DemRaster, GridCentreHeight)
{
  // 3 x 3 grid: centre post is (1, 1); with a hole there, the nearest valid post.
  std::vector<float> heights{ 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  GridCentre centre = findGridCentre(3, 3, heights.data());
  EXPECT_DOUBLE_EQ(centre.col, 1.5);
  EXPECT_DOUBLE_EQ(centre.heightM, 5.0);
  heights[4] = NAN;
  centre = findGridCentre(3, 3, heights.data());
  EXPECT_DOUBLE_EQ(centre.heightM, 2.0); // first of the four equidistant neighbours
  // 2 x 2: bilinear average.
  std::vector<double> square{ 0, 2, 4, 6 };
  EXPECT_DOUBLE_EQ(findGridCentre(2, 2, square.data()).heightM, 3.0);
  std::vector<double> empty(4, NAN);
  EXPECT_THROW(findGridCentre(2, 2, empty.data()), Error);
}

TEST(DemRaster, Errors)
{
  EXPECT_THROW(DemRaster("/no/such/dem.tif", 1), Error);
  EXPECT_THROW(DemRaster("", 1), Error);
  const std::string text = terralux_test::scratchDir() + "/not-a-raster.tif";
  std::ofstream(text) << "this is not a raster\n";
  EXPECT_THROW(DemRaster(text, 1), Error);
  const std::string path = writeRaster("ramp.tif", rampSpec());
  EXPECT_THROW(DemRaster(path, 2), Error);
  EXPECT_THROW(DemRaster(path, 0), Error);
  DemRaster raster(path, 1);
  std::vector<float> heights(1000);
  EXPECT_THROW(raster.read({ 20, 0, 10, 2 }, 1, heights.data()), Error);
  EXPECT_THROW(raster.read({ 0, 0, 0, 2 }, 1, heights.data()), Error);
  EXPECT_THROW(raster.read({ 0, 0, 2, 2 }, 0, heights.data()), Error);
  try
  {
    DemRaster("/no/such/dem.tif", 1);
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos);
  }
}
