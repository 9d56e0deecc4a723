#include "vtkRadiosityFilter.h"

#include "vtkCompositeDataSet.h"
#include "vtkCompositeDataIterator.h"
#include "vtkDataObjectTree.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRadiosityOutputs.h"
#include "vtkRadiosityFilterInternals.h"
#include "vtkRadiosityScene.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredGrid.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkTerrainPieces.h"
#include "vtkTerrainSource.h"

#include "base/error.h"
#include "base/finite_parameters.h"
#include "visibility/scene_geometry.h"
#include "solver/solver.h"
#include "visibility/visibility.h"
#include "parallel/terrain_window.h"
#include "parallel/work_split.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

namespace
{
// The leaf data sets of port 0, in connection order, composites flattened.
std::vector<vtkDataSet*> inputDataSets(vtkInformationVector* port)
{
  std::vector<vtkDataSet*> result;
  for (int k = 0; k < port->GetNumberOfInformationObjects(); ++k)
  {
    const std::vector<vtkDataSet*> dataSets =
      vtkRadiosityScene::DataSetsOf(port->GetInformationObject(k)->Get(vtkDataObject::DATA_OBJECT()));
    result.insert(result.end(), dataSets.begin(), dataSets.end());
  }
  return result;
}

} // namespace

//------------------------------------------------------------------------------
vtkRadiosityFilter::vtkRadiosityFilter(int inputPorts, int farTerrainPort)
  : FarTerrainPort(farTerrainPort)
  , ReuseGeometry(1)
  , ErrorTolerance(1e-2)
  , MinimumElementArea(0.0)
  , VisibilitySamples(4)
  , MaximumGatherRays(4096)
  , TargetError(0.008)
  , TargetErrorFloor(-1.0)
  , RandomSeed(0)
  , DetailDistance(0.0)
  , FarTerrainStride(1)
  , MaximumIterations(30)
  , ConvergenceTolerance(1e-3)
  , MaximumNumberOfElements(1000000)
  , DefaultReflectance(0.2)
  , UseTerrainHierarchy(1)
  , SkyFromHorizons(1)
  , EvaluateAtPoints(1)
  , NumberOfBands(1)
  , PostNormals(AREA_WEIGHTED_NORMALS)
{
  this->SetNumberOfInputPorts(inputPorts);
  this->SetNumberOfOutputPorts(3);
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::SetFarTerrainConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(this->FarTerrainPort, output);
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::SetFarTerrainData(vtkStructuredGrid* far)
{
  this->SetInputDataObject(this->FarTerrainPort, far);
}

//------------------------------------------------------------------------------
bool vtkRadiosityFilter::UsesFarTerrainInput(vtkInformationVector** inputVector)
{
  return this->DetailDistance > 0.0 && inputVector[this->FarTerrainPort]->GetNumberOfInformationObjects() == 1;
}

//------------------------------------------------------------------------------
vtkRadiosityFilter::~vtkRadiosityFilter()
{
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == this->FarTerrainPort)
  {
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkStructuredGrid");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  if (port != 0)
    return 0; // a subclass's own port
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkStructuredGrid");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkDataObject" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkRadiosityFilter::GetLeafMeshOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkPolyData* vtkRadiosityFilter::GetLinksOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::SetCellArrayToProcess(int index, const char* name)
{
  // Unchanged (the same name, already a cell array): not Modified.
  vtkInformation* info = this->GetInputArrayInformation(index);
  const char* current = info->Get(vtkDataObject::FIELD_NAME());
  const std::string wanted = name ? name : "";
  if (wanted == (current ? current : "") && info->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
    info->Get(vtkDataObject::FIELD_ASSOCIATION()) == vtkDataObject::FIELD_ASSOCIATION_CELLS)
    return;
  this->SetInputArrayToProcess(index, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, wanted.c_str());
}

//------------------------------------------------------------------------------
const char* vtkRadiosityFilter::CellArrayToProcess(int index)
{
  vtkInformation* info = this->GetInputArrayInformation(index);
  const char* name = info->Get(vtkDataObject::FIELD_NAME());
  // "None": what ParaView's array list passes when none is chosen.
  if (!name || !*name || std::string(name) == NoArrayName)
    return nullptr;
  return name;
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::CheckCellArraysToProcess()
{
  for (int index : { ReflectanceArray, EmissionArray })
  {
    vtkInformation* info = this->GetInputArrayInformation(index);
    if (this->CellArrayToProcess(index) && info->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
      info->Get(vtkDataObject::FIELD_ASSOCIATION()) != vtkDataObject::FIELD_ASSOCIATION_CELLS)
      throw terralux::Error(std::string("the ") + (index == ReflectanceArray ? "reflectance" : "emission") +
        " array '" + this->CellArrayToProcess(index) + "' must be a cell array: call SetInputArrayToProcess(" +
        std::to_string(index) + ", 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, name)");
  }
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // A terrain's piece (an MPI rank's, a stream's) is a sub-extent of output 0.
  vtkInformation* info = outputVector->GetInformationObject(0);
  if (inputVector[0]->GetNumberOfInformationObjects() == 1 &&
    info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    info->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The whole scene and whole sky are needed whatever piece is asked of output 0:
  // every piece solves the same scene (the same hierarchy, deterministically) and
  // evaluates its own posts.
  vtkTerraLuxFieldData::RequestWholeInputs(inputVector, this->GetNumberOfInputPorts());
  // With a far terrain, a terrain's piece needs the full resolution only within its
  // halo (TerrainWindow): the piece grown by it, from a multiple of the lattice's cell
  // (the window's lattice is the whole grid's), is what is asked for.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo =
    inputVector[0]->GetNumberOfInformationObjects() == 1 ? inputVector[0]->GetInformationObject(0) : nullptr;
  if (!this->UsesFarTerrainInput(inputVector) || !inInfo || !inInfo->Has(vtkTerrainSource::POST_SPACING()) ||
    !inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()) ||
    !outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
    return 1;
  const int halo = terralux::TerrainWindow::haloPosts(this->DetailDistance, inInfo->Get(vtkTerrainSource::POST_SPACING()));
  if (halo < 0)
    return 1;
  int whole[6], piece[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  vtkTerrainPieces::RequestedPiece(outInfo, piece);
  if (piece[1] < piece[0] || piece[3] < piece[2])
    return 1;
  const terralux::TerrainWindow::Extent asked = terralux::TerrainWindow::requested(
    { whole[0], whole[1], whole[2], whole[3] }, { piece[0], piece[1], piece[2], piece[3] }, halo);
  int window[6] = { asked.i0, asked.i1, asked.j0, asked.j1, whole[4], whole[5] };
  // Not EXACT_EXTENT: the pipeline would crop a larger grid it holds (from another
  // consumer's request) without its georeference; a larger window serves as well.
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), window, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // One input: output 0 has its type (a composite keeps its structure); several: a
  // multiblock with a block per input.
  vtkDataObject* first = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? inputVector[0]->GetInformationObject(0)->Get(vtkDataObject::DATA_OBJECT())
    : nullptr;
  vtkSmartPointer<vtkDataObject> wanted;
  if (first && (first->IsA("vtkPolyData") || first->IsA("vtkStructuredGrid") || first->IsA("vtkDataObjectTree")))
  {
    wanted.TakeReference(first->NewInstance());
  }
  else
  {
    wanted = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  }
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* current = info->Get(vtkDataObject::DATA_OBJECT());
  if (!current || strcmp(current->GetClassName(), wanted->GetClassName()) != 0)
  {
    info->Set(vtkDataObject::DATA_OBJECT(), wanted);
  }
  for (int port = 1; port < 3; ++port)
  {
    vtkInformation* portInfo = outputVector->GetInformationObject(port);
    if (!vtkPolyData::SafeDownCast(portInfo->Get(vtkDataObject::DATA_OBJECT())))
    {
      portInfo->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkRadiosityFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkPolyData* leafMesh = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* links = vtkPolyData::GetData(outputVector, 2);
  auto clearOutputs = [&]() {
    output->Initialize();
    leafMesh->Initialize();
    links->Initialize();
  };
  clearOutputs();
  // Pieces: a terrain's piece is the sub-extent asked of output 0; other geometry is
  // not split, piece 0 carries it and the leaf mesh and links, the others are empty.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  const int piece = pieces > 1 ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) : 0;
  int extent[6];
  const bool terrainPiece = pieces > 1 && vtkStructuredGrid::SafeDownCast(output) &&
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT());
  if (terrainPiece)
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  else if (piece > 0)
  {
    return 1;
  }
  try
  {
    PieceRequest request{ terrainPiece ? extent : nullptr, piece == 0, piece, pieces };
    const int status = this->Solve(inputVector, request, output, leafMesh, links);
    if (status == 0)
      clearOutputs();
    return status;
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory: raise ErrorTolerance or MinimumElementArea, lower "
                  "MaximumNumberOfElements, or give fewer posts (vtkTerrainSource's Stride).");
  }
  catch (const std::exception& error)
  {
    vtkErrorMacro("Radiosity failed: " << error.what());
  }
  clearOutputs();
  return 0;
}

//------------------------------------------------------------------------------
double vtkRadiosityFilter::GetEffectiveTargetErrorFloor()
{
  return this->TargetErrorFloor >= 0.0 ? this->TargetErrorFloor : FloorPerTargetError * this->TargetError;
}

//------------------------------------------------------------------------------
std::unique_ptr<vtkRadiosityScene> vtkRadiosityFilter::BuildScene(vtkInformationVector** inputVector)
{
  terralux::requireFiniteParameters({ { "ErrorTolerance", this->ErrorTolerance },
    { "MinimumElementArea", this->MinimumElementArea }, { "ConvergenceTolerance", this->ConvergenceTolerance },
    { "DefaultReflectance", this->DefaultReflectance }, { "TargetError", this->TargetError },
    { "TargetErrorFloor", this->TargetErrorFloor },
    { "DetailDistance", this->DetailDistance } });
  this->CheckCellArraysToProcess();
  auto scene = std::make_unique<vtkRadiosityScene>();
  // A far terrain first: the terrain's posts take its origin, the same on every rank.
  const bool far = this->UsesFarTerrainInput(inputVector);
  if (far)
  {
    vtkStructuredGrid* grid = vtkStructuredGrid::GetData(inputVector[this->FarTerrainPort], 0);
    vtkDataArray* stride = grid ? grid->GetFieldData()->GetArray(vtkTerraLuxFieldData::FarTerrainStrideName()) : nullptr;
    if (!grid || !stride || stride->GetNumberOfTuples() != 1 || !(stride->GetTuple1(0) >= 2))
      throw terralux::Error("the far terrain must be vtkTerrainSource's output port 1 (a structured grid with "
                            "field data FarTerrainStride >= 2): SetFarTerrainConnection(source.GetOutputPort(1))");
    scene->SetFarTerrain(grid, static_cast<int>(stride->GetTuple1(0)), this->DefaultReflectance,
      this->CellArrayToProcess(ReflectanceArray), this->CellArrayToProcess(EmissionArray));
  }
  else if (this->DetailDistance <= 0.0 && inputVector[this->FarTerrainPort]->GetNumberOfInformationObjects() > 0)
  {
    vtkWarningMacro("The far terrain is ignored: it needs a DetailDistance > 0, beyond which rays see it.");
  }
  for (vtkDataSet* input : inputDataSets(inputVector[0]))
    scene->AddDataSet(input, this->DefaultReflectance, this->CellArrayToProcess(ReflectanceArray),
      this->CellArrayToProcess(EmissionArray), this->UseTerrainHierarchy != 0);
  if (far)
  {
    // The window's first post in the whole grid: its extent from the whole extent's.
    vtkInformation* info = inputVector[0]->GetInformationObject(0);
    auto* terrain = vtkStructuredGrid::SafeDownCast(info->Get(vtkDataObject::DATA_OBJECT()));
    int extent[6] = { 0, 0, 0, 0, 0, 0 }, whole[6] = { 0, 0, 0, 0, 0, 0 };
    if (terrain)
      terrain->GetExtent(extent);
    if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    scene->FindWindowInFarTerrain(extent[0] - whole[0], extent[2] - whole[2]);
  }
  if (!this->AddLights(inputVector, *scene) && !scene->HasEmission)
    throw terralux::Error("no light source: connect a vtkSunSource or vtkSkySource with "
                          "AddLightConnection(), or give an EmissionArrayName");
  return scene;
}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::FinishOutputs(vtkDataObject*, vtkPolyData*) {}

//------------------------------------------------------------------------------
void vtkRadiosityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorTolerance: " << this->ErrorTolerance << "\n";
  os << indent << "MinimumElementArea: " << this->MinimumElementArea << "\n";
  os << indent << "VisibilitySamples: " << this->VisibilitySamples << "\n";
  os << indent << "MaximumGatherRays: " << this->MaximumGatherRays << "\n";
  os << indent << "TargetError: " << this->TargetError << "\n";
  os << indent << "TargetErrorFloor: " << this->TargetErrorFloor << "\n";
  os << indent << "EffectiveTargetErrorFloor: " << this->GetEffectiveTargetErrorFloor() << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "DetailDistance: " << this->DetailDistance << "\n";
  os << indent << "FarTerrainStride: " << this->FarTerrainStride << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "MaximumNumberOfElements: " << this->MaximumNumberOfElements << "\n";
  os << indent << "DefaultReflectance: " << this->DefaultReflectance << "\n";
  const char* reflectance = this->GetReflectanceArrayName();
  const char* emission = this->GetEmissionArrayName();
  os << indent << "ReflectanceArrayName: " << (reflectance ? reflectance : "(none)") << "\n";
  os << indent << "EmissionArrayName: " << (emission ? emission : "(none)") << "\n";
  os << indent << "EvaluateAtPoints: " << (this->EvaluateAtPoints ? "On" : "Off") << "\n";
  os << indent << "NumberOfBands: " << this->NumberOfBands << "\n";
  os << indent << "PostNormals: " << (this->PostNormals == HORN_NORMALS ? "Horn" : "AreaWeighted") << "\n";
  os << indent << "UseTerrainHierarchy: " << (this->UseTerrainHierarchy ? "On" : "Off") << "\n";
  os << indent << "SkyFromHorizons: " << (this->SkyFromHorizons ? "On" : "Off") << "\n";
  os << indent << "ReuseGeometry: " << (this->ReuseGeometry ? "On" : "Off") << "\n";
}
