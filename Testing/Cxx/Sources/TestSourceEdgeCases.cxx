// Sources and writer under hostile and unusual input: rasters of every orientation,
// rows past the pole, implausible heights, bad boxes, NaN parameters, clear skies at
// high sites, wrong writer inputs. Right answers or an error naming the fix.
#include "test_lights.h"
#include "test_rasters.h"
#include "vtk_test_support.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"
#include "vtkTerrainRasterWriter.h"
#include "vtkTerrainSource.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

using terralux_test::MessageCatcher;
using terralux_test::RasterSpec;
using terralux_test::runPipeline;
using terralux_test::uniformSky;
using terralux_test::writeRaster;

namespace
{
// A 20 x 16 UTM 32N raster of 30 m posts, a plane rising to the east: 100 + 0.1 x.
RasterSpec planeSpec(std::array<double, 6> geoTransform)
{
  RasterSpec spec;
  spec.width = 20;
  spec.height = 16;
  spec.crs = "EPSG:32632";
  spec.geoTransform = geoTransform;
  spec.elevation = [geoTransform](int col, int row) {
    const double x = geoTransform[0] + (col + 0.5) * geoTransform[1] + (row + 0.5) * geoTransform[2];
    return 100.0 + 0.1 * (x - 380000.0);
  };
  return spec;
}

// Upward normal of every cell: the z of (p10 - p00) x (p01 - p00) > 0.
bool allCellsFaceUp(vtkStructuredGrid* grid)
{
  int dims[3];
  grid->GetDimensions(dims);
  for (int j = 0; j + 1 < dims[1]; ++j)
    for (int i = 0; i + 1 < dims[0]; ++i)
    {
      double a[3], b[3], c[3];
      grid->GetPoint(i + j * dims[0], a);
      grid->GetPoint(i + 1 + j * dims[0], b);
      grid->GetPoint(i + (j + 1) * dims[0], c);
      const double z = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if (!(z > 0.0))
        return false;
    }
  return true;
}

double rasterValue(const std::string& path, int col, int row)
{
  GDALAllRegister();
  std::unique_ptr<GDALDataset> data(static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)));
  float value = 0.0f;
  EXPECT_EQ(data->GetRasterBand(1)->RasterIO(GF_Read, col, row, 1, 1, &value, 1, 1, GDT_Float32, 0, 0, nullptr),
    CE_None);
  return value;
}
} // namespace

TEST(SourceEdgeCases, EveryOrientationOfTheRasterFacesUp)
{
  // North-up, negative pixel width (columns run west), south-up (rows run north), both,
  // and rotated by 30 degrees: the same plane, facing up, lit by the whole sky, and
  // written back onto the raster's own grid.
  const double x0 = 380000.0, y0 = 5080000.0, s = 30.0;
  const double c = std::cos(M_PI / 6), n = std::sin(M_PI / 6);
  const std::pair<const char*, std::array<double, 6>> cases[] = {
    { "north-up", { x0, s, 0, y0, 0, -s } },
    { "west-running", { x0 + 20 * s, -s, 0, y0, 0, -s } },
    { "south-up", { x0, s, 0, y0 - 16 * s, 0, s } },
    { "both", { x0 + 20 * s, -s, 0, y0 - 16 * s, 0, s } },
    { "rotated", { x0, s * c, -s * n, y0, -s * n, -s * c } },
    { "rotated mirror", { x0, s * c, s * n, y0, -s * n, s * c } },
  };
  auto sky = uniformSky(100.0);
  for (const auto& [name, transform] : cases)
  {
    SCOPED_TRACE(name);
    const std::string path = writeRaster(std::string("orientation-") + name + ".tif", planeSpec(transform));
    vtkNew<vtkTerrainSource> terrain;
    terrain->SetFileName(path.c_str());
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(terrain, messages), 1) << messages->Errors;
    EXPECT_TRUE(allCellsFaceUp(terrain->GetOutput()));

    vtkNew<vtkHierarchicalRadiosity> radiosity;
    radiosity->SetInputConnection(terrain->GetOutputPort());
    radiosity->AddLightConnection(sky->GetOutputPort(0));
    radiosity->SetDefaultReflectance(0.0);
    vtkNew<MessageCatcher> solveMessages;
    ASSERT_EQ(runPipeline(radiosity, solveMessages), 1) << solveMessages->Errors;
    auto* lit = vtkStructuredGrid::SafeDownCast(radiosity->GetOutput());
    vtkDataArray* skyIrradiance = lit->GetPointData()->GetArray("SkyIrradiance");
    // A plane of slope atan(0.1) (0.1 m per east metre) sees (1 + cos b) / 2 of the sky.
    const double expected = 100.0 * (1.0 + std::cos(std::atan(0.1))) / 2.0;
    for (vtkIdType k = 0; k < lit->GetNumberOfPoints(); k += 13)
      EXPECT_NEAR(skyIrradiance->GetComponent(k, 0), expected, 0.01 * expected) << k;

    // Elevation written back lands on the raster's own pixels.
    vtkNew<vtkTerrainRasterWriter> writer;
    writer->SetInputConnection(terrain->GetOutputPort());
    writer->AddArrayName("Elevation");
    const std::string out = terralux_test::scratchDir() + "/orientation-out-" + name + ".tif";
    writer->SetFileName(out.c_str());
    ASSERT_EQ(writer->Write(), 1);
    const RasterSpec spec = planeSpec(transform);
    for (const auto& [col, row] : { std::pair<int, int>{ 0, 0 }, { 19, 0 }, { 3, 15 }, { 11, 7 } })
      EXPECT_NEAR(rasterValue(out, col, row), spec.elevation(col, row), 1e-3);
  }
}

