// vtkTerrainSource reading its raster: the window of posts, their places in the frame,
// the ghost posts of a piece and the georeference field data.
#include "vtkTerrainSource.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkExtentTranslator.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationExecutivePortVectorKey.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"

#include "raster/dem_raster.h"
#include "raster/geographic_window.h"
#include "base/error.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_projection.h"
#include "geodesy/terrain_placement.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkTerrainSourceInternals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>
#include <limits>
#include <memory>

using namespace TerrainSourceHeights;

namespace
{
// Marks the posts of `extent` outside `pieceExtent` (a piece's ghost posts, shared with
// its neighbours) duplicate; returns whether there were any.
bool markGhostPosts(const int extent[6], const int pieceExtent[6], vtkUnsignedCharArray* ghosts)
{
  if (std::equal(extent, extent + 6, pieceExtent))
  {
    return false;
  }
  const int nx = extent[1] - extent[0] + 1;
  bool any = false;
  for (int j = extent[2]; j <= extent[3]; ++j)
    for (int i = extent[0]; i <= extent[1]; ++i)
      if (i < pieceExtent[0] || i > pieceExtent[1] || j < pieceExtent[2] || j > pieceExtent[3])
      {
        ghosts->GetPointer(0)[(i - extent[0]) + static_cast<vtkIdType>(j - extent[2]) * nx] |=
          vtkDataSetAttributes::DUPLICATEPOINT;
        any = true;
      }
  return any;
}

// The georeference of a piece (of the whole grid when unsplit): CRS, GeoTransform,
// RasterSize and the no-data value.
void addGeoreference(vtkFieldData* fieldData, const terralux::RasterInfo& info,
  const terralux::GeoTransform& pieceTransform, int nx, int ny)
{
  auto crs = vtkSmartPointer<vtkStringArray>::New();
  crs->SetName(vtkTerraLuxFieldData::CRSName());
  crs->InsertNextValue(info.crsWkt);
  fieldData->AddArray(crs);
  vtkTerraLuxFieldData::AddVector(
    fieldData, vtkTerraLuxFieldData::GeoTransformName(), pieceTransform.coefficients.data(), 6);
  auto rasterSize = vtkSmartPointer<vtkIntArray>::New();
  rasterSize->SetName(vtkTerraLuxFieldData::RasterSizeName());
  rasterSize->InsertNextValue(nx);
  rasterSize->InsertNextValue(ny);
  fieldData->AddArray(rasterSize);
  if (info.hasNoData)
  {
    vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::NoDataValueName(), info.noData);
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> vtkTerrainSource::ReadElevation(const RasterRequest& request,
  const terralux::PixelWindow& piece, int stride, vtkIdType count, std::size_t& valid)
{
  // The raster is read straight into the Elevation array (raster order first).
  vtkSmartPointer<vtkDataArray> elevation = request.raster->info().needsDoublePrecision
    ? newValues<vtkDoubleArray>("Elevation", 1, count)
    : newValues<vtkFloatArray>("Elevation", 1, count);
  valid = withHeights(elevation, [&](auto* heights) { return request.raster->read(piece, stride, heights); });
  const vtkIdType implausible =
    withHeights(elevation, [&](auto* heights) { return dropImplausibleHeights(heights, count); });
  valid -= static_cast<std::size_t>(implausible);
  if (implausible > 0)
  {
    vtkWarningMacro(<< implausible << " post(s) of '" << this->FileName << "' hold heights beyond ["
                    << lowestPlausibleHeightM << ", " << highestPlausibleHeightM
                    << "] m, which no DEM holds: they are taken as no data. Set the band's no-data value "
                       "(gdal_edit.py -a_nodata) if they mark missing posts.");
  }
  if (valid == 0)
  {
    vtkErrorMacro("Every post of '" << this->FileName
                                    << "' in the requested window is no data: choose another "
                                       "window, band or file.");
    return nullptr;
  }
  return elevation;
}

//------------------------------------------------------------------------------
std::unique_ptr<terralux::TerrainPlacement> vtkTerrainSource::PlaceGrid(const terralux::GridGeoreference& grid,
  const terralux::RasterInfo& info, const terralux::GeoTransform& centreTransform, const terralux::GridCentre& centre,
  vtkFieldData* fieldData)
{
  if (info.crsWkt.empty())
  {
    vtkWarningMacro("'" << this->FileName
                        << "' has no coordinate reference system: its map coordinates are taken "
                           "as local metres. Assign a CRS (gdal_edit.py -a_srs) to georeference it.");
    double mapOrigin[3];
    centreTransform.pixelToMap(centre.col, centre.row, mapOrigin[0], mapOrigin[1]);
    mapOrigin[2] = centre.heightM;
    vtkTerraLuxFieldData::AddTuple(fieldData, "LocalOrigin", mapOrigin, 3);
    return std::make_unique<terralux::TerrainPlacement>(
      grid, terralux::LocalPoint{ mapOrigin[0], mapOrigin[1], mapOrigin[2] });
  }
  terralux::MapProjection projection(info.crsWkt);
  terralux::GeodeticPoint origin{ this->GeoOrigin[0], this->GeoOrigin[1], this->GeoOrigin[2] };
  if (!this->UseGeoOrigin)
  {
    origin = terralux::geodeticOfPixel(centreTransform, projection, centre.col, centre.row, centre.heightM);
  }
  const double originValues[3] = { origin.latitudeDeg, origin.longitudeDeg, origin.heightM };
  vtkTerraLuxFieldData::AddTuple(fieldData, vtkTerraLuxFieldData::GeoOriginName(), originValues, 3);
  return std::make_unique<terralux::TerrainPlacement>(grid, projection, terralux::LocalFrame(origin));
}

//------------------------------------------------------------------------------
bool vtkTerrainSource::ReadRaster(
  const int extent[6], const int pieceExtent[6], vtkStructuredGrid* output, int farStride)
{
  RasterRequest request;
  this->ResolveRasterRequest(request);
  const terralux::RasterInfo& info = request.raster->info();
  // The whole grid fixes the frame and the row order; the piece is what is read. The
  // far terrain's posts are every farStride-th of output 0's, in its frame.
  const int stride = this->Stride * farStride;
  const int wholeNx = terralux::PixelWindow::postCount(request.window.width, stride);
  const int wholeNy = terralux::PixelWindow::postCount(request.window.height, stride);
  const terralux::GeoTransform wholeTransform =
    info.geoTransform.window(request.window.col0, request.window.row0, stride);
  const terralux::GeoTransform frameTransform =
    info.geoTransform.window(request.window.col0, request.window.row0, this->Stride);
  const bool rowsReversed = wholeTransform.gridRow(0, wholeNy) != 0;
  if (extent[1] < extent[0] || extent[3] < extent[2])
  {
    return true; // an empty piece (more pieces than rows): nothing to read
  }
  if (extent[0] < 0 || extent[1] >= wholeNx || extent[2] < 0 || extent[3] >= wholeNy)
  {
    throw terralux::Error("the requested extent lies outside the DEM's " + std::to_string(wholeNx) + " x " +
      std::to_string(wholeNy) + " posts");
  }
  const int nx = extent[1] - extent[0] + 1;
  const int ny = extent[3] - extent[2] + 1;
  const int firstRow = wholeTransform.firstRasterRow(extent[2], extent[3], wholeNy);
  const terralux::PixelWindow whole = request.window;
  const terralux::PixelWindow piece{ whole.col0 + extent[0] * stride, whole.row0 + firstRow * stride,
    (nx - 1) * stride + 1, (ny - 1) * stride + 1 };
  const vtkIdType count = static_cast<vtkIdType>(nx) * ny;
  if (request.clipped)
  {
    vtkWarningMacro("PixelWindow extends beyond the " << info.width << " x " << info.height
                                                      << " raster; it was clipped to it.");
  }
  this->UpdateProgress(0.05);
  std::size_t valid = 0;
  const vtkSmartPointer<vtkDataArray> elevation = this->ReadElevation(request, piece, stride, count, valid);
  if (!elevation)
  {
    return false;
  }
  this->UpdateProgress(0.4);
  if (this->GetAbortExecute())
  {
    return false;
  }

  auto ghosts = vtkSmartPointer<vtkUnsignedCharArray>::New();
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(count);
  const double lowest =
    withHeights(elevation, [&](const auto* heights) { return blankNoDataPosts(heights, count, ghosts); });
  // The frame origin is output 0's whole grid's centre, whichever piece (or far
  // terrain) this is: the posts around it are read on their own, a few at a time (the
  // whole grid only if they are no data).
  std::vector<double> wholeHeights;
  int postsRead = 0;
  const int frameNx = request.nx, frameNy = request.ny;
  const terralux::GridCentre wholeCentre = terralux::findGridCentre(frameNx, frameNy, [&](int i, int row) {
    if (farStride == 1 && i >= extent[0] && i < extent[0] + nx && row >= firstRow && row < firstRow + ny)
    {
      const vtkIdType k = (i - extent[0]) + static_cast<vtkIdType>(row - firstRow) * nx;
      return withHeights(elevation, [&](const auto* heights) { return static_cast<double>(heights[k]); });
    }
    if (wholeHeights.empty() && postsRead < 4)
    {
      ++postsRead;
      double height = 0.0;
      request.raster->read({ whole.col0 + i * this->Stride, whole.row0 + row * this->Stride, 1, 1 }, 1, &height);
      dropImplausibleHeights(&height, 1);
      return height;
    }
    if (wholeHeights.empty())
    {
      wholeHeights.resize(static_cast<std::size_t>(frameNx) * frameNy);
      request.raster->read(whole, this->Stride, wholeHeights.data());
      dropImplausibleHeights(wholeHeights.data(), static_cast<vtkIdType>(wholeHeights.size()));
    }
    return wholeHeights[static_cast<std::size_t>(row) * frameNx + i];
  });

  terralux::GridGeoreference grid;
  grid.nx = nx;
  grid.ny = ny;
  grid.geoTransform = wholeTransform;
  grid.col0 = extent[0];
  grid.row0 = firstRow;
  const std::unique_ptr<terralux::TerrainPlacement> placement =
    this->PlaceGrid(grid, info, frameTransform, wholeCentre, output->GetFieldData());

  // Raster order -> grid order (GeoTransform::gridRow): reversed for north-up rasters.
  vtkNew<vtkPoints> points;
  points->SetDataType(this->OutputPointsPrecision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  vtkTerraLuxLargeArrays::Allocate(points->GetData(), count);
  void* xyz = points->GetData()->GetVoidPointer(0);
  withHeights(elevation, [&](auto* heights) {
    if (points->GetDataType() == VTK_DOUBLE)
    {
      placement->place(heights, lowest, static_cast<double*>(xyz));
    }
    else
    {
      placement->place(heights, lowest, static_cast<float*>(xyz));
    }
    if (rowsReversed)
      flipRows(heights, nx, ny);
  });
  if (rowsReversed)
    flipRows(ghosts->GetPointer(0), nx, ny);
  const bool anyGhost = markGhostPosts(extent, pieceExtent, ghosts) || valid < static_cast<std::size_t>(count);
  this->UpdateProgress(0.9);

  output->SetExtent(const_cast<int*>(extent));
  output->SetPoints(points);
  output->GetPointData()->AddArray(elevation);
  output->GetPointData()->SetScalars(elevation);
  if (anyGhost)
  {
    output->GetPointData()->AddArray(ghosts);
  }
  addGeoreference(output->GetFieldData(), info, wholeTransform.pieceOf(extent[0], extent[2], extent[3], wholeNy), nx, ny);
  if (farStride > 1)
  {
    auto strideArray = vtkSmartPointer<vtkIntArray>::New();
    strideArray->SetName(vtkTerraLuxFieldData::FarTerrainStrideName());
    strideArray->InsertNextValue(farStride);
    output->GetFieldData()->AddArray(strideArray);
  }
  return true;
}
