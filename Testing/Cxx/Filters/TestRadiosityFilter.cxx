// vtkHierarchicalRadiosity: pipelines against closed forms, output structure, leaf-mesh
// continuity, links, bands, and bad input.
#include "vtk_test_support.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityOutputs.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkSkySource.h"
#include "vtkSunSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using terralux_test::fieldValue;
using terralux_test::MessageCatcher;
using terralux_test::runPipeline;

namespace
{
vtkSmartPointer<vtkPolyData> plane(int resolution, double size = 10.0)
{
  vtkNew<vtkPlaneSource> source;
  source->SetOrigin(0, 0, 0);
  source->SetPoint1(size, 0, 0);
  source->SetPoint2(0, size, 0);
  source->SetResolution(resolution, resolution);
  source->Update();
  return source->GetOutput();
}

struct Lights
{
  vtkNew<vtkSunSource> sun;
  vtkNew<vtkSkySource> sky;
  Lights(double normalIrradiance, double diffuse)
  {
    sun->SetDateTime("2024-06-21T12:00:00+02:00");
    sun->SetLatitude(46.0);
    sun->SetLongitude(8.0);
    sun->SetIrradianceModelToUser();
    sun->SetUserNormalIrradiance(normalIrradiance);
    sun->SetUserDiffuseHorizontalIrradiance(diffuse);
    sky->SetSunConnection(sun->GetOutputPort());
    sky->SetSkyModelToUniform();
    sky->SetLevels(6);
  }
};

void expectError(vtkHierarchicalRadiosity* radiosity, const std::string& words)
{
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(radiosity, messages), 0);
  EXPECT_NE(messages->Errors.find(words), std::string::npos) << words << ": " << messages->Errors;
  EXPECT_EQ(radiosity->GetLeafMeshOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(radiosity->GetLinksOutput()->GetNumberOfCells(), 0);
}
} // namespace

TEST(RadiosityFilter, PlaneUnderSunAndSkyMatchesClosedForm)
{
  Lights lights(800.0, 120.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(plane(4));
  radiosity->AddLightConnection(lights.sun->GetOutputPort());
  radiosity->AddLightConnection(lights.sky->GetOutputPort(0));
  radiosity->SetErrorTolerance(1e-4);
  for (bool atPoints : { true, false })
  {
  SCOPED_TRACE(atPoints ? "evaluated at points" : "averaged over elements");
  radiosity->SetEvaluateAtPoints(atPoints);
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  auto* out = vtkPolyData::SafeDownCast(radiosity->GetOutput());
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->GetNumberOfPoints(), 25);
  EXPECT_EQ(out->GetNumberOfCells(), 16);
  const double sunExpected = 800.0 * lights.sun->GetDirection()[2];
  vtkDataArray* sun = out->GetPointData()->GetArray("SunIrradiance");
  vtkDataArray* sky = out->GetPointData()->GetArray("SkyIrradiance");
  vtkDataArray* global = out->GetPointData()->GetArray("Irradiance");
  vtkDataArray* radiosityArray = out->GetPointData()->GetArray("Radiosity");
  for (vtkIdType k = 0; k < out->GetNumberOfPoints(); ++k)
  {
    EXPECT_NEAR(sun->GetComponent(k, 0) / sunExpected, 1.0, 0.005);
    EXPECT_NEAR(sky->GetComponent(k, 0) / 120.0, 1.0, 0.005);
    EXPECT_NEAR(global->GetComponent(k, 0), sun->GetComponent(k, 0) + sky->GetComponent(k, 0), 1e-9);
    EXPECT_NEAR(radiosityArray->GetComponent(k, 0), 0.2 * global->GetComponent(k, 0), 1e-9);
  }
  EXPECT_GT(fieldValue(out, "Elements"), 0.0);
  EXPECT_GT(fieldValue(out, "Rays"), 0.0);
  EXPECT_EQ(fieldValue(out, "Links"), radiosity->GetLinksOutput()->GetNumberOfCells());
  EXPECT_EQ(out->GetPointData()->GetArray("SkyViewFactor"), nullptr); // not a terrain
  }
}