TEST(SourceEdgeCases, RowsPastThePoleAreRefused)
{
  RasterSpec spec;
  spec.width = 10;
  spec.height = 20;
  spec.crs = "EPSG:4326";
  spec.geoTransform = { 10.0, 0.1, 0.0, 91.0, 0.0, -0.2 }; // rows start beyond 90 N
  spec.elevation = [](int, int) { return 100.0; };
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(writeRaster("past-pole.tif", spec).c_str());
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(terrain, messages), 0);
  EXPECT_NE(messages->Errors.find("latitude 90"), std::string::npos) << messages->Errors;
  EXPECT_EQ(terrain->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SourceEdgeCases, ImplausibleHeightsAreNoData)
{
  // One post of 1e30 m in a 32 x 32 DEM: that post is no data, the rest is solved.
  RasterSpec spec = planeSpec({ 380000.0, 30.0, 0, 5080000.0, 0, -30.0 });
  spec.width = spec.height = 32;
  spec.elevation = [](int col, int row) { return col == 5 && row == 7 ? 1e30 : 200.0; };
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(writeRaster("spike.tif", spec).c_str());
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(terrain, messages), 1) << messages->Errors;
  EXPECT_NE(messages->Warnings.find("1 post(s)"), std::string::npos) << messages->Warnings;
  vtkStructuredGrid* grid = terrain->GetOutput();
  double bounds[6];
  grid->GetBounds(bounds);
  EXPECT_LT(bounds[5] - bounds[4], 1.0); // flat: no spike
  auto sky = uniformSky(100.0);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputConnection(terrain->GetOutputPort());
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  vtkNew<MessageCatcher> solveMessages;
  ASSERT_EQ(runPipeline(radiosity, solveMessages), 1) << solveMessages->Errors;
  auto* lit = vtkStructuredGrid::SafeDownCast(radiosity->GetOutput());
  EXPECT_NEAR(lit->GetPointData()->GetArray("SkyIrradiance")->GetComponent(0, 0), 100.0, 1.0);

  // The same in a height-field image.
  vtkNew<vtkImageData> image;
  image->SetDimensions(8, 8, 1);
  image->SetSpacing(10, 10, 1);
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(64);
  heights->Fill(50.0f);
  heights->SetValue(9, -20000.0f);
  image->GetPointData()->SetScalars(heights);
  vtkNew<vtkTerrainSource> field;
  field->SetInputData(image);
  vtkNew<MessageCatcher> fieldMessages;
  ASSERT_EQ(runPipeline(field, fieldMessages), 1) << fieldMessages->Errors;
  EXPECT_NE(fieldMessages->Warnings.find("1 height(s)"), std::string::npos) << fieldMessages->Warnings;
  EXPECT_TRUE(std::isnan(field->GetOutput()->GetPointData()->GetArray("Elevation")->GetComponent(9, 0)));
}

