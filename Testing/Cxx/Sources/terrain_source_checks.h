#pragma once
// What the terrain source and reader tests share: rasters and pipelines.

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

namespace terralux_test
{

// Map coordinates -> (latitude, longitude), computed without GDAL/OSR.
using MapToGeodetic = std::function<void(double x, double y, double& lat, double& lon)>;

inline void geographic(double x, double y, double& lat, double& lon)
{
  lat = y;
  lon = x;
}

struct Terrain
{
  vtkNew<vtkTerrainSource> source;
  vtkNew<MessageCatcher> messages;
  int status = 0;
  vtkStructuredGrid* output() { return this->source->GetOutput(); }
  int run()
  {
    this->status = runPipeline(this->source, this->messages);
    return this->status;
  }
};

inline double hills(int col, int row)
{
  return 800.0 + 120.0 * std::sin(0.31 * col) * std::cos(0.17 * row) + 3.0 * col - 2.0 * row;
}

inline RasterSpec utmSpec(const char* crs, double easting, double northing)
{
  RasterSpec spec;
  spec.width = 41;
  spec.height = 31;
  spec.geoTransform = { easting, 30.0, 0.0, northing, 0.0, -30.0 };
  spec.crs = crs;
  spec.elevation = hills;
  return spec;
}

inline void runDouble(Terrain& terrain, const std::string& path)
{
  terrain.source->SetFileName(path.c_str());
  terrain.source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  ASSERT_EQ(terrain.run(), 1) << terrain.messages->Errors;
}
} // namespace terralux_test
