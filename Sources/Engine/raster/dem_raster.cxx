#include "raster/dem_raster.h"

#include "base/error.h"
#include "raster/gdal_messages.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace terralux
{
struct DemRaster::Impl
{
  std::unique_ptr<GDALDataset> dataset;
  GDALRasterBand* band = nullptr;
};

namespace
{
// Rows read per RasterIO call before the band's block cache is dropped, so a huge
// raster never sits in memory twice (once in GDAL's cache, once in the output).
constexpr std::size_t rowChunkBytes = std::size_t(32) << 20;

template <typename T>
GDALDataType gdalTypeOf()
{
  return std::is_same<T, float>::value ? GDT_Float32 : GDT_Float64;
}
} // namespace

DemRaster::DemRaster(const std::string& fileName, int band)
  : State(std::make_unique<Impl>())
{
  GDALAllRegister();
  const QuietGdalErrors quiet;
  if (fileName.empty())
  {
    throw Error("no DEM file name given: call SetFileName() or connect a vtkImageData height field");
  }
  VSIStatBufL status;
  if (VSIStatL(fileName.c_str(), &status) != 0)
  {
    throw Error("DEM file '" + fileName + "' does not exist: check the path");
  }
  this->State->dataset.reset(
    GDALDataset::Open(fileName.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!this->State->dataset)
  {
    throw Error("'" + fileName + "' is not a raster GDAL can read (" + quiet.lastMessage() +
      "); give a GeoTIFF, SRTM .hgt, ESRI ASCII grid, USGS DEM or other GDAL raster");
  }
  GDALDataset& dataset = *this->State->dataset;
  this->Info.driver = dataset.GetDriverName() ? dataset.GetDriverName() : "";
  this->Info.width = dataset.GetRasterXSize();
  this->Info.height = dataset.GetRasterYSize();
  this->Info.bandCount = dataset.GetRasterCount();
  this->Info.band = band;
  if (band < 1 || band > this->Info.bandCount)
  {
    throw Error("band " + std::to_string(band) + " is out of range: '" + fileName + "' has " +
      std::to_string(this->Info.bandCount) + " band(s), numbered from 1");
  }
  this->State->band = dataset.GetRasterBand(band);
  this->Info.hasGeoTransform =
    dataset.GetGeoTransform(this->Info.geoTransform.coefficients.data()) == CE_None;
  if (!this->Info.hasGeoTransform)
  {
    this->Info.geoTransform = GeoTransform{};
  }
  if (!this->Info.geoTransform.isValid())
  {
    throw Error("'" + fileName + "' has a degenerate geotransform (zero pixel size)");
  }
  if (const OGRSpatialReference* crs = dataset.GetSpatialRef())
  {
    char* wkt = nullptr;
    const char* options[] = { "FORMAT=WKT2_2019", nullptr };
    if (crs->exportToWkt(&wkt, options) == OGRERR_NONE && wkt)
    {
      this->Info.crsWkt = wkt;
    }
    CPLFree(wkt);
  }
  int hasNoData = 0;
  const double noData = this->State->band->GetNoDataValue(&hasNoData);
  this->Info.hasNoData = hasNoData != 0 && !std::isnan(noData);
  this->Info.noData = noData;
  const GDALDataType type = this->State->band->GetRasterDataType();
  this->Info.needsDoublePrecision = type == GDT_Float64 || type == GDT_Int32 || type == GDT_UInt32;
}

DemRaster::~DemRaster() = default;

PixelWindow DemRaster::windowCovering(double xmin, double ymin, double xmax, double ymax) const
{
  // Pixel positions of the four corners; take their enclosing whole pixels.
  double cols[4], rows[4];
  const double xs[4] = { xmin, xmax, xmin, xmax };
  const double ys[4] = { ymin, ymin, ymax, ymax };
  for (int k = 0; k < 4; ++k)
  {
    this->Info.geoTransform.mapToPixel(xs[k], ys[k], cols[k], rows[k]);
  }
  const double colMin = std::max(0.0, std::floor(*std::min_element(cols, cols + 4)));
  const double rowMin = std::max(0.0, std::floor(*std::min_element(rows, rows + 4)));
  const double colMax = std::min<double>(this->Info.width, std::ceil(*std::max_element(cols, cols + 4)));
  const double rowMax = std::min<double>(this->Info.height, std::ceil(*std::max_element(rows, rows + 4)));
  if (!(colMax > colMin) || !(rowMax > rowMin))
  {
    return {};
  }
  return { static_cast<int>(colMin), static_cast<int>(rowMin), static_cast<int>(colMax - colMin),
    static_cast<int>(rowMax - rowMin) };
}

namespace
{
// Reads the posts of `window` at `stride` into `out` (elements of `type`, `size`
// bytes), in chunks of rows with the band's block cache dropped after each, so a huge
// raster never sits in GDAL's cache. False when GDAL fails.
bool readWindow(GDALRasterBand& band, const PixelWindow& window, int stride, GDALDataType type,
  std::size_t size, void* out)
{
  const int nx = PixelWindow::postCount(window.width, stride);
  const int ny = PixelWindow::postCount(window.height, stride);
  auto* bytes = static_cast<unsigned char*>(out);
  bool ok = true;
  if (stride == 1)
  {
    const int rowsPerChunk =
      static_cast<int>(std::max<std::size_t>(1, rowChunkBytes / (size * static_cast<std::size_t>(nx))));
    for (int row = 0; row < ny && ok; row += rowsPerChunk)
    {
      const int rows = std::min(rowsPerChunk, ny - row);
      ok = band.RasterIO(GF_Read, window.col0, window.row0 + row, nx, rows,
             bytes + static_cast<std::size_t>(row) * nx * size, nx, rows, type, 0, 0, nullptr) == CE_None;
      band.FlushCache();
    }
    return ok;
  }
  // Only the rows that hold posts are read; columns are picked from each row.
  std::vector<unsigned char> rowBuffer(static_cast<std::size_t>(window.width) * size);
  std::size_t bytesSinceFlush = 0;
  for (int j = 0; j < ny && ok; ++j)
  {
    ok = band.RasterIO(GF_Read, window.col0, window.row0 + j * stride, window.width, 1, rowBuffer.data(),
           window.width, 1, type, 0, 0, nullptr) == CE_None;
    unsigned char* row = bytes + static_cast<std::size_t>(j) * nx * size;
    for (int i = 0; i < nx; ++i)
      std::memcpy(row + static_cast<std::size_t>(i) * size, rowBuffer.data() + static_cast<std::size_t>(i) * stride * size, size);
    bytesSinceFlush += rowBuffer.size() * static_cast<std::size_t>(stride);
    if (bytesSinceFlush > rowChunkBytes)
    {
      band.FlushCache();
      bytesSinceFlush = 0;
    }
  }
  band.FlushCache();
  return ok;
}
} // namespace

std::size_t DemRaster::read(const PixelWindow& window, int stride, float* heights)
{
  return this->readPosts(window, stride, heights);
}

std::size_t DemRaster::read(const PixelWindow& window, int stride, double* heights)
{
  return this->readPosts(window, stride, heights);
}

template <typename T>
std::size_t DemRaster::readPosts(const PixelWindow& window, int stride, T* heights)
{
  if (stride < 1)
  {
    throw Error("stride must be at least 1");
  }
  if (window.isEmpty() || window.col0 < 0 || window.row0 < 0 ||
    window.col0 + window.width > this->Info.width || window.row0 + window.height > this->Info.height)
  {
    throw Error("pixel window (" + std::to_string(window.col0) + ", " + std::to_string(window.row0) +
      ", " + std::to_string(window.width) + ", " + std::to_string(window.height) +
      ") is empty or outside the " + std::to_string(this->Info.width) + " x " +
      std::to_string(this->Info.height) + " raster");
  }
  const QuietGdalErrors quiet;
  GDALRasterBand& band = *this->State->band;
  const int nx = PixelWindow::postCount(window.width, stride);
  const int ny = PixelWindow::postCount(window.height, stride);
  if (!readWindow(band, window, stride, gdalTypeOf<T>(), sizeof(T), heights))
  {
    throw Error("reading the DEM failed: " + quiet.lastMessage());
  }
  // A real mask (per dataset, alpha or per band; not the no-data value, handled below)
  // blanks the posts it marks as invalid (0).
  const int maskFlags = band.GetMaskFlags();
  std::vector<GByte> mask;
  if (!(maskFlags & GMF_ALL_VALID) && !(maskFlags & GMF_NODATA))
  {
    mask.resize(static_cast<std::size_t>(nx) * ny);
    if (!readWindow(*band.GetMaskBand(), window, stride, GDT_Byte, 1, mask.data()))
    {
      throw Error("reading the DEM's mask failed: " + quiet.lastMessage());
    }
  }

  const T noData = static_cast<T>(this->Info.noData);
  const bool hasNoData = this->Info.hasNoData;
  std::size_t valid = 0;
  const std::size_t count = static_cast<std::size_t>(nx) * ny;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(heights[k]) || (hasNoData && heights[k] == noData) || (!mask.empty() && mask[k] == 0))
    {
      heights[k] = std::numeric_limits<T>::quiet_NaN();
    }
    else
    {
      ++valid;
    }
  }
  return valid;
}
} // namespace terralux
