// Turns a solved radiosity hierarchy into VTK outputs (private to TerraLux::Filters):
// per-point arrays on the input geometry, the adaptive leaf mesh with T-vertices
// made continuous, and the links as lines.
#ifndef vtkRadiosityOutputs_h
#define vtkRadiosityOutputs_h

#include <vector>

class vtkDataArray;
class vtkDataSet;
class vtkFieldData;
class vtkPolyData;
class vtkRadiosityScene;

namespace terralux
{
class HierarchicalRadiosity;
class PointEvaluator;
}

struct vtkRadiosityOutputs
{
  /// The point arrays of each solve, in order: global, sun, sky and reflected
  /// irradiance, radiosity.
  static constexpr int Quantities = 5;
  static const char* QuantityName(int quantity);
  /// The same quantities summed over time (Wh/m^2), as vtkSolarIrradiation names them.
  static const char* IntegratedName(int quantity);
  /// The other point arrays: hours of direct sun, the sky view factor.
  static const char* SunshineDurationName() { return "SunshineDuration"; }
  static const char* SkyViewFactorName() { return "SkyViewFactor"; }
  /// The estimated error of the global irradiance at each point (W/m^2), with
  /// EvaluateAtPoints; summed over time (Wh/m^2) under its integrated name.
  static const char* IrradianceErrorName() { return "IrradianceError"; }
  static const char* IrradiationErrorName() { return "IrradiationError"; }
  /// The leaf mesh's cell arrays that map each leaf back to the input: the index of
  /// port 0's leaf data set (in connection and composite order) and its cell there
  /// (for a terrain leaf, the grid cell holding its centre; -1 on a far terrain).
  static const char* InputIndexName() { return "InputIndex"; }
  static const char* InputCellName() { return "InputCell"; }
  /// Every point array the filters write, in the order above (what a writer picks).
  static std::vector<const char*> AllNames();

  /// How output 0's point arrays are made.
  struct PointOptions
  {
    int bands = 1;
    bool evaluateAtPoints = true;
    bool hornNormals = false; ///< terrain posts take Horn's 3 x 3 normal, else the area-weighted one
    bool sunshine = false;    ///< add SunshineDuration: the hours of the suns that reach each point
    /// The terrain posts evaluated, grid indices i0, i1, j0, j1 (a piece); the others
    /// stay NaN. Default: all.
    int posts[4] = { 0, -1, 0, -1 };
    bool allPosts() const { return this->posts[1] < this->posts[0]; }
    /// The output holds those posts only (a piece cropped first, so that its arrays
    /// take the piece's memory, not the whole grid's), in grid order.
    bool croppedToPosts = false;
  };
  /// Adds Irradiance, SunIrradiance, SkyIrradiance, ReflectedIrradiance and Radiosity
  /// (SkyViewFactor for a terrain lit by a sky, SunshineDuration if asked) to `output`, a shallow copy of
  /// input `index` of the scene.
  /// With evaluateAtPoints off, each point takes the area-weighted average of the
  /// leaves that have it as a corner instead (fast; values smeared over the elements
  /// around the point; no SkyViewFactor).
  static void AddPointArrays(const terralux::PointEvaluator& evaluator, const vtkRadiosityScene& scene,
    int index, const PointOptions& options, vtkDataSet* output);
  /// withSky: add SkyViewFactor (the leaves' own, continuous like the other arrays).
  static void BuildLeafMesh(const terralux::HierarchicalRadiosity& solver, const vtkRadiosityScene& scene,
    int bands, bool withSky, vtkPolyData* output);
  static void BuildLinks(const terralux::HierarchicalRadiosity& solver, vtkPolyData* output);
  /// Adds a one-value double array to field data (counts, seconds).
  static void AddFieldValue(vtkFieldData* fieldData, const char* name, double value);
  /// Every value NaN ("not computed"), written on every core: an output array's memory
  /// is first touched here, and the system zeroes its pages on the core that touches
  /// them. Arrays of integers take vtkDataArray::Fill's value, on one core.
  static void FillWithNaN(vtkDataArray* array);
};

#endif
