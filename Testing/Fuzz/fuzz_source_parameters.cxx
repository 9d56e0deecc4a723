// Fuzz target: fuzzed parameter values (NaN, infinities, extremes among them) into
// vtkSunSource, vtkSkySource and a height-field vtkTerrainSource, chained as a user
// would. Each must fail with an error or give finite, physical values.
#include "fuzz_support.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSkySource.h"
#include "vtkSunSource.h"
#include "vtkTerrainSource.h"

#include <iostream>
#include <string>

namespace
{
void requireFiniteCells(vtkDataSet* data, const char* name, const char* what)
{
  vtkDataArray* array = data->GetCellData()->GetArray(name);
  if (!array)
    return;
  for (vtkIdType k = 0; k < array->GetNumberOfValues(); ++k)
  {
    const double v = array->GetComponent(k / array->GetNumberOfComponents(), k % array->GetNumberOfComponents());
    if (!(std::isfinite(v) && v >= 0.0))
      terralux_fuzz::finding(what);
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  terralux_fuzz::silenceVtk();
  terralux_fuzz::ByteReader reader(data, size);

  vtkNew<vtkSunSource> sun;
  static const char* const dates[] = { "2024-06-21T12:00:00+02:00", "2003-10-17T12:30:30-07:00",
    "1900-01-01T00:00:00Z", "2024-02-30T10:00:00Z", "2024-12-21T09:00:00-03:00", "" };
  const int dateChoice = reader.between(0, 6);
  std::string date = dateChoice < 6 ? dates[dateChoice] : std::string(reinterpret_cast<const char*>(reader.rest()),
                                                                 std::min<std::size_t>(reader.remaining(), 32));
  if (dateChoice == 6)
    for (int k = 0; k < 32; ++k)
      reader.take<std::uint8_t>();
  sun->SetDateTime(date.c_str());
  sun->SetLatitude(reader.number(100.0));
  sun->SetLongitude(reader.number(400.0));
  sun->SetHeight(reader.number(10000.0));
  sun->SetPressure(reader.number(1500.0));
  sun->SetTemperature(reader.number(60.0));
  sun->SetDeltaT(reader.number(200.0));
  sun->SetIrradianceModel(reader.between(0, 2));
  sun->SetLinkeTurbidity(reader.number(8.0));
  sun->SetSolarConstant(reader.number(2000.0));
  sun->SetUserNormalIrradiance(reader.number(1500.0));
  sun->SetUserDiffuseHorizontalIrradiance(reader.number(500.0));
  sun->SetAtmosphericRefraction(reader.between(0, 1));
  sun->Update();
  if (sun->GetOutput()->GetNumberOfPoints() > 0)
  {
    const double normal = sun->GetNormalIrradiance();
    if (!(std::isfinite(normal) && normal >= 0.0 && std::isfinite(sun->GetDiffuseHorizontalIrradiance()) &&
          std::isfinite(sun->GetZenith()) && std::isfinite(sun->GetAzimuth())))
    {
      std::fprintf(stderr, "normal %g diffuse %g zenith %g azimuth %g (date '%s', model %d)\n", normal,
        sun->GetDiffuseHorizontalIrradiance(), sun->GetZenith(), sun->GetAzimuth(), date.c_str(),
        sun->GetIrradianceModel());
      sun->Print(std::cerr);
      terralux_fuzz::finding("vtkSunSource gave a non-finite or negative value");
    }
    if (sun->GetIrradianceModel() != vtkSunSource::USER && normal > 1.0001 * sun->GetExtraterrestrialIrradiance())
      terralux_fuzz::finding("a clear-sky beam above the extraterrestrial irradiance");
  }

  vtkNew<vtkSkySource> sky;
  sky->SetSkyModel(reader.between(0, 3));
  sky->SetSkyType(reader.between(0, 16));
  sky->SetLevels(reader.between(0, 6));
  sky->SetUseSunSource(reader.between(0, 1));
  sky->SetSunZenith(reader.number(200.0));
  sky->SetSunAzimuth(reader.number(800.0));
  sky->SetDiffuseHorizontalIrradiance(reader.number(800.0));
  sky->SetDirectNormalIrradiance(reader.number(1200.0));
  sky->SetExtraterrestrialIrradiance(reader.number(1500.0));
  sky->SetSunConnection(sun->GetOutputPort());
  sky->Update();
  requireFiniteCells(sky->GetRadianceOutput(), "Radiance", "vtkSkySource gave a non-finite or negative radiance");

  vtkNew<vtkImageData> image;
  const int nx = reader.between(0, 6), ny = reader.between(0, 6);
  image->SetDimensions(nx, ny, 1);
  image->SetSpacing(reader.number(100.0), reader.number(100.0), 1.0);
  image->SetOrigin(reader.number(1e6), reader.number(1e6), 0.0);
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(static_cast<vtkIdType>(nx) * ny);
  for (vtkIdType k = 0; k < heights->GetNumberOfTuples(); ++k)
    heights->SetValue(k, static_cast<float>(reader.number(20000.0)));
  image->GetPointData()->SetScalars(heights);
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetInputData(image);
  if (reader.between(0, 1))
    terrain->SetGeoOrigin(reader.number(100.0), reader.number(200.0), reader.number(1000.0));
  terrain->Update();
  terralux_fuzz::requireFiniteOutput(terrain->GetOutput(), "vtkTerrainSource gave a non-finite point");
  return 0;
}
