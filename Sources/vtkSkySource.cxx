#include "vtkSkySource.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include "base/angles.h"
#include "sky/cie_sky.h"
#include "base/error.h"
#include "sky/perez_sky.h"
#include "sky/sky_hierarchy.h"
#include "base/finite_parameters.h"
#include "vtkTerraLuxFieldData.h"

#include <cmath>
#include <memory>

vtkStandardNewMacro(vtkSkySource);

namespace
{

const char* modelName(int model, int type)
{
  static thread_local std::string name;
  switch (model)
  {
    case vtkSkySource::CIE_GENERAL:
      name = "CIE standard general sky type " + std::to_string(type);
      return name.c_str();
    case vtkSkySource::CIE_OVERCAST:
      return "traditional CIE overcast sky";
    case vtkSkySource::PEREZ:
      return "Perez all-weather sky";
    default:
      return "uniform sky";
  }
}

// The texture's point scalars as a SkyTexture; throws on a bad image.
terralux::SkyTexture textureFrom(vtkImageData* image)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int dims[3];
  image->GetDimensions(dims);
  if (!scalars || (scalars->GetNumberOfComponents() != 1 && scalars->GetNumberOfComponents() != 3) ||
    dims[2] != 1)
  {
    throw terralux::Error("the sky texture must be a 2-D vtkImageData (azimuth x altitude) with "
                          "1 or 3 point-scalar components");
  }
  terralux::SkyTexture texture;
  texture.width = dims[0];
  texture.height = dims[1];
  texture.components = scalars->GetNumberOfComponents();
  texture.values.resize(static_cast<std::size_t>(dims[0]) * dims[1] * texture.components);
  for (vtkIdType k = 0; k < scalars->GetNumberOfTuples(); ++k)
    for (int c = 0; c < texture.components; ++c)
    {
      const double value = scalars->GetComponent(k, c);
      if (!std::isfinite(value) || value < 0.0)
      {
        throw terralux::Error("the sky texture holds a negative or non-finite value; it must "
                              "be a non-negative multiplier");
      }
      texture.values[static_cast<std::size_t>(k) * texture.components + c] = value;
    }
  return texture;
}
} // namespace

//------------------------------------------------------------------------------
vtkSkySource::vtkSkySource()
  : SkyModel(CIE_GENERAL)
  , SkyType(12)
  , SunZenith(45.0)
  , SunAzimuth(180.0)
  , DiffuseHorizontalIrradiance(100.0)
  , DirectNormalIrradiance(700.0)
  , ExtraterrestrialIrradiance(1367.0)
  , UseSunSource(1)
  , Levels(7)
  , DomeRadius(10000.0)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkSkySource::~vtkSkySource() = default;

//------------------------------------------------------------------------------
int vtkSkySource::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkDataObject" : "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSkySource::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
vtkImageData* vtkSkySource::GetRadianceOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(0));
}

//------------------------------------------------------------------------------
vtkPolyData* vtkSkySource::GetDomeOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkSkySource::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkTerraLuxFieldData::RequestWholeInputs(inputVector, this->GetNumberOfInputPorts());
  return 1;
}

//------------------------------------------------------------------------------
int vtkSkySource::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int n = 1 << this->Levels;
  const int extent[6] = { 0, n, 0, n, 0, 0 };
  const double spacing[3] = { 360.0 / n, 90.0 / n, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSkySource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* map = vtkImageData::GetData(outputVector, 0);
  vtkPolyData* dome = vtkPolyData::GetData(outputVector, 1);
  map->Initialize();
  dome->Initialize();
  try
  {
    const SkyConditions conditions = this->Conditions(vtkDataObject::GetData(inputVector[0], 0));
    std::unique_ptr<terralux::SkyModel> model = this->Model(conditions);
    terralux::SkyTexture texture;
    vtkImageData* textureImage = vtkImageData::GetData(inputVector[1], 0);
    if (textureImage)
      texture = textureFrom(textureImage);
    const terralux::SkyHierarchy sky(*model, conditions.diffuse, this->Levels, textureImage ? &texture : nullptr);
    this->UpdateProgress(0.6);
    this->FillRadianceMap(sky, conditions, dynamic_cast<const terralux::PerezSky*>(model.get()), map);
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
    map->Initialize();
    return 0;
  }
  this->FillDome(map->GetCellData()->GetArray(vtkTerraLuxFieldData::RadianceName()), dome);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkSkySource::SkyConditions vtkSkySource::Conditions(vtkDataObject* sun) const
{
  terralux::requireFiniteParameters({ { "SunZenith", this->SunZenith }, { "SunAzimuth", this->SunAzimuth },
    { "DiffuseHorizontalIrradiance", this->DiffuseHorizontalIrradiance },
    { "DirectNormalIrradiance", this->DirectNormalIrradiance },
    { "ExtraterrestrialIrradiance", this->ExtraterrestrialIrradiance }, { "DomeRadius", this->DomeRadius } });
  SkyConditions c{ this->SunZenith, this->SunAzimuth, this->DiffuseHorizontalIrradiance,
    this->DirectNormalIrradiance, this->ExtraterrestrialIrradiance };
  if (sun && this->UseSunSource &&
    !(vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::SunZenithName(), &c.sunZenith, 1) &&
      vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::SunAzimuthName(), &c.sunAzimuth, 1) &&
      vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::DiffuseHorizontalIrradianceName(), &c.diffuse, 1) &&
      vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::SunNormalIrradianceName(), &c.direct, 1) &&
      vtkTerraLuxFieldData::GetVector(
        sun, vtkTerraLuxFieldData::ExtraterrestrialIrradianceName(), &c.extraterrestrial, 1)))
    throw terralux::Error("Input port 0 must be a vtkSunSource output (field data SunZenith, SunAzimuth, "
                          "SunNormalIrradiance, DiffuseHorizontalIrradiance, ExtraterrestrialIrradiance); "
                          "or turn UseSunSource off.");
  return c;
}

