#include "vtkRadiosityOutputs.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkRadiosityScene.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"

#include "polygon_element.h"
#include "solver.h"
#include "polygon_leaf_mesh.h"
#include "terrain_mesh.h"
#include "terrain_patch.h"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <unordered_map>

namespace
{
using terralux::Spectrum;
using terralux::Vec3;

// The five output quantities of a leaf: global, sun, sky, reflected irradiance, radiosity.
constexpr int quantities = vtkRadiosityOutputs::Quantities;
const char* const quantityNames[quantities] = { "Irradiance", "SunIrradiance", "SkyIrradiance",
  "ReflectedIrradiance", "Radiosity" };
const char* const integratedNames[quantities] = { "GlobalIrradiation", "BeamIrradiation", "SkyIrradiation",
  "ReflectedIrradiation", "OutgoingIrradiation" };
using Values = std::array<Spectrum, quantities>;

// The irradiance quantities from irradiance by category; radiosity is left to the caller.
Values irradianceValues(const std::array<Spectrum, terralux::lightCategories>& irradiance)
{
  Values v{};
  for (int band = 0; band < terralux::maxBands; ++band)
  {
    v[1][band] = irradiance[terralux::SunLight][band];
    v[2][band] = irradiance[terralux::SkyLight][band];
    v[3][band] = irradiance[terralux::ReflectedLight][band];
  }
  v[0] = terralux::totalIrradiance(v[1], v[2], v[3]);
  return v;
}

Values valuesOf(const terralux::PolygonElement& leaf)
{
  Values v = irradianceValues(leaf.Irradiance);
  v[4] = leaf.Radiosity;
  return v;
}

// A leaf's weight in the averages at a point: its area, never zero, so that a point only
// zero-area leaves reach (those of a degenerate polygon) takes their plain mean, not 0/0.
double averagingWeight(const terralux::PolygonElement& leaf)
{
  return std::max(leaf.area(), 1e-200);
}

void accumulate(Values& sum, const Values& v, double weight)
{
  for (int q = 0; q < quantities; ++q)
    for (int band = 0; band < terralux::maxBands; ++band)
      sum[q][band] += weight * v[q][band];
}

// The leaf below `root` that has `corner` as one of its corners.
const terralux::PolygonElement* leafAtCorner(terralux::PolygonElement* element, const Vec3& corner)
{
  while (element->hasChildren())
  {
    terralux::PolygonElement* next = nullptr;
    for (terralux::HElement* child : element->children())
    {
      auto* polygon = static_cast<terralux::PolygonElement*>(child);
      for (int k = 0; k < polygon->cornerCount() && !next; ++k)
        if (polygon->corners()[k] == corner)
          next = polygon;
    }
    if (!next)
      break;
    element = next;
  }
  return element;
}

std::vector<vtkSmartPointer<vtkDoubleArray>> makeArrays(int bands, vtkIdType tuples, double fill = 0.0)
{
  std::vector<vtkSmartPointer<vtkDoubleArray>> arrays;
  for (int q = 0; q < quantities; ++q)
  {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(quantityNames[q]);
    array->SetNumberOfComponents(bands);
    array->SetNumberOfTuples(tuples);
    array->Fill(fill);
    arrays.push_back(array);
  }
  return arrays;
}

void store(const std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkIdType tuple, const Values& v, int bands)
{
  for (int q = 0; q < quantities; ++q)
    for (int band = 0; band < bands; ++band)
      arrays[q]->SetComponent(tuple, band, v[q][band]);
}

Values valuesAtPoint(const terralux::PointIrradiance& point, const Spectrum& reflectance, const Spectrum& emission)
{
  Values v = irradianceValues(point.irradiance);
  v[4] = terralux::radiosityOf(emission, reflectance, v[0]);
  return v;
}

// One value per point (SkyViewFactor, SunshineDuration), NaN until set.
vtkSmartPointer<vtkDoubleArray> scalarArray(const char* name, vtkIdType count)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(count);
  array->Fill(std::numeric_limits<double>::quiet_NaN());
  return array;
}

constexpr int skyViewComponent = quantities * terralux::maxBands;
constexpr int valueComponents = skyViewComponent + 1;

