// Ingest benchmark: vtkTerrainSource on one DEM; prints wall time, peak resident
// memory (getrusage) and the output's size against the raw raster.
//   benchmark_terrain_ingest DEM [STRIDE=1] [single|double]
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStructuredGrid.h"
#include "vtkTerrainSource.h"

#include <gdal_priv.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace
{
double peakResidentMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: benchmark_terrain_ingest DEM [STRIDE=1] [single|double]\n";
    return 2;
  }
  const int stride = argc > 2 ? std::atoi(argv[2]) : 1;
  const bool doublePoints = argc > 3 && std::strcmp(argv[3], "double") == 0;

  GDALAllRegister();
  double rawMiB = 0.0;
  {
    std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(argv[1], GDAL_OF_RASTER));
    if (!dataset)
      return 1;
    GDALRasterBand* band = dataset->GetRasterBand(1);
    rawMiB = double(dataset->GetRasterXSize()) * dataset->GetRasterYSize() *
      GDALGetDataTypeSizeBytes(band->GetRasterDataType()) / (1024.0 * 1024.0);
  }
  const double baselineMiB = peakResidentMiB();

  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(argv[1]);
  terrain->SetStride(stride);
  terrain->SetOutputPointsPrecision(
    doublePoints ? vtkAlgorithm::DOUBLE_PRECISION : vtkAlgorithm::SINGLE_PRECISION);
  const auto start = std::chrono::steady_clock::now();
  terrain->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  vtkStructuredGrid* grid = terrain->GetOutput();
  const double outputMiB = grid->GetActualMemorySize() / 1024.0;
  const double peakMiB = peakResidentMiB();
  std::cout << "DEM " << argv[1] << " stride " << stride << " points "
            << (doublePoints ? "double" : "single") << "\n"
            << "  posts          " << grid->GetNumberOfPoints() << "\n"
            << "  wall time      " << seconds << " s\n"
            << "  raw raster     " << rawMiB << " MiB\n"
            << "  output         " << outputMiB << " MiB (" << outputMiB / rawMiB << " x raw)\n"
            << "  peak RSS       " << peakMiB << " MiB (before reading: " << baselineMiB
            << " MiB; growth " << (peakMiB - baselineMiB) / rawMiB << " x raw)\n";
  return grid->GetNumberOfPoints() > 0 ? 0 : 1;
}
