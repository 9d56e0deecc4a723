// vtkTerrainSource's private pieces, shared by its source files (vtkTerrainSource.cxx,
// vtkTerrainSourceRaster.cxx, vtkTerrainSourceHeightField.cxx): what RequestInformation
// and RequestData agree to read, and the height helpers of the DEM file and the
// height-field image (private to TerraLux::Sources).
#ifndef vtkTerrainSourceInternals_h
#define vtkTerrainSourceInternals_h

#include "vtkTerrainSource.h"

#include "raster/dem_raster.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkSmartPointer.h"
#include "vtkTerraLuxLargeArrays.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>

struct vtkTerrainSource::RasterRequest
{
  std::unique_ptr<terralux::DemRaster> raster;
  terralux::PixelWindow window;
  int nx = 0;
  int ny = 0;
  bool clipped = false; // the PixelWindow reached beyond the raster
};

namespace TerrainSourceHeights
{
template <typename ArrayT>
inline vtkSmartPointer<vtkDataArray> newValues(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  vtkTerraLuxLargeArrays::Allocate(array, tuples);
  return array;
}

// Runs `work` on an Elevation array's heights as float* or double*, whichever it holds.
template <typename Work>
inline auto withHeights(vtkDataArray* elevation, Work&& work)
{
  if (auto* doubles = vtkDoubleArray::SafeDownCast(elevation))
  {
    return work(doubles->GetPointer(0));
  }
  return work(vtkFloatArray::SafeDownCast(elevation)->GetPointer(0));
}

// Heights no DEM on Earth holds (the Mariana Trench is at -11 km, Everest at 8.8 km).
constexpr double lowestPlausibleHeightM = -12000.0;
constexpr double highestPlausibleHeightM = 10000.0;

// Makes heights beyond the plausible range no data (NaN); returns how many there were.
template <typename HeightT>
inline vtkIdType dropImplausibleHeights(HeightT* heights, vtkIdType count)
{
  vtkIdType dropped = 0;
  for (vtkIdType k = 0; k < count; ++k)
    if (std::isfinite(heights[k]) && !(heights[k] >= lowestPlausibleHeightM && heights[k] <= highestPlausibleHeightM))
    {
      heights[k] = std::numeric_limits<HeightT>::quiet_NaN();
      ++dropped;
    }
  return dropped;
}

// Marks no-data posts (NaN heights) hidden; returns the lowest valid height.
template <typename HeightT>
inline double blankNoDataPosts(const HeightT* heights, vtkIdType count, vtkUnsignedCharArray* ghosts)
{
  double lowest = std::numeric_limits<double>::infinity();
  for (vtkIdType k = 0; k < count; ++k)
  {
    const bool valid = std::isfinite(heights[k]);
    ghosts->SetValue(k, valid ? 0 : vtkDataSetAttributes::HIDDENPOINT);
    if (valid && heights[k] < lowest)
    {
      lowest = heights[k];
    }
  }
  return lowest;
}

// Reverses the row order in place (raster row 0 first -> grid j = ny - 1 - row).
template <typename T>
inline void flipRows(T* values, int nx, int ny)
{
  for (int row = 0; row < ny / 2; ++row)
  {
    std::swap_ranges(values + static_cast<std::size_t>(row) * nx,
      values + static_cast<std::size_t>(row + 1) * nx,
      values + static_cast<std::size_t>(ny - 1 - row) * nx);
  }
}
} // namespace TerrainSourceHeights

#endif
