#include "vtkRadiosityScene.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSmartPointer.h"
#include "vtkSMPTools.h"
#include "vtkStructuredGrid.h"
#include "vtkTerraLuxFieldData.h"
#include "vtkUnsignedCharArray.h"

#include "base/error.h"

#include <array>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>

namespace
{
// Per-cell spectrum from an optional cell array; values checked against [low, high).
// Emission above this (W/m^2) is refused: the sun's surface emits 6.3e7, and sums of
// larger values over a scene's area leave the range of a double.
constexpr double largestEmission = 1e12;

class CellSpectrum
{
public:
  CellSpectrum(vtkDataSet* data, const char* name, double fallback, double low, double high, const char* what)
    : Fallback(fallback)
  {
    if (!name || !*name)
      return;
    this->Array = data->GetCellData()->GetArray(name);
    if (!this->Array)
    {
      throw terralux::Error(std::string(what) + " array '" + name + "' is not a cell array of the input");
    }
    const int components = this->Array->GetNumberOfComponents();
    if ((components != 1 && components != 3) || this->Array->GetNumberOfTuples() != data->GetNumberOfCells())
    {
      throw terralux::Error(std::string(what) + " array '" + name +
        "' must have 1 or 3 components and one tuple per cell");
    }
    for (vtkIdType k = 0; k < this->Array->GetNumberOfTuples(); ++k)
      for (int c = 0; c < components; ++c)
      {
        const double v = this->Array->GetComponent(k, c);
        if (!(v >= low && v < high))
        {
          std::ostringstream message;
          message << what << " array '" << name << "' holds " << v << " at cell " << k << ": values must lie in ["
                  << low << ", " << high << ")";
          throw terralux::Error(message.str());
        }
      }
  }
  terralux::Spectrum at(vtkIdType cell) const
  {
    if (!this->Array)
      return terralux::uniformSpectrum(this->Fallback);
    if (this->Array->GetNumberOfComponents() == 1)
      return terralux::uniformSpectrum(this->Array->GetComponent(cell, 0));
    return { this->Array->GetComponent(cell, 0), this->Array->GetComponent(cell, 1), this->Array->GetComponent(cell, 2) };
  }
  bool present() const { return this->Array != nullptr; }

private:
  vtkDataArray* Array = nullptr;
  double Fallback;
};

// Coordinates the engine can work with: finite and within 1e12 m of the origin (ray
// casting is in single precision relative to the scene's centre, and products of
// coordinates must not overflow).
bool usableCoordinate(const terralux::Vec3& p)
{
  constexpr double reach = 1e12;
  return std::abs(p.x) <= reach && std::abs(p.y) <= reach && std::abs(p.z) <= reach;
}

// Every point id of a cell must name a point of the data set (a corrupt cell array
// would otherwise read past the points).
void checkPointIds(vtkIdType cell, vtkIdType count, const vtkIdType* ids, vtkIdType pointCount, int owner)
{
  for (vtkIdType c = 0; c < count; ++c)
    if (ids[c] < 0 || ids[c] >= pointCount)
    {
      throw terralux::Error("cell " + std::to_string(cell) + " of input " + std::to_string(owner) +
        " uses point id " + std::to_string(ids[c]) + " but the data set has " + std::to_string(pointCount) +
        " points: repair the cell array (every id in [0, number of points))");
    }
}

// Ghost arrays must have one value per point / cell, or blanking reads past them.
void checkGhostArrays(vtkDataSet* data, int owner)
{
  vtkUnsignedCharArray* points = data->GetPointGhostArray();
  vtkUnsignedCharArray* cells = data->GetCellGhostArray();
  if ((points && points->GetNumberOfTuples() != data->GetNumberOfPoints()) ||
    (cells && cells->GetNumberOfTuples() != data->GetNumberOfCells()))
  {
    throw terralux::Error("the vtkGhostType array of input " + std::to_string(owner) +
      " does not have one value per point (or cell): remove it or give it the right size");
  }
}

// A quad whose diagonals cross: convex (and so safely one planar element).
bool convexQuad(const std::vector<terralux::Vec3>& points, vtkIdType first, const vtkIdType* ids)
{
  const terralux::Vec3 a = points[first + ids[0]], b = points[first + ids[1]];
  const terralux::Vec3 c = points[first + ids[2]], d = points[first + ids[3]];
  const terralux::Vec3 n = glm::cross(c - a, d - b); // the quad's area vector, twice
  // Each corner turns the same way as the whole quad.
  return glm::dot(glm::cross(b - a, c - b), n) > 0.0 && glm::dot(glm::cross(c - b, d - c), n) > 0.0 &&
    glm::dot(glm::cross(d - c, a - d), n) > 0.0 && glm::dot(glm::cross(a - d, b - a), n) > 0.0;
}

// Ear-clipping triangulation of a polygon cell (vtkPolygon), as point ids of the data set.
std::vector<std::array<vtkIdType, 3>> triangulate(const std::vector<terralux::Vec3>& points, vtkIdType first,
  vtkIdType cell, vtkIdType count, const vtkIdType* ids, int owner)
{
  vtkNew<vtkPolygon> polygon;
  polygon->GetPoints()->SetNumberOfPoints(count);
  polygon->GetPointIds()->SetNumberOfIds(count);
  for (vtkIdType c = 0; c < count; ++c)
  {
    const terralux::Vec3& p = points[first + ids[c]];
    polygon->GetPoints()->SetPoint(c, p.x, p.y, p.z);
    polygon->GetPointIds()->SetId(c, c);
  }
  vtkNew<vtkIdList> corners;
  std::vector<std::array<vtkIdType, 3>> triangles;
  if (polygon->Triangulate(corners) && corners->GetNumberOfIds() == 3 * (count - 2))
  {
    // Newell's normal of the whole polygon: each triangle keeps its orientation.
    terralux::Vec3 normal(0.0);
    for (vtkIdType c = 0; c < count; ++c)
      normal += glm::cross(points[first + ids[c]], points[first + ids[(c + 1) % count]]);
    for (vtkIdType t = 0; t < corners->GetNumberOfIds(); t += 3)
    {
      std::array<vtkIdType, 3> triangle{ ids[corners->GetId(t)], ids[corners->GetId(t + 1)],
        ids[corners->GetId(t + 2)] };
      const terralux::Vec3& a = points[first + triangle[0]];
      if (glm::dot(glm::cross(points[first + triangle[1]] - a, points[first + triangle[2]] - a), normal) < 0.0)
        std::swap(triangle[1], triangle[2]);
      triangles.push_back(triangle);
    }
    return triangles;
  }
  throw terralux::Error("polygon " + std::to_string(cell) + " of input " + std::to_string(owner) +
    " (" + std::to_string(count) + " points) cannot be triangulated (self-intersecting or not planar): "
    "run vtkTriangleFilter on the input, or repair the polygon");
}

// The engine keeps a terrain's posts as floats relative to the grid's centre (Embree
// shares them): a grid that spans far more than its cells (posts a metre apart half a
// million kilometres out) collapses cells to nothing there. Such a grid is refused
// rather than solved with cells that have no area. Grids within 1e6 m of their centre
// (a float's step there: 6 cm) are not checked.
void checkSinglePrecision(vtkStructuredGrid* grid, const terralux::TerrainGrid& terrain, int owner)
{
  double bounds[6];
  grid->GetBounds(bounds);
  const terralux::Vec3& o = terrain.origin();
  const double reach = std::max({ std::abs(bounds[0] - o.x), std::abs(bounds[1] - o.x), std::abs(bounds[2] - o.y),
    std::abs(bounds[3] - o.y), std::abs(bounds[4] - o.z), std::abs(bounds[5] - o.z) });
  if (!(reach > 1e6))
    return;
  int dims[3];
  grid->GetDimensions(dims);
  for (int j = 0; j + 1 < dims[1]; ++j)
    for (int i = 0; i + 1 < dims[0]; ++i)
    {
      if (!terrain.cellValid(i, j))
        continue;
      terralux::Vec3 p[4];
      for (int c = 0; c < 4; ++c)
      {
        double q[3];
        grid->GetPoint((i + c % 2) + static_cast<vtkIdType>(j + c / 2) * dims[0], q);
        p[c] = terralux::Vec3(q[0], q[1], q[2]);
      }
      // The cell's two triangles as TerrainGrid splits it, in double.
      const auto triangles = terralux::TerrainGrid::cellTriangles(p[0], p[1], p[2], p[3]);
      const bool hasArea = glm::length(terralux::TerrainGrid::areaVector(triangles[0])) > 0.0 ||
        glm::length(terralux::TerrainGrid::areaVector(triangles[1])) > 0.0;
      if (hasArea && !(glm::length(terrain.cellAreaVector(i, j)) > 0.0))
      {
        throw terralux::Error("cell (" + std::to_string(i) + ", " + std::to_string(j) + ") of input " +
          std::to_string(owner) + " has no area at single precision: the grid reaches " +
          std::to_string(static_cast<long long>(reach)) +
          " m from its centre, too far for its cell sizes; blank the far cells, split the grid, "
          "or bring its coordinates nearer together");
      }
    }
}

// A 2-D structured grid as a terrain grid: posts, blanked cells, materials per cell.
// `origin`: where the posts are kept relative to (null: the grid's centre).
std::unique_ptr<terralux::TerrainGrid> makeTerrainGrid(vtkStructuredGrid* grid, const CellSpectrum& reflectance,
  const CellSpectrum& emission, int owner, const terralux::Vec3* origin = nullptr)
{
  int dims[3];
  grid->GetDimensions(dims);
  double bounds[6];
  grid->GetBounds(bounds);
  const terralux::Vec3 centre(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const bool finite = std::isfinite(centre.x) && std::isfinite(centre.y) && std::isfinite(centre.z);
  auto terrain =
    std::make_unique<terralux::TerrainGrid>(dims[0], dims[1], origin ? *origin : finite ? centre : terralux::Vec3(0.0));
  std::atomic<vtkIdType> badPoint{ -1 };
  std::atomic<bool> anyNonFinite{ false };
  const bool blanking = grid->HasAnyBlankCells() || grid->HasAnyBlankPoints();
  vtkSMPTools::For(0, dims[1], [&](vtkIdType first, vtkIdType last) {
    double p[3];
    for (int j = static_cast<int>(first); j < last; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        grid->GetPoint(i + static_cast<vtkIdType>(j) * dims[0], p);
        const bool finite = usableCoordinate(terralux::Vec3(p[0], p[1], p[2]));
        terrain->setPost(i, j, finite ? terralux::Vec3(p[0], p[1], p[2]) : terrain->origin());
        if (!finite)
          anyNonFinite = true;
        if (i + 1 < dims[0] && j + 1 < dims[1])
        {
          const vtkIdType cell = i + static_cast<vtkIdType>(j) * (dims[0] - 1);
          terrain->setCellValid(i, j, !blanking || grid->IsCellVisible(cell));
        }
      }
  });
  // Posts with NaN or infinite coordinates are allowed only where no visible cell uses
  // them; the cells are checked only when there are such posts.
  vtkSMPTools::For(0, anyNonFinite ? dims[1] - 1 : 0, [&](vtkIdType first, vtkIdType last) {
    double p[3];
    for (int j = static_cast<int>(first); j < last; ++j)
      for (int i = 0; i + 1 < dims[0]; ++i)
      {
        if (!terrain->cellValid(i, j))
          continue;
        for (int c = 0; c < 4; ++c)
        {
          const vtkIdType id = (i + c % 2) + static_cast<vtkIdType>(j + c / 2) * dims[0];
          grid->GetPoint(id, p);
          if (!usableCoordinate(terralux::Vec3(p[0], p[1], p[2])))
            badPoint = id;
        }
      }
  });
  if (badPoint >= 0)
  {
    throw terralux::Error("point " + std::to_string(badPoint.load()) + " of input " + std::to_string(owner) +
      " has a NaN, infinite or huge coordinate (beyond 1e12 m): blank the cells around it or repair it");
  }
  checkSinglePrecision(grid, *terrain, owner);
  terrain->setUniformMaterial(reflectance.at(0), emission.at(0));
  if (reflectance.present() || emission.present())
  {
    for (int j = 0; j + 1 < dims[1]; ++j)
      for (int i = 0; i + 1 < dims[0]; ++i)
      {
        const vtkIdType cell = i + static_cast<vtkIdType>(j) * (dims[0] - 1);
        terrain->setCellMaterial(i, j, reflectance.at(cell), emission.at(cell));
      }
  }
  return terrain;
}

// A structured grid's dimensions, checked: a 2-D surface with one point per post.
std::array<int, 3> surfaceDimensions(vtkStructuredGrid* grid, int owner)
{
  std::array<int, 3> dims{};
  grid->GetDimensions(dims.data());
  if (dims[2] != 1 || dims[0] < 2 || dims[1] < 2)
  {
    throw terralux::Error("structured grids must be 2-D surfaces (dimensions nx x ny x 1, nx, ny >= 2), "
                          "as vtkTerrainSource makes them");
  }
  const vtkIdType posts = static_cast<vtkIdType>(dims[0]) * dims[1];
  if (grid->GetNumberOfPoints() != posts)
  {
    throw terralux::Error("structured grid " + std::to_string(owner) + " has dimensions " +
      std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " but " +
      std::to_string(grid->GetNumberOfPoints()) + " points: give it exactly nx * ny points "
      "(SetDimensions() and SetPoints() must agree)");
  }
  return dims;
}

// The polygons of one input as they enter the scene, their points checked.
class PolygonInput
{
public:
  PolygonInput(terralux::RadiosityScene& scene, vtkDataSet* data, int owner, const CellSpectrum& reflectance,
    const CellSpectrum& emission)
    : Scene(scene)
    , First(static_cast<vtkIdType>(scene.points.size()))
    , PointCount(data->GetNumberOfPoints())
    , Owner(owner)
    , Reflectance(reflectance)
    , Emission(emission)
  {
    for (vtkIdType k = 0; k < this->PointCount; ++k)
    {
      double p[3];
      data->GetPoint(k, p);
      scene.points.emplace_back(p[0], p[1], p[2]);
    }
  }

  // Cell `cell` with point ids `ids` (valid ones, of usable coordinates: else an error).
  void check(vtkIdType cell, vtkIdType count, const vtkIdType* ids) const
  {
    checkPointIds(cell, count, ids, this->PointCount, this->Owner);
    for (vtkIdType c = 0; c < count; ++c)
      if (!usableCoordinate(this->Scene.points[this->First + ids[c]]))
      {
        throw terralux::Error("point " + std::to_string(ids[c]) + " of input " + std::to_string(this->Owner) +
          " has a NaN, infinite or huge coordinate (beyond 1e12 m): remove or repair it, and give the "
          "scene in local metres");
      }
  }

  void add(vtkIdType cell, int count, const vtkIdType* ids) const
  {
    terralux::ScenePolygon polygon;
    polygon.vertexCount = count;
    for (int c = 0; c < count; ++c)
      polygon.vertices[c] = static_cast<int>(this->First + ids[c]);
    polygon.reflectance = this->Reflectance.at(cell);
    polygon.emission = this->Emission.at(cell);
    polygon.owner = this->Owner;
    polygon.cell = cell;
    this->Scene.polygons.push_back(polygon);
  }

  // A polygon cell of any size: convex quads are taken as planar, larger or concave
  // polygons ear-clipped into triangles (a fan would cover a notch). Returns false for
  // a cell of fewer than 3 points, which has no area.
  bool addPolygonCell(vtkIdType cell, vtkIdType count, const vtkIdType* ids) const
  {
    this->check(cell, count, ids);
    if (count < 3)
      return false;
    if (count == 3 || (count == 4 && convexQuad(this->Scene.points, this->First, ids)))
      this->add(cell, static_cast<int>(count), ids);
    else
      for (const auto& triangle : triangulate(this->Scene.points, this->First, cell, count, ids, this->Owner))
        this->add(cell, 3, triangle.data());
    return true;
  }

private:
  terralux::RadiosityScene& Scene;
  const vtkIdType First, PointCount;
  const int Owner;
  const CellSpectrum& Reflectance;
  const CellSpectrum& Emission;
};

// Terrain cells are not planar: two triangles each, skipping blanked cells, split as
// terrain patches and Embree's grids are (TerrainGrid::cellTriangleCorners), so both
// paths see the same surface.
void addGridTriangles(vtkStructuredGrid* grid, const std::array<int, 3>& dims, const PolygonInput& input)
{
  for (int j = 0; j + 1 < dims[1]; ++j)
    for (int i = 0; i + 1 < dims[0]; ++i)
    {
      const vtkIdType cell = i + static_cast<vtkIdType>(j) * (dims[0] - 1);
      if (!grid->IsCellVisible(cell))
        continue;
      const vtkIdType p00 = i + static_cast<vtkIdType>(j) * dims[0];
      const vtkIdType corners[4] = { p00, p00 + 1, p00 + dims[0], p00 + dims[0] + 1 };
      for (const auto& triangle : terralux::TerrainGrid::cellTriangleCorners)
      {
        const vtkIdType ids[3] = { corners[triangle[0]], corners[triangle[1]], corners[triangle[2]] };
        input.check(cell, 3, ids);
        input.add(cell, 3, ids);
      }
    }
}

// The polygons and strips of a poly data; returns how many cells were skipped
// (vertices, lines, polygons of fewer than 3 points).
std::size_t addPolyDataCells(vtkPolyData* polyData, const PolygonInput& input)
{
  std::size_t skipped = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines();
  vtkIdType cell = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines();
  vtkNew<vtkIdList> ids;
  auto polys = polyData->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids); ++cell)
    if (!input.addPolygonCell(cell, ids->GetNumberOfIds(), ids->GetPointer(0)))
      ++skipped;
  auto strips = polyData->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(ids); ++cell)
  {
    const vtkIdType* p = ids->GetPointer(0);
    input.check(cell, ids->GetNumberOfIds(), p);
    for (vtkIdType k = 0; k + 2 < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType tri[3] = { p[k], p[k % 2 ? k + 2 : k + 1], p[k % 2 ? k + 1 : k + 2] };
      input.add(cell, 3, tri);
    }
  }
  return skipped;
}
} // namespace

