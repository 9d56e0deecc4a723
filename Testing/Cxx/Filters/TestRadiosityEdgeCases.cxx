// vtkHierarchicalRadiosity on unusual input: runaway tolerances, several lights,
// concave polygons, bright closed scenes, composite structure, a small object on a
// huge polygon, a sun below the horizon. Each gives the right answer.
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
// A closed cube of inward faces, triangulated, with cell array Emission.
vtkSmartPointer<vtkPolyData> inwardBox(double size, double emission)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  return terralux_test::inwardBox(cube, emission);
}
} // namespace

TEST(RadiosityEdgeCases, RunawayToleranceStopsAtTheElementBudget)
{
  // A 4 x 4 m plane with a box on it at the smallest tolerance: refinement would grow
  // without bound; it stops at the budget with a warning and a finite solution.
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0, 0, 0.5);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  triangles->Update();
  auto sky = uniformSky(100.0);
  auto sun = userSun(800.0, "2024-06-21T10:00:00+02:00");
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(square(4.0));
  radiosity->AddInputData(triangles->GetOutput());
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  radiosity->AddLightConnection(sun->GetOutputPort());
  radiosity->SetErrorTolerance(1e-9);
  radiosity->SetMaximumNumberOfElements(20000);
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  EXPECT_NE(messages->Warnings.find("MaximumNumberOfElements"), std::string::npos) << messages->Warnings;
  auto* out = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
  ASSERT_NE(out, nullptr);
  const double elements = fieldValue(out, "Elements");
  EXPECT_LE(elements, 20000 + 4 * 5000); // the last refinement pass may finish its splits
  auto* ground = vtkDataSet::SafeDownCast(out->GetBlock(0));
  const double mean = meanOf(ground, "Irradiance");
  EXPECT_TRUE(std::isfinite(mean));
  EXPECT_GT(mean, 100.0);
}

TEST(RadiosityEdgeCases, EverySunAndSkyCounts)
{
  auto ground = square(10.0, 2);
  auto sunA = userSun(500.0, "2024-06-21T12:00:00+02:00");
  auto sunB = userSun(500.0, "2024-06-21T16:00:00+02:00");
  auto skyA = uniformSky(100.0);
  auto skyB = uniformSky(50.0);
  skyB->SetLevels(3); // another resolution: resampled onto the finer map
  for (auto* sun : { sunA.Get(), sunB.Get() })
    sun->Update();
  const double expectedSun = 500.0 * (std::cos(sunA->GetZenith() * M_PI / 180.0) +
    std::cos(sunB->GetZenith() * M_PI / 180.0));
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(ground);
  radiosity->SetDefaultReflectance(0.0);
  radiosity->AddLightConnection(sunA->GetOutputPort());
  radiosity->AddLightConnection(sunB->GetOutputPort());
  radiosity->AddLightConnection(skyA->GetOutputPort(0));
  radiosity->AddLightConnection(skyB->GetOutputPort(0));
  for (bool atPoints : { true, false })
  {
    SCOPED_TRACE(atPoints);
    radiosity->SetEvaluateAtPoints(atPoints);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    auto* out = vtkDataSet::SafeDownCast(radiosity->GetOutput());
    EXPECT_NEAR(meanOf(out, "SunIrradiance"), expectedSun, 1e-6 * expectedSun);
    EXPECT_NEAR(meanOf(out, "SkyIrradiance"), 150.0, 0.5);
  }
}

