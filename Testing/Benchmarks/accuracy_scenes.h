#pragma once
// The scenes of the accuracy report (issue "speed against error"), built in code with
// fixed seeds: what vtkHierarchicalRadiosity gets (geometry and lights as VTK data) and
// what the reference needs (the same geometry as a RadiosityScene, the sky map, suns).

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDataObject;
class vtkAlgorithm;

namespace terralux_bench
{
struct AccuracyScene
{
  std::string name;
  std::string description;
  vtkSmartPointer<vtkDataObject> geometry; ///< vtkStructuredGrid, vtkPolyData or a multiblock of them
  std::vector<vtkSmartPointer<vtkDataObject>> lights; ///< sky radiance maps and sun polydata
  double reflectance = 0.2;
  const char* emissionArray = nullptr;
  bool terrain = false; ///< a single terrain grid (the triangle path applies)
  /// Where the lights are one sun (compass azimuth, degrees; normal irradiance, W/m^2) and
  /// its CIE clear sky (diffuse horizontal irradiance): what a peer tool's inputs are
  /// matched to (Testing/Benchmarks/rsun_accuracy.py). sunIrradiance 0: other lights.
  double sunAltitude = 0.0, sunAzimuth = 0.0, sunIrradiance = 0.0, diffuseHorizontal = 0.0;
};

/// Names: olinda, fractal, hills, crater, canyon, box, house-sky, house-sun, olinda-sky (sun
/// below the horizon), olinda-black (reflectance 0), steep-morning and steep-noon (a crop of
/// the steep benchmark DEM), snowbowl (reflectance 0.8, relief on its walls). Throws std::runtime_error for others or
/// when Olinda's DEM is missing (dataDir: Testing/Data/External).
AccuracyScene makeAccuracyScene(const std::string& name, const std::string& dataDir);
std::vector<std::string> accuracySceneNames();
} // namespace terralux_bench