// Leaf values flattened for the leaf meshes: quantity-major, then band; the sky view
// factor last.
template <typename Leaf>
std::vector<double> flatLeafValues(const std::vector<const Leaf*>& leaves)
{
  std::vector<double> flat(leaves.size() * valueComponents);
  for (std::size_t k = 0; k < leaves.size(); ++k)
  {
    const Values v = valuesOf(*leaves[k]);
    for (int q = 0; q < quantities; ++q)
      for (int band = 0; band < terralux::maxBands; ++band)
        flat[k * valueComponents + q * terralux::maxBands + band] = v[q][band];
    flat[k * valueComponents + skyViewComponent] = leaves[k]->SkyViewFactor;
  }
  return flat;
}

// Per-post arrays of a terrain input: evaluated at each post, or interpolated from the
// continuous leaf mesh.
void addTerrainPointArrays(const terralux::HierarchicalRadiosity& solver, const terralux::TerrainPatch* root,
  const vtkRadiosityOutputs::PointOptions& options, bool withSky, vtkDataSet* output)
{
  const int bands = options.bands;
  const bool evaluateAtPoints = options.evaluateAtPoints;
  const vtkIdType count = output->GetNumberOfPoints();
  const double none = std::numeric_limits<double>::quiet_NaN();
  const auto arrays = makeArrays(bands, count, none);
  const vtkSmartPointer<vtkDoubleArray> skyViewFactor = withSky ? scalarArray(vtkRadiosityOutputs::SkyViewFactorName(), count) : nullptr;
  const vtkSmartPointer<vtkDoubleArray> sunshine = options.sunshine ? scalarArray(vtkRadiosityOutputs::SunshineDurationName(), count) : nullptr;
  std::array<double*, quantities> out{};
  for (int q = 0; q < quantities; ++q)
    out[q] = arrays[q]->GetPointer(0);
  auto put = [&](vtkIdType post, const Values& v) {
    for (int q = 0; q < quantities; ++q)
      for (int band = 0; band < bands; ++band)
        out[q][post * bands + band] = v[q][band];
  };
  if (root)
  {
    const terralux::TerrainGrid& grid = root->grid();
    const int nx = grid.postsX(), ny = grid.postsY();
    // The posts asked for: all, or a piece's.
    const int i0 = options.allPosts() ? 0 : std::max(0, options.posts[0]);
    const int i1 = options.allPosts() ? nx - 1 : std::min(nx - 1, options.posts[1]);
    const int j0 = options.allPosts() ? 0 : std::max(0, options.posts[2]);
    const int j1 = options.allPosts() ? ny - 1 : std::min(ny - 1, options.posts[3]);
    auto asked = [&](int i, int j) { return i >= i0 && i <= i1 && j >= j0 && j <= j1; };
    auto normalAt = [&](int i, int j) { return grid.normalAt(i, j, options.hornNormals); };
    if (evaluateAtPoints)
    {
      // Every post evaluated at itself from its most lit leaf, with the normal of the
      // cells around it, in parallel (a lattice of them was gathered first, see
      // HierarchicalRadiosity::gatherPostLattice).
      vtkSMPTools::For(j0, j1 + 1, [&](vtkIdType first, vtkIdType last) {
        for (int j = static_cast<int>(first); j < last; ++j)
          for (int i = i0; i <= i1; ++i)
          {
            if (!grid.postUsed(i, j))
              continue;
            const terralux::TerrainPatch* leaf = root->mostLitLeafAt(i, j);
            if (!leaf)
              continue;
            const terralux::PointIrradiance result = solver.irradianceAt(*leaf, grid.post(i, j), normalAt(i, j));
            const vtkIdType post = i + static_cast<vtkIdType>(j) * nx;
            put(post, valuesAtPoint(result, leaf->reflectance(), leaf->emission()));
            if (skyViewFactor)
              skyViewFactor->SetValue(post, result.skyViewFactor);
            if (sunshine)
              sunshine->SetValue(post, result.sunlitHours);
          }
      });
    }
    else
    {
      // Sky and reflected light vary slowly: interpolated from the continuous leaf mesh.
      // Direct sun does not, and costs one ray: taken at each post with its own normal.
      const terralux::TerrainLeafMesh mesh(*root);
      const std::vector<double> vertexValues = mesh.vertexValues(flatLeafValues(mesh.leaves()), valueComponents);
      vtkSMPTools::For(0, static_cast<vtkIdType>(mesh.leaves().size()), [&](vtkIdType first, vtkIdType last) {
        double flat[valueComponents];
        for (vtkIdType k = first; k < last; ++k)
        {
          const terralux::TerrainPatch& leaf = *mesh.leaves()[k];
          const terralux::ParameterRange& r = leaf.range();
          // A post on the range's border is written by the leaf that leafHolding finds
          // for it, so each post is written once (values agree anyway: the mesh is
          // continuous).
          for (int j = static_cast<int>(std::ceil(r.v0)); j <= static_cast<int>(std::floor(r.v1)); ++j)
            for (int i = static_cast<int>(std::ceil(r.u0)); i <= static_cast<int>(std::floor(r.u1)); ++i)
            {
              const bool border = i == r.u0 || i == r.u1 || j == r.v0 || j == r.v1;
              if (!asked(i, j) || !grid.postUsed(i, j) || (border && root->leafHolding(i, j) != &leaf))
                continue;
              mesh.interpolate(static_cast<std::size_t>(k), vertexValues, valueComponents, i, j, flat);
              Values v{};
              for (int q = 0; q < quantities; ++q)
                for (int band = 0; band < terralux::maxBands; ++band)
                  v[q][band] = flat[q * terralux::maxBands + band];
              double sunlitHours = 0.0;
              v[1] = solver.directSunAt(grid.post(i, j), normalAt(i, j), &sunlitHours);
              if (sunshine)
                sunshine->SetValue(i + static_cast<vtkIdType>(j) * nx, sunlitHours);
              if (skyViewFactor)
                skyViewFactor->SetValue(i + static_cast<vtkIdType>(j) * nx, flat[skyViewComponent]);
              v[0] = terralux::totalIrradiance(v[1], v[2], v[3]);
              v[4] = terralux::radiosityOf(leaf.emission(), leaf.reflectance(), v[0]);
              put(i + static_cast<vtkIdType>(j) * nx, v);
            }
        }
      });
    }
  }
  for (const auto& array : arrays)
    output->GetPointData()->AddArray(array);
  if (skyViewFactor)
    output->GetPointData()->AddArray(skyViewFactor);
  if (sunshine)
    output->GetPointData()->AddArray(sunshine);
  output->GetPointData()->SetActiveScalars(quantityNames[0]);
}

} // namespace

