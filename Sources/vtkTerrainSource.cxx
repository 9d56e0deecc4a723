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

vtkStandardNewMacro(vtkTerrainSource);

using namespace TerrainSourceHeights;

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