TEST(RadiosityFilter, LeafMeshIsContinuousAtTVertices)
{
  // A wall shading part of the ground forces uneven refinement.
  vtkNew<vtkPolyData> scene;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  const double p[8][3] = { { -5, -5, 0 }, { 5, -5, 0 }, { 5, 5, 0 }, { -5, 5, 0 }, { 2, 0, 0 }, { -2, 0, 0 },
    { -2, 0, 2 }, { 2, 0, 2 } };
  for (const auto& q : p)
    points->InsertNextPoint(q);
  const vtkIdType ground[4] = { 0, 1, 2, 3 }, wall[4] = { 4, 5, 6, 7 };
  quads->InsertNextCell(4, ground);
  quads->InsertNextCell(4, wall);
  scene->SetPoints(points);
  scene->SetPolys(quads);
  Lights lights(700.0, 100.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(scene);
  radiosity->AddLightConnection(lights.sun->GetOutputPort());
  radiosity->AddLightConnection(lights.sky->GetOutputPort(0));
  radiosity->SetErrorTolerance(2e-4);
  radiosity->SetMinimumElementArea(0.01);
  ASSERT_EQ(radiosity->GetExecutive()->Update(), 1);
  vtkPolyData* leaves = radiosity->GetLeafMeshOutput();
  ASSERT_GT(leaves->GetNumberOfCells(), 20);
  vtkDataArray* levels = leaves->GetCellData()->GetArray("Level");
  double levelRange[2];
  levels->GetRange(levelRange);
  EXPECT_GT(levelRange[1], levelRange[0]); // refinement is uneven

  // Every vertex lying in the middle of a leaf edge (a T-vertex) holds the value the
  // edge's linear interpolation gives, so shading is continuous across the edge.
  std::map<std::array<double, 3>, vtkIdType> byPosition;
  for (vtkIdType k = 0; k < leaves->GetNumberOfPoints(); ++k)
  {
    double x[3];
    leaves->GetPoint(k, x);
    byPosition[{ x[0], x[1], x[2] }] = k;
  }
  vtkDataArray* irradiance = leaves->GetPointData()->GetArray("Irradiance");
  int tVertices = 0;
  for (vtkIdType c = 0; c < leaves->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    leaves->GetCellPoints(c, n, ids);
    for (vtkIdType e = 0; e < n; ++e)
    {
      double a[3], b[3];
      leaves->GetPoint(ids[e], a);
      leaves->GetPoint(ids[(e + 1) % n], b);
      const auto it = byPosition.find({ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) });
      if (it == byPosition.end())
        continue;
      ++tVertices;
      const double expected = 0.5 * (irradiance->GetComponent(ids[e], 0) + irradiance->GetComponent(ids[(e + 1) % n], 0));
      EXPECT_NEAR(irradiance->GetComponent(it->second, 0), expected, 1e-9 * (1.0 + std::abs(expected)));
    }
  }
  EXPECT_GT(tVertices, 0);

  // Links: sky and sun links point up toward the sky; powers are finite and >= 0.
  vtkPolyData* links = radiosity->GetLinksOutput();
  vtkDataArray* power = links->GetCellData()->GetArray("Power");
  ASSERT_GT(links->GetNumberOfCells(), 0);
  for (vtkIdType k = 0; k < links->GetNumberOfCells(); ++k)
    EXPECT_TRUE(std::isfinite(power->GetComponent(k, 0)) && power->GetComponent(k, 0) >= 0.0);
}

