#include "hierarchy/terrain_edges.h"

#include <algorithm>

namespace terralux
{
namespace
{
double sideLine(const ParameterRange& r, Side side)
{
  switch (side)
  {
    case Side::LowV:
      return r.v0;
    case Side::HighU:
      return r.u1;
    case Side::HighV:
      return r.v1;
    default:
      return r.u0;
  }
}

Side opposite(Side side)
{
  return static_cast<Side>((static_cast<int>(side) + 2) % 4);
}

// Interval of a range along the direction of an edge.
void intervalAlong(const ParameterRange& r, bool alongU, double& from, double& to)
{
  from = alongU ? r.u0 : r.v0;
  to = alongU ? r.u1 : r.v1;
}

void collectTouching(const TerrainPatch& node, const GenericEdge& edge, Side facing,
  std::vector<const TerrainPatch*>& leaves)
{
  for (const HElement* element : node.existingChildren())
  {
    const auto& child = static_cast<const TerrainPatch&>(*element);
    double from, to;
    intervalAlong(child.range(), edge.alongU(), from, to);
    if (sideLine(child.range(), facing) != edge.line || to <= edge.from || from >= edge.to)
      continue;
    if (child.existingChildren().empty())
      leaves.push_back(&child);
    else
      collectTouching(child, edge, facing, leaves);
  }
}
} // namespace

GenericEdge edgeOf(const TerrainPatch& patch, Side side)
{
  GenericEdge edge;
  edge.patch = &patch;
  edge.side = side;
  edge.line = sideLine(patch.range(), side);
  intervalAlong(patch.range(), edge.alongU(), edge.from, edge.to);
  return edge;
}

std::vector<const TerrainPatch*> neighbourLeaves(const GenericEdge& edge)
{
  std::vector<const TerrainPatch*> leaves;
  // Up: the first ancestor with the line inside its range supports the whole edge.
  const TerrainPatch* support = edge.patch->up();
  while (support && sideLine(support->range(), edge.side) == edge.line)
    support = support->up();
  if (!support)
    return leaves; // the grid's border
  // Across and down: its children on the far side, then their descendants along the line.
  collectTouching(*support, edge, opposite(edge.side), leaves);
  const bool alongU = edge.alongU();
  std::sort(leaves.begin(), leaves.end(), [alongU](const TerrainPatch* a, const TerrainPatch* b) {
    return (alongU ? a->range().u0 : a->range().v0) < (alongU ? b->range().u0 : b->range().v0);
  });
  return leaves;
}

std::vector<double> tVertices(const GenericEdge& edge)
{
  std::vector<double> result;
  for (const TerrainPatch* leaf : neighbourLeaves(edge))
  {
    double from, to;
    intervalAlong(leaf->range(), edge.alongU(), from, to);
    for (double t : { from, to })
      if (t > edge.from && t < edge.to)
        result.push_back(t);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}
} // namespace terralux
