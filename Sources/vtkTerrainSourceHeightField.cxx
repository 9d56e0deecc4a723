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
#include "vtkTerrainHeights.h"

#include "error.h"
#include "local_frame.h"

#include <cmath>
#include <limits>

using namespace vtkTerrainHeights;

//------------------------------------------------------------------------------
bool vtkTerrainSource::ConvertHeightField(vtkImageData* input, vtkStructuredGrid* output)
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
  const vtkIdType count = input->GetNumberOfPoints();
  vtkUnsignedCharArray* inputGhosts = input->GetPointGhostArray();
  const bool useDouble = scalars->GetDataType() == VTK_DOUBLE ||
    scalars->GetDataType() == VTK_INT || scalars->GetDataType() == VTK_UNSIGNED_INT ||
    scalars->GetDataType() == VTK_LONG || scalars->GetDataType() == VTK_LONG_LONG;
  vtkSmartPointer<vtkDataArray> elevation = useDouble
    ? newValues<vtkDoubleArray>("Elevation", 1, count)
    : newValues<vtkFloatArray>("Elevation", 1, count);
  auto ghosts = vtkSmartPointer<vtkUnsignedCharArray>::New();
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(count);

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
  vtkIdType valid = 0, implausible = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (vtkIdType k = 0; k < count; ++k)
  {
    double h = scalars->GetComponent(k, 0);
    if (inputGhosts && (inputGhosts->GetValue(k) & vtkDataSetAttributes::HIDDENPOINT))
    {
      h = std::numeric_limits<double>::quiet_NaN();
    }
    if (std::isfinite(h) && !(h >= lowestPlausibleHeightM && h <= highestPlausibleHeightM))
    {
      h = std::numeric_limits<double>::quiet_NaN();
      ++implausible;
    }
    const bool isValid = std::isfinite(h);
    elevation->SetComponent(k, 0, isValid ? h : std::numeric_limits<double>::quiet_NaN());
    ghosts->SetValue(k, isValid ? 0 : vtkDataSetAttributes::HIDDENPOINT);
    if (isValid)
    {
      ++valid;
      lowest = std::min(lowest, h);
    }
  }
  if (implausible > 0)
  {
    vtkWarningMacro(<< implausible << " height(s) of the input image lie beyond [" << lowestPlausibleHeightM << ", "
                    << highestPlausibleHeightM << "] m, which no DEM holds: they are taken as no data.");
  }
  if (valid == 0)
  {
    vtkErrorMacro("Every height of the input image is NaN, blanked or implausible: nothing to build.");
    return false;
  }

  vtkNew<vtkPoints> points;
  points->SetDataType(this->OutputPointsPrecision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(count);
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
  if (valid < count)
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