//------------------------------------------------------------------------------
std::unique_ptr<terralux::SkyModel> vtkSkySource::Model(const SkyConditions& c) const
{
  const terralux::Direction sun =
    terralux::directionFromZenithAzimuth(c.sunZenith * terralux::degree, c.sunAzimuth * terralux::degree);
  switch (this->SkyModel)
  {
    case CIE_GENERAL:
      return std::make_unique<terralux::CieGeneralSky>(this->SkyType, sun);
    case CIE_OVERCAST:
      return std::make_unique<terralux::CieOvercastSky>();
    case PEREZ:
      return std::make_unique<terralux::PerezSky>(sun, c.direct, c.diffuse, c.extraterrestrial);
    default:
      return std::make_unique<terralux::UniformSky>();
  }
}

//------------------------------------------------------------------------------
void vtkSkySource::FillRadianceMap(const terralux::SkyHierarchy& sky, const SkyConditions& conditions,
  const terralux::PerezSky* perez, vtkImageData* map) const
{
  // Map cell (i along compass azimuth, j along altitude): terralux::skyMapCell.
  const int n = 1 << this->Levels;
  const int bands = sky.bands();
  map->SetExtent(0, n, 0, n, 0, 0);
  map->SetSpacing(360.0 / n, 90.0 / n, 1.0);
  map->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkDoubleArray> radiance;
  radiance->SetName(vtkTerraLuxFieldData::RadianceName());
  radiance->SetNumberOfComponents(bands);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  vtkNew<vtkDoubleArray> solidAngle;
  solidAngle->SetName("SolidAngle");
  solidAngle->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const terralux::SkyPatch patch = terralux::skyMapCell(this->Levels, i, j);
      const vtkIdType cell = i + static_cast<vtkIdType>(j) * n;
      for (int band = 0; band < bands; ++band)
        radiance->SetComponent(cell, band, sky.radiance(patch, band));
      solidAngle->SetValue(cell, patch.solidAngle());
    }
  map->GetCellData()->AddArray(radiance);
  map->GetCellData()->SetScalars(radiance);
  map->GetCellData()->AddArray(solidAngle);

  vtkFieldData* fieldData = map->GetFieldData();
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::DiffuseHorizontalIrradianceName(), conditions.diffuse);
  std::vector<double> horizontal(bands);
  for (int band = 0; band < bands; ++band)
    horizontal[band] = sky.horizontalIrradiance(band);
  vtkTerraLuxFieldData::AddVector(fieldData, "HorizontalIrradiance", horizontal.data(), bands);
  vtkTerraLuxFieldData::AddValue(fieldData, "RadianceScale", sky.radianceScale());
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::SunZenithName(), conditions.sunZenith);
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::SunAzimuthName(), conditions.sunAzimuth);
  if (perez)
  {
    vtkTerraLuxFieldData::AddValue(fieldData, "SkyClearness", perez->clearness());
    vtkTerraLuxFieldData::AddValue(fieldData, "SkyBrightness", perez->brightness());
  }
  vtkNew<vtkStringArray> name;
  name->SetName("SkyModel");
  name->InsertNextValue(modelName(this->SkyModel, this->SkyType));
  fieldData->AddArray(name);
}

//------------------------------------------------------------------------------
void vtkSkySource::FillDome(vtkDataArray* radiance, vtkPolyData* dome) const
{
  // The map's cell corners on a hemisphere of DomeRadius, its cells as quads.
  const int n = 1 << this->Levels;
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(static_cast<vtkIdType>(n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
    {
      const terralux::Direction d = terralux::skyMapCorner(this->Levels, i, j);
      points->SetPoint(i + static_cast<vtkIdType>(j) * (n + 1), this->DomeRadius * d[0],
        this->DomeRadius * d[1], this->DomeRadius * d[2]);
    }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = i + static_cast<vtkIdType>(j) * (n + 1);
      const vtkIdType ids[4] = { a, a + n + 1, a + n + 2, a + 1 }; // normals point inward
      quads->InsertNextCell(4, ids);
    }
  dome->SetPoints(points);
  dome->SetPolys(quads);
  dome->GetCellData()->AddArray(radiance);
  dome->GetCellData()->SetScalars(radiance);
}

//------------------------------------------------------------------------------
void vtkSkySource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SkyModel: " << modelName(this->SkyModel, this->SkyType) << "\n";
  os << indent << "SkyType: " << this->SkyType << "\n";
  os << indent << "SunZenith: " << this->SunZenith << "\n";
  os << indent << "SunAzimuth: " << this->SunAzimuth << "\n";
  os << indent << "DiffuseHorizontalIrradiance: " << this->DiffuseHorizontalIrradiance << "\n";
  os << indent << "DirectNormalIrradiance: " << this->DirectNormalIrradiance << "\n";
  os << indent << "ExtraterrestrialIrradiance: " << this->ExtraterrestrialIrradiance << "\n";
  os << indent << "UseSunSource: " << (this->UseSunSource ? "On" : "Off") << "\n";
  os << indent << "Levels: " << this->Levels << "\n";
  os << indent << "DomeRadius: " << this->DomeRadius << "\n";
}
