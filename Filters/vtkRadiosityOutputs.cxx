#include "vtkRadiosityOutputs.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityScene.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkTerraLuxLargeArrays.h"

#include "evaluation/point_values.h"
#include "hierarchy/polygon_element.h"
#include "evaluation/point_evaluator.h"
#include "solver/solver.h"
#include "evaluation/polygon_leaf_mesh.h"
#include "terrain/terrain_mesh.h"
#include "hierarchy/terrain_patch.h"
#include "terrain/terrain_grid.h"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>

namespace
{
using terralux::Spectrum;
using terralux::Vec3;

// The five output quantities: global, sun, sky, reflected irradiance, radiosity.
constexpr int quantities = vtkRadiosityOutputs::Quantities;
const char* const quantityNames[quantities] = { "Irradiance", "SunIrradiance", "SkyIrradiance",
  "ReflectedIrradiance", "Radiosity" };
const char* const integratedNames[quantities] = { "GlobalIrradiation", "BeamIrradiation", "SkyIrradiation",
  "ReflectedIrradiation", "OutgoingIrradiation" };

// The quantities of a point's values, in the order above.
std::array<Spectrum, quantities> quantitiesOf(const terralux::PointValues& v)
{
  return { v.globalIrradiance(), v.irradiance[terralux::SunLight], v.irradiance[terralux::SkyLight],
    v.irradiance[terralux::ReflectedLight], v.radiosity };
}

// vtkRadiosityOutputs::FillWithNaN's worker, for each real value type.
struct FillNaN
{
  template <typename ArrayT>
  void operator()(ArrayT* typed) const
  {
    using Value = vtk::GetAPIType<ArrayT>;
    auto values = vtk::DataArrayValueRange(typed);
    vtkSMPTools::Fill(values.begin(), values.end(), std::numeric_limits<Value>::quiet_NaN());
  }
};

// A point array of `components` values per point, NaN until set.
vtkSmartPointer<vtkDoubleArray> unsetArray(const char* name, int components, vtkIdType count)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  vtkTerraLuxLargeArrays::Allocate(array, count);
  // On every core (one core's zeroing of the pages took 3 s of a 4097^2 grid's solve).
  vtkRadiosityOutputs::FillWithNaN(array);
  return array;
}

// The point arrays of output 0 or the leaf mesh: the five quantities (`bands`
// components), SkyViewFactor and SunshineDuration if asked; NaN until set.
class PointArrays
{
public:
  PointArrays(int bands, vtkIdType count, bool skyViewFactor, bool sunshine, bool irradianceError)
    : Bands(bands)
  {
    if (irradianceError)
      this->IrradianceError = unsetArray(vtkRadiosityOutputs::IrradianceErrorName(), 1, count);
    for (int q = 0; q < quantities; ++q)
      this->Quantities[q] = unsetArray(quantityNames[q], bands, count);
    if (skyViewFactor)
      this->SkyViewFactor = unsetArray(vtkRadiosityOutputs::SkyViewFactorName(), 1, count);
    if (sunshine)
      this->Sunshine = unsetArray(vtkRadiosityOutputs::SunshineDurationName(), 1, count);
  }

  // Thread-safe for distinct points.
  void set(vtkIdType point, const terralux::PointValues& v) const
  {
    const auto values = quantitiesOf(v);
    for (int q = 0; q < quantities; ++q)
      std::copy_n(values[q].begin(), this->Bands, this->Quantities[q]->GetPointer(point * this->Bands));
    if (this->SkyViewFactor)
      this->SkyViewFactor->SetValue(point, v.skyViewFactor);
    if (this->Sunshine)
      this->Sunshine->SetValue(point, v.sunlitHours);
    if (this->IrradianceError)
      this->IrradianceError->SetValue(point, v.irradianceError);
  }

  void addTo(vtkPointData* pointData) const
  {
    for (const auto& array : this->Quantities)
      pointData->AddArray(array);
    if (this->SkyViewFactor)
      pointData->AddArray(this->SkyViewFactor);
    if (this->Sunshine)
      pointData->AddArray(this->Sunshine);
    if (this->IrradianceError)
      pointData->AddArray(this->IrradianceError);
    pointData->SetActiveScalars(quantityNames[0]);
  }

private:
  const int Bands;
  std::array<vtkSmartPointer<vtkDoubleArray>, quantities> Quantities;
  vtkSmartPointer<vtkDoubleArray> SkyViewFactor, Sunshine, IrradianceError;
};

