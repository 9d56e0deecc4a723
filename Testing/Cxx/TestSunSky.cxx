// vtkSunSource and vtkSkySource: the SPA case through VTK, terrain -> sun -> sky,
// below-horizon behaviour, map integrals, texture, bad input.
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

using terralux_test::MessageCatcher;
using terralux_test::runPipeline;

namespace
{
double field(vtkDataObject* data, const char* name, int k = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  // Value k, whether the array holds tuples of one value or one tuple of several.
  return array ? array->GetComponent(k / array->GetNumberOfComponents(), k % array->GetNumberOfComponents()) : NAN;
}

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
