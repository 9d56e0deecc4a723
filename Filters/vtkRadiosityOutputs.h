// Turns a solved radiosity hierarchy into VTK outputs (private to TerraLux::Filters):
// per-point arrays on the input geometry, the adaptive leaf mesh with T-vertices
// made continuous, and the links as lines.
#ifndef vtkRadiosityOutputs_h
#define vtkRadiosityOutputs_h

class vtkDataSet;
class vtkPolyData;
class vtkRadiosityScene;

namespace terralux
{
class HierarchicalRadiosity;
}

struct vtkRadiosityOutputs
{
  /// Adds Irradiance, SunIrradiance, SkyIrradiance, ReflectedIrradiance and Radiosity
  /// (and SkyViewFactor for a terrain lit by a sky) to `output`, a shallow copy of
  /// input `index` of the scene.
  static void AddPointArrays(const terralux::HierarchicalRadiosity& solver, const vtkRadiosityScene& scene,
    int index, int bands, vtkDataSet* output);
  static void BuildLeafMesh(const terralux::HierarchicalRadiosity& solver, int bands, vtkPolyData* output);
  static void BuildLinks(const terralux::HierarchicalRadiosity& solver, vtkPolyData* output);
};

#endif
