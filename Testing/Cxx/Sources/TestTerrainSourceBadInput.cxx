// vtkTerrainSource refusing what it cannot read: missing files, bad bands, empty
// windows, all no data, CRSs it cannot transform, NaN origins.
#include "terrain_source_checks.h"
#include "test_rasters.h"
#include "vtk_test_support.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkStructuredGrid.h"
#include "vtkTerrainReader.h"
#include "vtkTerrainSource.h"
#include "vtkUnsignedCharArray.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

using namespace terralux_test;

namespace
{
void expectFailure(Terrain& terrain, const std::string& expectedWords)
{
  EXPECT_EQ(terrain.run(), 0);
  EXPECT_NE(terrain.messages->Errors.find(expectedWords), std::string::npos)
    << "errors were: " << terrain.messages->Errors;
  EXPECT_EQ(terrain.output()->GetNumberOfPoints(), 0);
  EXPECT_EQ(terrain.output()->GetFieldData()->GetNumberOfArrays(), 0);
}
} // namespace

TEST(TerrainSourceBadInput, MissingFile)
{
  Terrain terrain;
  terrain.source->SetFileName("/no/such/dem.tif");
  expectFailure(terrain, "does not exist");
}

TEST(TerrainSourceBadInput, NoFileName)
{
  Terrain terrain;
  expectFailure(terrain, "no DEM file name");
}

TEST(TerrainSourceBadInput, UnreadableFormat)
{
  const std::string text = terralux_test::scratchDir() + "/notes.txt";
  std::ofstream(text) << "elevation: high\n";
  Terrain terrain;
  terrain.source->SetFileName(text.c_str());
  expectFailure(terrain, "not a raster GDAL can read");
}

TEST(TerrainSourceBadInput, BandOutOfRange)
{
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("band.tif", utmSpec("EPSG:32632", 380000.0, 5080000.0)).c_str());
  terrain.source->SetBand(2);
  expectFailure(terrain, "band 2 is out of range");
}

TEST(TerrainSourceBadInput, AllNoDataRasterAndWindow)
{
  RasterSpec spec = utmSpec("EPSG:32632", 380000.0, 5080000.0);
  spec.noData = -9999.0;
  spec.elevation = [](int, int) { return NAN; };
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("allnodata.tif", spec).c_str());
  expectFailure(terrain, "is no data");

  spec.elevation = [](int col, int) { return col < 10 ? NAN : 5.0; };
  Terrain window;
  window.source->SetFileName(writeRaster("leftnodata.tif", spec).c_str());
  window.source->SetPixelWindow(0, 0, 10, 10);
  expectFailure(window, "is no data");
  window.source->SetPixelWindow(0, 0, 11, 10);
  EXPECT_EQ(window.run(), 1); // recovers once the window holds data
}

TEST(TerrainSourceBadInput, EmptyWindows)
{
  const std::string path = writeRaster("window.tif", utmSpec("EPSG:32632", 380000.0, 5080000.0));
  Terrain terrain;
  terrain.source->SetFileName(path.c_str());
  terrain.source->SetPixelWindow(50, 0, 10, 10);
  expectFailure(terrain, "does not overlap");

  Terrain box;
  box.source->SetFileName(path.c_str());
  box.source->SetGeoBounds(10.0, 11.0, 20.0, 21.0);
  box.source->UseGeoBoundsOn();
  expectFailure(box, "does not overlap");

  Terrain inverted;
  inverted.source->SetFileName(path.c_str());
  inverted.source->SetGeoBounds(45.0, 46.0, 8.0, 7.0);
  inverted.source->UseGeoBoundsOn();
  expectFailure(inverted, "not a geographic box");

  Terrain both;
  both.source->SetFileName(path.c_str());
  both.source->SetGeoBounds(45.0, 46.0, 7.0, 8.0);
  both.source->UseGeoBoundsOn();
  both.source->SetPixelWindow(0, 0, 5, 5);
  expectFailure(both, "both PixelWindow and GeoBounds");

  Terrain partly;
  partly.source->SetFileName(path.c_str());
  partly.source->SetPixelWindow(35, -5, 10, 10);
  EXPECT_EQ(partly.run(), 1);
  EXPECT_NE(partly.messages->Warnings.find("clipped"), std::string::npos);
  EXPECT_EQ(partly.output()->GetNumberOfPoints(), 6 * 5);
}

TEST(TerrainSourceBadInput, CrsThatCannotBeTransformed)
{
  RasterSpec spec = utmSpec("IAU_2015:49900", 10.0, 10.0); // Mars: no way to WGS84
  spec.geoTransform = { 10.0, 0.001, 0.0, 10.0, 0.0, -0.001 };
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("mars.tif", spec).c_str());
  expectFailure(terrain, "cannot be transformed to WGS84");
}

TEST(TerrainSourceBadInput, NaNOrigin)
{
  Terrain terrain;
  terrain.source->SetFileName(writeRaster("origin.tif", utmSpec("EPSG:32632", 380000.0, 5080000.0)).c_str());
  terrain.source->SetGeoOrigin(NAN, 7.0, 0.0);
  expectFailure(terrain, "invalid geographic origin");
  terrain.source->SetGeoOriginToGridCenter();
  EXPECT_EQ(terrain.run(), 1);
}
