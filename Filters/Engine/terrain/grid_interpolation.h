#pragma once
// Bilinear reading of values held at the nodes of a regular grid, some of which may
// be missing (no-data posts): the nodes present share the weights. Values are arrays of
// doubles (a Spectrum, or several quantities at once).

#include "hierarchy/radiosity_types.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
/// The value at continuous node coordinates (x, y) (clamped to the grid of nx x ny
/// nodes) from the four nodes of its cell; `node(i, j, value)` gives a node's value
/// and returns false where there is none. False where the cell has no node.
template <class Node, class Value>
bool interpolateNodes(double x, double y, int nx, int ny, const Node& node, Value& result)
{
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, std::max(0, nx - 2));
  const int j = std::clamp(static_cast<int>(std::floor(y)), 0, std::max(0, ny - 2));
  const double fx = std::clamp(x - i, 0.0, 1.0), fy = std::clamp(y - j, 0.0, 1.0);
  result = Value{};
  double total = 0.0;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di)
    {
      const double w = (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy);
      Value value;
      if (!(w > 0.0) || i + di >= nx || j + dj >= ny || !node(i + di, j + dj, value))
        continue;
      total += w;
      for (std::size_t c = 0; c < result.size(); ++c)
        result[c] += w * value[c];
    }
  if (!(total > 0.0))
    return false;
  for (double& c : result)
    c /= total;
  return true;
}
} // namespace terralux
