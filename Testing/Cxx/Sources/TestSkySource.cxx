// vtkSkySource: terrain -> sun -> sky, map integrals against closed forms, texture,
// bad input.
#include "sun_sky_checks.h"
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

using namespace terralux_test;

namespace
{
// Horizontal irradiance from the map: sum of cell radiance times the integral of
// sin(altitude) over the cell's solid angle.
double mapHorizontalIrradiance(vtkImageData* map, int band = 0)
{
  int dims[3];
  map->GetDimensions(dims);
  const int nx = dims[0] - 1, ny = dims[1] - 1;
  vtkDataArray* radiance = map->GetCellData()->GetArray("Radiance");
  double sum = 0.0;
  for (int j = 0; j < ny; ++j)
  {
    const double u0 = 0.5 * M_PI * j / ny, u1 = 0.5 * M_PI * (j + 1) / ny;
    const double weight = (2.0 * M_PI / nx) * 0.5 * (std::pow(std::sin(u1), 2) - std::pow(std::sin(u0), 2));
    for (int i = 0; i < nx; ++i)
      sum += radiance->GetComponent(i + j * nx, band) * weight;
  }
  return sum;
}
} // namespace

TEST(SkySource, MapIntegratesToTheDiffuseIrradiance)
{
  vtkNew<vtkSkySource> sky;
  sky->SetDiffuseHorizontalIrradiance(137.0);
  for (int type = 1; type <= 15; type += 7)
  {
    sky->SetSkyType(type);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(sky, messages), 1) << messages->Errors;
    vtkImageData* map = sky->GetRadianceOutput();
    int dims[3];
    map->GetDimensions(dims);
    EXPECT_EQ(dims[0], 129);
    EXPECT_EQ(dims[1], 129);
    EXPECT_NEAR(mapHorizontalIrradiance(map) / 137.0, 1.0, 1e-3) << type;
    EXPECT_NEAR(field(map, "HorizontalIrradiance"), 137.0, 1e-9);
    double omega = 0.0;
    vtkDataArray* solidAngle = map->GetCellData()->GetArray("SolidAngle");
    for (vtkIdType k = 0; k < solidAngle->GetNumberOfTuples(); ++k)
      omega += solidAngle->GetComponent(k, 0);
    EXPECT_NEAR(omega, 2.0 * M_PI, 1e-9);
  }
  // Clear sky, sun at azimuth 180 (south): the brightest cell is near it in the map's
  // compass-azimuth axis, i.e. around x = 180 deg, y = 45 deg.
  sky->SetSkyType(12);
  sky->Update();
  vtkImageData* map = sky->GetRadianceOutput();
  vtkDataArray* radiance = map->GetCellData()->GetArray("Radiance");
  vtkIdType brightest = 0;
  for (vtkIdType k = 0; k < radiance->GetNumberOfTuples(); ++k)
    if (radiance->GetComponent(k, 0) > radiance->GetComponent(brightest, 0))
      brightest = k;
  const double azimuth = (brightest % 128 + 0.5) * 360.0 / 128;
  const double altitude = (brightest / 128 + 0.5) * 90.0 / 128;
  EXPECT_NEAR(azimuth, 180.0, 3.0);
  EXPECT_NEAR(altitude, 45.0, 2.0);
  // The dome: one quad per map cell, same radiance.
  vtkPolyData* dome = sky->GetDomeOutput();
  EXPECT_EQ(dome->GetNumberOfPolys(), 128 * 128);
  EXPECT_EQ(dome->GetCellData()->GetArray("Radiance")->GetComponent(brightest, 0),
    radiance->GetComponent(brightest, 0));
}

TEST(SkySource, TerrainSunSkyPipeline)
{
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2024-06-21T10:00:00+02:00");
  sun->SetLatitude(46.0);
  sun->SetLongitude(7.0);
  vtkNew<vtkSkySource> sky;
  sky->SetSunConnection(sun->GetOutputPort());
  sky->SetSkyModelToPerez();
  sky->SetLevels(6);
  ASSERT_EQ(sky->GetExecutive()->Update(), 1);
  vtkImageData* map = sky->GetRadianceOutput();
  EXPECT_NEAR(field(map, "SunZenith"), sun->GetZenith(), 1e-12);
  EXPECT_NEAR(field(map, "DiffuseHorizontalIrradiance"), sun->GetDiffuseHorizontalIrradiance(), 1e-12);
  EXPECT_NEAR(mapHorizontalIrradiance(map) / sun->GetDiffuseHorizontalIrradiance(), 1.0, 1e-3);
  EXPECT_GT(field(map, "SkyClearness"), 4.5); // a clear-sky input is a clear Perez sky

  // At night the sky is black, without error.
  sun->SetDateTime("2024-06-21T23:30:00+02:00");
  ASSERT_EQ(sky->GetExecutive()->Update(), 1);
  EXPECT_EQ(map->GetCellData()->GetArray("Radiance")->GetRange()[1], 0.0);
}

TEST(SkySource, TextureGivesBands)
{
  vtkNew<vtkImageData> clouds;
  clouds->SetDimensions(9, 5, 1);
  vtkNew<vtkFloatArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(45);
  for (vtkIdType k = 0; k < 45; ++k)
  {
    rgb->SetTuple3(k, 1.0, 0.8, 0.6);
  }
  clouds->GetPointData()->SetScalars(rgb);
  vtkNew<vtkSkySource> sky;
  sky->SetSkyModelToUniform();
  sky->SetDiffuseHorizontalIrradiance(100.0);
  sky->SetInputDataObject(1, clouds);
  sky->SetLevels(5);
  ASSERT_EQ(sky->GetExecutive()->Update(), 1);
  vtkImageData* map = sky->GetRadianceOutput();
  EXPECT_EQ(map->GetCellData()->GetArray("Radiance")->GetNumberOfComponents(), 3);
  // The texture is float: 0.8f and 0.6f, to 1e-7 relative.
  EXPECT_NEAR(mapHorizontalIrradiance(map, 1), 80.0, 1e-4);
  EXPECT_NEAR(field(map, "HorizontalIrradiance", 2), 60.0, 1e-4);

  rgb->SetTuple3(3, -1.0, 0.0, 0.0);
  rgb->Modified();
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(sky, messages), 0);
  EXPECT_NE(messages->Errors.find("negative"), std::string::npos);
  EXPECT_EQ(sky->GetRadianceOutput()->GetNumberOfCells(), 0);
}

TEST(SkySource, SunAtZenithAndOnTheHorizon)
{
  vtkNew<vtkSkySource> sky;
  sky->SetLevels(5);
  for (double zenith : { 0.0, 90.0, 90.5 })
    for (int model : { vtkSkySource::CIE_GENERAL, vtkSkySource::PEREZ })
    {
      sky->SetSunZenith(zenith);
      sky->SetSkyModel(model);
      ASSERT_EQ(sky->GetExecutive()->Update(), 1);
      double range[2];
      sky->GetRadianceOutput()->GetCellData()->GetArray("Radiance")->GetRange(range);
      EXPECT_TRUE(std::isfinite(range[0]) && std::isfinite(range[1]));
      EXPECT_GE(range[0], 0.0);
    }
}
