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
#include "vtkTerrainHeights.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>
#include <limits>
#include <memory>

vtkStandardNewMacro(vtkTerrainSource);

// What RequestInformation and RequestData agree to read.
struct vtkTerrainSource::RasterRequest
{
  std::unique_ptr<terralux::DemRaster> raster;
  terralux::PixelWindow window;
  int nx = 0;
  int ny = 0;
  bool clipped = false; // the PixelWindow reached beyond the raster
};

using namespace vtkTerrainHeights;

//------------------------------------------------------------------------------
vtkTerrainSource::vtkTerrainSource()
  : FileName(nullptr)
  , Band(1)
  , PixelWindow{ 0, 0, 0, 0 }
  , GeoBounds{ 0.0, 0.0, 0.0, 0.0 }
  , UseGeoBounds(0)
  , Stride(1)
  , FarTerrainStride(4)
  , GeoOrigin{ 0.0, 0.0, 0.0 }
  , UseGeoOrigin(0)
  , OutputPointsPrecision(SINGLE_PRECISION)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
}

vtkInformationKeyMacro(vtkTerrainSource, POST_SPACING, Double);

//------------------------------------------------------------------------------
vtkTerrainSource::~vtkTerrainSource()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkTerrainSource::SetGeoOrigin(double latitude, double longitude, double height)
{
  if (this->GeoOrigin[0] != latitude || this->GeoOrigin[1] != longitude ||
    this->GeoOrigin[2] != height || !this->UseGeoOrigin)
  {
    this->GeoOrigin[0] = latitude;
    this->GeoOrigin[1] = longitude;
    this->GeoOrigin[2] = height;
    this->UseGeoOrigin = 1;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkTerrainSource::SetGeoOrigin(const double origin[3])
{
  this->SetGeoOrigin(origin[0], origin[1], origin[2]);
}

//------------------------------------------------------------------------------
void vtkTerrainSource::SetGeoBounds(double south, double north, double west, double east)
{
  const double bounds[4] = { south, north, west, east };
  if (!std::equal(bounds, bounds + 4, this->GeoBounds) || !this->UseGeoBounds)
  {
    std::copy(bounds, bounds + 4, this->GeoBounds);
    this->UseGeoBounds = 1;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkTerrainSource::SetGeoBounds(const double bounds[4])
{
  this->SetGeoBounds(bounds[0], bounds[1], bounds[2], bounds[3]);
}

//------------------------------------------------------------------------------
int vtkTerrainSource::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTerrainSource::ResolveRasterRequest(RasterRequest& request)
{
  request.raster = std::make_unique<terralux::DemRaster>(this->FileName ? this->FileName : "", this->Band);
  const terralux::RasterInfo& info = request.raster->info();
  const bool useWindow = this->PixelWindow[2] > 0 && this->PixelWindow[3] > 0;
  const bool useBounds = this->UseGeoBounds != 0;
  std::ostringstream message;

  if (useWindow && useBounds)
  {
    throw terralux::Error("both PixelWindow and GeoBounds are set: use one of them "
                          "(SetPixelWindow(0, 0, 0, 0) or UseGeoBoundsOff() clears it)");
  }
  const double* b = this->GeoBounds;
  if (!std::all_of(b, b + 4, [](double v) { return std::isfinite(v); }))
  {
    message << "GeoBounds (" << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3]
            << ") is not a geographic box: give finite south < north and west < east, in degrees";
    throw terralux::Error(message.str());
  }
  if (useBounds)
  {
    if (info.crsWkt.empty())
    {
      throw terralux::Error(std::string("GeoBounds needs a georeferenced raster, but '") +
        this->FileName + "' has no CRS: use SetPixelWindow() instead");
    }
    terralux::MapProjection projection(info.crsWkt);
    request.window = terralux::windowOfGeographicBox(*request.raster, projection, b[0], b[1], b[2], b[3]);
    if (request.window.isEmpty())
    {
      message << "GeoBounds (" << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3]
              << ") does not overlap the raster '" << this->FileName << "' (an empty window)";
      throw terralux::Error(message.str());
    }
  }
  else if (useWindow)
  {
    const int* w = this->PixelWindow;
    const int col0 = std::max(0, w[0]);
    const int row0 = std::max(0, w[1]);
    const long long col1 = std::min<long long>(info.width, static_cast<long long>(w[0]) + w[2]);
    const long long row1 = std::min<long long>(info.height, static_cast<long long>(w[1]) + w[3]);
    if (col1 <= col0 || row1 <= row0)
    {
      message << "PixelWindow (" << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3]
              << ") does not overlap the " << info.width << " x " << info.height << " raster '"
              << this->FileName << "' (an empty window)";
      throw terralux::Error(message.str());
    }
    request.window = { col0, row0, static_cast<int>(col1 - col0), static_cast<int>(row1 - row0) };
    request.clipped = request.window.col0 != w[0] || request.window.row0 != w[1] ||
      request.window.width != w[2] || request.window.height != w[3];
  }
  else
  {
    request.window = request.raster->fullWindow();
  }
  request.nx = terralux::PixelWindow::postCount(request.window.width, this->Stride);
  request.ny = terralux::PixelWindow::postCount(request.window.height, this->Stride);
}

//------------------------------------------------------------------------------
int vtkTerrainSource::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* farInfo = outputVector->GetInformationObject(1);
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  int farExtent[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Remove(POST_SPACING());
  vtkInformation* inInfo =
    this->GetNumberOfInputPorts() > 0 ? inputVector[0]->GetInformationObject(0) : nullptr;
  if (inInfo)
  {
    int inputExtent[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), inputExtent);
    extent[1] = inputExtent[1] - inputExtent[0];
    extent[3] = inputExtent[3] - inputExtent[2];
    extent[5] = inputExtent[5] - inputExtent[4];
  }
  else
  {
    // Errors are reported once, by RequestData, which also empties the output.
    try
    {
      RasterRequest request;
      this->ResolveRasterRequest(request);
      extent[1] = request.nx - 1;
      extent[3] = request.ny - 1;
      extent[5] = 0;
      const int farStride = this->Stride * this->FarTerrainStride;
      farExtent[1] = terralux::PixelWindow::postCount(request.window.width, farStride) - 1;
      farExtent[3] = terralux::PixelWindow::postCount(request.window.height, farStride) - 1;
      farExtent[5] = 0;
      outInfo->Set(POST_SPACING(), this->LeastPostSpacing(request));
    }
    catch (const terralux::Error&)
    {
    }
    // Pieces (MPI ranks, streaming) read their own window of the raster.
    outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  farInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), farExtent, 6);
  return 1;
}

