// Per-vertex values of input polygons (see point_values.h).
#include "evaluation/point_values.h"

#include "hierarchy/polygon_element.h"
#include "evaluation/point_evaluator.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <unordered_map>

namespace terralux
{
namespace
{
// The polygons around a point, grouped by orientation: a point on a smooth or flat
// surface has one group (the area-weighted normal, as a GIS takes a post's slope from
// its neighbours), a point on a crease (a box's edge or corner) one per face, each
// evaluated on its own side and the results averaged by area. One normal averaged
// across a crease would point out of every face.
struct Side
{
  Vec3 normalSum{ 0.0 };
  double area = 0.0;
  const PolygonElement* leaf = nullptr;
  // Other leaves of this side with the point as a corner: where a surface runs under
  // another (ground under a building), the point takes the value of its most open
  // leaf, the limit a user sees from the visible side.
  std::vector<const PolygonElement*> otherLeaves;
  Vec3 centroidSum{ 0.0 }; // centres of its polygons weighted as `area`: where the point moves
  PointValues leafSum;     // averaged mode: area-weighted leaf values
  double leafWeight = 0.0;
};

// A leaf's weight in the averages at a point: its area, never zero, so that a point only
// zero-area leaves reach (those of a degenerate polygon) takes their plain mean, not 0/0.
double averagingWeight(const PolygonElement& leaf)
{
  return std::max(leaf.area(), 1e-200);
}

// The leaf below `element` that has `corner` as one of its corners.
const PolygonElement* leafAtCorner(PolygonElement* element, const Vec3& corner)
{
  while (element->hasChildren())
  {
    PolygonElement* next = nullptr;
    for (HElement* child : element->children())
    {
      auto* polygon = static_cast<PolygonElement*>(child);
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

// The sides of every point of one input.
class PointSides
{
public:
  PointSides(std::size_t count, bool oneNormal, bool averaged)
    : Sides(count)
    , SameSide(oneNormal ? -2.0 : 0.94) // cos 20 deg
    , OneNormal(oneNormal)
    , Averaged(averaged)
  {
  }

  // Point `point` of the surface of `root`, on its leaf `leaf`, joins the side of its
  // orientation.
  void add(std::size_t point, const PolygonElement* root, const PolygonElement* leaf)
  {
    const Vec3 n = root->normal();
    Side* side = nullptr;
    for (Side& candidate : this->Sides[point])
      if (glm::dot(glm::normalize(candidate.normalSum), n) > this->SameSide)
        side = &candidate;
    if (!side)
    {
      this->Sides[point].emplace_back();
      side = &this->Sides[point].back();
      side->leaf = leaf;
    }
    else if (!this->OneNormal && leaf != side->leaf &&
      std::find(side->otherLeaves.begin(), side->otherLeaves.end(), leaf) == side->otherLeaves.end())
    {
      side->otherLeaves.push_back(leaf);
    }
    side->normalSum += root->area() * n;
    side->centroidSum += averagingWeight(*root) * root->centre();
    side->area += averagingWeight(*root);
    if (this->Averaged)
    {
      side->leafSum.accumulate(PointValues::ofLeaf(*leaf), averagingWeight(*leaf));
      side->leafWeight += averagingWeight(*leaf);
    }
  }

  const std::vector<Side>& of(std::size_t point) const { return this->Sides[point]; }
  bool empty(std::size_t point) const { return this->Sides[point].empty(); }

private:
  std::vector<std::vector<Side>> Sides;
  const double SameSide;
  const bool OneNormal, Averaged;
};

// Every side of every point of input `owner`.
PointSides sidesOf(const PointEvaluator& evaluator, const RadiosityScene& scene, int owner,
  std::size_t firstPoint, std::size_t count, bool oneNormal, bool averaged)
{
  PointSides sides(count, oneNormal, averaged);
  const auto& roots = evaluator.solver().polygonRoots();
  // The largest part of each cell (a polygon is split into triangles), for vertices
  // that only its degenerate parts reach.
  std::unordered_map<std::int64_t, std::size_t> largestPart;
  for (std::size_t k = 0; k < roots.size(); ++k)
  {
    const ScenePolygon& polygon = scene.polygons[k];
    if (!roots[k] || polygon.owner != owner)
      continue;
    auto found = largestPart.find(polygon.cell);
    if (found == largestPart.end() || roots[found->second]->area() < roots[k]->area())
      largestPart[polygon.cell] = k;
    for (int c = 0; c < polygon.vertexCount; ++c)
      sides.add(polygon.vertices[c] - firstPoint, roots[k], leafAtCorner(roots[k], scene.points[polygon.vertices[c]]));
  }
  // A vertex of a cell with area that only a zero-area part of it reaches (a spike of a
  // concave polygon, whose ear clipping left a degenerate triangle) takes the value of
  // the cell's largest part at the vertex, from the leaf nearest to it.
  for (std::size_t k = 0; k < roots.size(); ++k)
  {
    const ScenePolygon& polygon = scene.polygons[k];
    const auto part = roots[k] || polygon.owner != owner ? largestPart.end() : largestPart.find(polygon.cell);
    if (part == largestPart.end())
      continue;
    for (int c = 0; c < polygon.vertexCount; ++c)
    {
      const std::size_t point = polygon.vertices[c] - firstPoint;
      if (sides.empty(point))
        sides.add(point, roots[part->second], roots[part->second]->leafHolding(scene.points[polygon.vertices[c]]));
    }
  }
  return sides;
}

// One evaluation per side: the side's first leaf, then its other leaves; the clearly
// most open wins. An other leaf is evaluated only where its side is clearly more open
// than the first's (more of the gather's first probes meet no surface's back, or
// nothing at all: a corner's outside against a wall's foot): on a flat surface the
// leaves around a vertex give the same rays from next to the same place.
std::vector<PointValues> evaluatedAtPoints(const PointEvaluator& evaluator,
  const std::vector<const Side*>& sides, const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
  const std::vector<Vec3>& towards)
{
  std::vector<const PolygonElement*> leaves;
  for (const Side* side : sides)
    leaves.push_back(side->leaf);
  // Each other leaf of a side (the side's index in evaluationOf), and how open each
  // side with other leaves is from its first leaf and from each other.
  std::vector<std::size_t> evaluationOf;
  std::vector<const PolygonElement*> otherLeaves;
  for (std::size_t k = 0; k < sides.size(); ++k)
    for (const PolygonElement* other : sides[k]->otherLeaves)
    {
      otherLeaves.push_back(other);
      evaluationOf.push_back(k);
    }
  std::vector<PointEvaluator::Openness> firstOpen(points.size()), otherOpen(evaluationOf.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t k) {
    if (!sides[k]->otherLeaves.empty())
      firstOpen[k] = evaluator.opennessAt(points[k], normals[k], towards[k]);
  });
  tbb::parallel_for(std::size_t(0), evaluationOf.size(), [&](std::size_t m) {
    const std::size_t k = evaluationOf[m];
    otherOpen[m] = evaluator.opennessAt(points[k], normals[k], otherLeaves[m]->centre());
  });
  std::vector<Vec3> allPoints = points, allNormals = normals, allTowards = towards;
  std::vector<std::size_t> evaluated; // of the other leaves, those evaluated
  for (std::size_t m = 0; m < evaluationOf.size(); ++m)
    if (otherOpen[m].clearlyMoreOpenThan(firstOpen[evaluationOf[m]]))
    {
      const std::size_t k = evaluationOf[m];
      leaves.push_back(otherLeaves[m]);
      allPoints.push_back(points[k]);
      allNormals.push_back(normals[k]);
      allTowards.push_back(otherLeaves[m]->centre());
      evaluated.push_back(m);
    }
  std::vector<PointIrradiance> results;
  evaluator.irradianceAt(leaves, allPoints, allNormals, allTowards, results);
  auto openness = [](const PointIrradiance& r) {
    return r.irradiance[0][0] + r.irradiance[1][0] + r.irradiance[2][0];
  };
  std::vector<std::size_t> best(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
    best[k] = k;
  for (std::size_t e = 0; e < evaluated.size(); ++e)
  {
    const std::size_t k = evaluationOf[evaluated[e]], candidate = points.size() + e;
    // Only a clearly more open leaf (a hidden one next to a visible one), not the larger
    // of two noisy estimates of the same value.
    if (openness(results[candidate]) > 1.1 * openness(results[best[k]]) + 1e-9)
      best[k] = candidate;
  }
  std::vector<PointValues> values(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
    values[k] = PointValues::atPoint(results[best[k]], *leaves[best[k]]);
  return values;
}

// Averaged over the leaves around the point, except direct sun: one ray from the point,
// so shadows stay sharp.
std::vector<PointValues> averagedAroundPoints(const PointEvaluator& evaluator,
  const std::vector<const Side*>& sides, const std::vector<Vec3>& points, const std::vector<Vec3>& normals)
{
  std::vector<PointValues> values(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t k) {
    const Side& side = *sides[k];
    PointValues& v = values[k];
    v.accumulate(side.leafSum, 1.0 / side.leafWeight);
    v.sunlitHours = 0.0;
    v.irradiance[SunLight] = evaluator.directSunAt(points[k], normals[k], &v.sunlitHours);
    v.radiosity = radiosityOf(side.leaf->emission(), side.leaf->reflectance(), v.globalIrradiance());
  });
  return values;
}
} // namespace

std::vector<PointValues> polygonPointValues(const PointEvaluator& evaluator, const RadiosityScene& scene,
  int owner, std::size_t firstPoint, std::size_t count, bool oneNormal, const PointEvaluation& how,
  std::vector<bool>& reached)
{
  const PointSides sides = sidesOf(evaluator, scene, owner, firstPoint, count, oneNormal, !how.atPoints);
  // One evaluation per side of each point.
  std::vector<const Side*> allSides;
  std::vector<Vec3> points, normals, towards;
  std::vector<std::size_t> pointOf;
  for (std::size_t p = 0; p < count; ++p)
    for (const Side& side : sides.of(p))
    {
      const double length = glm::length(side.normalSum);
      // The point moves toward the centre of its side's cells (the limit from inside the
      // surface, whatever leaf holds it); where that centre is the point itself (cells
      // all around it: a ground vertex at a building's corner, some cells under the
      // building), toward its leaf's, and the side's other leaves are tried too.
      const Vec3 point = scene.points[firstPoint + p];
      const Vec3 centroid = side.centroidSum / side.area;
      towards.push_back(glm::length(centroid - point) > 1e-3 * glm::length(side.leaf->centre() - point)
          ? centroid
          : side.leaf->centre());
      points.push_back(point);
      normals.push_back(length > 0.0 ? side.normalSum / length : side.leaf->normal());
      allSides.push_back(&side);
      pointOf.push_back(p);
    }
  const std::vector<PointValues> sideValues = how.atPoints
    ? evaluatedAtPoints(evaluator, allSides, points, normals, towards)
    : averagedAroundPoints(evaluator, allSides, points, normals);
  // Sides of one point weighted by their area.
  std::vector<PointValues> values(count);
  std::vector<double> weights(count, 0.0);
  for (std::size_t k = 0; k < allSides.size(); ++k)
  {
    values[pointOf[k]].accumulate(sideValues[k], allSides[k]->area);
    weights[pointOf[k]] += allSides[k]->area;
  }
  reached.assign(count, false);
  for (std::size_t p = 0; p < count; ++p)
    if (weights[p] > 0.0)
    {
      reached[p] = true;
      PointValues mean;
      mean.accumulate(values[p], 1.0 / weights[p]);
      values[p] = mean;
    }
  return values;
}
} // namespace terralux
