// vtkSunSource: the SPA case through VTK, the place from a terrain, below-horizon
// behaviour, bad input.
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

TEST(SunSource, NrelSpaReferenceCase)
{
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2003-10-17T12:30:30-07:00");
  sun->SetLatitude(39.742476);
  sun->SetLongitude(-105.1786);
  sun->SetHeight(1830.14);
  sun->SetPressure(820.0);
  sun->SetTemperature(11.0);
  sun->SetDeltaT(67.0);
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(sun, messages), 1) << messages->Errors;
  EXPECT_NEAR(sun->GetZenith(), 50.111622, 0.0003);
  EXPECT_NEAR(sun->GetAzimuth(), 194.340241, 0.0003);
  vtkPolyData* out = sun->GetOutput();
  EXPECT_DOUBLE_EQ(field(out, "SunZenith"), sun->GetZenith());
  EXPECT_DOUBLE_EQ(field(out, "SunAzimuth"), sun->GetAzimuth());
  // Direction: toward azimuth 194.3 (south-south-west), 39.9 deg up.
  const double* d = sun->GetDirection();
  EXPECT_NEAR(d[2], std::cos(50.111622 * M_PI / 180), 1e-9);
  EXPECT_LT(d[0], 0.0);
  EXPECT_LT(d[1], 0.0);
  EXPECT_NEAR(std::hypot(std::hypot(d[0], d[1]), d[2]), 1.0, 1e-12);
  double p[3];
  out->GetPoint(0, p);
  EXPECT_NEAR(p[2], 10000.0 * d[2], 1e-6);
  EXPECT_EQ(out->GetNumberOfVerts(), 1);
  EXPECT_EQ(vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("DateTime"))->GetValue(0),
    "2003-10-17T19:30:30.000Z");
  // ESRA at 1830 m, TL 3: a clear beam; diffuse 5-25 % of global.
  EXPECT_GT(sun->GetNormalIrradiance(), 800.0);
  EXPECT_LT(sun->GetNormalIrradiance(), sun->GetExtraterrestrialIrradiance());
  EXPECT_NEAR(sun->GetExtraterrestrialIrradiance(), 1367.0 / (0.9965423 * 0.9965423), 0.01);
  EXPECT_GT(field(out, "DiffuseHorizontalIrradiance"), 0.05 * field(out, "GlobalHorizontalIrradiance"));

  sun->SetAtmosphericRefraction(false);
  sun->Update();
  EXPECT_GT(sun->GetZenith(), 50.111622); // refraction lifts the sun
}

TEST(SunSource, BelowTheHorizonIsDarkButPlaced)
{
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2024-06-21T23:00:00+02:00");
  sun->SetLatitude(46.0);
  sun->SetLongitude(7.0);
  for (int model : { vtkSunSource::ESRA, vtkSunSource::INEICHEN_PEREZ, vtkSunSource::USER })
  {
    sun->SetIrradianceModel(model);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(sun, messages), 1);
    EXPECT_TRUE(messages->Errors.empty());
    EXPECT_GT(sun->GetZenith(), 90.0);
    EXPECT_EQ(sun->GetNormalIrradiance(), 0.0);
    EXPECT_EQ(sun->GetDiffuseHorizontalIrradiance(), 0.0);
    EXPECT_LT(sun->GetDirection()[2], 0.0);
  }
}

TEST(SunSource, UserIrradianceAndModels)
{
  vtkNew<vtkSunSource> sun;
  sun->SetDateTime("2024-06-21T12:00:00+02:00");
  sun->SetLatitude(46.0);
  sun->SetLongitude(7.0);
  sun->SetIrradianceModelToUser();
  sun->SetUserNormalIrradiance(640.0);
  sun->SetUserDiffuseHorizontalIrradiance(85.0);
  sun->Update();
  EXPECT_EQ(sun->GetNormalIrradiance(), 640.0);
  EXPECT_EQ(sun->GetDiffuseHorizontalIrradiance(), 85.0);
  sun->SetIrradianceModelToIneichenPerez();
  sun->Update();
  const double ineichen = sun->GetNormalIrradiance();
  sun->SetIrradianceModelToESRA();
  sun->Update();
  EXPECT_NEAR(sun->GetNormalIrradiance() / ineichen, 1.0, 0.08);
}

TEST(SunSource, PlaceFromTerrainGeoOrigin)
{
  terralux_test::RasterSpec spec;
  spec.width = spec.height = 5;
  spec.geoTransform = { 288776.25, 90.0, 0.0, 9120760.75, 0.0, -90.0 };
  spec.crs = "EPSG:32725";
  spec.elevation = [](int, int) { return 40.0; };
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(terralux_test::writeRaster("sun-terrain.tif", spec).c_str());
  vtkNew<vtkSunSource> sun;
  sun->SetInputConnection(terrain->GetOutputPort());
  sun->SetLatitude(60.0); // ignored: the terrain's GeoOrigin wins
  sun->SetDateTime("2024-03-20T12:00:00-03:00");
  sun->Update();
  vtkPolyData* out = sun->GetOutput();
  EXPECT_NEAR(field(out, "GeoOrigin", 0), field(terrain->GetOutput(), "GeoOrigin", 0), 1e-12);
  EXPECT_NEAR(field(out, "GeoOrigin", 2), 40.0, 1e-9);
  // Near the equator at the equinox around noon: high sun.
  EXPECT_LT(sun->GetZenith(), 20.0);

  // An input without GeoOrigin is an error, and the output is empty.
  vtkNew<vtkPolyData> plain;
  sun->SetInputData(plain);
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(sun, messages), 0);
  EXPECT_NE(messages->Errors.find("GeoOrigin"), std::string::npos);
  EXPECT_EQ(sun->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SunSource, BadDateTime)
{
  vtkNew<vtkSunSource> sun;
  for (const char* text : { "2024-06-21T12:00:00", "2024-02-30T12:00:00Z", "tomorrow" })
  {
    sun->SetDateTime(text);
    vtkNew<MessageCatcher> messages;
    EXPECT_EQ(runPipeline(sun, messages), 0) << text;
    EXPECT_FALSE(messages->Errors.empty());
    EXPECT_EQ(sun->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(sun->GetOutput()->GetFieldData()->GetNumberOfArrays(), 0);
  }
}