TEST(SourceEdgeCases, BadBoxesAndSpacingsAreRefused)
{
  RasterSpec spec = planeSpec({ 380000.0, 30.0, 0, 5080000.0, 0, -30.0 });
  const std::string path = writeRaster("boxes.tif", spec);
  const std::array<double, 4> boxes[] = { { 45.9, 45.8, 7.4, 7.5 }, { NAN, 45.9, 7.4, 7.5 },
    { 45.8, 45.9, 7.5, 7.4 }, { 45.8, 45.8, 7.4, 7.5 } };
  for (const auto& b : boxes)
  {
    vtkNew<vtkTerrainSource> terrain;
    terrain->SetFileName(path.c_str());
    terrain->SetGeoBounds(b[0], b[1], b[2], b[3]);
    terrain->UseGeoBoundsOn();
    vtkNew<MessageCatcher> messages;
    EXPECT_EQ(runPipeline(terrain, messages), 0) << b[0] << " " << b[1];
    EXPECT_NE(messages->Errors.find("not a geographic box"), std::string::npos) << messages->Errors;
  }
  for (double spacing : { double(NAN), 0.0, double(INFINITY) })
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 1);
    image->SetSpacing(spacing, 10, 1);
    vtkNew<vtkFloatArray> heights;
    heights->SetNumberOfTuples(16);
    heights->Fill(5.0f);
    image->GetPointData()->SetScalars(heights);
    vtkNew<vtkTerrainSource> field;
    field->SetInputData(image);
    vtkNew<MessageCatcher> messages;
    EXPECT_EQ(runPipeline(field, messages), 0) << spacing;
    EXPECT_NE(messages->Errors.find("spacing"), std::string::npos) << messages->Errors;
  }
}

TEST(SourceEdgeCases, GeoBoundsAreUsedOnceSetAndNaNAnywhereIsRefused)
{
  const std::string path = writeRaster("setboxes.tif", planeSpec({ 380000.0, 30.0, 0, 5080000.0, 0, -30.0 }));
  // Setting a box turns UseGeoBounds on: a box beside the raster is an error, not the
  // whole raster with a warning.
  vtkNew<vtkTerrainSource> beside;
  beside->SetFileName(path.c_str());
  beside->SetGeoBounds(10.0, 11.0, 10.0, 11.0);
  EXPECT_TRUE(beside->GetUseGeoBounds());
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(beside, messages), 0);
  EXPECT_NE(messages->Errors.find("does not overlap"), std::string::npos) << messages->Errors;
  EXPECT_EQ(beside->GetOutput()->GetNumberOfPoints(), 0);
  // NaN is refused even with the box turned off.
  vtkNew<vtkTerrainSource> nan;
  nan->SetFileName(path.c_str());
  nan->SetGeoBounds(NAN, 45.9, 7.4, 7.5);
  nan->UseGeoBoundsOff();
  vtkNew<MessageCatcher> nanMessages;
  EXPECT_EQ(runPipeline(nan, nanMessages), 0);
  EXPECT_NE(nanMessages->Errors.find("not a geographic box"), std::string::npos) << nanMessages->Errors;
  EXPECT_EQ(nan->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SourceEdgeCases, GeoBoundsAcrossTheAntimeridianReadTheRightWindow)
{
  // Geographic rasters of 0.01 deg pixels around the antimeridian: one from 179 to
  // 181 E, one from -181 to -179, one the whole globe. The box runs from 179.9 E to
  // 180.2 E (-179.8): 30 columns where a raster holds it whole.
  auto raster = [](const char* name, double west, int width, double pixel) {
    RasterSpec spec;
    spec.width = width;
    spec.height = 40;
    spec.crs = "EPSG:4326";
    spec.geoTransform = { west, pixel, 0.0, 50.0, 0.0, -pixel };
    spec.elevation = [](int col, int) { return 100.0 + col; };
    return writeRaster(name, spec);
  };
  for (const auto& [name, west, expectedWest] : { std::tuple<const char*, double, double>{ "east.tif", 179.0, 179.9 },
         std::tuple<const char*, double, double>{ "west.tif", -181.0, -180.1 } })
  {
    vtkNew<vtkTerrainSource> terrain;
    terrain->SetFileName(raster(name, west, 200, 0.01).c_str());
    terrain->SetGeoBounds(49.8, 49.9, 179.9, 180.2);
    vtkNew<MessageCatcher> messages;
    ASSERT_EQ(runPipeline(terrain, messages), 1) << name << messages->Errors;
    int dims[3];
    terrain->GetOutput()->GetDimensions(dims);
    EXPECT_NEAR(dims[0], 30, 1) << name;
    vtkDataArray* transform = terrain->GetOutput()->GetFieldData()->GetArray("GeoTransform");
    ASSERT_NE(transform, nullptr);
    EXPECT_NEAR(transform->GetComponent(0, 0), expectedWest, 0.011) << name;
  }
  vtkNew<vtkTerrainSource> globe;
  globe->SetFileName(raster("globe.tif", -180.0, 360, 1.0).c_str());
  globe->SetGeoBounds(49.0, 50.0, 179.9, 180.2);
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(globe, messages), 0);
  EXPECT_NE(messages->Errors.find("wraps around the raster's edge"), std::string::npos) << messages->Errors;
  EXPECT_EQ(globe->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SourceEdgeCases, NaNParametersOfTheSunAndSkyAreRefused)
{
  using SunSetter = void (*)(vtkSunSource*);
  const std::pair<const char*, SunSetter> sunCases[] = {
    { "LinkeTurbidity", [](vtkSunSource* s) { s->SetLinkeTurbidity(std::nan("")); } },
    { "SolarConstant", [](vtkSunSource* s) { s->SetSolarConstant(std::nan("")); } },
    { "Latitude", [](vtkSunSource* s) { s->SetLatitude(std::nan("")); } },
    { "Pressure", [](vtkSunSource* s) { s->SetPressure(std::nan("")); } },
    { "DeltaT", [](vtkSunSource* s) { s->SetDeltaT(std::nan("")); } },
  };
  for (const auto& [name, set] : sunCases)
  {
    SCOPED_TRACE(name);
    vtkNew<vtkSunSource> sun;
    sun->SetDateTime("2024-06-21T12:00:00+02:00");
    set(sun);
    vtkNew<MessageCatcher> messages;
    EXPECT_EQ(runPipeline(sun, messages), 0);
    EXPECT_NE(messages->Errors.find(std::string(name) + " is NaN"), std::string::npos) << messages->Errors;
  }
  using SkySetter = void (*)(vtkSkySource*);
  const std::pair<const char*, SkySetter> skyCases[] = {
    { "DiffuseHorizontalIrradiance", [](vtkSkySource* s) { s->SetDiffuseHorizontalIrradiance(std::nan("")); } },
    { "SunZenith", [](vtkSkySource* s) { s->SetSunZenith(std::nan("")); } },
    { "SunAzimuth", [](vtkSkySource* s) { s->SetSunAzimuth(std::nan("")); } },
  };
  for (const auto& [name, set] : skyCases)
  {
    SCOPED_TRACE(name);
    vtkNew<vtkSkySource> sky;
    sky->UseSunSourceOff();
    set(sky);
    vtkNew<MessageCatcher> messages;
    EXPECT_EQ(runPipeline(sky, messages), 0);
    EXPECT_NE(messages->Errors.find(std::string(name) + " is NaN"), std::string::npos) << messages->Errors;
    EXPECT_EQ(sky->GetRadianceOutput()->GetNumberOfPoints(), 0);
  }
}

