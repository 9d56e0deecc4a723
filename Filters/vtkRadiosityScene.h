// Gathers VTK data sets and light sources into the radiosity engine's scene (private
// to TerraLux::Filters). Errors are thrown as terralux::Error with a message that
// names the problem and the fix.
#ifndef vtkRadiosityScene_h
#define vtkRadiosityScene_h

#include "hierarchy/radiosity_types.h"
#include "sky/sky_hierarchy.h"
#include "terrain/terrain_grid.h"

#include "vtkType.h"

#include <memory>
#include <vector>

class vtkDataObject;
class vtkDataSet;
class vtkStructuredGrid;

class vtkRadiosityScene
{
public:
  /// A data set itself, or the leaf data sets of a composite in its order (null and
  /// non-data-set blocks left out).
  static std::vector<vtkDataSet*> DataSetsOf(vtkDataObject* data);

  struct Input
  {
    vtkDataSet* data;
    vtkIdType firstPoint;
    int terrain; ///< index into Terrains, or -1 for polygons
  };

  /// Adds a vtkPolyData or a 2-D vtkStructuredGrid. With `terrainHierarchy`, a grid
  /// enters as a TerrainGrid (terrain patches, Embree grid geometry); otherwise as
  /// two triangles per cell.
  void AddDataSet(vtkDataSet* data, double defaultReflectance, const char* reflectanceName,
    const char* emissionName, bool terrainHierarchy);
  /// The far terrain of the one terrain grid AddDataSet adds next (a window of the
  /// full grid, e.g. an MPI rank's piece and its halo): vtkTerrainSource's output 1,
  /// every `stride`-th post of the full grid. Its materials are its own (the same
  /// arrays, or the default). The window's posts are then kept relative to the far
  /// terrain's origin, the same on every rank. Call FindWindowInFarTerrain after.
  void SetFarTerrain(vtkStructuredGrid* far, int stride, double defaultReflectance, const char* reflectanceName,
    const char* emissionName);
  /// Where the one terrain (a window whose post (0, 0) is the full grid's (i0, j0))
  /// lies in the far terrain: its posts must be the far terrain's, bit for bit but for
  /// rounding, at one offset of fewer than `stride` posts. Throws terralux::Error naming
  /// the fix when they are not.
  void FindWindowInFarTerrain(int i0, int j0);
  /// Adds a vtkSkySource radiance map or a vtkSunSource output. Every light counts:
  /// suns each become a sun element, skies are summed into one radiance map (at the
  /// finest resolution among them; a one-band sky lights every band alike).
  void AddLight(vtkDataObject* light);

  struct SunLight
  {
    terralux::Vec3 direction;
    terralux::Spectrum irradiance;
    double hours = 0.0; ///< the time a step of a time series stands for; 0 for an instant
  };

  terralux::RadiosityScene Scene;
  std::vector<Input> Inputs;
  std::vector<std::unique_ptr<terralux::TerrainGrid>> Terrains;
  std::unique_ptr<terralux::TerrainGrid> FarTerrain; ///< SetFarTerrain's, or null
  std::unique_ptr<terralux::SkyHierarchy> Sky; ///< the sum of the skies added, or null
  std::vector<SunLight> Suns;
  bool HasEmission = false;
  bool SunshineDuration = false; ///< the outputs add SunshineDuration (the suns' hours at each point)
  std::size_t SkippedCells = 0; ///< vertices, lines and polygons of fewer than 3 points: no area

private:
  void AddSky(int level, int bands, std::vector<double> averages);
  // The summed skies' cell averages, finest pyramid order ((iu * side + iv) * bands + band).
  int SkyLevel = 0;
  int SkyBands = 0;
  std::vector<double> SkyAverages;
};

#endif
