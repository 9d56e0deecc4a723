#include "vtkSunSource.h"

#include "vtkCellArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include "base/angles.h"
#include "sun/clear_sky.h"
#include "sun/date_time.h"
#include "base/error.h"
#include "sky/sky_model.h"
#include "sun/solar_position.h"
#include "base/finite_parameters.h"
#include "vtkTerraLuxFieldData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkSunSource);

//------------------------------------------------------------------------------
vtkSunSource::vtkSunSource()
  : DateTime(nullptr)
  , Latitude(0.0)
  , Longitude(0.0)
  , Height(0.0)
  , Pressure(1013.25)
  , Temperature(12.0)
  , AtmosphericRefraction(1)
  , DeltaT(69.0)
  , IrradianceModel(ESRA)
  , LinkeTurbidity(3.0)
  , SolarConstant(terralux::solarConstantWm2)
  , UserNormalIrradiance(800.0)
  , UserDiffuseHorizontalIrradiance(100.0)
  , DisplayDistance(10000.0)
  , Zenith(0.0)
  , Azimuth(0.0)
  , Direction{ 0.0, 0.0, 1.0 }
  , NormalIrradiance(0.0)
  , DiffuseHorizontalIrradiance(0.0)
  , ExtraterrestrialIrradiance(0.0)
  , EarthSunDistance(1.0)
{
  this->SetDateTime("2000-01-01T12:00:00Z");
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
vtkSunSource::~vtkSunSource()
{
  this->SetDateTime(nullptr);
}

//------------------------------------------------------------------------------
int vtkSunSource::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSunSource::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Only the input's field data is read: ask for all of it, whatever extent our own
  // consumers request (a sky map's extent means nothing to a terrain).
  vtkTerraLuxFieldData::RequestWholeInputs(inputVector, this->GetNumberOfInputPorts());
  return 1;
}

namespace
{
// NREL SPA for `sun`'s settings at `place` (latitude, longitude, height) and its
// DateTime, which `instant` gets; throws terralux::Error naming a bad setting.
terralux::SolarPosition solarPosition(vtkSunSource* sun, const double place[3], terralux::DateTime& instant)
{
  terralux::requireFiniteParameters({ { "Latitude", place[0] }, { "Longitude", place[1] }, { "Height", place[2] },
    { "Pressure", sun->GetPressure() }, { "Temperature", sun->GetTemperature() }, { "DeltaT", sun->GetDeltaT() },
    { "LinkeTurbidity", sun->GetLinkeTurbidity() }, { "SolarConstant", sun->GetSolarConstant() },
    { "UserNormalIrradiance", sun->GetUserNormalIrradiance() },
    { "UserDiffuseHorizontalIrradiance", sun->GetUserDiffuseHorizontalIrradiance() },
    { "DisplayDistance", sun->GetDisplayDistance() } });
  if (!(std::abs(place[1]) <= 360.0))
    throw terralux::Error("Longitude " + std::to_string(place[1]) +
      " is out of range: give degrees east in [-180, 180] (or [0, 360])");
  if (!(place[2] >= -12000.0 && place[2] <= 100000.0))
    throw terralux::Error("Height " + std::to_string(place[2]) +
      " m is out of range: give metres above the ellipsoid in [-12000, 100000]");
  instant = terralux::DateTime::parse(sun->GetDateTime() ? sun->GetDateTime() : "");
  terralux::SolarPositionInput in;
  in.julianDayUT = instant.julianDay();
  in.deltaT = sun->GetDeltaT();
  in.latitudeDeg = place[0];
  in.longitudeDeg = place[1];
  in.heightM = place[2];
  in.pressureHPa = sun->GetPressure();
  in.temperatureC = sun->GetTemperature();
  in.refraction = sun->GetAtmosphericRefraction() != 0;
  return terralux::computeSolarPosition(in);
}

// The output: one vertex at DisplayDistance toward the sun, and the field data of the
// sun's results (what vtkSkySource and vtkHierarchicalRadiosity read).
void fillOutput(vtkSunSource* sun, double globalHorizontal, const double place[3], const terralux::DateTime& instant,
  vtkPolyData* output)
{
  const double* d = sun->GetDirection();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(sun->GetDisplayDistance() * d[0], sun->GetDisplayDistance() * d[1],
    sun->GetDisplayDistance() * d[2]);
  vtkNew<vtkCellArray> vertices;
  const vtkIdType vertex = 0;
  vertices->InsertNextCell(1, &vertex);
  output->SetPoints(points);
  output->SetVerts(vertices);

  vtkFieldData* fieldData = output->GetFieldData();
  vtkTerraLuxFieldData::AddTuple(fieldData, vtkTerraLuxFieldData::SunDirectionName(), d, 3);
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::SunZenithName(), sun->GetZenith());
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::SunAzimuthName(), sun->GetAzimuth());
  vtkTerraLuxFieldData::AddValue(fieldData, "SunAltitude", 90.0 - sun->GetZenith());
  vtkTerraLuxFieldData::AddValue(
    fieldData, vtkTerraLuxFieldData::SunNormalIrradianceName(), sun->GetNormalIrradiance());
  vtkTerraLuxFieldData::AddValue(
    fieldData, vtkTerraLuxFieldData::DiffuseHorizontalIrradianceName(), sun->GetDiffuseHorizontalIrradiance());
  vtkTerraLuxFieldData::AddValue(fieldData, "GlobalHorizontalIrradiance", globalHorizontal);
  vtkTerraLuxFieldData::AddValue(
    fieldData, vtkTerraLuxFieldData::ExtraterrestrialIrradianceName(), sun->GetExtraterrestrialIrradiance());
  vtkTerraLuxFieldData::AddValue(fieldData, "EarthSunDistance", sun->GetEarthSunDistance());
  vtkTerraLuxFieldData::AddTuple(fieldData, vtkTerraLuxFieldData::GeoOriginName(), place, 3);
  auto utc = vtkSmartPointer<vtkStringArray>::New();
  utc->SetName("DateTime");
  utc->InsertNextValue(instant.toUtcString());
  fieldData->AddArray(utc);
}
} // namespace