void vtkRadiosityScene::AddDataSet(vtkDataSet* data, double defaultReflectance, const char* reflectanceName,
  const char* emissionName, bool terrainHierarchy)
{
  const CellSpectrum reflectance(data, reflectanceName, defaultReflectance, 0.0, 1.0, "reflectance");
  const CellSpectrum emission(data, emissionName, 0.0, 0.0, largestEmission, "emission");
  this->HasEmission = this->HasEmission || emission.present();
  const vtkIdType first = static_cast<vtkIdType>(this->Scene.points.size());
  const int owner = static_cast<int>(this->Inputs.size());
  auto* structured = vtkStructuredGrid::SafeDownCast(data);
  auto* polyData = vtkPolyData::SafeDownCast(data);
  if (!structured && !polyData)
  {
    throw terralux::Error(std::string("input of type ") + data->GetClassName() +
      " is not supported: give vtkPolyData or vtkStructuredGrid");
  }
  const std::array<int, 3> dims = structured ? surfaceDimensions(structured, owner) : std::array<int, 3>{};
  checkGhostArrays(data, owner);
  if (structured && terrainHierarchy)
  {
    this->Terrains.push_back(makeTerrainGrid(
      structured, reflectance, emission, owner, this->FarTerrain ? &this->FarTerrain->origin() : nullptr));
    this->Scene.terrains.push_back(this->Terrains.back().get());
    this->Inputs.push_back({ data, first, static_cast<int>(this->Terrains.size()) - 1 });
    return;
  }
  this->Inputs.push_back({ data, first, -1 });
  const PolygonInput input(this->Scene, data, owner, reflectance, emission);
  if (structured)
    addGridTriangles(structured, dims, input);
  else
    this->SkippedCells += addPolyDataCells(polyData, input);
}

