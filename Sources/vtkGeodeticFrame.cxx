#include "vtkGeodeticFrame.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkObjectFactory.h"

#include "base/error.h"
#include "geodesy/local_frame.h"
#include "vtkTerraLuxFieldData.h"

#include <limits>

vtkStandardNewMacro(vtkGeodeticFrame);

struct vtkGeodeticFrame::Internals
{
  std::unique_ptr<terralux::LocalFrame> frame;
  vtkMTimeType builtAt = 0;
};

//------------------------------------------------------------------------------
vtkGeodeticFrame::vtkGeodeticFrame()
  : Origin{ 0.0, 0.0, 0.0 }
  , Internal(new Internals)
  , Result{ 0.0, 0.0, 0.0 }
{
}

//------------------------------------------------------------------------------
vtkGeodeticFrame::~vtkGeodeticFrame() = default;

//------------------------------------------------------------------------------
bool vtkGeodeticFrame::SetOriginFromFieldData(vtkDataObject* data)
{
  double origin[3];
  if (!vtkTerraLuxFieldData::GetGeoOrigin(data, origin))
  {
    vtkErrorMacro("The data object has no 3-value `GeoOrigin` field data: take it from a "
                  "vtkTerrainSource output of a georeferenced raster, or call SetOrigin().");
    return false;
  }
  this->SetOrigin(origin);
  return true;
}

//------------------------------------------------------------------------------
bool vtkGeodeticFrame::UpdateFrame()
{
  if (this->Internal->frame && this->Internal->builtAt >= this->GetMTime())
  {
    return true;
  }
  try
  {
    this->Internal->frame = std::make_unique<terralux::LocalFrame>(
      terralux::GeodeticPoint{ this->Origin[0], this->Origin[1], this->Origin[2] });
    this->Internal->builtAt = this->GetMTime();
    return true;
  }
  catch (const terralux::Error& error)
  {
    this->Internal->frame.reset();
    vtkErrorMacro(<< error.what());
    return false;
  }
}

//------------------------------------------------------------------------------
bool vtkGeodeticFrame::LocalToGeodetic(const double local[3], double geodetic[3])
{
  if (!this->UpdateFrame())
  {
    geodetic[0] = geodetic[1] = geodetic[2] = std::numeric_limits<double>::quiet_NaN();
    return false;
  }
  const terralux::GeodeticPoint point =
    this->Internal->frame->toGeodetic({ local[0], local[1], local[2] });
  geodetic[0] = point.latitudeDeg;
  geodetic[1] = point.longitudeDeg;
  geodetic[2] = point.heightM;
  return true;
}

//------------------------------------------------------------------------------
double* vtkGeodeticFrame::LocalToGeodetic(double east, double north, double up)
{
  const double local[3] = { east, north, up };
  this->LocalToGeodetic(local, this->Result);
  return this->Result;
}

//------------------------------------------------------------------------------
bool vtkGeodeticFrame::GeodeticToLocal(const double geodetic[3], double local[3])
{
  if (!this->UpdateFrame())
  {
    local[0] = local[1] = local[2] = std::numeric_limits<double>::quiet_NaN();
    return false;
  }
  const terralux::LocalPoint point =
    this->Internal->frame->toLocal({ geodetic[0], geodetic[1], geodetic[2] });
  local[0] = point[0];
  local[1] = point[1];
  local[2] = point[2];
  return true;
}

//------------------------------------------------------------------------------
double* vtkGeodeticFrame::GeodeticToLocal(double latitude, double longitude, double height)
{
  const double geodetic[3] = { latitude, longitude, height };
  this->GeodeticToLocal(geodetic, this->Result);
  return this->Result;
}

//------------------------------------------------------------------------------
void vtkGeodeticFrame::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
}
