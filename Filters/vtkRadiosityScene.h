// Gathers VTK data sets and light sources into the radiosity engine's scene (private
// to TerraLux::Filters). Errors are thrown as terralux::Error with a message that
// names the problem and the fix.
#ifndef vtkRadiosityScene_h
#define vtkRadiosityScene_h

#include "radiosity_types.h"
#include "sky_hierarchy.h"

#include "vtkType.h"

#include <memory>
#include <vector>

class vtkDataObject;
class vtkDataSet;

class vtkRadiosityScene
{
public:
  struct Input
  {
    vtkDataSet* data;
    vtkIdType firstPoint;
  };

  /// Adds a vtkPolyData or a 2-D vtkStructuredGrid.
  void AddDataSet(vtkDataSet* data, double defaultReflectance, const char* reflectanceName,
    const char* emissionName);
  /// Adds a vtkSkySource radiance map or a vtkSunSource output.
  void AddLight(vtkDataObject* light);

  terralux::RadiosityScene Scene;
  std::vector<Input> Inputs;
  std::unique_ptr<terralux::SkyHierarchy> Sky;
  bool HasSun = false;
  terralux::Vec3 SunDirection{ 0.0 };
  terralux::Spectrum SunIrradiance{};
  bool HasEmission = false;
  std::size_t SkippedCells = 0; ///< vertices and lines, ignored
};

#endif
