#include "vtkSolarIrradiation.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityOutputs.h"
#include "vtkRadiosityScene.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTerraLuxFieldData.h"

#include "base/angles.h"
#include "sky/cie_sky.h"
#include "cumulative_sky.h"
#include "sun/date_time.h"
#include "base/error.h"
#include "base/finite_parameters.h"
#include "sky/perez_sky.h"
#include "solar_steps.h"
#include "weather_file.h"

#include <chrono>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSolarIrradiation);

namespace
{

// The sums' names and units (vtkDataArray::UNITS_LABEL, which vtkTerrainRasterWriter
// writes into the GeoTIFF's bands).
void renameSums(vtkDataSet* data)
{
  vtkPointData* pointData = data->GetPointData();
  for (int k = 0; k < vtkRadiosityOutputs::Quantities; ++k)
    if (vtkDataArray* array = pointData->GetArray(vtkRadiosityOutputs::QuantityName(k)))
    {
      array->SetName(vtkRadiosityOutputs::IntegratedName(k));
      array->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), "Wh/m^2");
    }
  if (vtkDataArray* sunshine = pointData->GetArray(vtkRadiosityOutputs::SunshineDurationName()))
    sunshine->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), "h");
  if (vtkDataArray* error = pointData->GetArray(vtkRadiosityOutputs::IrradianceErrorName()))
  {
    error->SetName(vtkRadiosityOutputs::IrradiationErrorName());
    error->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), "Wh/m^2");
  }
  pointData->SetActiveScalars(vtkRadiosityOutputs::IntegratedName(0));
}

// The first data set of port 0 with a GeoOrigin (latitude, longitude, height).
bool geoOrigin(vtkInformationVector* port, double place[3])
{
  auto fromData = [&](vtkDataObject* data) { return vtkTerraLuxFieldData::GetGeoOrigin(data, place); };
  for (int k = 0; k < port->GetNumberOfInformationObjects(); ++k)
  {
    vtkDataObject* data = port->GetInformationObject(k)->Get(vtkDataObject::DATA_OBJECT());
    if (fromData(data)) // a composite's own field data first, then its blocks'
      return true;
    for (vtkDataSet* block : vtkRadiosityScene::DataSetsOf(data))
      if (fromData(block))
        return true;
  }
  return false;
}
} // namespace

struct vtkSolarIrradiation::Internals
{
  std::vector<terralux::SolarStep> Steps; // of the last solve
  double RequestedHours = 0.0;            // UPDATE_TIME_STEP, with IntegrateOverTime off
  double SecondsSteps = 0.0;
  terralux::WeatherSummary WeatherCounts;
};

//------------------------------------------------------------------------------
vtkSolarIrradiation::vtkSolarIrradiation()
  : vtkRadiosityFilter(2, FAR_TERRAIN_PORT)
  , StartTime(nullptr)
  , EndTime(nullptr)
  , TimeStep(30.0)
  , IntegrateOverTime(1)
  , UseGeoOrigin(1)
  , Latitude(0.0)
  , Longitude(0.0)
  , Height(0.0)
  , IrradianceModel(ESRA)
  , SkyType(12)
  , SkyLevels(7)
  , WeatherFileName(nullptr)
  , DeltaT(69.0)
  , Internal(new Internals)
{
  this->SetStartTime("2000-01-01T00:00:00Z");
  this->SetEndTime("2000-01-02T00:00:00Z");
  for (double& value : this->MonthlyLinkeTurbidity)
    value = 3.0;
}

//------------------------------------------------------------------------------
vtkSolarIrradiation::~vtkSolarIrradiation()
{
  this->SetStartTime(nullptr);
  this->SetEndTime(nullptr);
  this->SetWeatherFileName(nullptr);
  delete this->Internal;
}

//------------------------------------------------------------------------------
void vtkSolarIrradiation::SetLinkeTurbidity(double value)
{
  const double monthly[12] = { value, value, value, value, value, value, value, value, value, value, value,
    value };
  this->SetMonthlyLinkeTurbidity(monthly);
}

