#include "terrain/terrain_mesh.h"

#include "hierarchy/terrain_edges.h"

#include <algorithm>
#include <map>

namespace terralux
{
namespace
{
void collectLeaves(const TerrainPatch& patch, std::vector<const TerrainPatch*>& leaves)
{
  if (patch.existingChildren().empty())
  {
    if (patch.complete())
      leaves.push_back(&patch);
    return;
  }
  for (const HElement* child : patch.existingChildren())
    collectLeaves(static_cast<const TerrainPatch&>(*child), leaves);
}
} // namespace

TerrainLeafMesh::TerrainLeafMesh(const TerrainPatch& root)
  : Grid(&root.grid())
{
  collectLeaves(root, this->Leaves);
  // Coarse leaves first: a T-vertex's value then comes from corners already final.
  std::stable_sort(this->Leaves.begin(), this->Leaves.end(), [](const TerrainPatch* a, const TerrainPatch* b) {
    return a->range().width() * a->range().height() > b->range().width() * b->range().height();
  });
  std::map<std::array<double, 2>, std::size_t> index; // parameters are exact dyadic numbers
  auto vertexAt = [&](double u, double v) {
    auto [it, added] = index.emplace(std::array<double, 2>{ u, v }, this->Parameters.size());
    if (added)
      this->Parameters.push_back({ u, v });
    return it->second;
  };
  std::vector<bool> anchored;
  this->Boundaries.resize(this->Leaves.size());
  this->Corners.resize(this->Leaves.size());
  this->MostOnAnEdge.assign(this->Leaves.size(), 0);
  for (std::size_t k = 0; k < this->Leaves.size(); ++k)
  {
    const ParameterRange& r = this->Leaves[k]->range();
    const std::array<std::array<double, 2>, 4> corners{ { { r.u0, r.v0 }, { r.u1, r.v0 }, { r.u1, r.v1 },
      { r.u0, r.v1 } } };
    for (int c = 0; c < 4; ++c)
      this->Corners[k][c] = vertexAt(corners[c][0], corners[c][1]);
    for (int side = 0; side < 4; ++side)
    {
      const std::size_t a = this->Corners[k][side], b = this->Corners[k][(side + 1) % 4];
      this->Boundaries[k].push_back(a);
      const GenericEdge edge = edgeOf(*this->Leaves[k], static_cast<Side>(side));
      std::vector<double> ts = tVertices(edge);
      this->MostOnAnEdge[k] = std::max(this->MostOnAnEdge[k], static_cast<int>(ts.size()));
      // Counter-clockwise: the high sides run backwards along their parameter.
      if (side >= 2)
        std::reverse(ts.begin(), ts.end());
      for (double t : ts)
      {
        const std::size_t vertex = edge.alongU() ? vertexAt(t, edge.line) : vertexAt(edge.line, t);
        this->Boundaries[k].push_back(vertex);
        anchored.resize(this->Parameters.size(), false);
        if (!anchored[vertex])
        {
          anchored[vertex] = true;
          const double ta = edge.alongU() ? this->Parameters[a][0] : this->Parameters[a][1];
          const double tb = edge.alongU() ? this->Parameters[b][0] : this->Parameters[b][1];
          this->Anchors.push_back({ vertex, a, b, (t - ta) / (tb - ta) });
        }
      }
    }
  }
}

Vec3 TerrainLeafMesh::position(std::size_t vertex) const
{
  return this->Grid->surfacePoint(this->Parameters[vertex][0], this->Parameters[vertex][1]).position;
}

std::vector<double> TerrainLeafMesh::vertexValues(const std::vector<double>& leafValues, int components) const
{
  const std::size_t n = this->Parameters.size();
  std::vector<double> values(n * components, 0.0), weights(n, 0.0);
  for (std::size_t k = 0; k < this->Leaves.size(); ++k)
  {
    const double area = this->Leaves[k]->area();
    for (std::size_t vertex : this->Corners[k])
    {
      weights[vertex] += area;
      for (int c = 0; c < components; ++c)
        values[vertex * components + c] += area * leafValues[k * components + c];
    }
  }
  for (std::size_t vertex = 0; vertex < n; ++vertex)
    if (weights[vertex] > 0.0)
      for (int c = 0; c < components; ++c)
        values[vertex * components + c] /= weights[vertex];
  for (const Anchor& anchor : this->Anchors)
    for (int c = 0; c < components; ++c)
      values[anchor.vertex * components + c] =
        (1.0 - anchor.t) * values[anchor.a * components + c] + anchor.t * values[anchor.b * components + c];
  return values;
}

void TerrainLeafMesh::interpolate(std::size_t leaf, const std::vector<double>& vertexValues, int components,
  double u, double v, double* out) const
{
  const ParameterRange& r = this->Leaves[leaf]->range();
  const double s = (u - r.u0) / r.width(), t = (v - r.v0) / r.height();
  const double w[4] = { (1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t };
  for (int c = 0; c < components; ++c)
  {
    out[c] = 0.0;
    for (int k = 0; k < 4; ++k)
      out[c] += w[k] * vertexValues[this->Corners[leaf][k] * components + c];
  }
}
} // namespace terralux
