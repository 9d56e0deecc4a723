#include "vtkTerrainRasterWriter.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkStructuredGrid.h"
#include "vtkRadiosityOutputs.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkTerrainPieces.h"
#include "vtkUnsignedCharArray.h"

#include "base/error.h"
#include "raster/raster_writer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <limits>
#include <cstring>

vtkStandardNewMacro(vtkTerrainRasterWriter);

namespace
{

const char* const noPieceToWrite = "no rank has a terrain piece with vtkTerrainSource's georeference to write";

// The array's own units (vtkDataArray::UNITS_LABEL, as vtkSolarIrradiation sets
// them), else those of the known names.
std::string unitOf(vtkDataArray* array, const std::string& name)
{
  vtkInformation* info = array->HasInformation() ? array->GetInformation() : nullptr;
  if (info && info->Has(vtkDataArray::UNITS_LABEL()))
    return info->Get(vtkDataArray::UNITS_LABEL());
  if (name.find("Irradiance") != std::string::npos || name == "Radiosity")
    return "W/m^2";
  if (name == "Elevation")
    return "m";
  if (name == vtkRadiosityOutputs::SkyViewFactorName())
    return "1";
  return "";
}

// The GeoTIFF of a terrain grid written piece by piece: bands from the grid's point
// arrays, each piece's values into its window, so the writer holds one piece's array
// at a time, never the whole grid's bands.
class PieceRaster
{
public:
  // `fieldData`: the whole grid's (GeoTransform, RasterSize, CRS, NoDataValue), of
  // dimensions `dims`; `arrays`: its point arrays (values unused); `names`: those to
  // write (empty: what the filters compute, else every one); `uncovered`: whether some
  // post will get no piece (it is then no data).
  PieceRaster(const std::string& fileName, vtkFieldData* fieldData, const int dims[3],
    const std::vector<vtkDataArray*>& arrays, std::vector<std::string> names, double defaultNoData, bool uncovered)
  {
    vtkDataArray* geoTransform = fieldData->GetArray(vtkTerraLuxFieldData::GeoTransformName());
    vtkDataArray* rasterSize = fieldData->GetArray(vtkTerraLuxFieldData::RasterSizeName());
    if (!geoTransform || geoTransform->GetNumberOfValues() != 6 || !rasterSize ||
      rasterSize->GetNumberOfValues() != 2)
    {
      throw terralux::Error("the input has no raster georeference (field data GeoTransform and "
                            "RasterSize): write grids that come from vtkTerrainSource");
    }
    if (rasterSize->GetComponent(0, 0) != dims[0] || rasterSize->GetComponent(1, 0) != dims[1] || dims[2] != 1)
    {
      throw terralux::Error("the grid's dimensions no longer match its RasterSize field data");
    }
    this->Raster.width = dims[0];
    this->Raster.height = dims[1];
    for (int k = 0; k < 6; ++k)
      this->Raster.geoTransform.coefficients[k] = geoTransform->GetComponent(k, 0);
    if (auto* crs = vtkStringArray::SafeDownCast(fieldData->GetAbstractArray(vtkTerraLuxFieldData::CRSName())))
    {
      this->Raster.crsWkt = crs->GetNumberOfValues() > 0 ? crs->GetValue(0) : "";
    }
    vtkDataArray* noData = fieldData->GetArray(vtkTerraLuxFieldData::NoDataValueName());
    this->Raster.noData = noData ? noData->GetComponent(0, 0) : defaultNoData;
    this->Raster.hasNoData = noData != nullptr || uncovered;

    auto find = [&arrays](const std::string& name) -> vtkDataArray* {
      for (vtkDataArray* array : arrays)
        if (array->GetName() && name == array->GetName())
          return array;
      return nullptr;
    };
    if (names.empty())
    {
      for (const char* name : vtkRadiosityOutputs::AllNames()) // what the filters compute
        if (find(name))
          names.emplace_back(name);
      if (names.empty())
        for (vtkDataArray* array : arrays)
          if (array->GetName() && std::strcmp(array->GetName(), vtkDataSetAttributes::GhostArrayName()) != 0)
            names.emplace_back(array->GetName());
    }
    std::vector<terralux::RasterBand> bands;
    for (const std::string& name : names)
    {
      vtkDataArray* array = find(name);
      if (!array)
      {
        throw terralux::Error("the input has no point array '" + name + "' to write");
      }
      if (this->FirstBand.count(name))
        continue; // named twice: its bands once
      this->FirstBand[name] = static_cast<int>(bands.size());
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        terralux::RasterBand band;
        band.description = array->GetNumberOfComponents() == 1 ? name : name + "[" + std::to_string(c) + "]";
        band.unit = unitOf(array, name);
        bands.push_back(std::move(band));
      }
    }
    this->Writer = std::make_unique<terralux::GeoTiffWriter>(fileName, this->Raster, bands);
  }