//------------------------------------------------------------------------------
int vtkSolarIrradiation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  this->Internal->RequestedHours = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    : 0.0;
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkSolarIrradiation::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector))
    return 0;
  // Time steps are advertised where the range is valid; a bad one is reported by
  // RequestData, which leaves the outputs empty.
  std::vector<double> hours;
  try
  {
    const double start = terralux::DateTime::parse(this->StartTime ? this->StartTime : "").julianDay();
    const double end = terralux::DateTime::parse(this->EndTime ? this->EndTime : "").julianDay();
    for (double instant : terralux::stepInstants(start, end, this->TimeStep))
      hours.push_back((instant - start) * 24.0);
  }
  catch (const terralux::Error&)
  {
  }
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    if (!hours.empty())
    {
      info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), hours.data(), static_cast<int>(hours.size()));
      const double range[2] = { hours.front(), hours.back() };
      info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkSolarIrradiation::AddLights(vtkInformationVector** inputVector, vtkRadiosityScene& scene)
{
  const auto start = std::chrono::steady_clock::now();
  terralux::requireFiniteParameters({ { "TimeStep", this->TimeStep }, { "Latitude", this->Latitude },
    { "Longitude", this->Longitude }, { "Height", this->Height }, { "DeltaT", this->DeltaT } });
  for (double linke : this->MonthlyLinkeTurbidity)
    if (!(linke >= 0.5 && linke <= 10.0))
      throw terralux::Error("a Linke turbidity of " + terralux::numberText(linke) +
        " is out of range: give values in [0.5, 10] (r.sun's range; 3 is a rural clear sky)");

  terralux::SolarSite site;
  double place[3] = { this->Latitude, this->Longitude, this->Height };
  if (this->UseGeoOrigin)
    geoOrigin(inputVector[0], place);
  site.position.latitudeDeg = place[0];
  site.position.longitudeDeg = place[1];
  site.position.heightM = place[2];
  site.position.deltaT = this->DeltaT;
  site.model = this->IrradianceModel == ESRA ? terralux::ClearSkyModel::Esra : terralux::ClearSkyModel::IneichenPerez;
  std::copy(this->MonthlyLinkeTurbidity, this->MonthlyLinkeTurbidity + 12, site.linkeByMonth.begin());

  const double startDay = terralux::DateTime::parse(this->StartTime ? this->StartTime : "").julianDay();
  const double endDay = terralux::DateTime::parse(this->EndTime ? this->EndTime : "").julianDay();
  auto& steps = this->Internal->Steps;
  const bool integrated = this->IntegrateOverTime != 0, weather = this->UsesWeatherFile();
  scene.SunshineDuration = integrated;
  double from = startDay, to = endDay;
  if (!integrated)
  {
    terralux::stepInstants(startDay, endDay, this->TimeStep); // validates the range
    const double hours = this->Internal->RequestedHours;
    if (!std::isfinite(hours))
      throw terralux::Error("the requested time step is not a finite number of hours");
    from = startDay + std::min(std::max(hours, 0.0), (endDay - startDay) * 24.0) / 24.0;
    to = from + 1.0 / 1440.0; // the minute from the instant: its weather hour, its sun
  }
  if (weather)
  {
    const terralux::WeatherFile file = terralux::readWeatherFile(this->WeatherFileName);
    const double km = terralux::distanceKm(file.latitudeDeg, file.longitudeDeg, place[0], place[1]);
    if (km > 50.0)
      vtkWarningMacro("The weather file " << this->WeatherFileName << " is " << km
        << " km from the place (" << place[0] << ", " << place[1] << "): its sky may not be this place's.");
    steps = terralux::weatherSteps(file, from, to, site, &this->Internal->WeatherCounts);
  }
  else if (integrated)
  {
    steps = terralux::daylightSteps(startDay, endDay, this->TimeStep, site); // validates the range too
  }
  else
  {
    steps.assign(1, terralux::solarStepAt(from, site));
  }

  // Each step's sun (irradiance x hours: Wh/m^2) and sky into the cumulative sky. An
  // instant counts one hour with no duration, so its values stay W/m^2.
  terralux::CumulativeSky sky(this->SkyLevels);
  for (std::size_t k = 0; k < steps.size(); ++k)
  {
    const terralux::SolarStep& step = steps[k];
    if (k % 64 == 0)
      this->UpdateProgress(0.1 * static_cast<double>(k) / static_cast<double>(steps.size()));
    const double weight = integrated ? step.hours : 1.0;
    const terralux::Direction toward =
      terralux::directionFromZenithAzimuth(step.position.zenithDeg * terralux::degree, step.position.azimuthDeg * terralux::degree);
    if (step.irradiance.directNormalWm2 > 0.0)
      scene.Suns.push_back({ terralux::Vec3(toward[0], toward[1], toward[2]),
        terralux::uniformSpectrum(step.irradiance.directNormalWm2 * weight),
        integrated ? step.hours : 0.0 });
    if (step.irradiance.diffuseHorizontalWm2 > 0.0 && weather)
      sky.add(terralux::PerezSky(toward, step.irradiance.directNormalWm2, step.irradiance.diffuseHorizontalWm2,
                step.extraterrestrialWm2),
        toward, step.irradiance.diffuseHorizontalWm2, weight);
    else if (step.irradiance.diffuseHorizontalWm2 > 0.0)
      sky.add(terralux::CieGeneralSky(this->SkyType, toward), toward, step.irradiance.diffuseHorizontalWm2, weight);
    if (this->GetAbortExecute())
      break;
  }
  scene.Sky = sky.hierarchy();
  this->Internal->SecondsSteps = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!scene.Sky && scene.Suns.empty())
  {
    // Polar night, or an instant after sunset: darkness is an answer, not an error.
    scene.Sky = std::make_unique<terralux::SkyHierarchy>(terralux::SkyHierarchy::fromCellAverages(
      1, 1, std::vector<double>(4, 0.0)));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSolarIrradiation::FinishOutputs(vtkDataObject* output, vtkPolyData* leafMesh)
{
  const auto& steps = this->Internal->Steps;
  if (this->IntegrateOverTime)
  {
    for (vtkDataSet* dataSet : vtkRadiosityScene::DataSetsOf(output))
      renameSums(dataSet);
    renameSums(leafMesh);
  }
  vtkFieldData* fieldData = output->GetFieldData();
  auto addValue = [&](const char* name, double value) { vtkRadiosityOutputs::AddFieldValue(fieldData, name, value); };
  addValue("Steps", static_cast<double>(steps.size()));
  auto perStep = [&](const char* name, auto value) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(name);
    for (const terralux::SolarStep& step : steps)
      array->InsertNextValue(value(step));
    fieldData->AddArray(array);
  };
  vtkNew<vtkStringArray> times;
  times->SetName("StepTime");
  for (const terralux::SolarStep& step : steps)
    times->InsertNextValue(terralux::DateTime::fromJulianDay(step.julianDay).toUtcString());
  fieldData->AddArray(times);
  perStep("StepHours", [](const terralux::SolarStep& s) { return s.hours; });
  perStep(vtkTerraLuxFieldData::SunZenithName(), [](const terralux::SolarStep& s) { return s.position.zenithDeg; });
  perStep(vtkTerraLuxFieldData::SunAzimuthName(), [](const terralux::SolarStep& s) { return s.position.azimuthDeg; });
  perStep(vtkTerraLuxFieldData::SunNormalIrradianceName(), [](const terralux::SolarStep& s) { return s.irradiance.directNormalWm2; });
  perStep(
    vtkTerraLuxFieldData::DiffuseHorizontalIrradianceName(), [](const terralux::SolarStep& s) { return s.irradiance.diffuseHorizontalWm2; });
  addValue("SecondsSteps", this->Internal->SecondsSteps);
  if (this->UsesWeatherFile())
  {
    addValue("WeatherHours", this->Internal->WeatherCounts.hours);
    addValue("UnlitDirectIrradiation", this->Internal->WeatherCounts.unlitDirectWh);
  }
}

//------------------------------------------------------------------------------
void vtkSolarIrradiation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StartTime: " << (this->StartTime ? this->StartTime : "(none)") << "\n";
  os << indent << "EndTime: " << (this->EndTime ? this->EndTime : "(none)") << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "IntegrateOverTime: " << (this->IntegrateOverTime ? "On" : "Off") << "\n";
  os << indent << "UseGeoOrigin: " << (this->UseGeoOrigin ? "On" : "Off") << "\n";
  os << indent << "Latitude: " << this->Latitude << "\n";
  os << indent << "Longitude: " << this->Longitude << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "IrradianceModel: " << (this->IrradianceModel == ESRA ? "ESRA" : "Ineichen-Perez") << "\n";
  os << indent << "MonthlyLinkeTurbidity:";
  for (double value : this->MonthlyLinkeTurbidity)
    os << " " << value;
  os << "\n";
  os << indent << "SkyType: " << this->SkyType << "\n";
  os << indent << "SkyLevels: " << this->SkyLevels << "\n";
  os << indent << "WeatherFileName: " << (this->WeatherFileName ? this->WeatherFileName : "(none)") << "\n";
  os << indent << "DeltaT: " << this->DeltaT << "\n";
}
