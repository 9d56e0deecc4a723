// vtkTerrainReader: a DEM file as georeferenced terrain, as vtkTerrainSource reads it.
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

// vtkTerrainReader is the file path alone, as a reader: no input port, the source's
// posts and field data, and CanReadFile for ParaView's reader factory.
TEST(TerrainReader, ReadsWhatTheSourceReadsWithoutAnInputPort)
{
  const std::string path = terralux_test::externalDataDir() + "/olinda_dem_utm25s.tif";
  Terrain terrain;
  runDouble(terrain, path);
  vtkNew<vtkTerrainReader> reader;
  EXPECT_EQ(reader->GetNumberOfInputPorts(), 0);
  EXPECT_EQ(reader->CanReadFile(path.c_str()), 1);
  EXPECT_EQ(reader->CanReadFile((terralux_test::externalDataDir() + "/no_such.tif").c_str()), 0);
  EXPECT_EQ(reader->CanReadFile(nullptr), 0);
  reader->SetFileName(path.c_str());
  reader->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  vtkNew<MessageCatcher> messages;
  ASSERT_EQ(runPipeline(reader, messages), 1) << messages->Errors;
  vtkStructuredGrid* read = reader->GetOutput();
  ASSERT_EQ(read->GetNumberOfPoints(), terrain.output()->GetNumberOfPoints());
  for (vtkIdType k = 0; k < read->GetNumberOfPoints(); k += 97)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(read->GetPoint(k)[c], terrain.output()->GetPoint(k)[c]);
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(fieldValue(read, "GeoTransform", k), fieldValue(terrain.output(), "GeoTransform", k));
  // A bad file: the source's error, output empty.
  reader->SetFileName("no_such_dem.tif");
  EXPECT_EQ(runPipeline(reader, messages), 0);
  EXPECT_NE(messages->Errors.find("does not exist"), std::string::npos);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}