//------------------------------------------------------------------------------
double vtkTerrainSource::LeastPostSpacing(const RasterRequest& request)
{
  // 2 x 2 posts at the grid's corners and centre, placed at height 0 in a frame at the
  // centre: on a map projection or a geographic grid cells change size smoothly, the
  // narrowest at an edge (toward a pole, or off a projection's central meridian).
  const terralux::RasterInfo& info = request.raster->info();
  const terralux::GeoTransform transform =
    info.geoTransform.window(request.window.col0, request.window.row0, this->Stride);
  const int nx = request.nx, ny = request.ny;
  if (nx < 2 || ny < 2)
    return 0.0;
  std::unique_ptr<terralux::MapProjection> projection;
  std::unique_ptr<terralux::LocalFrame> frame;
  if (!info.crsWkt.empty())
  {
    projection = std::make_unique<terralux::MapProjection>(info.crsWkt);
    frame = std::make_unique<terralux::LocalFrame>(
      terralux::geodeticOfPixel(transform, *projection, 0.5 * nx, 0.5 * ny, 0.0));
  }
  double least = std::numeric_limits<double>::infinity();
  for (const auto& corner : { std::array<int, 2>{ 0, 0 }, { nx - 2, 0 }, { 0, ny - 2 }, { nx - 2, ny - 2 },
         { (nx - 2) / 2, (ny - 2) / 2 } })
  {
    terralux::GridGeoreference cell;
    cell.nx = 2;
    cell.ny = 2;
    cell.geoTransform = transform;
    cell.col0 = corner[0];
    cell.row0 = corner[1];
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    double xyz[12];
    if (projection)
      terralux::TerrainPlacement(cell, *projection, *frame).place(zero, 0.0, xyz);
    else
      terralux::TerrainPlacement(cell, terralux::LocalPoint{ 0.0, 0.0, 0.0 }).place(zero, 0.0, xyz);
    for (const auto& [a, b] : { std::array<int, 2>{ 0, 1 }, { 2, 3 }, { 0, 2 }, { 1, 3 } })
      least = std::min(least, std::hypot(xyz[3 * a] - xyz[3 * b], xyz[3 * a + 1] - xyz[3 * b + 1]));
  }
  // A margin for what the five cells do not see.
  return std::isfinite(least) ? 0.99 * least : 0.0;
}

//------------------------------------------------------------------------------
int vtkTerrainSource::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // A height-field image is converted whole, whatever is asked of the output, whose
  // extent starts at 0 where the image's need not: ask for the image's own extent.
  vtkTerraLuxFieldData::RequestWholeInputs(inputVector, this->GetNumberOfInputPorts());
  return 1;
}

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
  points->SetNumberOfPoints(count);
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

