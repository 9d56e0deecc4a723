// Engine tests: GeoTIFFs written a window at a time (GeoTiffWriter, as rank 0 writes the
// pieces MPI ranks send) hold what one write of the whole raster holds, and posts no
// window covers read as no data.
#include "raster/dem_raster.h"
#include "base/error.h"
#include "raster/raster_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace terralux;

namespace
{
// Large enough to be tiled (512 x 512 or more), so windows cross tiles.
constexpr int width = 600, height = 530;

float valueAt(int band, int col, int row)
{
  return static_cast<float>(1000.0 * band + 0.5 * col - 0.25 * row);
}

RasterGrid grid(bool noData)
{
  RasterGrid raster;
  raster.width = width;
  raster.height = height;
  raster.geoTransform = GeoTransform{ { 400000.0, 30.0, 0.0, 5000000.0, 0.0, -30.0 } };
  raster.crsWkt = "EPSG:32632";
  raster.hasNoData = noData;
  raster.noData = -9999.0;
  return raster;
}

std::vector<RasterBand> describedBands()
{
  std::vector<RasterBand> bands(2);
  bands[0].description = "GlobalIrradiance";
  bands[1].description = "SkyViewFactor";
  bands[0].unit = "W/m^2";
  bands[1].unit = "1";
  return bands;
}

std::vector<float> readBand(const std::string& file, int band)
{
  DemRaster raster(file, band);
  std::vector<float> values(static_cast<std::size_t>(width) * height);
  raster.read(PixelWindow{ 0, 0, width, height }, 1, values.data());
  return values;
}
} // namespace

TEST(GeoTiffWriter, WindowsInAnyOrderHoldWhatOneWholeWriteHolds)
{
  const std::string whole = testing::TempDir() + "whole.tif", windows = testing::TempDir() + "windows.tif";
  {
    GeoTiffWriter writer(whole, grid(false), describedBands());
    for (int b = 0; b < 2; ++b)
    {
      std::vector<float> values;
      for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col)
          values.push_back(valueAt(b, col, row));
      writer.writeWindow(b, 0, 0, width, height, values.data());
    }
    writer.close();
  }

  // Pieces as VTK cuts them (blocks sharing their border posts), written out of order;
  // rows 400 to 449 of the west half stay uncovered.
  struct Window
  {
    int col, row, w, h;
  };
  const std::vector<Window> pieces{ { 300, 0, 300, 530 }, { 0, 0, 301, 400 }, { 0, 450, 301, 80 } };
  {
    GeoTiffWriter writer(windows, grid(true), describedBands());
    for (const Window& p : pieces)
      for (int b = 0; b < 2; ++b)
      {
        std::vector<float> values;
        for (int row = p.row; row < p.row + p.h; ++row)
          for (int col = p.col; col < p.col + p.w; ++col)
            values.push_back(valueAt(b, col, row));
        writer.writeWindow(b, p.col, p.row, p.w, p.h, values.data());
      }
    EXPECT_THROW(writer.writeWindow(0, 550, 0, 51, 10, std::vector<float>(510).data()), Error);
    EXPECT_THROW(writer.writeWindow(2, 0, 0, 1, 1, std::vector<float>(1).data()), Error);
    writer.close();
  }
  for (int b = 1; b <= 2; ++b)
  {
    const std::vector<float> expected = readBand(whole, b), written = readBand(windows, b);
    int differences = 0, noData = 0;
    for (int row = 0; row < height; ++row)
      for (int col = 0; col < width; ++col)
      {
        const std::size_t k = static_cast<std::size_t>(row) * width + col;
        const bool uncovered = col < 300 && row >= 400 && row < 450;
        noData += std::isnan(written[k]); // DemRaster reads no data as NaN
        differences += uncovered ? !std::isnan(written[k]) : written[k] != expected[k];
      }
    EXPECT_EQ(differences, 0) << "band " << b;
    EXPECT_EQ(noData, 300 * 50);
  }
  EXPECT_EQ(DemRaster(windows, 1).info().crsWkt, DemRaster(whole, 1).info().crsWkt);
  std::remove(whole.c_str());
  std::remove(windows.c_str());
}

TEST(GeoTiffWriter, RastersThatMayPassFourGibibytesAreBigTiff)
{
  // 33,000^2 Float32 posts are 4.4 GB before compression: a classic TIFF could not hold
  // them once the values do not compress well. Only a window is written (the rest is
  // no data, and compresses to little).
  RasterGrid huge = grid(true);
  huge.width = huge.height = 33000;
  const std::string file = testing::TempDir() + "huge.tif";
  GeoTiffWriter writer(file, huge, std::vector<RasterBand>(1));
  const std::vector<float> values(64 * 64, 1.0f), later(64 * 64, 2.0f);
  writer.writeWindow(0, 1000, 2000, 64, 64, values.data());
  // Large: flushed blocks leave GDAL's cache; a window into a block already written
  // (as two pieces share one) reads it back and stores it again, keeping both.
  writer.flush();
  writer.writeWindow(0, 1064, 2000, 64, 64, later.data());
  writer.flush();
  writer.close();
  char magic[4] = {};
  std::FILE* f = std::fopen(file.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(std::fread(magic, 1, 4, f), 4u);
  std::fclose(f);
  EXPECT_EQ(magic[2], 43) << "BigTIFF's version is 43, classic TIFF's 42";
  std::vector<float> read(64 * 64);
  DemRaster(file, 1).read(PixelWindow{ 1000, 2000, 64, 64 }, 1, read.data());
  EXPECT_EQ(read, values);
  DemRaster(file, 1).read(PixelWindow{ 1064, 2000, 64, 64 }, 1, read.data());
  EXPECT_EQ(read, later);
  std::remove(file.c_str());

  // A small raster stays a classic TIFF, which every reader takes.
  const std::string small = testing::TempDir() + "small.tif";
  GeoTiffWriter(small, grid(false), describedBands()).close();
  f = std::fopen(small.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(std::fread(magic, 1, 4, f), 4u);
  std::fclose(f);
  EXPECT_EQ(magic[2], 42);
  std::remove(small.c_str());
}

TEST(GeoTiffWriter, RefusesWhatItCannotWrite)
{
  EXPECT_THROW(GeoTiffWriter(testing::TempDir() + "none.tif", grid(false), {}), Error);
  EXPECT_THROW(GeoTiffWriter("/nonexistent-folder/out.tif", grid(false), describedBands()), Error);
}
