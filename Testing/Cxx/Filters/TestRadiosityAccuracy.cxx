// Accuracy where users look, against closed forms: points at concave junctions (the
// foot and the corner of a building on open ground), a scene moved far from the origin,
// and Horn's post normals.
#include "vtk_test_support.h"

#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"
#include "vtkTessellatedBoxSource.h"
#include "vtkTerrainSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using terralux_test::MessageCatcher;
using terralux_test::runPipeline;

namespace
{
vtkSmartPointer<vtkPolyData> ground(double half, int resolution)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-half, -half, 0);
  plane->SetPoint1(half, -half, 0);
  plane->SetPoint2(-half, half, 0);
  plane->SetResolution(resolution, resolution);
  plane->Update();
  return plane->GetOutput();
}

vtkSmartPointer<vtkPolyData> building(double x, double y, double height, double base = 0.0)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(x);
  cube->SetYLength(y);
  cube->SetZLength(height - base);
  cube->SetCenter(0, 0, 0.5 * (height + base));
  cube->Update();
  return cube->GetOutput();
}

// A copy of the polydata with every point moved by (dx, dy), in double precision.
vtkSmartPointer<vtkPolyData> moved(vtkPolyData* data, double dx, double dy)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(data);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(data->GetNumberOfPoints());
  for (vtkIdType k = 0; k < data->GetNumberOfPoints(); ++k)
  {
    double p[3];
    data->GetPoint(k, p);
    points->SetPoint(k, p[0] + dx, p[1] + dy, p[2]);
  }
  copy->SetPoints(points);
  return copy;
}

double valueAt(vtkDataSet* data, const char* name, double x, double y, double z)
{
  return data->GetPointData()->GetArray(name)->GetComponent(data->FindPoint(x, y, z), 0);
}
} // namespace

TEST(RadiosityAccuracy, FootAndCornerOfABuildingSeeTheirShareOfTheSky)
{
  // A 10 x 10 x 6 m building on open ground under a uniform sky, reflectance 0: a ground
  // point at the foot of a wall sees half the sky, one at a corner three quarters.
  vtkNew<vtkSkySource> sky;
  sky->UseSunSourceOff();
  sky->SetSkyModelToUniform();
  sky->SetDiffuseHorizontalIrradiance(100.0);
  for (bool atPoints : { true, false })
  {
    SCOPED_TRACE(atPoints);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(ground(200.0, 80)); // posts every 5 m: on the walls' feet
    radiosity->AddInputData(building(10.0, 10.0, 6.0));
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetDefaultReflectance(0.0);
    radiosity->SetEvaluateAtPoints(atPoints);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    auto* floor = vtkDataSet::SafeDownCast(vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput())->GetBlock(0));
    if (atPoints)
    {
      // The four feet and the four corners; at the default 4 visibility samples a point
      // may be a few per cent off (sampling noise), at 16 within 2 %.
      const double feet[4][2] = { { 5, 0 }, { -5, 0 }, { 0, 5 }, { 0, -5 } };
      const double corners[4][2] = { { 5, 5 }, { -5, 5 }, { 5, -5 }, { -5, -5 } };
      for (int samples : { 4, 16 })
      {
        radiosity->SetVisibilitySamples(samples);
        radiosity->Update();
        floor = vtkDataSet::SafeDownCast(vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput())->GetBlock(0));
        const double tolerance = samples == 4 ? 0.06 : 0.02;
        for (const auto& f : feet)
          EXPECT_NEAR(valueAt(floor, "SkyIrradiance", f[0], f[1], 0.0), 50.0, tolerance * 50.0) << samples;
        for (const auto& c : corners)
          EXPECT_NEAR(valueAt(floor, "SkyIrradiance", c[0], c[1], 0.0), 75.0, tolerance * 75.0) << samples;
      }
    }
    else
    {
      // Averaged over the elements around the point: above zero, below the open sky.
      EXPECT_GT(valueAt(floor, "SkyIrradiance", 5.0, 0.0, 0.0), 20.0);
      EXPECT_LT(valueAt(floor, "SkyIrradiance", 5.0, 0.0, 0.0), 100.0);
    }
  }
}

