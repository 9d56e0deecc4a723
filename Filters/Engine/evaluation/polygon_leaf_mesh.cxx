#include "evaluation/polygon_leaf_mesh.h"

#include "hierarchy/polygon_element.h"

#include <algorithm>
#include <functional>
#include <numeric>
#include <unordered_map>

namespace terralux
{
namespace
{
void collectLeaves(PolygonElement* element, std::vector<const PolygonElement*>& leaves)
{
  if (!element->hasChildren())
  {
    leaves.push_back(element);
    return;
  }
  for (HElement* child : element->children())
    collectLeaves(static_cast<PolygonElement*>(child), leaves);
}

struct PositionHash
{
  std::size_t operator()(const Vec3& p) const { return hashPosition(p); }
};

double weightOf(const PolygonElement& leaf)
{
  return std::max(leaf.area(), 1e-200);
}
} // namespace

PolygonLeafMesh::PolygonLeafMesh(const std::vector<PolygonElement*>& roots)
{
  for (PolygonElement* root : roots)
    if (root)
      collectLeaves(root, this->Leaves);

  std::unordered_map<Vec3, std::size_t, PositionHash> index;
  this->Corners.resize(this->Leaves.size());
  for (std::size_t k = 0; k < this->Leaves.size(); ++k)
  {
    const PolygonElement& leaf = *this->Leaves[k];
    for (int c = 0; c < leaf.cornerCount(); ++c)
    {
      const auto added = index.emplace(leaf.corners()[c], this->Positions.size());
      if (added.second)
        this->Positions.push_back(leaf.corners()[c]);
      this->Corners[k][c] = added.first->second;
    }
  }

  // T-vertices: along each edge of the coarsest leaves first, the vertex at the
  // midpoint of two others takes their mean, recursively down the edge.
  std::vector<std::size_t> order(this->Leaves.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b) { return this->Leaves[a]->area() > this->Leaves[b]->area(); });
  std::function<void(std::size_t, std::size_t)> anchor = [&](std::size_t a, std::size_t b) {
    const auto it = index.find(0.5 * (this->Positions[a] + this->Positions[b]));
    // In floating point the midpoint of two (nearly) equal corners is one of them.
    if (it == index.end() || it->second == a || it->second == b)
      return;
    this->Midpoints.push_back({ it->second, a, b });
    anchor(a, it->second);
    anchor(it->second, b);
  };
  for (std::size_t k : order)
  {
    const int count = this->Leaves[k]->cornerCount();
    for (int c = 0; c < count; ++c)
      anchor(this->Corners[k][c], this->Corners[k][(c + 1) % count]);
  }
}

std::vector<double> PolygonLeafMesh::vertexValues(const std::vector<double>& leafValues, int components) const
{
  const std::size_t n = static_cast<std::size_t>(components);
  std::vector<double> values(this->Positions.size() * n, 0.0), weights(this->Positions.size(), 0.0);
  for (std::size_t k = 0; k < this->Leaves.size(); ++k)
  {
    const double w = weightOf(*this->Leaves[k]);
    for (int c = 0; c < this->Leaves[k]->cornerCount(); ++c)
    {
      const std::size_t vertex = this->Corners[k][c];
      weights[vertex] += w;
      for (std::size_t q = 0; q < n; ++q)
        values[vertex * n + q] += w * leafValues[k * n + q];
    }
  }
  for (std::size_t vertex = 0; vertex < weights.size(); ++vertex)
    for (std::size_t q = 0; q < n; ++q)
      values[vertex * n + q] *= 1.0 / weights[vertex];
  for (const Midpoint& m : this->Midpoints)
    for (std::size_t q = 0; q < n; ++q)
      values[m.vertex * n + q] = 0.5 * values[m.a * n + q] + 0.5 * values[m.b * n + q];
  return values;
}
} // namespace terralux