  // One point array of the piece whose first post is (i0, j0) of the whole grid and
  // that has `dims` posts (nothing where the array is not written).
  void Write(int i0, int j0, const int dims[2], vtkDataArray* ghosts, vtkDataArray* array)
  {
    const auto band = this->FirstBand.find(array->GetName() ? array->GetName() : "");
    if (band == this->FirstBand.end())
      return;
    const int width = dims[0], height = dims[1];
    if (array->GetNumberOfTuples() != static_cast<vtkIdType>(width) * height)
    {
      throw terralux::Error(std::string("point array '") + array->GetName() + "' does not have one value per post");
    }
    const terralux::GeoTransform& transform = this->Raster.geoTransform;
    const int row0 = transform.firstRasterRow(j0, j0 + height - 1, this->Raster.height);
    std::vector<float> window(static_cast<std::size_t>(width) * height);
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col)
        {
          // Raster row -> grid j as vtkTerrainSource laid it (reversed for north-up).
          const vtkIdType point = col + static_cast<vtkIdType>(transform.gridRow(row, height)) * width;
          double value = array->GetComponent(point, c);
          const bool hidden = ghosts && (static_cast<int>(ghosts->GetComponent(point, 0)) & vtkDataSetAttributes::HIDDENPOINT);
          // Float32 holds magnitudes up to about 3.4e38; beyond is no data, not inf.
          if (hidden || !std::isfinite(value) || std::abs(value) > std::numeric_limits<float>::max())
          {
            value = this->Raster.noData;
            this->NoDataWritten = true;
          }
          window[static_cast<std::size_t>(row) * width + col] = static_cast<float>(value);
        }
      this->Writer->writeWindow(band->second + c, i0, row0, width, height, window.data());
    }
    this->Writer->flush(); // the array's blocks leave GDAL's cache: it holds one array's at most
  }

  void Close()
  {
    if (this->NoDataWritten && !this->Raster.hasNoData)
      this->Writer->setNoData(this->Raster.noData);
    this->Writer->close();
  }

private:
  terralux::RasterGrid Raster;
  std::map<std::string, int> FirstBand; // of each array written
  std::unique_ptr<terralux::GeoTiffWriter> Writer;
  bool NoDataWritten = false;
};
} // namespace

//------------------------------------------------------------------------------
vtkTerrainRasterWriter::vtkTerrainRasterWriter()
  : FileName(nullptr)
  , NoDataValue(-9999.0)
  , WritePieces(0)
{
}

//------------------------------------------------------------------------------
vtkTerrainRasterWriter::~vtkTerrainRasterWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkTerrainRasterWriter::AddArrayName(const char* name)
{
  if (name && *name)
  {
    this->ArrayNames.emplace_back(name);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkTerrainRasterWriter::RemoveAllArrayNames()
{
  if (!this->ArrayNames.empty())
  {
    this->ArrayNames.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkTerrainRasterWriter::FillInputPortInformation(int, vtkInformation* info)
{
  // Any data set is accepted so that a wrong one gets WriteData's message (and
  // Write() returns 0) instead of a pipeline error that Write() does not report.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkTerrainRasterWriter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Succeeded = false;
  this->SetErrorCode(vtkErrorCode::NoError);
  this->Superclass::RequestData(request, inputVector, outputVector);
  if (!this->Succeeded)
  {
    this->SetErrorCode(vtkErrorCode::UserError); // Write() returns 0
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkTerrainRasterWriter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Under MPI each rank asks for its own piece; WriteData assembles them on rank 0.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()) && controller &&
    controller->GetNumberOfProcesses() > 1)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), controller->GetLocalProcessId());
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), controller->GetNumberOfProcesses());
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkTerrainRasterWriter::WriteData()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  try
  {
    if (!this->FileName || !*this->FileName)
    {
      throw terralux::Error("no file name: call SetFileName()");
    }
    if (this->WritePieces)
    {
      this->WritePiecesAndMosaic(controller);
    }
    else if (controller && controller->GetNumberOfProcesses() > 1)
    {
      // Collective: every rank sends its piece, rank 0 writes each into its window.
      std::unique_ptr<PieceRaster> raster;
      int whole[6] = { 0, -1, 0, -1, 0, 0 };
      const bool root = vtkTerrainPieces::SendToRoot(
        controller, vtkDataSet::SafeDownCast(this->GetInput()), 0,
        [&](const vtkTerrainPieces::Layout& layout) {
          std::copy_n(layout.whole, 6, whole);
          const int dims[3] = { whole[1] - whole[0] + 1, whole[3] - whole[2] + 1, 1 };
          raster = std::make_unique<PieceRaster>(
            this->FileName, layout.fieldData, dims, layout.arrays, this->ArrayNames, this->NoDataValue, !layout.covered);
        },
        [&](const vtkTerrainPieces::PieceArray& piece) {
          const int* e = piece.extent;
          const int dims[2] = { e[1] - e[0] + 1, e[3] - e[2] + 1 };
          raster->Write(e[0] - whole[0], e[2] - whole[2], dims, piece.ghosts, piece.values);
        });
      if (controller->GetLocalProcessId() != 0)
      {
        this->Succeeded = true;
        return;
      }
      if (!root)
      {
        throw terralux::Error(noPieceToWrite);
      }
      raster->Close();
    }
    else
    {
      auto* grid = vtkStructuredGrid::SafeDownCast(this->GetInput());
      if (!grid)
      {
        throw terralux::Error("the input must be a vtkStructuredGrid from vtkTerrainSource");
      }
      this->WriteGrid(grid, this->FileName);
    }
    this->Succeeded = true;
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
  }
}

