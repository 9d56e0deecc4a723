// vtkTerrainSource's height-field path: a vtkImageData on input port 0 as terrain.
#include "vtkTerrainSource.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkStructuredGrid.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkTerrainSourceInternals.h"

#include "base/error.h"
#include "geodesy/local_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace TerrainSourceHeights;

//------------------------------------------------------------------------------
bool vtkTerrainSource::CheckHeightField(vtkImageData* input)
{
  int dims[3];
  input->GetDimensions(dims);
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    vtkErrorMacro("The input image must be a 2-D height field (dimensions nx x ny x 1), not "
      << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
    return false;
  }
  if (!scalars || scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The input image needs one-component point scalars holding the heights.");
    return false;
  }
  double spacing[3], origin[3];
  input->GetSpacing(spacing);
  input->GetOrigin(origin);
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(spacing[k]) || !std::isfinite(origin[k]))
    {
      vtkErrorMacro("The input image's spacing or origin holds NaN or infinity: give it finite values "
                    "(SetSpacing(), SetOrigin(), in metres).");
      return false;
    }
  const double largest = this->OutputPointsPrecision == DOUBLE_PRECISION ? std::numeric_limits<double>::max()
                                                                        : std::numeric_limits<float>::max();
  for (int k = 0; k < 2; ++k)
    if (!(std::abs(origin[k]) <= largest && std::abs(origin[k] + spacing[k] * (dims[k] - 1)) <= largest))
    {
      vtkErrorMacro("The input image's points reach infinite coordinates (origin + spacing x dimension "
                    "overflows): give a spacing and origin in metres.");
      return false;
    }
  if (!(spacing[0] != 0.0 && spacing[1] != 0.0))
  {
    vtkErrorMacro("The input image's x or y spacing is 0: give it the post spacing in metres (SetSpacing()).");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTerrainSource::ConvertHeightField(vtkImageData* input, vtkStructuredGrid* output)
{
  if (!this->CheckHeightField(input))
  {
    return false;
  }
  int dims[3];
  input->GetDimensions(dims);
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  const vtkIdType count = input->GetNumberOfPoints();
  // Integers wider than a float's mantissa stay exact in double.
  const bool useDouble = scalars->GetDataType() == VTK_DOUBLE ||
    scalars->GetDataType() == VTK_INT || scalars->GetDataType() == VTK_UNSIGNED_INT ||
    scalars->GetDataType() == VTK_LONG || scalars->GetDataType() == VTK_LONG_LONG;
  vtkSmartPointer<vtkDataArray> elevation = useDouble
    ? newValues<vtkDoubleArray>("Elevation", 1, count)
    : newValues<vtkFloatArray>("Elevation", 1, count);
  // Hidden posts of the input are no data, as NaN heights are.
  vtkUnsignedCharArray* inputGhosts = input->GetPointGhostArray();
  for (vtkIdType k = 0; k < count; ++k)
  {
    const bool hidden = inputGhosts && (inputGhosts->GetValue(k) & vtkDataSetAttributes::HIDDENPOINT);
    elevation->SetComponent(k, 0, hidden ? std::numeric_limits<double>::quiet_NaN() : scalars->GetComponent(k, 0));
  }
  const vtkIdType implausible =
    withHeights(elevation, [&](auto* heights) { return dropImplausibleHeights(heights, count); });
  if (implausible > 0)
  {
    vtkWarningMacro(<< implausible << " height(s) of the input image lie beyond [" << lowestPlausibleHeightM << ", "
                    << highestPlausibleHeightM << "] m, which no DEM holds: they are taken as no data.");
  }
  auto ghosts = vtkSmartPointer<vtkUnsignedCharArray>::New();
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(count);
  const double lowest =
    withHeights(elevation, [&](const auto* heights) { return blankNoDataPosts(heights, count, ghosts); });
  if (!std::isfinite(lowest))
  {
    vtkErrorMacro("Every height of the input image is NaN, blanked or implausible: nothing to build.");
    return false;
  }

  vtkNew<vtkPoints> points;
  points->SetDataType(this->OutputPointsPrecision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  vtkTerraLuxLargeArrays::Allocate(points->GetData(), count);
  vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
    double xyz[3];
    for (vtkIdType k = begin; k < end; ++k)
    {
      input->GetPoint(k, xyz);
      const double h = elevation->GetComponent(k, 0);
      xyz[2] = std::isfinite(h) ? h : lowest;
      points->SetPoint(k, xyz);
    }
  });

  output->SetDimensions(dims[0], dims[1], 1);
  output->SetPoints(points);
  output->GetPointData()->AddArray(elevation);
  output->GetPointData()->SetScalars(elevation);
  const unsigned char* ghost = ghosts->GetPointer(0);
  if (std::any_of(ghost, ghost + count, [](unsigned char g) { return g != 0; }))
  {
    output->GetPointData()->AddArray(ghosts);
  }
  if (this->UseGeoOrigin)
  {
    try
    {
      terralux::LocalFrame({ this->GeoOrigin[0], this->GeoOrigin[1], this->GeoOrigin[2] });
    }
    catch (const terralux::Error& error)
    {
      vtkErrorMacro("GeoOrigin: " << error.what());
      output->Initialize();
      return false;
    }
    vtkTerraLuxFieldData::AddTuple(output->GetFieldData(), vtkTerraLuxFieldData::GeoOriginName(), this->GeoOrigin, 3);
  }
  return true;
}
