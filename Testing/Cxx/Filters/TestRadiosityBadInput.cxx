// vtkHierarchicalRadiosity refusing bad input: corrupt cells and grids, self-intersecting
// polygons, NaN parameters, emission beyond any light source, the fuzzers' findings.
// Each gives an error naming the fix with empty outputs, never a crash.
#include "radiosity_edge_checks.h"
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

using namespace terralux_test;

namespace
{
// Polygons of double-precision points (denormals kept), as a fuzzer would give them.
vtkSmartPointer<vtkPolyData> polygons(
  const std::vector<std::array<double, 3>>& corners, const std::vector<std::vector<vtkIdType>>& cells)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : corners)
    points->InsertNextPoint(p.data());
  vtkNew<vtkCellArray> polys;
  for (const auto& cell : cells)
    polys->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  return data;
}

// Runs and expects an error containing `words`, status 0 and every output empty.
void expectRefused(vtkHierarchicalRadiosity* radiosity, const std::string& words)
{
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(radiosity, messages), 0);
  EXPECT_NE(messages->Errors.find(words), std::string::npos) << messages->Errors;
  auto* out = vtkDataSet::SafeDownCast(radiosity->GetOutput());
  if (out)
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(radiosity->GetLeafMeshOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(radiosity->GetLinksOutput()->GetNumberOfCells(), 0);
}
} // namespace

TEST(RadiosityBadInput, CellPointIdsOutOfRangeAreRefused)
{
  auto sky = uniformSky(100.0);
  for (vtkIdType badId : { vtkIdType(7), vtkIdType(1000000000), vtkIdType(-1) })
  {
    SCOPED_TRACE(badId);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(triangle({ { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } } }, { 0, 1, badId }));
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    expectRefused(radiosity, "point id " + std::to_string(badId));
  }
}

TEST(RadiosityBadInput, GridWithFewerPointsThanItsDimensionsIsRefused)
{
  auto sky = uniformSky(100.0);
  for (bool hierarchy : { true, false })
  {
    vtkNew<vtkPoints> points;
    for (int k = 0; k < 5; ++k)
      points->InsertNextPoint(k, 0, 0);
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(10, 10, 1);
    grid->SetPoints(points);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(grid);
    radiosity->SetUseTerrainHierarchy(hierarchy);
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    expectRefused(radiosity, "10 x 10 but 5 points");
  }
}

