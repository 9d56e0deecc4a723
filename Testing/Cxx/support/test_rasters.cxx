#include "test_rasters.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <filesystem>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace terralux_test
{
std::string scratchDir()
{
  static const std::string dir = [] {
    auto path = std::filesystem::temp_directory_path() /
      ("terralux-test-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::create_directories(path);
    return path.string();
  }();
  return dir;
}

std::string externalDataDir()
{
  return TERRALUX_EXTERNAL_DATA_DIR;
}

std::string writeRaster(const std::string& name, const RasterSpec& spec, const char* driverName)
{
  GDALAllRegister();
  const std::string path = scratchDir() + "/" + name;
  const GDALDataType type = spec.float64 ? GDT_Float64 : GDT_Float32;
  // Drivers without Create() (e.g. AAIGrid) get a copy of an in-memory raster.
  GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
  std::unique_ptr<GDALDataset> dataset(memory->Create("", spec.width, spec.height, 1, type, nullptr));
  std::array<double, 6> geoTransform = spec.geoTransform;
  dataset->SetGeoTransform(geoTransform.data());
  if (!spec.crs.empty())
  {
    OGRSpatialReference crs;
    if (crs.SetFromUserInput(spec.crs.c_str()) != OGRERR_NONE)
    {
      throw std::runtime_error("bad test CRS " + spec.crs);
    }
    dataset->SetSpatialRef(&crs);
  }
  GDALRasterBand* band = dataset->GetRasterBand(1);
  if (spec.noData)
  {
    band->SetNoDataValue(*spec.noData);
  }
  std::vector<double> values(static_cast<std::size_t>(spec.width) * spec.height);
  for (int row = 0; row < spec.height; ++row)
  {
    for (int col = 0; col < spec.width; ++col)
    {
      const double h = spec.elevation(col, row);
      values[static_cast<std::size_t>(row) * spec.width + col] =
        std::isnan(h) && spec.noData ? *spec.noData : h;
    }
  }
  if (band->RasterIO(GF_Write, 0, 0, spec.width, spec.height, values.data(), spec.width,
        spec.height, GDT_Float64, 0, 0, nullptr) != CE_None)
  {
    throw std::runtime_error("cannot fill test raster " + name);
  }
  if (spec.masked)
  {
    std::vector<GByte> mask(values.size());
    for (int row = 0; row < spec.height; ++row)
      for (int col = 0; col < spec.width; ++col)
        mask[static_cast<std::size_t>(row) * spec.width + col] = spec.masked(col, row) ? 0 : 255;
    if (dataset->CreateMaskBand(GMF_PER_DATASET) != CE_None ||
      band->GetMaskBand()->RasterIO(GF_Write, 0, 0, spec.width, spec.height, mask.data(), spec.width,
        spec.height, GDT_Byte, 0, 0, nullptr) != CE_None)
    {
      throw std::runtime_error("cannot write the mask of test raster " + name);
    }
  }
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driverName);
  std::unique_ptr<GDALDataset> copy(
    driver->CreateCopy(path.c_str(), dataset.get(), FALSE, nullptr, nullptr, nullptr));
  if (!copy)
  {
    throw std::runtime_error("cannot write test raster " + path);
  }
  return path;
}
} // namespace terralux_test