TEST(RadiosityEdgeCases, ConcavePolygonLightsWhatItsShapeLights)
{
  // A U-shaped emitter 1 m above the ground: the notch (x in [1, 2], y in [1, 3]) emits
  // nothing, as after vtkTriangleFilter; a fan from the first corner would cover it.
  auto makeU = []() {
    vtkNew<vtkPoints> points;
    const double corners[8][2] = { { 0, 0 }, { 3, 0 }, { 3, 3 }, { 2, 3 }, { 2, 1 }, { 1, 1 }, { 1, 3 }, { 0, 3 } };
    for (const auto& c : corners)
      points->InsertNextPoint(c[0], c[1], 1.0);
    vtkNew<vtkCellArray> cells;
    // Facing down (-z): clockwise seen from above.
    const vtkIdType ids[8] = { 7, 6, 5, 4, 3, 2, 1, 0 };
    cells->InsertNextCell(8, ids);
    auto u = vtkSmartPointer<vtkPolyData>::New();
    u->SetPoints(points);
    u->SetPolys(cells);
    vtkNew<vtkDoubleArray> emission;
    emission->SetName("Emission");
    emission->InsertNextValue(1000.0);
    u->GetCellData()->AddArray(emission);
    return u;
  };
  auto solveWith = [&](vtkPolyData* emitter) {
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->AddInputData(emitter);
    vtkNew<vtkPlaneSource> floor;
    floor->SetOrigin(0, 0, 0);
    floor->SetPoint1(3, 0, 0);
    floor->SetPoint2(0, 3, 0);
    floor->SetResolution(6, 6);
    floor->Update();
    vtkNew<vtkDoubleArray> none;
    none->SetName("Emission");
    none->SetNumberOfTuples(floor->GetOutput()->GetNumberOfCells());
    none->Fill(0.0);
    floor->GetOutput()->GetCellData()->AddArray(none);
    radiosity->AddInputData(floor->GetOutput());
    radiosity->SetEmissionArrayName("Emission");
    radiosity->SetDefaultReflectance(0.0);
    radiosity->SetErrorTolerance(1e-4);
    vtkNew<MessageCatcher> messages;
    EXPECT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    auto* out = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
    auto* ground = vtkDataSet::SafeDownCast(out->GetBlock(1));
    // The floor point under the middle of the notch: (1.5, 2.5).
    const vtkIdType id = ground->FindPoint(1.5, 2.5, 0.0);
    return ground->GetPointData()->GetArray("Irradiance")->GetComponent(id, 0);
  };
  auto u = makeU();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(u);
  triangles->Update();
  const double reference = solveWith(triangles->GetOutput());
  const double direct = solveWith(u);
  EXPECT_NEAR(direct, reference, 0.01 * reference);
  // A fan from the first corner covers the notch: the test would see it.
  auto fan = vtkSmartPointer<vtkPolyData>::New();
  fan->DeepCopy(u);
  vtkNew<vtkCellArray> fanCells;
  const vtkIdType ids[8] = { 7, 6, 5, 4, 3, 2, 1, 0 };
  for (int k = 1; k + 1 < 8; ++k)
  {
    const vtkIdType triangle[3] = { ids[0], ids[k], ids[k + 1] };
    fanCells->InsertNextCell(3, triangle);
  }
  fan->SetPolys(fanCells);
  vtkNew<vtkDoubleArray> fanEmission;
  fanEmission->SetName("Emission");
  fanEmission->SetNumberOfTuples(6);
  fanEmission->Fill(1000.0);
  fan->GetCellData()->AddArray(fanEmission);
  EXPECT_GT(solveWith(fan), 1.1 * reference);
}