TEST(RadiosityBadInput, SelfIntersectingPolygonIsRefusedNamingTheTriangleFilter)
{
  vtkNew<vtkPoints> points;
  const double corners[5][2] = { { 0, 0 }, { 2, 2 }, { 2, 0 }, { 0, 2 }, { 1, 3 } };
  for (const auto& c : corners)
    points->InsertNextPoint(c[0], c[1], 0.0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[5] = { 0, 1, 2, 3, 4 };
  cells->InsertNextCell(5, ids);
  vtkNew<vtkPolyData> bowtie;
  bowtie->SetPoints(points);
  bowtie->SetPolys(cells);
  auto sky = uniformSky(100.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(bowtie);
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  vtkNew<MessageCatcher> messages;
  const int status = runPipeline(radiosity, messages);
  // Either triangulated into a surface that faces the sky or refused by name.
  if (status == 0)
    EXPECT_NE(messages->Errors.find("vtkTriangleFilter"), std::string::npos) << messages->Errors;
  else
    EXPECT_TRUE(std::isfinite(meanOf(vtkDataSet::SafeDownCast(radiosity->GetOutput()), "Irradiance")));
}

TEST(RadiosityBadInput, EmissionBeyondAnyLightSourceIsRefused)
{
  // 1e308 W/m^2 would overflow the scene's power; no surface emits more than the
  // sun's 6.3e7 W/m^2.
  auto ground = square(10.0, 2);
  vtkNew<vtkDoubleArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfTuples(ground->GetNumberOfCells());
  emission->Fill(1e308);
  ground->GetCellData()->AddArray(emission);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(ground);
  radiosity->SetEmissionArrayName("Emission");
  expectRefused(radiosity, "emission array 'Emission' holds 1e+308");
  EXPECT_EQ(emission->GetValue(0), 1e308); // the input untouched
}

TEST(RadiosityBadInput, NaNParametersAreRefused)
{
  auto sky = uniformSky(100.0);
  const double nan = std::nan("");
  using Setter = void (*)(vtkHierarchicalRadiosity*);
  const std::pair<const char*, Setter> cases[] = {
    { "DefaultReflectance", [](vtkHierarchicalRadiosity* r) { r->SetDefaultReflectance(std::nan("")); } },
    { "ErrorTolerance", [](vtkHierarchicalRadiosity* r) { r->SetErrorTolerance(std::nan("")); } },
    { "ConvergenceTolerance", [](vtkHierarchicalRadiosity* r) { r->SetConvergenceTolerance(std::nan("")); } },
    { "MinimumElementArea", [](vtkHierarchicalRadiosity* r) { r->SetMinimumElementArea(std::nan("")); } },
    { "DetailDistance", [](vtkHierarchicalRadiosity* r) { r->SetDetailDistance(std::nan("")); } },
  };
  (void)nan;
  for (const auto& [name, set] : cases)
  {
    SCOPED_TRACE(name);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(square(10.0));
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    set(radiosity);
    expectRefused(radiosity, std::string(name) + " is NaN");
  }
}

TEST(RadiosityBadInput, AFarTerrainStrideItCannotUseIsIgnoredWithAWarning)
{
  // Polygons only, then no DetailDistance: rays keep the full resolution, and say so.
  auto sky = uniformSky(100.0);
  for (const double detail : { 100.0, 0.0 })
  {
    SCOPED_TRACE(detail);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(square(10.0));
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetDetailDistance(detail);
    radiosity->SetFarTerrainStride(4);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    EXPECT_NE(messages->Warnings.find("FarTerrainStride 4 is ignored"), std::string::npos) << messages->Warnings;
    EXPECT_NE(messages->Warnings.find("1 polygon(s)"), std::string::npos) << messages->Warnings;
    auto* out = vtkDataSet::SafeDownCast(radiosity->GetOutput());
    ASSERT_NE(out, nullptr);
    vtkDataArray* skyIrradiance = out->GetPointData()->GetArray("SkyIrradiance");
    ASSERT_NE(skyIrradiance, nullptr);
    EXPECT_NEAR(skyIrradiance->GetComponent(0, 0), 100.0, 1.0); // open flat ground under the uniform sky
  }
}

// Regression tests of the fuzzers' findings (Testing/Fuzz/corpus/*/finding-*).
TEST(RadiosityBadInput, FuzzFindingsStayFixed)
{
  auto sky = uniformSky(100.0);
  // A point at 1e199 m: refused, not NaN.
  {
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(triangle({ { { 0, 0, 0 }, { 10, 0, 0 }, { 0, 1.2e199, 0 } } }));
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    expectRefused(radiosity, "huge coordinate");
  }
  // Corners a denormal apart: the leaf mesh's T-vertex walk ends (it recursed forever).
  {
    const auto data = polygons({ { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 0, 1e-322, 0 }, { 4, 4, 0 } },
      { { 0, 1, 2 }, { 3, 1, 4 }, { 1, 4, 2 } });
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(data);
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetErrorTolerance(1e-4);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    EXPECT_GT(radiosity->GetLeafMeshOutput()->GetNumberOfCells(), 0);
  }
  // A quad whose first vertex is a spike on the line of two others: ear clipping leaves
  // it only a zero-area triangle. It takes the quad's value there, not NaN.
  {
    const auto data = polygons({ { 1.0682006905399515e-255, 0.06103515625, 1.0674197922632749e-255 },
                                 { 1.3908197025675319e-309, 0.00732421875, 0 },
                                 { 0.625, 0.0042724609375, 0.46875 },
                                 { 5.0058479970112312e-247, 0.0152587890625, 0 } },
      { { 0, 1, 2, 3 } });
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(data);
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    vtkDataArray* irradiance =
      vtkPolyData::SafeDownCast(radiosity->GetOutput())->GetPointData()->GetArray("Irradiance");
    for (vtkIdType k = 0; k < 4; ++k)
    {
      EXPECT_TRUE(std::isfinite(irradiance->GetComponent(k, 0))) << k;
      EXPECT_GT(irradiance->GetComponent(k, 0), 0.0) << k;
    }
  }
  // A 3 x 3 grid with one post 6e8 m out: kept as floats about the grid's centre, the
  // other posts (metres apart) collapse onto each other, cells without area whose
  // posts were NaN. Refused with what to do instead.
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& p : std::vector<std::array<double, 3>>{ { 0, 0.02, 0 }, { 2, -9.7, -595821443.5 },
           { -595821443.5, 0, 0 }, { 0, 0, 0 }, { 0.018, 0, 0.0018 }, { 0.007, 0, 0 }, { -12.97, 0.34, 0 },
           { 2, 4, 2 }, { 4, 4, 1 } })
      points->InsertNextPoint(p.data());
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(3, 3, 1);
    grid->SetPoints(points);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(grid);
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    expectRefused(radiosity, "has no area at single precision");
  }
  // A sliver quad (two corners a denormal from the origin, one 2 mm above it) under the
  // sun: leaves of zero area meet at leaf-mesh vertices, which took 0/0.
  {
    const auto data = polygons({ { 7.4415891827805358e-68, 3.2466618484640403e-312, 3.1126135687998532e-322 },
                                 { 1.99951171875, 1.99951171875, 0 },
                                 { 5.3047064716705865e-315, 0, 1.7796245020678025e-308 },
                                 { 0, 0, 0.001983642578125 } },
      { { 0, 1, 2, 3 } });
    auto sun = userSun(800.0, "2024-06-21T10:00:00+02:00");
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(data);
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->AddLightConnection(sun->GetOutputPort());
    radiosity->SetErrorTolerance(1e-2);
    radiosity->SetVisibilitySamples(2);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    vtkPolyData* mesh = radiosity->GetLeafMeshOutput();
    ASSERT_GT(mesh->GetNumberOfPoints(), 0);
    for (const char* name : { "Irradiance", "Radiosity" })
    {
      vtkDataArray* values = mesh->GetPointData()->GetArray(name);
      ASSERT_NE(values, nullptr) << name;
      for (vtkIdType k = 0; k < values->GetNumberOfTuples(); ++k)
        EXPECT_TRUE(std::isfinite(values->GetComponent(k, 0))) << name << " at leaf-mesh point " << k;
    }
  }
}
