#include "raster/raster_writer.h"

#include "base/error.h"
#include "raster/gdal_messages.h"

#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <memory>

namespace terralux
{
struct GeoTiffWriter::Dataset
{
  QuietGdalErrors quiet; // first made, last gone: GDAL's errors in closing are caught too
  std::unique_ptr<GDALDataset> gdal;
};

GeoTiffWriter::GeoTiffWriter(const std::string& fileName, const RasterGrid& grid, const std::vector<RasterBand>& bands)
  : File(std::make_unique<Dataset>())
  , FileName(fileName)
  , Width(grid.width)
  , Height(grid.height)
  , Large(4.0 * grid.width * grid.height * bands.size() > 64.0 * (1 << 20))
{
  if (grid.width <= 0 || grid.height <= 0 || bands.empty())
  {
    throw Error("nothing to write: the grid is empty or no array was chosen");
  }
  if (!grid.geoTransform.isValid())
  {
    const auto& c = grid.geoTransform.coefficients;
    throw Error("the GeoTransform (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " +
      std::to_string(c[2]) + ", " + std::to_string(c[3]) + ", " + std::to_string(c[4]) + ", " + std::to_string(c[5]) +
      ") is not finite and invertible: write grids whose field data GeoTransform vtkTerrainSource made");
  }
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  const bool tiled = grid.width >= 512 && grid.height >= 512;
  // Compressed by every core, quickly (ZLEVEL=1, docs/tuning.md), after the
  // floating-point predictor (TIFF's PREDICTOR=3, which GDAL and GIS read alike).
  // BigTIFF where the file might pass 4 GiB: GDAL's default decides on the size before
  // compression only when uncompressed, and a compressed file past 4 GiB then fails.
  const char* options[] = { "COMPRESS=DEFLATE", "PREDICTOR=3", "ZLEVEL=1", "NUM_THREADS=ALL_CPUS", "BIGTIFF=IF_SAFER",
    "INTERLEAVE=BAND",
    tiled ? "TILED=YES" : nullptr, nullptr };
  this->File->gdal.reset(driver->Create(fileName.c_str(), grid.width, grid.height,
    static_cast<int>(bands.size()), GDT_Float32, const_cast<char**>(options)));
  GDALDataset* dataset = this->File->gdal.get();
  if (!dataset)
  {
    throw Error("cannot create '" + fileName + "' (" + this->File->quiet.lastMessage() + "): check the folder and permissions");
  }
  std::array<double, 6> coefficients = grid.geoTransform.coefficients;
  dataset->SetGeoTransform(coefficients.data());
  if (!grid.crsWkt.empty())
  {
    OGRSpatialReference crs;
    if (crs.SetFromUserInput(grid.crsWkt.c_str()) != OGRERR_NONE || dataset->SetSpatialRef(&crs) != CE_None)
    {
      throw Error("cannot set the CRS of '" + fileName + "': " + this->File->quiet.lastMessage());
    }
  }
  for (std::size_t k = 0; k < bands.size(); ++k)
  {
    GDALRasterBand* band = dataset->GetRasterBand(static_cast<int>(k) + 1);
    band->SetDescription(bands[k].description.c_str());
    band->SetUnitType(bands[k].unit.c_str());
  }
  // Before any value: blocks GDAL starts then begin as no data, not 0.
  if (grid.hasNoData)
    this->setNoData(grid.noData);
}

GeoTiffWriter::~GeoTiffWriter() = default;

void GeoTiffWriter::setNoData(double noData)
{
  GDALDataset& dataset = *this->File->gdal;
  for (int k = 1; k <= dataset.GetRasterCount(); ++k)
    dataset.GetRasterBand(k)->SetNoDataValue(noData);
}

void GeoTiffWriter::writeWindow(int band, int column, int row, int width, int height, const float* values)
{
  GDALDataset& dataset = *this->File->gdal;
  if (band < 0 || band >= dataset.GetRasterCount() || column < 0 || row < 0 || width <= 0 || height <= 0 ||
    column + width > this->Width || row + height > this->Height)
  {
    throw Error("a window of values lies outside the raster '" + this->FileName + "'");
  }
  if (dataset.GetRasterBand(band + 1)->RasterIO(GF_Write, column, row, width, height, const_cast<float*>(values),
        width, height, GDT_Float32, 0, 0, nullptr) != CE_None)
    this->failed();
}

void GeoTiffWriter::failed() const
{
  throw Error("writing '" + this->FileName + "' failed: " + this->File->quiet.lastMessage());
}

void GeoTiffWriter::flush()
{
  if (!this->Large)
    return;
  this->File->gdal->FlushCache();
  if (CPLGetLastErrorType() >= CE_Failure)
    this->failed();
}

void GeoTiffWriter::close()
{
  if (!this->File->gdal)
    return;
  this->File->gdal->FlushCache();
  this->File->gdal.reset(); // GDAL writes the file's last blocks and directory here
  if (CPLGetLastErrorType() >= CE_Failure)
    this->failed();
}

void writeVrtMosaic(const std::string& fileName, const std::vector<std::string>& tiles)
{
  if (tiles.empty())
  {
    throw Error("no piece to mosaic into '" + fileName + "'");
  }
  GDALAllRegister();
  const QuietGdalErrors quiet;
  std::vector<const char*> names;
  for (const std::string& tile : tiles)
    names.push_back(tile.c_str());
  int usageError = 0;
  GDALDatasetH vrt = GDALBuildVRT(fileName.c_str(), static_cast<int>(names.size()), nullptr, names.data(), nullptr, &usageError);
  if (!vrt || usageError)
  {
    throw Error("cannot build the VRT '" + fileName + "' over the pieces (" + quiet.lastMessage() + ")");
  }
  // A VRT's bands keep no description of their own: take the first piece's.
  std::unique_ptr<GDALDataset> first(GDALDataset::Open(tiles.front().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  auto* mosaic = GDALDataset::FromHandle(vrt);
  for (int k = 1; first && k <= std::min(first->GetRasterCount(), mosaic->GetRasterCount()); ++k)
  {
    mosaic->GetRasterBand(k)->SetDescription(first->GetRasterBand(k)->GetDescription());
    mosaic->GetRasterBand(k)->SetUnitType(first->GetRasterBand(k)->GetUnitType());
  }
  GDALClose(vrt);
}
} // namespace terralux
