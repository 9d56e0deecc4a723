#include "vtkHierarchicalRadiosity.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRadiosityOutputs.h"
#include "vtkRadiosityScene.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredGrid.h"

#include "error.h"
#include "solver.h"

#include <vector>

vtkStandardNewMacro(vtkHierarchicalRadiosity);

namespace
{
// The leaf data sets of port 0, in connection order, composites flattened.
std::vector<vtkDataSet*> inputDataSets(vtkInformationVector* port)
{
  std::vector<vtkDataSet*> result;
  for (int k = 0; k < port->GetNumberOfInformationObjects(); ++k)
  {
    vtkDataObject* data = port->GetInformationObject(k)->Get(vtkDataObject::DATA_OBJECT());
    if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
    {
      vtkSmartPointer<vtkDataObjectTreeIterator> it;
      it.TakeReference(vtkDataObjectTreeIterator::SafeDownCast(composite->NewIterator()));
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
        if (auto* dataSet = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
          result.push_back(dataSet);
    }
    else if (auto* dataSet = vtkDataSet::SafeDownCast(data))
    {
      result.push_back(dataSet);
    }
  }
  return result;
}

class FilterProgress : public terralux::RadiosityProgress
{
public:
  explicit FilterProgress(vtkHierarchicalRadiosity* filter)
    : Filter(filter)
  {
  }
  bool report(double fraction) override
  {
    this->Filter->UpdateProgress(0.1 + 0.8 * fraction);
    return !this->Filter->GetAbortExecute();
  }

private:
  vtkHierarchicalRadiosity* Filter;
};
} // namespace

//------------------------------------------------------------------------------
vtkHierarchicalRadiosity::vtkHierarchicalRadiosity()
  : ErrorTolerance(1e-3)
  , MinimumElementArea(0.0)
  , VisibilitySamples(4)
  , MaximumIterations(30)
  , ConvergenceTolerance(1e-3)
  , DefaultReflectance(0.2)
  , ReflectanceArrayName(nullptr)
  , EmissionArrayName(nullptr)
  , UseTerrainHierarchy(1)
  , EvaluateAtPoints(1)
  , NumberOfBands(1)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
}

//------------------------------------------------------------------------------
vtkHierarchicalRadiosity::~vtkHierarchicalRadiosity()
{
  this->SetReflectanceArrayName(nullptr);
  this->SetEmissionArrayName(nullptr);
}

