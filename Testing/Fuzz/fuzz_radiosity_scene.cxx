// Fuzz target: a polydata (or a 2-D structured grid) built from fuzzed points, cells and
// cell arrays, lit by a uniform sky and a sun, into vtkHierarchicalRadiosity. It must
// fail with an error or give finite values everywhere; never crash or hang.
#include "fuzz_support.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkIdList.h"
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
  if (std::getenv("TERRALUX_FUZZ_PRINT")) // to reproduce a finding elsewhere
  {
    std::fprintf(stderr, "flags %d\n", flags);
    if (auto* grid = vtkStructuredGrid::SafeDownCast(scene))
    {
      int dims[3];
      grid->GetDimensions(dims);
      std::fprintf(stderr, "dimensions %d %d %d\n", dims[0], dims[1], dims[2]);
    }
    for (vtkIdType k = 0; k < scene->GetNumberOfPoints(); ++k)
    {
      double p[3];
      scene->GetPoint(k, p);
      std::fprintf(stderr, "point %lld %.17g %.17g %.17g\n", static_cast<long long>(k), p[0], p[1], p[2]);
    }
    if (auto* polyData = vtkPolyData::SafeDownCast(scene))
    {
      vtkNew<vtkIdList> ids;
      for (vtkCellArray* cells : { polyData->GetPolys(), polyData->GetStrips() })
        for (cells->InitTraversal(); cells->GetNextCell(ids);)
        {
          std::fprintf(stderr, "%s:", cells == polyData->GetPolys() ? "polygon" : "strip");
          for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
            std::fprintf(stderr, " %lld", static_cast<long long>(ids->GetId(k)));
          std::fprintf(stderr, "\n");
        }
    }
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
  // Points on no polygon of some area have no value by design (NaN, documented):
  // only points of polygons (or of a grid cell's two triangles) of some area are checked.
  auto* output = vtkDataSet::SafeDownCast(radiosity->GetOutput());
  std::vector<bool> onSurface(output ? output->GetNumberOfPoints() : 0, false);
  auto markIfNotDegenerate = [&](vtkIdType n, const vtkIdType* ids) {
    double area[3] = { 0, 0, 0 }, low[3] = { 1e300, 1e300, 1e300 }, high[3] = { -1e300, -1e300, -1e300 };
    for (vtkIdType k = 0; k < n; ++k)
    {
      double a[3], b[3];
      output->GetPoint(ids[k], a);
      output->GetPoint(ids[(k + 1) % n], b);
      area[0] += a[1] * b[2] - a[2] * b[1];
      area[1] += a[2] * b[0] - a[0] * b[2];
      area[2] += a[0] * b[1] - a[1] * b[0];
      for (int d = 0; d < 3; ++d)
      {
        low[d] = std::min(low[d], a[d]);
        high[d] = std::max(high[d], a[d]);
      }
    }
    const double size2 = (high[0] - low[0]) * (high[0] - low[0]) + (high[1] - low[1]) * (high[1] - low[1]) +
      (high[2] - low[2]) * (high[2] - low[2]);
    const double twiceArea = std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
    if (std::isfinite(size2) && twiceArea > 1e-3 * size2)
      for (vtkIdType k = 0; k < n; ++k)
        onSurface[ids[k]] = true;
  };
  if (auto* polyData = vtkPolyData::SafeDownCast(output))
  {
    vtkNew<vtkIdList> ids;
    vtkCellArray* polys = polyData->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(ids);)
      if (ids->GetNumberOfIds() >= 3)
        markIfNotDegenerate(ids->GetNumberOfIds(), ids->GetPointer(0));
  }
  else if (auto* grid = vtkStructuredGrid::SafeDownCast(output))
  {
    int dims[3];
    grid->GetDimensions(dims);
    for (int j = 0; j + 1 < dims[1]; ++j)
      for (int i = 0; i + 1 < dims[0]; ++i)
      {
        const vtkIdType p00 = i + static_cast<vtkIdType>(j) * dims[0], p10 = p00 + 1, p01 = p00 + dims[0];
        const vtkIdType a[3] = { p00, p10, p01 }, b[3] = { p01 + 1, p01, p10 };
        markIfNotDegenerate(3, a);
        markIfNotDegenerate(3, b);
      }
  }
  terralux_fuzz::requireFiniteOutput(output, "vtkHierarchicalRadiosity gave a non-finite value", &onSurface);
  terralux_fuzz::requireFiniteOutput(radiosity->GetLeafMeshOutput(), "the leaf mesh holds a non-finite value");
  return 0;
}
