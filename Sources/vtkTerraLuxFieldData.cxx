#include "vtkTerraLuxFieldData.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
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
