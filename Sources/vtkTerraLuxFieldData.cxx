#include "vtkTerraLuxFieldData.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkNew.h"

#include <cmath>

void vtkTerraLuxFieldData::AddVector(
  vtkFieldData* fieldData, const char* name, const double* values, int count)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(count);
  for (int k = 0; k < count; ++k)
  {
    array->SetValue(k, values[k]);
  }
  fieldData->AddArray(array);
}

void vtkTerraLuxFieldData::AddTuple(
  vtkFieldData* fieldData, const char* name, const double* values, int components)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->InsertNextTuple(values);
  fieldData->AddArray(array);
}

bool vtkTerraLuxFieldData::GetVector(vtkDataObject* data, const char* name, double* values, int count)
{
  vtkFieldData* fieldData = data ? data->GetFieldData() : nullptr;
  vtkDataArray* array = fieldData ? fieldData->GetArray(name) : nullptr;
  if (!array || array->GetNumberOfValues() != count)
  {
    return false;
  }
  for (int k = 0; k < count; ++k)
  {
    values[k] = array->GetComponent(k / array->GetNumberOfComponents(), k % array->GetNumberOfComponents());
    if (!std::isfinite(values[k]))
    {
      return false;
    }
  }
  return true;
}

void vtkTerraLuxFieldData::RequestWholeInputs(vtkInformationVector** inputVector, int ports)
{
  for (int port = 0; port < ports; ++port)
  {
    for (int k = 0; k < inputVector[port]->GetNumberOfInformationObjects(); ++k)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(k);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
      if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      {
        info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
          info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
    }
  }
}
