// vtkTerrainRasterWriter: results back on the DEM's own grid, read with GDAL's API.
#include "test_rasters.h"
#include "vtk_test_support.h"

#include "vtkDataArray.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"
#include "vtkTerrainRasterWriter.h"
#include "vtkTerrainSource.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using terralux_test::MessageCatcher;
using terralux_test::RasterSpec;
using terralux_test::runPipeline;

namespace
{
RasterSpec hillWithHole()
{
  RasterSpec spec;
  spec.width = 33;
  spec.height = 25;
  spec.geoTransform = { 500000.0, 30.0, 0.0, 5100000.0, 0.0, -30.0 };
  spec.crs = "EPSG:32633";
  spec.noData = -32768.0;
  spec.elevation = [](int col, int row) -> double {
    if (col >= 5 && col < 8 && row >= 4 && row < 6)
      return NAN;
    return 300.0 + 50.0 * std::exp(-((col - 16) * (col - 16) + (row - 12) * (row - 12)) / 40.0);
  };
  return spec;
}
} // namespace

TEST(TerrainRasterWriter, RadiosityResultsLandOnTheDemGrid)
{
  const RasterSpec spec = hillWithHole();
  const std::string dem = terralux_test::writeRaster("writer-dem.tif", spec);
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(dem.c_str());
  terrain->SetPixelWindow(2, 1, 29, 23);
  terrain->SetStride(2);
  vtkNew<vtkSunSource> sun;
  sun->SetInputConnection(terrain->GetOutputPort());
  sun->SetDateTime("2024-06-21T11:00:00+02:00");
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputConnection(terrain->GetOutputPort());
  radiosity->AddLightConnection(sun->GetOutputPort());
  const std::string out = terralux_test::scratchDir() + "/irradiance.tif";
  vtkNew<vtkTerrainRasterWriter> writer;
  writer->SetInputConnection(radiosity->GetOutputPort(0));
  writer->SetFileName(out.c_str());
  ASSERT_EQ(writer->Write(), 1);

  GDALAllRegister();
  std::unique_ptr<GDALDataset> written(GDALDataset::Open(out.c_str(), GDAL_OF_RASTER));
  std::unique_ptr<GDALDataset> source(GDALDataset::Open(dem.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(written && source);
  EXPECT_EQ(written->GetRasterXSize(), 15); // posts 2, 4, ..., 30
  EXPECT_EQ(written->GetRasterYSize(), 12); // posts 1, 3, ..., 23
  EXPECT_EQ(written->GetRasterCount(), 6); // the four irradiances, radiosity, IrradianceError
  EXPECT_TRUE(written->GetSpatialRef()->IsSame(source->GetSpatialRef()));
  // Compressed losslessly, after the floating-point predictor (the values are compared
  // exactly below).
  const char* compression = written->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE");
  const char* predictor = written->GetMetadataItem("PREDICTOR", "IMAGE_STRUCTURE");
  ASSERT_TRUE(compression && predictor);
  EXPECT_STREQ(compression, "DEFLATE");
  EXPECT_STREQ(predictor, "3");
  // Pixel centres of the written raster sit on the DEM posts that were kept.
  double gtw[6], gts[6];
  written->GetGeoTransform(gtw);
  source->GetGeoTransform(gts);
  for (int i : { 0, 7, 14 })
    for (int j : { 0, 11 })
    {
      const double xw = gtw[0] + (i + 0.5) * gtw[1] + (j + 0.5) * gtw[2];
      const double yw = gtw[3] + (i + 0.5) * gtw[4] + (j + 0.5) * gtw[5];
      const double xs = gts[0] + (2 + 2 * i + 0.5) * gts[1];
      const double ys = gts[3] + (1 + 2 * j + 0.5) * gts[5];
      EXPECT_NEAR(xw, xs, 1e-6);
      EXPECT_NEAR(yw, ys, 1e-6);
    }

  vtkStructuredGrid* grid = vtkStructuredGrid::SafeDownCast(radiosity->GetOutput());
  const char* names[] = { "Irradiance", "SunIrradiance", "SkyIrradiance", "ReflectedIrradiance", "Radiosity" };
  for (int b = 0; b < 5; ++b)
  {
    GDALRasterBand* band = written->GetRasterBand(b + 1);
    EXPECT_STREQ(band->GetDescription(), names[b]);
    EXPECT_STREQ(band->GetUnitType(), "W/m^2");
    int hasNoData = 0;
    EXPECT_EQ(band->GetNoDataValue(&hasNoData), -32768.0);
    EXPECT_TRUE(hasNoData);
    std::vector<float> values(15 * 12);
    ASSERT_EQ(band->RasterIO(GF_Read, 0, 0, 15, 12, values.data(), 15, 12, GDT_Float32, 0, 0, nullptr), CE_None);
    vtkDataArray* array = grid->GetPointData()->GetArray(names[b]);
    int nodata = 0;
    for (int row = 0; row < 12; ++row)
      for (int col = 0; col < 15; ++col)
      {
        const vtkIdType point = col + static_cast<vtkIdType>(11 - row) * 15;
        const float value = values[row * 15 + col];
        if (!grid->IsPointVisible(point))
        {
          EXPECT_EQ(value, -32768.0f);
          ++nodata;
        }
        else
        {
          EXPECT_EQ(value, static_cast<float>(array->GetComponent(point, 0)));
        }
      }
    EXPECT_GT(nodata, 0); // the hole survived the window and the stride
  }
}

TEST(TerrainRasterWriter, BadInput)
{
  vtkNew<vtkStructuredGrid> plain;
  plain->SetDimensions(2, 2, 1);
  vtkNew<vtkTerrainRasterWriter> writer;
  writer->SetInputData(plain);
  writer->SetFileName((terralux_test::scratchDir() + "/plain.tif").c_str());
  vtkNew<MessageCatcher> messages;
  writer->AddObserver(vtkCommand::ErrorEvent, messages);
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_NE(messages->Errors.find("georeference"), std::string::npos);

  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(terralux_test::writeRaster("writer-plain.tif", hillWithHole()).c_str());
  writer->SetInputConnection(terrain->GetOutputPort());
  writer->AddArrayName("Irradiance");
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_NE(messages->Errors.find("no point array 'Irradiance'"), std::string::npos);
  writer->RemoveAllArrayNames();
  writer->AddArrayName("Elevation");
  writer->AddArrayName("Elevation"); // named twice: written once, every post of it
  EXPECT_EQ(writer->Write(), 1);
  GDALAllRegister();
  std::unique_ptr<GDALDataset> written(
    GDALDataset::Open((terralux_test::scratchDir() + "/plain.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(written);
  EXPECT_EQ(written->GetRasterCount(), 1);
}

TEST(TerrainRasterWriter, PiecesWithAVrtOverThem)
{
  // One process: its one piece as <name>_0.tif and the VRT over it, the values of the
  // GeoTIFF the writer writes whole. Under MPI each rank adds its own piece
  // (Testing/MPI checks 2 and 3 ranks against 1).
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(terralux_test::writeRaster("writer-pieces.tif", hillWithHole()).c_str());
  const std::string dir = terralux_test::scratchDir();
  vtkNew<vtkTerrainRasterWriter> whole, pieces;
  for (vtkTerrainRasterWriter* writer : { whole.GetPointer(), pieces.GetPointer() })
  {
    writer->SetInputConnection(terrain->GetOutputPort());
    writer->AddArrayName("Elevation");
  }
  whole->SetFileName((dir + "/whole.tif").c_str());
  pieces->SetFileName((dir + "/pieces.vrt").c_str());
  pieces->WritePiecesOn();
  ASSERT_EQ(whole->Write(), 1);
  ASSERT_EQ(pieces->Write(), 1);

  GDALAllRegister();
  std::unique_ptr<GDALDataset> a(GDALDataset::Open((dir + "/whole.tif").c_str(), GDAL_OF_RASTER));
  std::unique_ptr<GDALDataset> b(GDALDataset::Open((dir + "/pieces.vrt").c_str(), GDAL_OF_RASTER));
  std::unique_ptr<GDALDataset> tile(GDALDataset::Open((dir + "/pieces_0.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(a && b && tile);
  ASSERT_EQ(b->GetRasterXSize(), a->GetRasterXSize());
  ASSERT_EQ(b->GetRasterYSize(), a->GetRasterYSize());
  EXPECT_STREQ(b->GetRasterBand(1)->GetDescription(), "Elevation");
  const int n = a->GetRasterXSize() * a->GetRasterYSize();
  std::vector<float> va(n), vb(n);
  ASSERT_EQ(a->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, a->GetRasterXSize(), a->GetRasterYSize(), va.data(),
              a->GetRasterXSize(), a->GetRasterYSize(), GDT_Float32, 0, 0, nullptr), CE_None);
  ASSERT_EQ(b->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, b->GetRasterXSize(), b->GetRasterYSize(), vb.data(),
              b->GetRasterXSize(), b->GetRasterYSize(), GDT_Float32, 0, 0, nullptr), CE_None);
  EXPECT_EQ(va, vb);

  // Nothing to write: a piece without the georeference is refused, no VRT over nothing.
  vtkNew<vtkStructuredGrid> plain;
  plain->SetDimensions(2, 2, 1);
  vtkNew<vtkTerrainRasterWriter> refused;
  refused->SetInputData(plain);
  refused->SetFileName((dir + "/refused.vrt").c_str());
  refused->WritePiecesOn();
  vtkNew<MessageCatcher> messages;
  refused->AddObserver(vtkCommand::ErrorEvent, messages);
  EXPECT_EQ(refused->Write(), 0);
  EXPECT_NE(messages->Errors.find("georeference"), std::string::npos);
}
