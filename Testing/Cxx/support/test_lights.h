#pragma once
// Test support: light sources and small polydata the adapter tests share.

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSkySource.h"
#include "vtkSmartPointer.h"

#include <array>

namespace terralux_test
{
/// A uniform sky of the given diffuse horizontal irradiance (W/m^2), 32 x 32 cells.
inline vtkSmartPointer<vtkSkySource> uniformSky(double diffuse)
{
  auto sky = vtkSmartPointer<vtkSkySource>::New();
  sky->UseSunSourceOff();
  sky->SetSkyModelToUniform();
  sky->SetDiffuseHorizontalIrradiance(diffuse);
  sky->SetLevels(5);
  return sky;
}

/// One triangle cell over the given points, with the given point ids (which may be
/// wrong on purpose).
inline vtkSmartPointer<vtkPolyData> triangle(const std::array<std::array<double, 3>, 3>& corners,
  const std::array<vtkIdType, 3>& ids = { 0, 1, 2 })
{
  vtkNew<vtkPoints> points;
  for (const auto& c : corners)
    points->InsertNextPoint(c[0], c[1], c[2]);
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(3, ids.data());
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  return data;
}
} // namespace terralux_test