//------------------------------------------------------------------------------
int vtkHierarchicalRadiosity::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkStructuredGrid");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  }
  else
  {
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHierarchicalRadiosity::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkDataObject" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkHierarchicalRadiosity::GetLeafMeshOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkPolyData* vtkHierarchicalRadiosity::GetLinksOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

//------------------------------------------------------------------------------
vtkTypeBool vtkHierarchicalRadiosity::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inputVector, outputVector);
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    // The whole scene and whole sky are needed whatever extent is asked of output 0.
    for (int port = 0; port < 2; ++port)
      for (int k = 0; k < inputVector[port]->GetNumberOfInformationObjects(); ++k)
      {
        vtkInformation* info = inputVector[port]->GetInformationObject(k);
        if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
          info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
            info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkHierarchicalRadiosity::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // One plain input: output 0 has its type; several or a composite: a multiblock.
  vtkDataObject* first = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? inputVector[0]->GetInformationObject(0)->Get(vtkDataObject::DATA_OBJECT())
    : nullptr;
  vtkSmartPointer<vtkDataObject> wanted;
  if (first && (first->IsA("vtkPolyData") || first->IsA("vtkStructuredGrid")))
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
int vtkHierarchicalRadiosity::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkPolyData* leafMesh = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* links = vtkPolyData::GetData(outputVector, 2);
  output->Initialize();
  leafMesh->Initialize();
  links->Initialize();

  vtkRadiosityScene scene;
  std::unique_ptr<terralux::HierarchicalRadiosity> solver;
  try
  {
    const std::vector<vtkDataSet*> inputs = inputDataSets(inputVector[0]);
    for (vtkDataSet* input : inputs)
    {
      scene.AddDataSet(input, this->DefaultReflectance, this->ReflectanceArrayName, this->EmissionArrayName,
        this->UseTerrainHierarchy != 0);
    }
    for (int k = 0; k < inputVector[1]->GetNumberOfInformationObjects(); ++k)
    {
      scene.AddLight(inputVector[1]->GetInformationObject(k)->Get(vtkDataObject::DATA_OBJECT()));
    }
    if (!scene.Sky && !scene.HasSun && !scene.HasEmission)
    {
      throw terralux::Error("no light source: connect a vtkSunSource or vtkSkySource with "
                            "AddLightConnection(), or give an EmissionArrayName");
    }
    terralux::RadiosityOptions options;
    options.errorTolerance = this->ErrorTolerance;
    options.minimumElementArea = this->MinimumElementArea;
    options.visibilitySamples = this->VisibilitySamples;
    options.maximumIterations = this->MaximumIterations;
    options.convergenceTolerance = this->ConvergenceTolerance;
    solver = std::make_unique<terralux::HierarchicalRadiosity>(scene.Scene, options);
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
    return 0;
  }
  if (solver->degeneratePolygons() > 0)
  {
    vtkWarningMacro("Skipped " << solver->degeneratePolygons()
                               << " degenerate polygon(s) with zero area.");
  }
  if (scene.HasSun)
  {
    solver->setSun(scene.SunDirection, scene.SunIrradiance);
  }
  solver->setSky(scene.Sky.get());
  this->UpdateProgress(0.1);
  FilterProgress progress(this);
  if (!solver->solve(&progress))
  {
    vtkWarningMacro("Aborted.");
    return 1;
  }

  // Output 0: the inputs, same points and cells, with the point arrays.
  auto addResults = [&](vtkDataSet* copy, int index) {
    vtkRadiosityOutputs::AddPointArrays(
      *solver, scene, index, this->NumberOfBands, this->EvaluateAtPoints != 0, copy);
  };
  if (auto* multiblock = vtkMultiBlockDataSet::SafeDownCast(output))
  {
    multiblock->SetNumberOfBlocks(static_cast<unsigned int>(scene.Inputs.size()));
    for (std::size_t k = 0; k < scene.Inputs.size(); ++k)
    {
      vtkSmartPointer<vtkDataSet> copy;
      copy.TakeReference(scene.Inputs[k].data->NewInstance());
      copy->ShallowCopy(scene.Inputs[k].data);
      addResults(copy, static_cast<int>(k));
      multiblock->SetBlock(static_cast<unsigned int>(k), copy);
    }
  }
  else
  {
    auto* dataSet = vtkDataSet::SafeDownCast(output);
    dataSet->ShallowCopy(scene.Inputs[0].data);
    addResults(dataSet, 0);
  }
  const terralux::RadiosityStatistics& stats = solver->statistics();
  vtkFieldData* fieldData = output->GetFieldData();
  auto addValue = [&](const char* name, double value) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(name);
    array->InsertNextValue(value);
    fieldData->AddArray(array);
  };
  addValue("Elements", static_cast<double>(stats.elements));
  addValue("Links", static_cast<double>(stats.links));
  addValue("Rays", static_cast<double>(solver->raysCast())); // the solve's and the points'
  addValue("Iterations", stats.iterations);
  addValue("DegeneratePolygons", static_cast<double>(solver->degeneratePolygons()));
  addValue("SecondsVisibilityBuild", stats.secondsVisibilityBuild);
  addValue("SecondsRefine", stats.secondsRefine);
  addValue("SecondsGather", stats.secondsGather);
  addValue("SecondsPushPull", stats.secondsPushPull);

  vtkRadiosityOutputs::BuildLeafMesh(*solver, this->NumberOfBands, scene.Sky != nullptr, leafMesh);
  vtkRadiosityOutputs::BuildLinks(*solver, links);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkHierarchicalRadiosity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorTolerance: " << this->ErrorTolerance << "\n";
  os << indent << "MinimumElementArea: " << this->MinimumElementArea << "\n";
  os << indent << "VisibilitySamples: " << this->VisibilitySamples << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "DefaultReflectance: " << this->DefaultReflectance << "\n";
  os << indent << "ReflectanceArrayName: " << (this->ReflectanceArrayName ? this->ReflectanceArrayName : "(none)") << "\n";
  os << indent << "EmissionArrayName: " << (this->EmissionArrayName ? this->EmissionArrayName : "(none)") << "\n";
  os << indent << "EvaluateAtPoints: " << (this->EvaluateAtPoints ? "On" : "Off") << "\n";
  os << indent << "NumberOfBands: " << this->NumberOfBands << "\n";
  os << indent << "UseTerrainHierarchy: " << (this->UseTerrainHierarchy ? "On" : "Off") << "\n";
}
