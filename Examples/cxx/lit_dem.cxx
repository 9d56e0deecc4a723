// A DEM lit by the sun and a clear sky at a given time, its irradiance written as a
// GeoTIFF on the DEM's grid: the Python pipeline of the README, in C++.
//
//   lit_dem DEM OUTPUT.tif [ISO-8601 time, default 2024-08-15T08:30:00-03:00]
#include <vtkHierarchicalRadiosity.h>
#include <vtkSkySource.h>
#include <vtkSunSource.h>
#include <vtkTerrainRasterWriter.h>
#include <vtkTerrainSource.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStructuredGrid.h>

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3 || argc > 4)
  {
    std::cerr << "usage: lit_dem DEM OUTPUT.tif [ISO-8601 time]\n";
    return 2;
  }
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(argv[1]);
  vtkNew<vtkSunSource> sun; // placed at the DEM's GeoOrigin
  sun->SetInputConnection(terrain->GetOutputPort());
  sun->SetDateTime(argc == 4 ? argv[3] : "2024-08-15T08:30:00-03:00");
  vtkNew<vtkSkySource> sky;
  sky->SetSunConnection(sun->GetOutputPort());
  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputConnection(terrain->GetOutputPort());
  radiosity->AddLightConnection(sun->GetOutputPort());
  radiosity->AddLightConnection(sky->GetOutputPort(0));
  radiosity->SetDefaultReflectance(0.2);
  vtkNew<vtkTerrainRasterWriter> writer;
  writer->SetInputConnection(radiosity->GetOutputPort());
  writer->SetFileName(argv[2]);
  writer->AddArrayName("Irradiance");
  writer->AddArrayName("SunIrradiance");
  writer->AddArrayName("SkyIrradiance");
  writer->AddArrayName("ReflectedIrradiance");
  if (!writer->Write())
    return 1; // the errors above say why
  auto* lit = vtkStructuredGrid::SafeDownCast(radiosity->GetOutputDataObject(0));
  double range[2];
  lit->GetPointData()->GetArray("Irradiance")->GetRange(range);
  std::cout << "wrote " << argv[2] << ": global irradiance " << range[0] << " to " << range[1] << " W/m^2\n";
  return 0;
}