TEST(RadiosityFilter, SeveralInputsAndBands)
{
  auto ground = plane(2);
  vtkNew<vtkDoubleArray> colour;
  colour->SetName("Albedo");
  colour->SetNumberOfComponents(3);
  colour->SetNumberOfTuples(ground->GetNumberOfCells());
  for (vtkIdType k = 0; k < ground->GetNumberOfCells(); ++k)
    colour->SetTuple3(k, 0.1, 0.3, 0.6);
  ground->GetCellData()->AddArray(colour);
  auto other = plane(1, 3.0);
  Lights lights(600.0, 100.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->AddInputData(ground);
  radiosity->AddInputData(other);
  radiosity->AddLightConnection(lights.sun->GetOutputPort());
  radiosity->SetReflectanceArrayName("Albedo");
  radiosity->SetNumberOfBands(3);
  vtkNew<MessageCatcher> messages;
  // The second plane has no Albedo array: a clear error.
  EXPECT_EQ(runPipeline(radiosity, messages), 0);
  EXPECT_NE(messages->Errors.find("Albedo"), std::string::npos);
  other->GetCellData()->AddArray(colour);
  vtkNew<vtkDoubleArray> small;
  small->DeepCopy(colour);
  small->SetNumberOfTuples(other->GetNumberOfCells());
  other->GetCellData()->RemoveArray("Albedo");
  other->GetCellData()->AddArray(small);
  ASSERT_EQ(runPipeline(radiosity, messages), 1);
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
  ASSERT_NE(blocks, nullptr);
  ASSERT_EQ(blocks->GetNumberOfBlocks(), 2u);
  auto* first = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
  vtkDataArray* b = first->GetPointData()->GetArray("Radiosity");
  ASSERT_EQ(b->GetNumberOfComponents(), 3);
  EXPECT_NEAR(b->GetComponent(4, 2) / b->GetComponent(4, 0), 6.0, 1e-6); // 0.6 / 0.1

  // The array chosen the VTK way (what ParaView's array lists call) is the same array.
  const double named = b->GetComponent(4, 2);
  radiosity->SetReflectanceArrayName(nullptr);
  EXPECT_EQ(radiosity->GetReflectanceArrayName(), nullptr);
  radiosity->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Albedo");
  EXPECT_STREQ(radiosity->GetReflectanceArrayName(), "Albedo");
  ASSERT_EQ(runPipeline(radiosity, messages), 1);
  blocks = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
  b = vtkPolyData::SafeDownCast(blocks->GetBlock(0))->GetPointData()->GetArray("Radiosity");
  EXPECT_DOUBLE_EQ(b->GetComponent(4, 2), named);
  // A point array is refused, naming the call that chooses a cell array.
  radiosity->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Albedo");
  EXPECT_EQ(runPipeline(radiosity, messages), 0);
  EXPECT_NE(messages->Errors.find("must be a cell array"), std::string::npos) << messages->Errors;
  // Naming it again makes it the cell array.
  radiosity->SetReflectanceArrayName("Albedo");
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  // ParaView's "None" entry (passed with the point association) is no array: the
  // DefaultReflectance everywhere, grey.
  radiosity->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
  EXPECT_EQ(radiosity->GetReflectanceArrayName(), nullptr);
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  blocks = vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput());
  b = vtkPolyData::SafeDownCast(blocks->GetBlock(0))->GetPointData()->GetArray("Radiosity");
  EXPECT_NEAR(b->GetComponent(4, 2) / b->GetComponent(4, 0), 1.0, 1e-9);
}

TEST(RadiosityFilter, BadInput)
{
  Lights lights(600.0, 100.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->AddLightConnection(lights.sun->GetOutputPort());

  vtkNew<vtkPolyData> empty;
  radiosity->SetInputData(empty);
  expectError(radiosity, "non-zero area");

  auto nan = plane(1);
  nan->GetPoints()->SetPoint(2, NAN, 0, 0);
  radiosity->SetInputData(nan);
  expectError(radiosity, "NaN");

  auto ground = plane(2);
  vtkNew<vtkDoubleArray> reflectance;
  reflectance->SetName("rho");
  reflectance->SetNumberOfTuples(ground->GetNumberOfCells());
  reflectance->Fill(1.0);
  ground->GetCellData()->AddArray(reflectance);
  radiosity->SetInputData(ground);
  radiosity->SetReflectanceArrayName("rho");
  expectError(radiosity, "values must lie in [0");
  reflectance->SetNumberOfTuples(2);
  ground->Modified();
  expectError(radiosity, "one tuple per cell");
  radiosity->SetReflectanceArrayName(nullptr);

  vtkNew<vtkHierarchicalRadiosity> dark;
  dark->SetInputData(plane(1));
  expectError(dark, "no light source");

  // Degenerate triangles among good ones: skipped, counted, warned about.
  vtkNew<vtkPolyData> mixed;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(2, 0, 0);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType good[3] = { 0, 1, 2 }, flat[3] = { 0, 1, 3 };
  triangles->InsertNextCell(3, good);
  triangles->InsertNextCell(3, flat);
  triangles->InsertNextCell(3, flat);
  mixed->SetPoints(points);
  mixed->SetPolys(triangles);
  radiosity->SetInputData(mixed);
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(radiosity, messages), 1);
  EXPECT_NE(messages->Warnings.find("Skipped 2 degenerate"), std::string::npos) << messages->Warnings;
  EXPECT_EQ(fieldValue(radiosity->GetOutput(), "DegeneratePolygons"), 2.0);
  // The input is not modified.
  EXPECT_EQ(mixed->GetPointData()->GetNumberOfArrays(), 0);
}