TEST(RadiosityEdgeCases, BrightClosedBoxConvergesAndWarnsWhenStoppedEarly)
{
  // Exact: B = E / (1 - rho) = 100 / 0.001 = 100000 everywhere.
  auto box = inwardBox(2.0, 100.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(box);
  radiosity->SetEmissionArrayName("Emission");
  radiosity->SetDefaultReflectance(0.999);
  radiosity->SetEvaluateAtPoints(false);
  radiosity->SetErrorTolerance(1e-2); // the iterations are the point here, not the mesh
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  EXPECT_EQ(messages->Warnings.find("did not converge"), std::string::npos) << messages->Warnings;
  auto* out = vtkDataSet::SafeDownCast(radiosity->GetOutput());
  EXPECT_NEAR(meanOf(out, "Radiosity"), 100000.0, 1000.0);
  EXPECT_LE(fieldValue(out, "Iterations"), 30);

  radiosity->SetMaximumIterations(3);
  vtkNew<MessageCatcher> early;
  ASSERT_EQ(runPipeline(radiosity, early), 1) << early->Errors;
  EXPECT_NE(early->Warnings.find("did not converge"), std::string::npos) << early->Warnings;
  EXPECT_NE(early->Warnings.find("MaximumIterations"), std::string::npos);
}

TEST(RadiosityEdgeCases, CompositeStructureIsKept)
{
  auto sky = uniformSky(100.0);
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0, 0, 5);
  cube->Update();
  vtkNew<vtkMultiBlockDataSet> nested;
  nested->SetNumberOfBlocks(1);
  nested->SetBlock(0, cube->GetOutput());
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkMultiBlockDataSet> input;
  input->SetNumberOfBlocks(4);
  input->SetBlock(0, empty);
  input->SetBlock(1, square(10.0, 2));
  input->SetBlock(2, nullptr);
  input->SetBlock(3, nested);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(input);
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  auto* out = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfBlocks(), 4u);
  EXPECT_EQ(vtkPolyData::SafeDownCast(out->GetBlock(0))->GetNumberOfPoints(), 0);
  auto* plane = vtkPolyData::SafeDownCast(out->GetBlock(1));
  ASSERT_NE(plane, nullptr);
  EXPECT_NE(plane->GetPointData()->GetArray("Irradiance"), nullptr);
  EXPECT_EQ(out->GetBlock(2), nullptr);
  auto* inner = vtkMultiBlockDataSet::SafeDownCast(out->GetBlock(3));
  ASSERT_NE(inner, nullptr);
  auto* box = vtkPolyData::SafeDownCast(inner->GetBlock(0));
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->GetNumberOfPoints(), cube->GetOutput()->GetNumberOfPoints());
  EXPECT_NE(box->GetPointData()->GetArray("Irradiance"), nullptr);
  // The input is untouched.
  EXPECT_EQ(cube->GetOutput()->GetPointData()->GetArray("Irradiance"), nullptr);

  // Every leaf of the leaf mesh names its input data set (the leaf data sets in
  // order: the empty one, the square, the cube) and its cell there, which holds it.
  vtkPolyData* leaves = radiosity->GetLeafMeshOutput();
  vtkDataArray* inputIndex = leaves->GetCellData()->GetArray("InputIndex");
  vtkDataArray* inputCell = leaves->GetCellData()->GetArray("InputCell");
  ASSERT_NE(inputIndex, nullptr);
  ASSERT_NE(inputCell, nullptr);
  vtkPolyData* inputs[3] = { empty, plane, cube->GetOutput() };
  int perInput[3] = { 0, 0, 0 };
  for (vtkIdType k = 0; k < leaves->GetNumberOfCells(); ++k)
  {
    const int index = static_cast<int>(inputIndex->GetComponent(k, 0));
    ASSERT_TRUE(index == 1 || index == 2) << index;
    ++perInput[index];
    const vtkIdType cell = static_cast<vtkIdType>(inputCell->GetComponent(k, 0));
    ASSERT_GE(cell, 0);
    ASSERT_LT(cell, inputs[index]->GetNumberOfCells());
    double leafBounds[6], cellBounds[6];
    leaves->GetCell(k)->GetBounds(leafBounds);
    inputs[index]->GetCell(cell)->GetBounds(cellBounds);
    for (int axis = 0; axis < 3; ++axis)
    {
      EXPECT_GE(leafBounds[2 * axis], cellBounds[2 * axis] - 1e-6) << k;
      EXPECT_LE(leafBounds[2 * axis + 1], cellBounds[2 * axis + 1] + 1e-6) << k;
    }
  }
  EXPECT_GE(perInput[1], plane->GetNumberOfCells());
  EXPECT_GE(perInput[2], cube->GetOutput()->GetNumberOfCells());
}