// The cell of the scene's terrain grid that holds a terrain leaf's centre; -1 where the
// hierarchy is solved on the far terrain, whose leaves span cells of another grid.
vtkIdType postGridCell(const terralux::HierarchicalRadiosity& solver, const terralux::TerrainPatch& leaf)
{
  if (solver.hierarchyTerrain())
    return -1;
  const terralux::ParameterRange& range = leaf.range();
  const terralux::TerrainGrid& grid = leaf.grid();
  const int i = std::min(grid.postsX() - 2, static_cast<int>(0.5 * (range.u0 + range.u1)));
  const int j = std::min(grid.postsY() - 2, static_cast<int>(0.5 * (range.v0 + range.v1)));
  return static_cast<vtkIdType>(j) * (grid.postsX() - 1) + i;
}
} // namespace

void vtkRadiosityOutputs::AddPointArrays(const terralux::PointEvaluator& evaluator,
  const vtkRadiosityScene& scene, int index, const PointOptions& options, vtkDataSet* output)
{
  const terralux::HierarchicalRadiosity& solver = evaluator.solver();
  const vtkRadiosityScene::Input& input = scene.Inputs[index];
  const vtkIdType count = output->GetNumberOfPoints();
  terralux::PointEvaluation how;
  how.atPoints = options.evaluateAtPoints;
  how.hornNormals = options.hornNormals;
  const bool terrainGrid = vtkStructuredGrid::SafeDownCast(input.data) != nullptr;
  // A DEM's sky view factor, averaged or not; a mesh's only where evaluated at points.
  const bool skyViewFactor = scene.Sky && (input.terrain >= 0 || terrainGrid);
  const PointArrays arrays(options.bands, count, skyViewFactor, options.sunshine, options.evaluateAtPoints);
  if (input.terrain >= 0)
  {
    if (const terralux::TerrainPatch* root = solver.terrainRoots()[input.terrain])
    {
      const terralux::TerrainGrid& grid = solver.postGrid(*root);
      const int nx = grid.postsX();
      const int all[4] = { 0, nx - 1, 0, grid.postsY() - 1 };
      const int* posts = options.allPosts() ? all : options.posts;
      const std::size_t pieceX = static_cast<std::size_t>(posts[1] - posts[0] + 1);
      auto pointOf = [&](std::size_t post) {
        if (!options.croppedToPosts)
          return static_cast<vtkIdType>(post);
        const std::size_t i = post % nx, j = post / nx;
        return static_cast<vtkIdType>((j - posts[2]) * pieceX + (i - posts[0]));
      };
      terralux::terrainPostValues(evaluator, *root, posts, how,
        [&](std::size_t post, const terralux::PointValues& v) { arrays.set(pointOf(post), v); });
    }
  }
  else
  {
    // A terrain grid's posts take one normal (the GIS convention, as terrain patches do).
    std::vector<bool> reached;
    const std::vector<terralux::PointValues> values = terralux::polygonPointValues(
      evaluator, scene.Scene, index, input.firstPoint, static_cast<std::size_t>(count), terrainGrid, how, reached);
    for (vtkIdType p = 0; p < count; ++p)
      if (reached[p]) // points on no polygon (no-data posts, loose vertices) stay NaN
        arrays.set(p, values[p]);
  }
  arrays.addTo(output->GetPointData());
}