TEST(RadiosityAccuracy, AWallsPartBelowTheGroundSendsNothingAndHidesNothing)
{
  // A house on a terrain whose walls reach 1 m below the ground, as houses modelled on
  // terrain do: the posts at its foot see the part above the ground only, so they read
  // what they read beside a house standing on the ground. The walls' lowest leaves
  // straddle the ground: averaged with their buried part, they sent 20-40 % too little
  // onto those posts (38 % at the house of the accuracy report).
  vtkNew<vtkSkySource> sky;
  sky->UseSunSourceOff();
  sky->SetSkyModelToUniform();
  sky->SetDiffuseHorizontalIrradiance(100.0);
  vtkNew<vtkImageData> heights;
  heights->SetDimensions(41, 41, 1);
  heights->SetSpacing(2.0, 2.0, 1.0);
  heights->SetOrigin(-40.0, -40.0, 0.0);
  heights->AllocateScalars(VTK_FLOAT, 1);
  heights->GetPointData()->GetScalars()->Fill(0.0);
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetInputData(heights);
  double reflected[2][5];
  for (int buried : { 0, 1 })
  {
    vtkNew<vtkTessellatedBoxSource> house;
    house->SetBounds(-5, 5, -4, 4, buried ? -1.0 : 0.0, 6.0);
    house->SetLevel(2);
    house->QuadsOn();
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputConnection(terrain->GetOutputPort());
    radiosity->AddInputConnection(house->GetOutputPort());
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetDefaultReflectance(0.3);
    // Reflected light of about 6 W/m^2 compared within 5 %: each post's gather to 0.6 %
    // of its global, with no floor in W/m^2.
    radiosity->SetTargetError(0.006);
    radiosity->SetTargetErrorFloor(0.0);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    auto* ground = vtkDataSet::SafeDownCast(vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput())->GetBlock(0));
    for (int k = 0; k < 5; ++k) // posts on the south wall's line
      reflected[buried][k] = valueAt(ground, "ReflectedIrradiance", -4.0 + 2.0 * k, -4.0, 0.0);
  }
  for (int k = 0; k < 5; ++k)
  {
    // About half the wall's radiosity: 0.3 x (50 of sky + what the ground sends) / 2.
    EXPECT_GT(reflected[0][k], 6.0) << k;
    EXPECT_NEAR(reflected[1][k], reflected[0][k], 0.05 * reflected[0][k]) << k;
  }
}

TEST(RadiosityAccuracy, ClosedBoxesReadTheirRadiosityEverywhereInBothModes)
{
  // Inward faces, emission 100, reflectance 0.5: radiosity 200 at every corner, edge and
  // face point. Averaged over leaves, the tessellated box read 155 at an edge: a link
  // between clusters whose 4 visibility samples all fell on faces turned away from each
  // other counted as occluded and was dropped.
  for (int level : { 0, 4 })
  {
    vtkNew<vtkCubeSource> cube;
    vtkNew<vtkTessellatedBoxSource> tessellated;
    tessellated->SetLevel(level);
    tessellated->QuadsOn();
    const vtkSmartPointer<vtkPolyData> closed =
      terralux_test::inwardBox(level == 0 ? static_cast<vtkAlgorithm*>(cube) : tessellated, 100.0);
    for (bool atPoints : { true, false })
    {
      SCOPED_TRACE(std::to_string(level) + (atPoints ? " at points" : " averaged"));
      vtkNew<vtkHierarchicalRadiosity> radiosity;
      radiosity->SetInputData(closed);
      radiosity->SetEmissionArrayName("Emission");
      radiosity->SetDefaultReflectance(0.5);
      radiosity->SetEvaluateAtPoints(atPoints);
      vtkNew<MessageCatcher> messages;
      ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
      auto* output = vtkDataSet::SafeDownCast(radiosity->GetOutput());
      ASSERT_NE(output, nullptr);
      vtkDataArray* b = output->GetPointData()->GetArray("Radiosity");
      ASSERT_NE(b, nullptr);
      for (vtkIdType k = 0; k < b->GetNumberOfTuples(); ++k)
        EXPECT_NEAR(b->GetComponent(k, 0), 200.0, 2.0) << k;
    }
  }
}

