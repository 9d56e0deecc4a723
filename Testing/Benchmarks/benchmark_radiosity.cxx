// Radiosity benchmark: a DEM under the sun and a CIE clear sky of 09:00 local solar time
// on 21 December at its centre (r.sun's time=9.0 of day 356; TERRALUX_BENCH_SOLAR_TIME
// sets another hour), reflectance 0.2, at one tolerance. Prints wall time, peak memory,
// elements, links, rays; with a reference file (per-vertex global irradiance of a
// converged run) also the relative RMS error and the 95th percentile of the absolute
// relative error.
//   benchmark_radiosity DEM TOLERANCE SAMPLES [--write REF | --compare REF]
// With TERRALUX_BENCH_AVERAGED=1 in the environment, point values are averaged over
// elements (EvaluateAtPoints off) instead of evaluated at the points; with
// TERRALUX_BENCH_TRIANGLES=1 the terrain enters as two triangles per cell
// (UseTerrainHierarchy off) instead of as terrain patches; with
// TERRALUX_BENCH_SKY_BY_RAYS=1 the hidden sky comes from rays (SkyFromHorizons off);
// TERRALUX_BENCH_TARGET_ERROR and TERRALUX_BENCH_TARGET_FLOOR set TargetError and
// TargetErrorFloor.
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"
#include "vtkTerrainSource.h"

#include "sun/date_time.h"
#include "sun/solar_position.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// The UTC instant of `hour` local apparent solar time on 2024-12-21 at a longitude: mean
// solar time runs lon / 15 h ahead of UTC, apparent time the equation of time further.
std::string localSolarTime(double hour, double latitude, double longitude)
{
  const terralux::DateTime midnight = terralux::DateTime::parse("2024-12-21T00:00:00Z");
  double julianDay = midnight.julianDay() + (hour - longitude / 15.0) / 24.0;
  terralux::SolarPositionInput input;
  input.latitudeDeg = latitude;
  input.longitudeDeg = longitude;
  input.julianDayUT = julianDay;
  julianDay -= terralux::computeSolarPosition(input).equationOfTimeMinutes / (24.0 * 60.0);
  return terralux::DateTime::fromJulianDay(julianDay).toUtcString();
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 4)
  {
    std::cerr << "usage: benchmark_radiosity DEM TOLERANCE SAMPLES [--write REF | --compare REF]\n";
    return 2;
  }
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(argv[1]);
  vtkNew<vtkSunSource> sun;
  sun->SetInputConnection(terrain->GetOutputPort());
  vtkNew<vtkSkySource> sky;
  sky->SetSunConnection(sun->GetOutputPort());
  sky->SetSkyType(12);
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputConnection(terrain->GetOutputPort());
  radiosity->AddLightConnection(sun->GetOutputPort());
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  radiosity->SetDefaultReflectance(0.2);
  radiosity->SetErrorTolerance(std::atof(argv[2]));
  radiosity->SetVisibilitySamples(std::atoi(argv[3]));
  radiosity->SetEvaluateAtPoints(std::getenv("TERRALUX_BENCH_AVERAGED") == nullptr);
  radiosity->SetUseTerrainHierarchy(std::getenv("TERRALUX_BENCH_TRIANGLES") == nullptr);
  radiosity->SetSkyFromHorizons(std::getenv("TERRALUX_BENCH_SKY_BY_RAYS") == nullptr);
  if (const char* value = std::getenv("TERRALUX_BENCH_TARGET_ERROR"))
    radiosity->SetTargetError(std::atof(value));
  if (const char* value = std::getenv("TERRALUX_BENCH_TARGET_FLOOR"))
    radiosity->SetTargetErrorFloor(std::atof(value));
  const auto processStart = std::chrono::steady_clock::now();
  terrain->Update();
  const double terrainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - processStart).count();
  vtkDataArray* origin = terrain->GetOutput()->GetFieldData()->GetArray("GeoOrigin");
  if (!origin)
  {
    std::cerr << "benchmark_radiosity: " << argv[1] << " gave no terrain\n";
    return 1;
  }
  const char* hour = std::getenv("TERRALUX_BENCH_SOLAR_TIME");
  sun->SetDateTime(
    localSolarTime(hour ? std::atof(hour) : 9.0, origin->GetComponent(0, 0), origin->GetComponent(0, 1)).c_str());
  sky->Update();
  std::cerr << "terrain " << terrainSeconds << " s, sun and sky "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - processStart).count() - terrainSeconds << " s\n";

  const auto start = std::chrono::steady_clock::now();
  radiosity->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);

  vtkDataObject* output = radiosity->GetOutput();
  auto stat = [&](const char* name) { return output->GetFieldData()->GetArray(name)->GetComponent(0, 0); };
  vtkDataArray* irradiance = vtkStructuredGrid::SafeDownCast(output)->GetPointData()->GetArray("Irradiance");
  std::vector<double> values(irradiance->GetNumberOfTuples());
  for (std::size_t k = 0; k < values.size(); ++k)
    values[k] = irradiance->GetComponent(static_cast<vtkIdType>(k), 0);

  std::cout << "tolerance " << argv[2] << "  samples " << argv[3] << "  time " << seconds << " s  peak RSS " << usage.ru_maxrss / 1024.0
            << " MiB  elements " << stat("Elements") << "  links " << stat("Links") << "  rays " << stat("Rays")
            << "  iterations " << stat("Iterations") << "  horizons " << stat("SecondsHorizons") << " s  points "
            << stat("SecondsPoints") << " s, "
            << stat("RaysPoints") << " rays  sun " << 90.0 - sun->GetOutput()->GetFieldData()->GetArray("SunZenith")->GetComponent(0, 0)
            << " deg up";
  if (argc == 6 && std::strcmp(argv[4], "--write") == 0)
  {
    std::ofstream(argv[5], std::ios::binary)
      .write(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  }
  else if (argc == 6 && std::strcmp(argv[4], "--compare") == 0)
  {
    std::vector<double> reference(values.size());
    std::ifstream(argv[5], std::ios::binary)
      .read(reinterpret_cast<char*>(reference.data()), reference.size() * sizeof(double));
    double squared = 0.0, referenceSquared = 0.0;
    std::vector<double> relative;
    for (std::size_t k = 0; k < values.size(); ++k)
    {
      squared += (values[k] - reference[k]) * (values[k] - reference[k]);
      referenceSquared += reference[k] * reference[k];
      relative.push_back(std::abs(values[k] - reference[k]) / std::max(1e-9, reference[k]));
    }
    std::sort(relative.begin(), relative.end());
    std::cout << "  relative RMS error " << std::sqrt(squared / referenceSquared) << "  p95 relative error "
              << relative[static_cast<std::size_t>(0.95 * (relative.size() - 1))];
  }
  std::cout << std::endl;
  // Every phase's seconds and rays, and the horizon map's azimuths, as the output's
  // field data keeps them (on standard error: scripts read the line above as the run's
  // figures).
  std::cerr << "phases:";
  vtkFieldData* fields = output->GetFieldData();
  for (int a = 0; a < fields->GetNumberOfArrays(); ++a)
    if (const char* name = fields->GetArrayName(a);
        name && (std::strncmp(name, "Seconds", 7) == 0 || std::strncmp(name, "Rays", 4) == 0 ||
                  std::strncmp(name, "Horizon", 7) == 0))
      std::cerr << " " << name << " " << fields->GetArray(a)->GetComponent(0, 0);
  std::cerr << "\n";
  return 0;
}