TEST(RadiosityEdgeCases, SmallBoxOnHugeGroundGetsTheSameLightOnEveryWall)
{
  // A 1 m cube on a 100 km square ground of 10 x 10 quads under a uniform sky: by
  // symmetry every wall receives the same ground-reflected light.
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0.0, 0.0, 0.5);
  cube->Update();
  auto sky = uniformSky(100.0);
  for (bool atPoints : { false, true })
  {
    SCOPED_TRACE(atPoints);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(square(100000.0, 10));
    radiosity->AddInputData(cube->GetOutput());
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetEvaluateAtPoints(atPoints);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    auto* out = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
    auto* box = vtkPolyData::SafeDownCast(out->GetBlock(1));
    vtkDataArray* reflected = box->GetPointData()->GetArray("ReflectedIrradiance");
    vtkDataArray* normals = box->GetPointData()->GetNormals();
    ASSERT_NE(normals, nullptr);
    // Ground radiosity 0.2 * 100 = 20 W/m^2; a vertical wall sees half the ground (view
    // factor 1/2 minus the part the box hides): about 10 W/m^2.
    double low = 1e9, high = -1e9;
    for (vtkIdType k = 0; k < box->GetNumberOfPoints(); ++k)
    {
      double n[3];
      normals->GetTuple(k, n);
      if (std::abs(n[2]) > 0.5)
        continue; // roof and floor points
      const double value = reflected->GetComponent(k, 0);
      low = std::min(low, value);
      high = std::max(high, value);
    }
    EXPECT_GT(low, 7.0);
    EXPECT_LT(high, 10.5);
    EXPECT_LT(high - low, 0.15 * high);
  }
}

TEST(RadiosityEdgeCases, SunBelowTheHorizonCostsNothing)
{
  // Work follows the scene: a user sun 5 deg below the horizon adds no element, link or
  // light to a sky-lit terrain (it once refined toward the slopes at the DEM's edge).
  auto sky = uniformSky(100.0);
  auto solve = [&](bool withSun) {
    vtkNew<vtkPlaneSource> hills;
    hills->SetResolution(8, 8);
    hills->SetOrigin(-100, -100, 0);
    hills->SetPoint1(100, -100, 0);
    hills->SetPoint2(-100, 100, 0);
    hills->Update();
    vtkNew<vtkPolyData> ground;
    ground->DeepCopy(hills->GetOutput());
    for (vtkIdType k = 0; k < ground->GetNumberOfPoints(); ++k)
    {
      double p[3];
      ground->GetPoint(k, p);
      ground->GetPoints()->SetPoint(k, p[0], p[1], 20.0 * std::sin(p[0] / 30.0) * std::cos(p[1] / 40.0));
    }
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(ground);
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    vtkNew<vtkPolyData> sun;
    vtkNew<vtkDoubleArray> direction, flux;
    direction->SetName("SunDirection");
    for (double c : { 0.0, std::cos(5.0 * M_PI / 180.0), -std::sin(5.0 * M_PI / 180.0) })
      direction->InsertNextValue(c);
    flux->SetName("SunNormalIrradiance");
    flux->InsertNextValue(800.0);
    sun->GetFieldData()->AddArray(direction);
    sun->GetFieldData()->AddArray(flux);
    if (withSun)
      radiosity->AddInputDataObject(1, sun);
    radiosity->Update();
    return vtkSmartPointer<vtkDataObject>(radiosity->GetOutput());
  };
  auto without = solve(false), with = solve(true);
  for (const char* name : { "Elements", "Links" })
    EXPECT_EQ(fieldValue(with, name), fieldValue(without, name)) << name;
  auto* lit = vtkDataSet::SafeDownCast(with);
  vtkDataArray* sunIrradiance = lit->GetPointData()->GetArray("SunIrradiance");
  for (vtkIdType k = 0; k < sunIrradiance->GetNumberOfTuples(); ++k)
    EXPECT_EQ(sunIrradiance->GetComponent(k, 0), 0.0);
}
