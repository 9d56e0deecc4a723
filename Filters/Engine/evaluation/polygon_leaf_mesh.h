#pragma once
// The leaves of the input polygons as one mesh with continuous values (the polygons'
// counterpart of TerrainLeafMesh): corners shared between leaves become one vertex, whose
// value is the area-weighted mean of the leaves around it, and a vertex in the middle of
// a coarser leaf's edge (a T-vertex) takes the value interpolated along that edge, so
// shading across subdivision levels has no cracks.

#include "hierarchy/radiosity_types.h"

#include <array>
#include <vector>

namespace terralux
{
class PolygonElement;

class PolygonLeafMesh
{
public:
  /// The leaves below each root (null roots, degenerate polygons, are skipped).
  explicit PolygonLeafMesh(const std::vector<PolygonElement*>& roots);

  const std::vector<const PolygonElement*>& leaves() const { return this->Leaves; }
  std::size_t vertexCount() const { return this->Positions.size(); }
  const Vec3& position(std::size_t vertex) const { return this->Positions[vertex]; }
  /// The corner vertices of leaf k, in its own order (3 or 4; the rest unused).
  const std::array<std::size_t, 4>& corners(std::size_t leaf) const { return this->Corners[leaf]; }

  /// Continuous per-vertex values (`components` per vertex) from per-leaf values:
  /// area-weighted at shared corners (a zero-area leaf weighs 1e-200, so a vertex only
  /// such leaves reach takes their plain mean), then interpolated at T-vertices, coarse
  /// leaves first.
  std::vector<double> vertexValues(const std::vector<double>& leafValues, int components) const;

private:
  struct Midpoint // vertex = (a + b) / 2, along a coarser leaf's edge
  {
    std::size_t vertex, a, b;
  };
  std::vector<const PolygonElement*> Leaves;
  std::vector<Vec3> Positions;
  std::vector<std::array<std::size_t, 4>> Corners;
  std::vector<Midpoint> Midpoints; // in the order they apply
};
} // namespace terralux