//------------------------------------------------------------------------------
vtkTypeBool vtkTerrainSource::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Only what is asked for is read: output 1 alone (the far terrain, or a sun reading
  // its georeference there) leaves output 0 as it is, whatever piece that holds; output
  // 1 is read with output 0 only where something takes it.
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_NOT_GENERATED()))
  {
    vtkInformation* farInfo = outputVector->GetInformationObject(1);
    const int from =
      request->Has(vtkExecutive::FROM_OUTPUT_PORT()) ? request->Get(vtkExecutive::FROM_OUTPUT_PORT()) : 0;
    if (from == 1)
      outputVector->GetInformationObject(0)->Set(vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
    else if (vtkExecutive::CONSUMERS()->Length(farInfo) == 0)
      farInfo->Set(vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkTerrainSource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkStructuredGrid* output = vtkStructuredGrid::GetData(outputVector, 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* farInfo = outputVector->GetInformationObject(1);
  vtkStructuredGrid* far = vtkStructuredGrid::GetData(outputVector, 1);
  if (!outInfo->Get(vtkDemandDrivenPipeline::DATA_NOT_GENERATED()))
    output->Initialize();
  if (!farInfo->Get(vtkDemandDrivenPipeline::DATA_NOT_GENERATED()))
    far->Initialize();
  vtkImageData* input = this->GetNumberOfInputPorts() > 0 ? vtkImageData::GetData(inputVector[0], 0) : nullptr;

  bool ok = false;
  try
  {
    if (input)
    {
      // A height-field image has no far terrain: output 1 stays empty.
      ok = outInfo->Get(vtkDemandDrivenPipeline::DATA_NOT_GENERATED()) || this->ConvertHeightField(input, output);
    }
    else
    {
      const double* b = this->GeoBounds;
      if (!this->UseGeoBounds && (b[0] != 0.0 || b[1] != 0.0 || b[2] != 0.0 || b[3] != 0.0))
        vtkWarningMacro("GeoBounds is set but UseGeoBounds is off: the whole raster is read. "
                        "Call UseGeoBoundsOn() to read the box only.");
      // The piece asked for (UPDATE_EXTENT, ghost posts included) and the same piece
      // without ghost levels, which its posts beyond are marked against.
      int whole[6], extent[6], pieceExtent[6];
      outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
      std::copy(whole, whole + 6, extent);
      std::copy(whole, whole + 6, pieceExtent);
      if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
      {
        outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
      }
      const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
        ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
        : 1;
      if (pieces > 1 && !std::equal(extent, extent + 6, whole))
      {
        vtkNew<vtkExtentTranslator> translator;
        translator->PieceToExtentThreadSafe(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()),
          pieces, 0, whole, pieceExtent, vtkExtentTranslator::BLOCK_MODE, 0);
      }
      else
      {
        std::copy(extent, extent + 6, pieceExtent);
      }
      // Each output only where it is generated (see ProcessRequest).
      ok = outInfo->Get(vtkDemandDrivenPipeline::DATA_NOT_GENERATED()) ||
        this->ReadRaster(extent, pieceExtent, output);
      if (ok && !farInfo->Get(vtkDemandDrivenPipeline::DATA_NOT_GENERATED()))
      {
        int farWhole[6];
        farInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), farWhole);
        ok = this->ReadRaster(farWhole, farWhole, far, this->FarTerrainStride);
      }
    }
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
    ok = false;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory reading the DEM: use SetStride(), SetPixelWindow() or "
                  "GeoBounds (with UseGeoBoundsOn()) to read fewer posts.");
    ok = false;
  }
  if (!ok)
  {
    output->Initialize();
    far->Initialize();
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTerrainSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Band: " << this->Band << "\n";
  os << indent << "PixelWindow: (" << this->PixelWindow[0] << ", " << this->PixelWindow[1] << ", "
     << this->PixelWindow[2] << ", " << this->PixelWindow[3] << ")\n";
  os << indent << "UseGeoBounds: " << this->UseGeoBounds << "\n";
  os << indent << "GeoBounds: (" << this->GeoBounds[0] << ", " << this->GeoBounds[1] << ", "
     << this->GeoBounds[2] << ", " << this->GeoBounds[3] << ")\n";
  os << indent << "Stride: " << this->Stride << "\n";
  os << indent << "FarTerrainStride: " << this->FarTerrainStride << "\n";
  os << indent << "GeoOrigin: (" << this->GeoOrigin[0] << ", " << this->GeoOrigin[1] << ", "
     << this->GeoOrigin[2] << ")\n";
  os << indent << "UseGeoOrigin: " << (this->UseGeoOrigin ? "On" : "Off") << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