//------------------------------------------------------------------------------
int vtkSunSource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  double place[3] = { this->Latitude, this->Longitude, this->Height };
  if (vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0))
  {
    if (!vtkTerraLuxFieldData::GetGeoOrigin(input, place))
    {
      vtkErrorMacro("The input has no `GeoOrigin` field data (latitude, longitude, height): "
                    "connect a vtkTerrainSource of a georeferenced DEM, or disconnect the input "
                    "and set Latitude, Longitude and Height.");
      return 0;
    }
  }
  terralux::SolarPosition position;
  terralux::DateTime instant;
  try
  {
    position = solarPosition(this, place, instant);
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
    return 0;
  }

  const terralux::Direction direction =
    terralux::directionFromZenithAzimuth(position.zenithDeg * terralux::degree, position.azimuthDeg * terralux::degree);
  this->Zenith = position.zenithDeg;
  this->Azimuth = position.azimuthDeg;
  std::copy(direction.begin(), direction.end(), this->Direction);
  this->EarthSunDistance = position.earthSunDistanceAU;
  this->ExtraterrestrialIrradiance =
    this->SolarConstant / (position.earthSunDistanceAU * position.earthSunDistanceAU);
  const terralux::ClearSkyIrradiance irradiance = this->IrradianceModel == USER
    ? terralux::givenIrradiance(position.zenithDeg, this->UserNormalIrradiance, this->UserDiffuseHorizontalIrradiance)
    : terralux::clearSkyIrradiance(
        this->IrradianceModel == ESRA ? terralux::ClearSkyModel::Esra : terralux::ClearSkyModel::IneichenPerez,
        position.zenithDeg, position.geometricZenithDeg, place[2], this->LinkeTurbidity,
        this->ExtraterrestrialIrradiance);
  this->NormalIrradiance = irradiance.directNormalWm2;
  this->DiffuseHorizontalIrradiance = irradiance.diffuseHorizontalWm2;
  fillOutput(this, irradiance.globalHorizontalWm2, place, instant, output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSunSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DateTime: " << (this->DateTime ? this->DateTime : "(none)") << "\n";
  os << indent << "Latitude: " << this->Latitude << "\n";
  os << indent << "Longitude: " << this->Longitude << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Pressure: " << this->Pressure << "\n";
  os << indent << "Temperature: " << this->Temperature << "\n";
  os << indent << "AtmosphericRefraction: " << (this->AtmosphericRefraction ? "On" : "Off") << "\n";
  os << indent << "DeltaT: " << this->DeltaT << "\n";
  os << indent << "IrradianceModel: " << this->IrradianceModel << "\n";
  os << indent << "LinkeTurbidity: " << this->LinkeTurbidity << "\n";
  os << indent << "SolarConstant: " << this->SolarConstant << "\n";
  os << indent << "UserNormalIrradiance: " << this->UserNormalIrradiance << "\n";
  os << indent << "UserDiffuseHorizontalIrradiance: " << this->UserDiffuseHorizontalIrradiance << "\n";
  os << indent << "DisplayDistance: " << this->DisplayDistance << "\n";
}