void vtkRadiosityOutputs::BuildLeafMesh(const terralux::HierarchicalRadiosity& solver,
  const vtkRadiosityScene& scene, int bands, bool withSky, vtkPolyData* output)
{
  // The engine's leaf meshes, continuous across T-vertices: the polygons', then each
  // terrain's; their vertex values flattened as PointValues lays them out.
  std::vector<Vec3> positions;
  std::vector<double> vertexValues;
  vtkNew<vtkCellArray> polygons;
  vtkNew<vtkIntArray> level;
  level->SetName("Level");
  // Where each leaf lies in the input: which of port 0's data sets (the leaf data sets
  // in connection and composite order, as output 0 holds them) and which of its cells.
  vtkNew<vtkIntArray> inputIndex;
  inputIndex->SetName(InputIndexName());
  vtkNew<vtkIdTypeArray> inputCell;
  inputCell->SetName(InputCellName());
  std::vector<int> terrainOwners(scene.Terrains.size(), -1);
  for (std::size_t k = 0; k < scene.Inputs.size(); ++k)
    if (scene.Inputs[k].terrain >= 0)
      terrainOwners[static_cast<std::size_t>(scene.Inputs[k].terrain)] = static_cast<int>(k);
  auto appendVertices = [&](std::size_t count, const std::function<Vec3(std::size_t)>& positionOf,
                          const std::vector<double>& values) {
    for (std::size_t k = 0; k < count; ++k)
      positions.push_back(positionOf(k));
    vertexValues.insert(vertexValues.end(), values.begin(), values.end());
  };
  std::vector<vtkIdType> ids;
  const terralux::PolygonLeafMesh polygonMesh(solver.polygonRoots());
  appendVertices(polygonMesh.vertexCount(), [&](std::size_t k) { return polygonMesh.position(k); },
    polygonMesh.vertexValues(terralux::flatLeafValues(polygonMesh.leaves()), terralux::PointValues::flatComponents));
  for (std::size_t k = 0; k < polygonMesh.leaves().size(); ++k)
  {
    ids.assign(polygonMesh.corners(k).begin(), polygonMesh.corners(k).begin() + polygonMesh.leaves()[k]->cornerCount());
    polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    level->InsertNextValue(polygonMesh.leaves()[k]->level());
    const terralux::ScenePolygon& input =
      scene.Scene.polygons[static_cast<std::size_t>(polygonMesh.leaves()[k]->rootPolygon())];
    inputIndex->InsertNextValue(input.owner);
    inputCell->InsertNextValue(static_cast<vtkIdType>(input.cell));
  }
  for (const terralux::TerrainPatch* root : solver.terrainRoots())
  {
    if (!root)
      continue;
    const terralux::TerrainLeafMesh mesh(*root);
    const vtkIdType first = static_cast<vtkIdType>(positions.size());
    appendVertices(mesh.vertexCount(), [&](std::size_t k) { return mesh.position(k); },
      mesh.vertexValues(terralux::flatLeafValues(mesh.leaves()), terralux::PointValues::flatComponents));
    for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
    {
      ids.clear();
      for (std::size_t vertex : mesh.boundary(k))
        ids.push_back(first + static_cast<vtkIdType>(vertex));
      polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      level->InsertNextValue(mesh.leaves()[k]->level());
      inputIndex->InsertNextValue(terrainOwners[static_cast<std::size_t>(root->terrain())]);
      inputCell->InsertNextValue(postGridCell(solver, *mesh.leaves()[k]));
    }
  }

  const vtkIdType count = static_cast<vtkIdType>(positions.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  const PointArrays arrays(bands, count, withSky, false, false);
  for (vtkIdType k = 0; k < count; ++k)
  {
    points->SetPoint(k, positions[k].x, positions[k].y, positions[k].z);
    arrays.set(k, terralux::PointValues::unflatten(vertexValues.data() + k * terralux::PointValues::flatComponents));
  }
  output->SetPoints(points);
  output->SetPolys(polygons);
  arrays.addTo(output->GetPointData());
  output->GetCellData()->AddArray(level);
  output->GetCellData()->AddArray(inputIndex);
  output->GetCellData()->AddArray(inputCell);
}

const char* vtkRadiosityOutputs::QuantityName(int quantity)
{
  return quantityNames[quantity];
}

const char* vtkRadiosityOutputs::IntegratedName(int quantity)
{
  return integratedNames[quantity];
}

std::vector<const char*> vtkRadiosityOutputs::AllNames()
{
  std::vector<const char*> names(quantityNames, quantityNames + quantities);
  names.insert(names.end(), integratedNames, integratedNames + quantities);
  names.push_back(SunshineDurationName());
  names.push_back(SkyViewFactorName());
  names.push_back(IrradianceErrorName());
  names.push_back(IrradiationErrorName());
  return names;
}

void vtkRadiosityOutputs::AddFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

//------------------------------------------------------------------------------
void vtkRadiosityOutputs::FillWithNaN(vtkDataArray* array)
{
  using Reals = vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>;
  if (array && !Reals::Execute(array, FillNaN{}))
    array->Fill(std::numeric_limits<double>::quiet_NaN()); // integers: as VTK casts NaN, on one core
}
