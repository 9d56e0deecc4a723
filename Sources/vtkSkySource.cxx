#include "vtkSkySource.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include "angles.h"
#include "cie_sky.h"
#include "error.h"
#include "perez_sky.h"
#include "sky_hierarchy.h"
#include "finite_parameters.h"
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
    terralux::requireFiniteParameters({ { "SunZenith", this->SunZenith }, { "SunAzimuth", this->SunAzimuth },
      { "DiffuseHorizontalIrradiance", this->DiffuseHorizontalIrradiance },
      { "DirectNormalIrradiance", this->DirectNormalIrradiance },
      { "ExtraterrestrialIrradiance", this->ExtraterrestrialIrradiance }, { "DomeRadius", this->DomeRadius } });
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
    return 0;
  }
  double sunZenith = this->SunZenith, sunAzimuth = this->SunAzimuth;
  double diffuse = this->DiffuseHorizontalIrradiance, direct = this->DirectNormalIrradiance;
  double extraterrestrial = this->ExtraterrestrialIrradiance;
  vtkDataObject* sun = vtkDataObject::GetData(inputVector[0], 0);
  if (sun && this->UseSunSource)
  {
    if (!vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::SunZenithName(), &sunZenith, 1) ||
      !vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::SunAzimuthName(), &sunAzimuth, 1) ||
      !vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::DiffuseHorizontalIrradianceName(), &diffuse, 1) ||
      !vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::SunNormalIrradianceName(), &direct, 1) ||
      !vtkTerraLuxFieldData::GetVector(sun, vtkTerraLuxFieldData::ExtraterrestrialIrradianceName(), &extraterrestrial, 1))
    {
      vtkErrorMacro("Input port 0 must be a vtkSunSource output (field data SunZenith, "
                    "SunAzimuth, SunNormalIrradiance, DiffuseHorizontalIrradiance, "
                    "ExtraterrestrialIrradiance); or turn UseSunSource off.");
      return 0;
    }
  }
  if (!std::isfinite(sunAzimuth))
  {
    vtkErrorMacro("SunAzimuth must be a finite number of degrees.");
    return 0;
  }
  const terralux::Direction sunDirection =
    terralux::directionFromZenithAzimuth(sunZenith * terralux::degree, sunAzimuth * terralux::degree);

  std::unique_ptr<terralux::SkyHierarchy> sky;
  std::unique_ptr<terralux::PerezSky> perez;
  try
  {
    std::unique_ptr<terralux::SkyModel> model;
    switch (this->SkyModel)
    {
      case CIE_GENERAL:
        model = std::make_unique<terralux::CieGeneralSky>(this->SkyType, sunDirection);
        break;
      case CIE_OVERCAST:
        model = std::make_unique<terralux::CieOvercastSky>();
        break;
      case PEREZ:
        model = std::make_unique<terralux::PerezSky>(sunDirection, direct, diffuse, extraterrestrial);
        break;
      default:
        model = std::make_unique<terralux::UniformSky>();
    }
    terralux::SkyTexture texture;
    vtkImageData* textureImage = vtkImageData::GetData(inputVector[1], 0);
    if (textureImage)
    {
      texture = textureFrom(textureImage);
    }
    sky = std::make_unique<terralux::SkyHierarchy>(
      *model, diffuse, this->Levels, textureImage ? &texture : nullptr);
    if (this->SkyModel == PEREZ)
    {
      perez.reset(static_cast<terralux::PerezSky*>(model.release()));
    }
  }
  catch (const terralux::Error& error)
  {
    vtkErrorMacro(<< error.what());
    return 0;
  }
  this->UpdateProgress(0.6);

  // Map cell (i along compass azimuth, j along altitude): terralux::skyMapCell.
  const int n = 1 << this->Levels;
  const int bands = sky->bands();
  map->SetExtent(0, n, 0, n, 0, 0);
  map->SetSpacing(360.0 / n, 90.0 / n, 1.0);
  map->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkDoubleArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(bands);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  vtkNew<vtkDoubleArray> solidAngle;
  solidAngle->SetName("SolidAngle");
  solidAngle->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const terralux::SkyPatch patch = terralux::skyMapCell(this->Levels, i, j);
      const vtkIdType cell = i + static_cast<vtkIdType>(j) * n;
      for (int band = 0; band < bands; ++band)
      {
        radiance->SetComponent(cell, band, sky->radiance(patch, band));
      }
      solidAngle->SetValue(cell, patch.solidAngle());
    }
  }
  map->GetCellData()->AddArray(radiance);
  map->GetCellData()->SetScalars(radiance);
  map->GetCellData()->AddArray(solidAngle);

  vtkFieldData* fieldData = map->GetFieldData();
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::DiffuseHorizontalIrradianceName(), diffuse);
  std::vector<double> horizontal(bands);
  for (int band = 0; band < bands; ++band)
  {
    horizontal[band] = sky->horizontalIrradiance(band);
  }
  vtkTerraLuxFieldData::AddVector(fieldData, "HorizontalIrradiance", horizontal.data(), bands);
  vtkTerraLuxFieldData::AddValue(fieldData, "RadianceScale", sky->radianceScale());
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::SunZenithName(), sunZenith);
  vtkTerraLuxFieldData::AddValue(fieldData, vtkTerraLuxFieldData::SunAzimuthName(), sunAzimuth);
  if (perez)
  {
    vtkTerraLuxFieldData::AddValue(fieldData, "SkyClearness", perez->clearness());
    vtkTerraLuxFieldData::AddValue(fieldData, "SkyBrightness", perez->brightness());
  }
  vtkNew<vtkStringArray> name;
  name->SetName("SkyModel");
  name->InsertNextValue(modelName(this->SkyModel, this->SkyType));
  fieldData->AddArray(name);

  // Dome: the map's cell corners on a hemisphere.
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
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = i + static_cast<vtkIdType>(j) * (n + 1);
      const vtkIdType ids[4] = { a, a + n + 1, a + n + 2, a + 1 }; // normals point inward
      quads->InsertNextCell(4, ids);
    }
  }
  dome->SetPoints(points);
  dome->SetPolys(quads);
  dome->GetCellData()->AddArray(radiance);
  dome->GetCellData()->SetScalars(radiance);
  this->UpdateProgress(1.0);
  return 1;
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