void vtkRadiosityScene::SetFarTerrain(vtkStructuredGrid* far, int stride, double defaultReflectance,
  const char* reflectanceName, const char* emissionName)
{
  const CellSpectrum reflectance(far, reflectanceName, defaultReflectance, 0.0, 1.0, "reflectance");
  const CellSpectrum emission(far, emissionName, 0.0, 0.0, largestEmission, "emission");
  const std::array<int, 3> dims = surfaceDimensions(far, -1);
  if (dims[0] < 2 || dims[1] < 2)
    throw terralux::Error("the far terrain has fewer than 2 x 2 posts: connect vtkTerrainSource's output port 1, "
                          "or lower its FarTerrainStride");
  checkGhostArrays(far, -1);
  this->FarTerrain = makeTerrainGrid(far, reflectance, emission, -1);
  this->Scene.farTerrain.grid = this->FarTerrain.get();
  this->Scene.farTerrain.stride = stride;
}

void vtkRadiosityScene::FindWindowInFarTerrain(int i0, int j0)
{
  if (!this->FarTerrain)
    return;
  if (this->Scene.terrains.size() != 1 || !this->Scene.polygons.empty())
    throw terralux::Error("a far terrain serves one terrain grid alone: connect one vtkTerrainSource output 0 to "
                          "port 0, with UseTerrainHierarchy on, or disconnect the far terrain");
  const terralux::TerrainGrid& window = *this->Scene.terrains.front();
  const terralux::TerrainGrid& far = *this->FarTerrain;
  const int stride = this->Scene.farTerrain.stride;
  // The far terrain's post (k, l) is the full grid's (k stride + ci, l stride + cj) for
  // one (ci, cj) within a stride (a north-up raster's strided rows start at its north
  // edge, the grid's last row). Found on the first posts of the window that valid
  // cells use in both (no-data posts sit at heights of their own piece).
  auto matches = [&](int ci, int cj) {
    int compared = 0;
    const int k0 = std::max(0, (i0 - ci + stride - 1) / stride), l0 = std::max(0, (j0 - cj + stride - 1) / stride);
    for (int l = l0; l < far.postsY() && compared < 16; ++l)
      for (int k = k0; k < far.postsX() && compared < 16; ++k)
      {
        const int i = k * stride + ci - i0, j = l * stride + cj - j0;
        if (i < 0 || j < 0 || i >= window.postsX() || j >= window.postsY())
          break;
        if (!far.postUsed(k, l) || !window.postUsed(i, j))
          continue;
        const terralux::Vec3 a = far.post(k, l), b = window.post(i, j);
        // Floats 1e-6 of the grid's reach apart, and a post apart by far more.
        if (glm::length(a - b) > 1e-3 + 1e-6 * glm::length(b - far.origin()))
          return false;
        ++compared;
      }
    return compared > 0;
  };
  for (int cj = 0; cj < stride; ++cj)
    for (int ci = 0; ci < stride; ++ci)
      if (matches(ci, cj))
      {
        this->Scene.farTerrain.i0 = i0 - ci;
        this->Scene.farTerrain.j0 = j0 - cj;
        return;
      }
  throw terralux::Error("the far terrain's posts are not every " + std::to_string(stride) +
    "th post of the terrain: connect output ports 0 and 1 of the same vtkTerrainSource");
}

std::vector<vtkDataSet*> vtkRadiosityScene::DataSetsOf(vtkDataObject* data)
{
  std::vector<vtkDataSet*> result;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      if (auto* dataSet = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
        result.push_back(dataSet);
  }
  else if (auto* dataSet = vtkDataSet::SafeDownCast(data))
  {
    result.push_back(dataSet);
  }
  return result;
}