void vtkRadiosityOutputs::AddPointArrays(const terralux::HierarchicalRadiosity& solver,
  const vtkRadiosityScene& scene, int index, const PointOptions& options, vtkDataSet* output)
{
  const int bands = options.bands;
  const bool evaluateAtPoints = options.evaluateAtPoints;
  const vtkRadiosityScene::Input& input = scene.Inputs[index];
  if (input.terrain >= 0)
  {
    addTerrainPointArrays(solver, solver.terrainRoots()[input.terrain], options, scene.Sky != nullptr, output);
    return;
  }
  // The polygons around a point, grouped by orientation: a point on a smooth or flat
  // surface has one group (the area-weighted normal, as a GIS takes a post's slope from
  // its neighbours), a point on a crease (a box's edge or corner) one per face, each
  // evaluated on its own side and the results averaged by area. One normal averaged
  // across a crease would point out of every face.
  struct Side
  {
    Vec3 normalSum{ 0.0 };
    double area = 0.0;
    const terralux::PolygonElement* leaf = nullptr;
    // Other leaves of this side with the point as a corner: where a surface runs under
    // another (ground under a building), the point takes the value of its most open
    // leaf, the limit a user sees from the visible side.
    std::vector<const terralux::PolygonElement*> otherLeaves;
    Vec3 centroidSum{ 0.0 }; // centres of its polygons weighted as `area`: where the point moves
    Values leafSum{};      // averaged mode: area-weighted leaf values
    double leafWeight = 0.0;
    double skyView = 0.0;
  };
  // A terrain grid's posts take one normal (the GIS convention, as terrain patches do).
  const bool terrainGrid = vtkStructuredGrid::SafeDownCast(input.data) != nullptr;
  const double sameSide = terrainGrid ? -2.0 : 0.94; // cos 20 deg
  const vtkIdType count = input.data->GetNumberOfPoints();
  std::vector<std::vector<Side>> sides(count);
  const auto& roots = solver.polygonRoots();
  // Point `point` of the surface of `root`, on its leaf `leaf`, joins the side of its
  // orientation.
  auto addToSide = [&](vtkIdType point, const terralux::PolygonElement* root, const terralux::PolygonElement* leaf) {
    const Vec3 n = root->normal();
    Side* side = nullptr;
    for (Side& candidate : sides[point])
      if (glm::dot(glm::normalize(candidate.normalSum), n) > sameSide)
        side = &candidate;
    if (!side)
    {
      sides[point].emplace_back();
      side = &sides[point].back();
      side->leaf = leaf;
    }
    else if (!terrainGrid && leaf != side->leaf &&
      std::find(side->otherLeaves.begin(), side->otherLeaves.end(), leaf) == side->otherLeaves.end())
    {
      side->otherLeaves.push_back(leaf);
    }
    side->normalSum += root->area() * n;
    side->centroidSum += averagingWeight(*root) * root->centre();
    side->area += averagingWeight(*root);
    if (!evaluateAtPoints)
    {
      accumulate(side->leafSum, valuesOf(*leaf), averagingWeight(*leaf));
      side->skyView += leaf->SkyViewFactor * averagingWeight(*leaf);
      side->leafWeight += averagingWeight(*leaf);
    }
  };
  // The largest part of each cell (a polygon is split into triangles), for vertices
  // that only its degenerate parts reach.
  std::unordered_map<std::int64_t, std::size_t> largestPart;
  for (std::size_t k = 0; k < roots.size(); ++k)
  {
    const terralux::ScenePolygon& polygon = scene.Scene.polygons[k];
    if (!roots[k] || polygon.owner != index)
      continue;
    auto found = largestPart.find(polygon.cell);
    if (found == largestPart.end() || roots[found->second]->area() < roots[k]->area())
      largestPart[polygon.cell] = k;
    for (int c = 0; c < polygon.vertexCount; ++c)
      addToSide(polygon.vertices[c] - input.firstPoint, roots[k],
        leafAtCorner(roots[k], scene.Scene.points[polygon.vertices[c]]));
  }
  // A vertex of a cell with area that only a zero-area part of it reaches (a spike of
  // a concave polygon, whose ear clipping left a degenerate triangle) takes the value of
  // the cell's largest part at the vertex, from the leaf nearest to it.
  for (std::size_t k = 0; k < roots.size(); ++k)
  {
    const terralux::ScenePolygon& polygon = scene.Scene.polygons[k];
    const auto part = roots[k] || polygon.owner != index ? largestPart.end() : largestPart.find(polygon.cell);
    if (part == largestPart.end())
      continue;
    for (int c = 0; c < polygon.vertexCount; ++c)
    {
      const vtkIdType point = polygon.vertices[c] - input.firstPoint;
      if (sides[point].empty())
        addToSide(point, roots[part->second], roots[part->second]->leafHolding(scene.Scene.points[polygon.vertices[c]]));
    }
  }
  // Points on no polygon (no-data posts, loose vertices) have no value: NaN.
  const double none = std::numeric_limits<double>::quiet_NaN();
  const auto arrays = makeArrays(bands, count, none);
  const vtkSmartPointer<vtkDoubleArray> skyViewFactor =
    scene.Sky && terrainGrid ? scalarArray(vtkRadiosityOutputs::SkyViewFactorName(), count) : nullptr;
  if (skyViewFactor)
    output->GetPointData()->AddArray(skyViewFactor);
  const vtkSmartPointer<vtkDoubleArray> sunshine =
    options.sunshine ? scalarArray(vtkRadiosityOutputs::SunshineDurationName(), count) : nullptr;
  if (sunshine)
    output->GetPointData()->AddArray(sunshine);

  // One evaluation per side of each point, in parallel.
  std::vector<const terralux::PolygonElement*> leaves;
  std::vector<Vec3> points, normals, towards;
  std::vector<std::pair<vtkIdType, const Side*>> owners;
  for (vtkIdType p = 0; p < count; ++p)
    for (const Side& side : sides[p])
    {
      const double length = glm::length(side.normalSum);
      leaves.push_back(side.leaf);
      // The point moves toward the centre of its side's cells (the limit from inside
      // the surface, whatever leaf holds it); where that centre is the point itself
      // (cells all around it: a ground vertex at a building's corner, some cells under
      // the building), toward its leaf's, and the side's other leaves are tried too.
      const Vec3 point = scene.Scene.points[input.firstPoint + p];
      const Vec3 centroid = side.centroidSum / side.area;
      towards.push_back(glm::length(centroid - point) > 1e-3 * glm::length(side.leaf->centre() - point)
          ? centroid
          : side.leaf->centre());
      points.push_back(point);
      normals.push_back(length > 0.0 ? side.normalSum / length : side.leaf->normal());
      owners.emplace_back(p, &side);
    }
  std::vector<Values> values(points.size());
  std::vector<double> skyViews(points.size(), 0.0), sunlitHours(points.size(), 0.0);
  if (evaluateAtPoints)
  {
    // The first leaf of each side, then the side's other leaves; the most open wins.
    std::vector<const terralux::PolygonElement*> allLeaves = leaves;
    std::vector<Vec3> allPoints = points, allNormals = normals, allTowards = towards;
    std::vector<std::size_t> evaluationOf;
    for (std::size_t k = 0; k < owners.size(); ++k)
      for (const terralux::PolygonElement* other : owners[k].second->otherLeaves)
      {
        allLeaves.push_back(other);
        allPoints.push_back(points[k]);
        allNormals.push_back(normals[k]);
        allTowards.push_back(other->centre());
        evaluationOf.push_back(k);
      }
    std::vector<terralux::PointIrradiance> results;
    solver.irradianceAt(allLeaves, allPoints, allNormals, allTowards, results);
    auto openness = [](const terralux::PointIrradiance& r) {
      return r.irradiance[0][0] + r.irradiance[1][0] + r.irradiance[2][0];
    };
    std::vector<std::size_t> best(points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
      best[k] = k;
    for (std::size_t m = 0; m < evaluationOf.size(); ++m)
    {
      const std::size_t k = evaluationOf[m], candidate = points.size() + m;
      // Only a clearly more open leaf (a hidden one next to a visible one), not the
      // larger of two noisy estimates of the same value.
      if (openness(results[candidate]) > 1.1 * openness(results[best[k]]) + 1e-9)
        best[k] = candidate;
    }
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const std::size_t b = best[k];
      values[k] = valuesAtPoint(results[b], allLeaves[b]->reflectance(), allLeaves[b]->emission());
      skyViews[k] = results[b].skyViewFactor;
      sunlitHours[k] = results[b].sunlitHours;
    }
  }
  else
  {
    // Averaged over the leaves around the point, except direct sun: one ray from the
    // point, so shadows stay sharp.
    vtkSMPTools::For(0, static_cast<vtkIdType>(points.size()), [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType k = first; k < last; ++k)
      {
        const Side& side = *owners[k].second;
        Values v{};
        accumulate(v, side.leafSum, 1.0 / side.leafWeight);
        v[1] = solver.directSunAt(points[k], normals[k], &sunlitHours[k]);
        v[0] = terralux::totalIrradiance(v[1], v[2], v[3]);
        v[4] = terralux::radiosityOf(leaves[k]->emission(), leaves[k]->reflectance(), v[0]);
        values[k] = v;
        skyViews[k] = side.skyView / side.leafWeight;
      }
    });
  }
  // Sides of one point weighted by their area.
  for (std::size_t k = 0; k < owners.size();)
  {
    const vtkIdType p = owners[k].first;
    Values sum{};
    double weight = 0.0, skyView = 0.0, sunlit = 0.0;
    for (; k < owners.size() && owners[k].first == p; ++k)
    {
      accumulate(sum, values[k], owners[k].second->area);
      skyView += skyViews[k] * owners[k].second->area;
      sunlit += sunlitHours[k] * owners[k].second->area;
      weight += owners[k].second->area;
    }
    Values mean{};
    accumulate(mean, sum, 1.0 / weight);
    store(arrays, p, mean, bands);
    if (skyViewFactor)
      skyViewFactor->SetValue(p, skyView / weight);
    if (sunshine)
      sunshine->SetValue(p, sunlit / weight);
  }
  for (const auto& array : arrays)
    output->GetPointData()->AddArray(array);
  output->GetPointData()->SetActiveScalars(quantityNames[0]);
}

