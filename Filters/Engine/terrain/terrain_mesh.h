#pragma once
// The leaf mesh of a terrain tree made continuous: every leaf becomes a polygon whose
// boundary holds its corners and the T-vertices its neighbours put on its edges (so
// the surface has no cracks), and per-vertex values are made continuous across levels
// by setting each T-vertex to the linear interpolation along the coarser edge
// (coarse leaves first). Values inside a leaf interpolate its corners bilinearly in
// parameter space, which along an edge is exactly that linear interpolation.

#include "hierarchy/terrain_patch.h"

#include <array>
#include <vector>

namespace terralux
{
class TerrainLeafMesh
{
public:
  /// The leaves below `root` (complete patches without children).
  explicit TerrainLeafMesh(const TerrainPatch& root);

  const std::vector<const TerrainPatch*>& leaves() const { return this->Leaves; }
  std::size_t vertexCount() const { return this->Parameters.size(); }
  /// Parameter (u, v) and position on the true surface of each vertex.
  const std::vector<std::array<double, 2>>& parameters() const { return this->Parameters; }
  Vec3 position(std::size_t vertex) const;
  /// Boundary of leaf k, counter-clockwise: corners and T-vertices.
  const std::vector<std::size_t>& boundary(std::size_t leaf) const { return this->Boundaries[leaf]; }
  /// The four corner vertices of leaf k, counter-clockwise from (u0, v0).
  const std::array<std::size_t, 4>& corners(std::size_t leaf) const { return this->Corners[leaf]; }
  std::size_t tVertexCount() const { return this->Anchors.size(); }
  /// The most T-vertices on one edge of leaf k. More than one means a neighbour two or
  /// more levels finer: a restricted subdivision splits the leaf.
  int mostTVerticesOnAnEdge(std::size_t leaf) const { return this->MostOnAnEdge[leaf]; }

  /// Continuous per-vertex values (`components` per vertex) from per-leaf values:
  /// area-weighted at shared corners, interpolated at T-vertices.
  std::vector<double> vertexValues(const std::vector<double>& leafValues, int components) const;
  /// Value at parameter (u, v) inside leaf k: bilinear in its corners' vertex values.
  void interpolate(std::size_t leaf, const std::vector<double>& vertexValues, int components, double u, double v,
    double* out) const;

private:
  struct Anchor // vertex = (1 - t) a + t b, along a coarser leaf's edge
  {
    std::size_t vertex, a, b;
    double t;
  };
  const TerrainGrid* Grid;
  std::vector<const TerrainPatch*> Leaves;
  std::vector<std::array<double, 2>> Parameters;
  std::vector<std::vector<std::size_t>> Boundaries;
  std::vector<std::array<std::size_t, 4>> Corners;
  std::vector<Anchor> Anchors;
  std::vector<int> MostOnAnEdge;
};
} // namespace terralux
