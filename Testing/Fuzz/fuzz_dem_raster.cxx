// Fuzz target: raster bytes (any format GDAL opens) through GDAL's /vsimem/ into
// vtkTerrainSource, with a fuzzed window, box and stride. It must either fail with an
// error or give a grid whose points are all finite.
#include "fuzz_support.h"

#include "vtkNew.h"
#include "vtkStructuredGrid.h"
#include "vtkTerrainSource.h"

#include <cpl_vsi.h>
#include <gdal_priv.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  terralux_fuzz::silenceVtk();
  GDALAllRegister();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  terralux_fuzz::ByteReader reader(data, size);
  // The first bytes choose the request, the rest is the file.
  const int mode = reader.between(0, 3);
  const int stride = reader.between(1, 4);
  const int window[4] = { reader.between(-2, 40), reader.between(-2, 40), reader.between(-2, 60),
    reader.between(-2, 60) };
  const std::string path = "/vsimem/fuzz_dem_" + std::to_string(reinterpret_cast<std::uintptr_t>(data));
  VSILFILE* file = VSIFileFromMemBuffer(path.c_str(), const_cast<GByte*>(reader.rest()),
    static_cast<vsi_l_offset>(reader.remaining()), FALSE);
  if (file)
    VSIFCloseL(file);
  // Rasters of more than 4 M posts are left to the unit tests (the reader refuses or
  // reads them in chunks); here they would only measure memory.
  bool small = true;
  if (auto* probe = static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)))
  {
    small = static_cast<double>(probe->GetRasterXSize()) * probe->GetRasterYSize() <= 4e6;
    GDALClose(probe);
  }
  if (small)
  {
    vtkNew<vtkTerrainSource> terrain;
    terrain->SetFileName(path.c_str());
    terrain->SetStride(stride);
    if (mode == 1)
      terrain->SetPixelWindow(window[0], window[1], window[2], window[3]);
    else if (mode == 2)
      terrain->SetGeoBounds(window[0] - 20.0, window[1] - 20.0 + 0.5, window[2] - 30.0, window[3] - 30.0 + 0.5);
    else if (mode == 3)
      terrain->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    terrain->Update();
    terralux_fuzz::requireFiniteOutput(terrain->GetOutput(), "vtkTerrainSource gave a non-finite point");
  }
  VSIUnlink(path.c_str());
  CPLPopErrorHandler();
  return 0;
}
