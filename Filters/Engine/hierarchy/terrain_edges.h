#pragma once
// Generic edges of terrain patches (paper section 4.2): an edge is a side of a patch
// plus the parameter interval it spans. Neighbours are found in three steps: up to the
// ancestor whose range holds the edge's line inside (the edge's full support), across
// to the children on the other side of that line, down to the leaves touching the line
// over the interval. T-vertices are the neighbours' corners strictly inside the edge.

#include "hierarchy/terrain_patch.h"

#include <vector>

namespace terralux
{
/// Sides of a parameter range, counter-clockwise from the low-v side.
enum class Side
{
  LowV = 0,  ///< v = v0
  HighU = 1, ///< u = u1
  HighV = 2, ///< v = v1
  LowU = 3   ///< u = u0
};

struct GenericEdge
{
  const TerrainPatch* patch = nullptr;
  Side side = Side::LowV;
  double line = 0.0;     ///< the fixed parameter (v for LowV/HighV, u otherwise)
  double from = 0.0;     ///< interval along the line, from < to
  double to = 0.0;
  bool alongU() const { return this->side == Side::LowV || this->side == Side::HighV; }
};

GenericEdge edgeOf(const TerrainPatch& patch, Side side);

/// Leaves (patches without children) on the other side of `edge` that share part of
/// its interval, ordered along it. Empty at the grid's border and along holes.
std::vector<const TerrainPatch*> neighbourLeaves(const GenericEdge& edge);

/// Parameters along the edge's line, strictly inside its interval and sorted, where a
/// neighbour leaf has a corner: the T-vertices a continuous mesh must honour.
std::vector<double> tVertices(const GenericEdge& edge);
} // namespace terralux
