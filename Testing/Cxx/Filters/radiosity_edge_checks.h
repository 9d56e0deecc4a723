#pragma once
// What the radiosity filter's edge-case and bad-input tests share.

#include "test_lights.h"
#include "vtk_test_support.h"

#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace terralux_test
{

inline vtkSmartPointer<vtkPolyData> square(double size, int resolution = 1, double z = 0.0)
{
  vtkNew<vtkPlaneSource> source;
  source->SetOrigin(-0.5 * size, -0.5 * size, z);
  source->SetPoint1(0.5 * size, -0.5 * size, z);
  source->SetPoint2(-0.5 * size, 0.5 * size, z);
  source->SetResolution(resolution, resolution);
  source->Update();
  return source->GetOutput();
}

inline vtkSmartPointer<vtkSunSource> userSun(double normalIrradiance, const char* dateTime)
{
  auto sun = vtkSmartPointer<vtkSunSource>::New();
  sun->SetDateTime(dateTime);
  sun->SetLatitude(46.0);
  sun->SetLongitude(8.0);
  sun->SetIrradianceModelToUser();
  sun->SetUserNormalIrradiance(normalIrradiance);
  sun->SetUserDiffuseHorizontalIrradiance(0.0);
  return sun;
}

inline double meanOf(vtkDataSet* data, const char* name, int component = 0)
{
  vtkDataArray* array = data->GetPointData()->GetArray(name);
  double sum = 0.0;
  for (vtkIdType k = 0; k < array->GetNumberOfTuples(); ++k)
    sum += array->GetComponent(k, component);
  return sum / array->GetNumberOfTuples();
}
} // namespace terralux_test
