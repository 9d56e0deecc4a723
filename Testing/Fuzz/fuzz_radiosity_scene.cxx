// Fuzz target: a polydata (or a 2-D structured grid) built from fuzzed points, cells and
// cell arrays, lit by a uniform sky and a sun, into vtkHierarchicalRadiosity. It must
// fail with an error or give finite values everywhere; never crash or hang.
#include "fuzz_support.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  terralux_fuzz::silenceVtk();
  terralux_fuzz::ByteReader reader(data, size);
  const int flags = reader.between(0, 255);
  const int pointCount = reader.between(0, 40);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k < pointCount; ++k)
  {
    const double x = reader.number(20.0), y = reader.number(20.0), z = reader.number(5.0);
    points->InsertNextPoint(x, y, z);
  }
  vtkSmartPointer<vtkDataSet> scene;
  if (flags & 1)
  {
    // A structured grid whose dimensions may not match its points.
    auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
    grid->SetDimensions(reader.between(0, 8), reader.between(0, 8), reader.between(0, 2));
    grid->SetPoints(points);
    scene = grid;
  }
  else
  {
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    vtkNew<vtkCellArray> polys, strips;
    const int cellCount = reader.between(0, 24);
    for (int c = 0; c < cellCount; ++c)
    {
      const int n = reader.between(0, 9);
      std::vector<vtkIdType> ids(n);
      for (vtkIdType& id : ids)
        id = reader.between(-2, pointCount + 2) ; // out of range now and then
      ((flags & 2) && c % 3 == 0 ? strips : polys)->InsertNextCell(n, ids.data());
    }
    polyData->SetPolys(polys);
    polyData->SetStrips(strips);
    scene = polyData;
  }
  if (flags & 4)
  {
    vtkNew<vtkDoubleArray> emission;
    emission->SetName("Emission");
    emission->SetNumberOfComponents(flags & 8 ? 3 : 1);
    const vtkIdType tuples = scene->GetNumberOfCells() + (flags & 16 ? 1 : 0);
    emission->SetNumberOfTuples(tuples);
    for (vtkIdType k = 0; k < emission->GetNumberOfValues(); ++k)
      emission->SetValue(k, reader.number(500.0));
    scene->GetCellData()->AddArray(emission);
  }
  vtkNew<vtkSkySource> sky;
  sky->UseSunSourceOff();
  sky->SetSkyModelToUniform();
  sky->SetLevels(3);
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2024-06-21T10:00:00+02:00");
  sun->SetLatitude(46.0);
  sun->SetIrradianceModelToUser();
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(scene);
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  if (flags & 32)
    radiosity->AddLightConnection(sun->GetOutputPort());
  if (flags & 4)
    radiosity->SetEmissionArrayName("Emission");
  radiosity->SetDefaultReflectance(flags & 64 ? 0.9 : 0.3);
  radiosity->SetEvaluateAtPoints(flags & 128 ? 1 : 0);
  radiosity->SetUseTerrainHierarchy(flags & 2 ? 1 : 0);
  radiosity->SetErrorTolerance(1e-2);
  radiosity->SetMaximumNumberOfElements(5000);
  radiosity->SetVisibilitySamples(2);
  radiosity->SetMaximumIterations(8);
  radiosity->Update();
  terralux_fuzz::requireFiniteOutput(vtkDataSet::SafeDownCast(radiosity->GetOutput()),
    "vtkHierarchicalRadiosity gave a non-finite value");
  terralux_fuzz::requireFiniteOutput(radiosity->GetLeafMeshOutput(), "the leaf mesh holds a non-finite value");
  return 0;
}