void vtkRadiosityOutputs::BuildLeafMesh(
  const terralux::HierarchicalRadiosity& solver, int bands, bool withSky, vtkPolyData* output)
{
  // The engine's leaf meshes, continuous across T-vertices: the polygons', then each
  // terrain's; their vertex values flattened as flatLeafValues lays them out.
  std::vector<Vec3> positions;
  std::vector<double> vertexValues;
  vtkNew<vtkCellArray> polygons;
  vtkNew<vtkIntArray> level;
  level->SetName("Level");
  auto appendVertices = [&](std::size_t count, const std::function<Vec3(std::size_t)>& positionOf,
                          const std::vector<double>& values) {
    for (std::size_t k = 0; k < count; ++k)
      positions.push_back(positionOf(k));
    vertexValues.insert(vertexValues.end(), values.begin(), values.end());
  };
  std::vector<vtkIdType> ids;
  const terralux::PolygonLeafMesh polygonMesh(solver.polygonRoots());
  appendVertices(polygonMesh.vertexCount(), [&](std::size_t k) { return polygonMesh.position(k); },
    polygonMesh.vertexValues(flatLeafValues(polygonMesh.leaves()), valueComponents));
  for (std::size_t k = 0; k < polygonMesh.leaves().size(); ++k)
  {
    ids.assign(polygonMesh.corners(k).begin(), polygonMesh.corners(k).begin() + polygonMesh.leaves()[k]->cornerCount());
    polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    level->InsertNextValue(polygonMesh.leaves()[k]->level());
  }
  for (const terralux::TerrainPatch* root : solver.terrainRoots())
  {
    if (!root)
      continue;
    const terralux::TerrainLeafMesh mesh(*root);
    const vtkIdType first = static_cast<vtkIdType>(positions.size());
    appendVertices(mesh.vertexCount(), [&](std::size_t k) { return mesh.position(k); },
      mesh.vertexValues(flatLeafValues(mesh.leaves()), valueComponents));
    for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
    {
      ids.clear();
      for (std::size_t vertex : mesh.boundary(k))
        ids.push_back(first + static_cast<vtkIdType>(vertex));
      polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      level->InsertNextValue(mesh.leaves()[k]->level());
    }
  }

  const vtkIdType count = static_cast<vtkIdType>(positions.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  const auto arrays = makeArrays(bands, count);
  const auto skyViewFactor = withSky ? scalarArray(vtkRadiosityOutputs::SkyViewFactorName(), count) : nullptr;
  for (vtkIdType k = 0; k < count; ++k)
  {
    points->SetPoint(k, positions[k].x, positions[k].y, positions[k].z);
    const double* vertex = vertexValues.data() + k * valueComponents;
    Values v{};
    for (int q = 0; q < quantities; ++q)
      for (int band = 0; band < terralux::maxBands; ++band)
        v[q][band] = vertex[q * terralux::maxBands + band];
    store(arrays, k, v, bands);
    if (skyViewFactor)
      skyViewFactor->SetValue(k, vertex[skyViewComponent]);
  }
  output->SetPoints(points);
  output->SetPolys(polygons);
  for (const auto& array : arrays)
    output->GetPointData()->AddArray(array);
  if (skyViewFactor)
    output->GetPointData()->AddArray(skyViewFactor);
  output->GetPointData()->SetActiveScalars(quantityNames[0]);
  output->GetCellData()->AddArray(level);
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
  return names;
}

void vtkRadiosityOutputs::AddFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}