TEST(SourceEdgeCases, ClearSkyAtHighSitesStaysBelowTheExtraterrestrial)
{
  for (double linke : { 0.5, 1.0, 2.0, 3.0 })
  {
    vtkNew<vtkSunSource> sun;
    sun->SetDateTime("2024-06-21T12:00:00+02:00");
    sun->SetLatitude(28.0);
    sun->SetLongitude(86.9);
    sun->SetHeight(8000.0);
    sun->SetIrradianceModelToIneichenPerez();
    sun->SetLinkeTurbidity(linke);
    sun->Update();
    EXPECT_LE(sun->GetNormalIrradiance(), sun->GetExtraterrestrialIrradiance()) << linke;
    EXPECT_GT(sun->GetNormalIrradiance(), 0.8 * sun->GetExtraterrestrialIrradiance()) << linke;
  }
}

TEST(SourceEdgeCases, WriterRefusesWhatItCannotWrite)
{
  vtkNew<vtkPolyData> notAGrid;
  vtkNew<vtkTerrainRasterWriter> writer;
  writer->SetInputData(notAGrid);
  const std::string out = terralux_test::scratchDir() + "/not-a-grid.tif";
  writer->SetFileName(out.c_str());
  vtkNew<MessageCatcher> messages;
  writer->AddObserver(vtkCommand::ErrorEvent, messages);
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_NE(messages->Errors.find("vtkStructuredGrid"), std::string::npos) << messages->Errors;

  // A value beyond float32 is written as no data, not as infinity.
  RasterSpec spec = planeSpec({ 380000.0, 30.0, 0, 5080000.0, 0, -30.0 });
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(writeRaster("overflow.tif", spec).c_str());
  terrain->Update();
  vtkNew<vtkStructuredGrid> grid;
  grid->ShallowCopy(terrain->GetOutput());
  vtkNew<vtkDoubleArray> huge;
  huge->SetName("Huge");
  huge->SetNumberOfTuples(grid->GetNumberOfPoints());
  huge->Fill(1e39);
  grid->GetPointData()->AddArray(huge);
  vtkNew<vtkTerrainRasterWriter> hugeWriter;
  hugeWriter->SetInputData(grid);
  hugeWriter->AddArrayName("Huge");
  const std::string hugeOut = terralux_test::scratchDir() + "/overflow-out.tif";
  hugeWriter->SetFileName(hugeOut.c_str());
  ASSERT_EQ(hugeWriter->Write(), 1);
  EXPECT_EQ(rasterValue(hugeOut, 3, 3), -9999.0);

  // A georeference that is not one (NaN, or a singular transform) writes no file.
  for (double bad : { double(NAN), 0.0 })
  {
    vtkNew<vtkStructuredGrid> badGrid;
    badGrid->DeepCopy(terrain->GetOutput());
    vtkDataArray* transform = badGrid->GetFieldData()->GetArray("GeoTransform");
    transform->SetComponent(1, 0, bad);
    transform->SetComponent(2, 0, 0.0);
    vtkNew<vtkTerrainRasterWriter> badWriter;
    badWriter->SetInputData(badGrid);
    badWriter->AddArrayName("Elevation");
    const std::string badOut = terralux_test::scratchDir() + "/bad-transform.tif";
    std::remove(badOut.c_str());
    badWriter->SetFileName(badOut.c_str());
    vtkNew<MessageCatcher> badMessages;
    badWriter->AddObserver(vtkCommand::ErrorEvent, badMessages);
    EXPECT_EQ(badWriter->Write(), 0);
    EXPECT_NE(badMessages->Errors.find("GeoTransform"), std::string::npos) << badMessages->Errors;
    EXPECT_EQ(std::fopen(badOut.c_str(), "rb"), nullptr);
    // The input keeps its (bad) field data: nothing of it was modified.
    EXPECT_EQ(std::isnan(transform->GetComponent(1, 0)), std::isnan(bad));
  }
}