TEST(RadiosityAccuracy, SceneMovedFarFromTheOriginGivesTheSameValues)
{
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2024-06-21T10:00:00+02:00");
  sun->SetLatitude(46.0);
  sun->SetIrradianceModelToUser();
  sun->SetUserNormalIrradiance(800.0);
  sun->SetUserDiffuseHorizontalIrradiance(100.0);
  vtkNew<vtkSkySource> sky;
  sky->SetSunConnection(sun->GetOutputPort());
  auto base = ground(60.0, 12);
  auto house = building(10.0, 8.0, 6.0);
  auto solve = [&](double shift, bool atPoints) {
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputData(moved(base, shift, shift));
    radiosity->AddInputData(moved(house, shift, shift));
    radiosity->AddLightConnection(sun->GetOutputPort());
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetEvaluateAtPoints(atPoints);
    radiosity->Update();
    vtkSmartPointer<vtkDataArray> values = vtkDataSet::SafeDownCast(
      vtkMultiBlockDataSet::SafeDownCast(radiosity->GetOutput())->GetBlock(0))->GetPointData()->GetArray("Irradiance");
    return values;
  };
  for (bool atPoints : { true, false })
  {
    SCOPED_TRACE(atPoints);
    const auto here = solve(0.0, atPoints);
    for (double shift : { 1e5, 1e7 })
    {
      const auto far = solve(shift, atPoints);
      ASSERT_EQ(far->GetNumberOfTuples(), here->GetNumberOfTuples());
      double worst = 0.0;
      for (vtkIdType k = 0; k < here->GetNumberOfTuples(); ++k)
        worst = std::max(worst, std::abs(far->GetComponent(k, 0) / here->GetComponent(k, 0) - 1.0));
      EXPECT_LT(worst, 1e-3) << "moved by " << shift;
    }
  }
}

TEST(RadiosityAccuracy, HornNormalsFollowGisSlopes)
{
  // z = 0.001 x^2 + 0.002 y^2 + 0.0005 x y: Horn's weighted central differences are exact
  // for a quadratic, so the sun on a post is E n . s with n = (-dz/dx, -dz/dy, 1) / |.|.
  const int n = 21;
  const double spacing = 10.0;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, 1);
  image->SetSpacing(spacing, spacing, 1.0);
  image->SetOrigin(-100.0, -100.0, 0.0);
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(n * n);
  auto z = [](double x, double y) { return 200.0 + 0.001 * x * x + 0.002 * y * y + 0.0005 * x * y; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      heights->SetValue(i + j * n, static_cast<float>(z(-100.0 + i * spacing, -100.0 + j * spacing)));
  image->GetPointData()->SetScalars(heights);
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetInputData(image);
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2024-06-21T12:00:00Z"); // high: no post shadows another
  sun->SetLatitude(46.0);
  sun->SetIrradianceModelToUser();
  sun->SetUserNormalIrradiance(1000.0);
  sun->Update();
  const double* s = sun->GetDirection();
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputConnection(terrain->GetOutputPort());
  radiosity->AddLightConnection(sun->GetOutputPort());
  radiosity->SetPostNormalsToHorn();
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  auto* out = vtkDataSet::SafeDownCast(radiosity->GetOutput());
  vtkDataArray* sunIrradiance = out->GetPointData()->GetArray("SunIrradiance");
  for (int j = 2; j < n - 2; j += 3)
    for (int i = 2; i < n - 2; i += 3)
    {
      const double x = -100.0 + i * spacing, y = -100.0 + j * spacing;
      const double p = 0.002 * x + 0.0005 * y, q = 0.004 * y + 0.0005 * x, length = std::sqrt(p * p + q * q + 1.0);
      const double expected = 1000.0 * std::max(0.0, (-p * s[0] - q * s[1] + s[2]) / length);
      EXPECT_NEAR(sunIrradiance->GetComponent(i + j * n, 0), expected, 1e-3 * expected) << i << " " << j;
    }
}
