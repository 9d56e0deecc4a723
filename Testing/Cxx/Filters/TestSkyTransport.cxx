// Sky transport against closed forms: an open flat terrain (reflectance 0) receives
// exactly the diffuse horizontal irradiance the sky is scaled to, for every sky model
// and sun position, in both output modes; a tilted plane under a uniform sky
// receives pi L (1 + cos b) / 2.
#include "vtk_test_support.h"

#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkTerrainSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using terralux_test::MessageCatcher;
using terralux_test::runPipeline;

namespace
{
vtkSmartPointer<vtkTerrainSource> heightField(int n, double spacing, const std::function<double(double, double)>& z)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, 1);
  image->SetSpacing(spacing, spacing, 1.0);
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      heights->SetValue(i + j * n, static_cast<float>(z(i * spacing, j * spacing)));
  image->GetPointData()->SetScalars(heights);
  auto terrain = vtkSmartPointer<vtkTerrainSource>::New();
  terrain->SetInputData(image);
  return terrain;
}

// Largest relative deviation of SkyIrradiance from `expected` over the posts.
double worstSkyError(vtkTerrainSource* terrain, vtkSkySource* sky, bool atPoints, double expected)
{
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputConnection(terrain->GetOutputPort());
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  radiosity->SetDefaultReflectance(0.0);
  radiosity->SetEvaluateAtPoints(atPoints);
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
  vtkDataArray* values = vtkDataSet::SafeDownCast(radiosity->GetOutput())->GetPointData()->GetArray("SkyIrradiance");
  double worst = 0.0;
  for (vtkIdType k = 0; k < values->GetNumberOfTuples(); ++k)
    worst = std::max(worst, std::abs(values->GetComponent(k, 0) / expected - 1.0));
  return worst;
}
} // namespace

TEST(SkyTransport, OpenFlatTerrainReceivesTheDiffuseHorizontalIrradiance)
{
  auto terrain = heightField(12, 30.0, [](double, double) { return 100.0; });
  struct Sky
  {
    int model;
    int type;
  };
  std::vector<Sky> skies;
  for (int type = 1; type <= 15; ++type)
    skies.push_back({ vtkSkySource::CIE_GENERAL, type });
  skies.push_back({ vtkSkySource::CIE_OVERCAST, 0 });
  skies.push_back({ vtkSkySource::PEREZ, 0 });
  skies.push_back({ vtkSkySource::UNIFORM, 0 });
  for (const Sky& s : skies)
    for (double zenith : { 0.0, 10.0, 45.0, 85.0, 89.0 })
    {
      SCOPED_TRACE(std::to_string(s.model) + " type " + std::to_string(s.type) + " zenith " + std::to_string(zenith));
      vtkNew<vtkSkySource> sky;
      sky->UseSunSourceOff();
      sky->SetSkyModel(s.model);
      if (s.type > 0)
        sky->SetSkyType(s.type);
      sky->SetSunZenith(zenith);
      sky->SetSunAzimuth(135.0);
      sky->SetDiffuseHorizontalIrradiance(100.0);
      for (bool atPoints : { true, false })
        EXPECT_LT(worstSkyError(terrain, sky, atPoints, 100.0), 1e-3) << (atPoints ? "at points" : "averaged");
    }
}

TEST(SkyTransport, TiltedPlaneUnderAUniformSky)
{
  for (double slope : { 10.0, 30.0, 60.0 })
  {
    SCOPED_TRACE(slope);
    const double t = std::tan(slope * M_PI / 180.0);
    auto terrain = heightField(12, 10.0, [t](double x, double) { return 100.0 + t * x; });
    vtkNew<vtkSkySource> sky;
    sky->UseSunSourceOff();
    sky->SetSkyModelToUniform();
    sky->SetDiffuseHorizontalIrradiance(100.0);
    const double expected = 100.0 * (1.0 + std::cos(slope * M_PI / 180.0)) / 2.0;
    for (bool atPoints : { true, false })
      EXPECT_LT(worstSkyError(terrain, sky, atPoints, expected), 1e-3) << atPoints;
  }
}

TEST(SkyTransport, ValleyBottomPostsSeeCosOfTheSlopeFromTheirHorizons)
{
  // A straight V valley 2 km long whose sides rise at `slope` to 50 m: a post on its
  // floor sees a uniform sky's cos(slope) (horizons at atan(tan b |sin phi|) across
  // the valley's axis). Evaluated at the posts, the sky comes from the horizons of all
  // posts found at once (SecondsHorizons), not from rays.
  for (double slope : { 20.0, 40.0 })
  {
    SCOPED_TRACE(slope);
    const double t = std::tan(slope * M_PI / 180.0);
    auto terrain = heightField(201, 10.0, [t](double, double y) { return std::min(50.0, std::abs(y - 1000.0) * t); });
    vtkNew<vtkSkySource> sky;
    sky->UseSunSourceOff();
    sky->SetSkyModelToUniform();
    sky->SetDiffuseHorizontalIrradiance(100.0);
    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputConnection(terrain->GetOutputPort());
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetDefaultReflectance(0.0);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    vtkDataSet* output = vtkDataSet::SafeDownCast(radiosity->GetOutput());
    vtkFieldData* field = output->GetFieldData();
    EXPECT_GT(field->GetArray("SecondsHorizons")->GetTuple1(0), 0.0);
    // The lattice of posts gathered first is a part of the points' phase, in rays and
    // time (no rays here: nothing but the sky of the horizons reaches the posts).
    EXPECT_EQ(field->GetArray("RaysLattice")->GetTuple1(0), 0.0);
    EXPECT_GT(field->GetArray("SecondsLattice")->GetTuple1(0), 0.0);
    EXPECT_LE(field->GetArray("SecondsLattice")->GetTuple1(0), field->GetArray("SecondsPoints")->GetTuple1(0));
    vtkDataArray* values = output->GetPointData()->GetArray("SkyIrradiance");
    // The floor's posts (row 100), away from the valley's ends.
    for (int i = 60; i <= 140; i += 8)
      EXPECT_NEAR(values->GetComponent(i + 100 * 201, 0), 100.0 * std::cos(slope * M_PI / 180.0), 0.5) << i;
    // With light from the valley's sides, the lattice's posts gather it with rays.
    radiosity->SetDefaultReflectance(0.3);
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    field = vtkDataSet::SafeDownCast(radiosity->GetOutput())->GetFieldData();
    EXPECT_GT(field->GetArray("RaysLattice")->GetTuple1(0), 0.0);
    EXPECT_LT(field->GetArray("RaysLattice")->GetTuple1(0), field->GetArray("RaysPoints")->GetTuple1(0));
    // The interpolated output needs no horizons.
    radiosity->SetEvaluateAtPoints(false);
    ASSERT_EQ(runPipeline(radiosity, messages), 1) << messages->Errors;
    output = vtkDataSet::SafeDownCast(radiosity->GetOutput());
    EXPECT_EQ(output->GetFieldData()->GetArray("SecondsHorizons")->GetTuple1(0), 0.0);
    EXPECT_EQ(output->GetFieldData()->GetArray("RaysLattice")->GetTuple1(0), 0.0);
  }
}
