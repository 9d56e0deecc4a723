#pragma once
// What the sun and sky source tests share.

#include "test_rasters.h"
#include "vtk_test_support.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSkySource.h"
#include "vtkStringArray.h"
#include "vtkSunSource.h"
#include "vtkTerrainSource.h"

#include <gtest/gtest.h>

#include <cmath>

namespace terralux_test
{

inline double field(vtkDataObject* data, const char* name, int k = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  // Value k, whether the array holds tuples of one value or one tuple of several.
  return array ? array->GetComponent(k / array->GetNumberOfComponents(), k % array->GetNumberOfComponents()) : NAN;
}
} // namespace terralux_test