//------------------------------------------------------------------------------
void vtkTerrainRasterWriter::WritePiecesAndMosaic(vtkMultiProcessController* controller)
{
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  std::string base = this->FileName; // without its extension
  const std::size_t slash = base.find_last_of('/');
  const std::size_t dot = base.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    base.erase(dot);
  auto tileOf = [&base](int r) { return base + "_" + std::to_string(r) + ".tif"; };
  auto* grid = vtkStructuredGrid::SafeDownCast(this->GetInput());
  // A rank without posts (more ranks than rows) writes nothing. A rank's error would
  // leave rank 0 waiting, so every rank's outcome is gathered before anyone throws.
  enum Outcome : int { Nothing = 0, Wrote = 1, Failed = 2 };
  std::string problem;
  int outcome = Nothing;
  if (grid && grid->GetNumberOfPoints() > 0)
  {
    try
    {
      this->WriteGrid(grid, tileOf(rank));
      outcome = Wrote;
    }
    catch (const terralux::Error& error)
    {
      problem = error.what();
      outcome = Failed;
    }
  }
  std::vector<int> outcomes(ranks, outcome);
  if (controller && ranks > 1)
    controller->AllGather(&outcome, outcomes.data(), 1);
  if (!problem.empty())
    throw terralux::Error(problem);
  for (int r = 0; r < ranks; ++r)
    if (outcomes[r] == Failed)
      throw terralux::Error("rank " + std::to_string(r) + " could not write its piece");
  if (rank == 0)
  {
    std::vector<std::string> tiles;
    for (int r = 0; r < ranks; ++r)
      if (outcomes[r] == Wrote)
        tiles.push_back(tileOf(r));
    if (tiles.empty())
      throw terralux::Error(noPieceToWrite);
    terralux::writeVrtMosaic(this->FileName, tiles);
  }
}

//------------------------------------------------------------------------------
void vtkTerrainRasterWriter::WriteGrid(vtkStructuredGrid* grid, const std::string& fileName)
{
  int dims[3];
  grid->GetDimensions(dims);
  std::vector<vtkDataArray*> arrays;
  vtkPointData* pointData = grid->GetPointData();
  for (int k = 0; k < pointData->GetNumberOfArrays(); ++k)
    if (vtkDataArray* array = pointData->GetArray(k))
      arrays.push_back(array);
  PieceRaster raster(fileName, grid->GetFieldData(), dims, arrays, this->ArrayNames, this->NoDataValue, false);
  for (vtkDataArray* array : arrays)
    raster.Write(0, 0, dims, grid->GetPointGhostArray(), array);
  raster.Close();
}

//------------------------------------------------------------------------------
void vtkTerrainRasterWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NoDataValue: " << this->NoDataValue << "\n";
  os << indent << "WritePieces: " << this->WritePieces << "\n";
  os << indent << "ArrayNames:";
  for (const std::string& name : this->ArrayNames)
    os << " " << name;
  os << "\n";
}