// Regression tests of the fuzzers' findings (Testing/Fuzz/corpus/*/finding-*).
TEST(SourceEdgeCases, FuzzFindingsStayFixed)
{
  // A geotransform whose posts overflow to infinite coordinates (no CRS).
  RasterSpec overflow;
  overflow.width = 4;
  overflow.height = 3;
  overflow.geoTransform = { -1e308, -1e308, 0, 0, 0, -1 };
  overflow.elevation = [](int, int) { return 15.0; };
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(writeRaster("overflow-transform.tif", overflow).c_str());
  vtkNew<MessageCatcher> messages;
  EXPECT_EQ(runPipeline(terrain, messages), 0);
  EXPECT_NE(messages->Errors.find("infinite or NaN coordinates"), std::string::npos) << messages->Errors;

  // A height field whose spacing carries points beyond float range.
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 3, 1);
  image->SetSpacing(1e38, 10, 1); // 4e38 m: beyond single precision
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(15);
  heights->Fill(5.0f);
  image->GetPointData()->SetScalars(heights);
  vtkNew<vtkTerrainSource> field;
  field->SetInputData(image);
  vtkNew<MessageCatcher> fieldMessages;
  EXPECT_EQ(runPipeline(field, fieldMessages), 0);
  EXPECT_NE(fieldMessages->Errors.find("infinite coordinates"), std::string::npos) << fieldMessages->Errors;

  // A sun at an absurd longitude or height.
  for (auto [longitude, height] : { std::pair<double, double>{ -2.2e256, 0.0 }, { 8.0, -1.9e44 } })
  {
    vtkNew<vtkSunSource> sun;
    sun->SetDateTime("2024-12-21T09:00:00-03:00");
    sun->SetLongitude(longitude);
    sun->SetHeight(height);
    vtkNew<MessageCatcher> sunMessages;
    EXPECT_EQ(runPipeline(sun, sunMessages), 0);
    EXPECT_NE(sunMessages->Errors.find("out of range"), std::string::npos) << sunMessages->Errors;
  }
}
