#pragma once
// Bilinear reading of values held at the nodes of a regular grid, some of which may
// be missing (no-data posts): the nodes present share the weights. Values are arrays of
// doubles (a Spectrum, or several quantities at once).

#include "hierarchy/radiosity_types.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace terralux
{
/// A node of a cell and its bilinear weight.
struct NodeWeight
{
  int i, j;
  double weight;
};

/// The nodes of the cell holding continuous node coordinates (x, y) (clamped to the
/// grid of nx x ny nodes) that `present(i, j)` holds, with their bilinear weights (not
/// normalised: `total` is their sum); how many (0: none).
template <class Present>
int nodeWeights(double x, double y, int nx, int ny, const Present& present, std::array<NodeWeight, 4>& nodes,
  double& total)
{
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, std::max(0, nx - 2));
  const int j = std::clamp(static_cast<int>(std::floor(y)), 0, std::max(0, ny - 2));
  const double fx = std::clamp(x - i, 0.0, 1.0), fy = std::clamp(y - j, 0.0, 1.0);
  int count = 0;
  total = 0.0;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di)
    {
      const double w = (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy);
      if (!(w > 0.0) || i + di >= nx || j + dj >= ny || !present(i + di, j + dj))
        continue;
      nodes[count++] = { i + di, j + dj, w };
      total += w;
    }
  return total > 0.0 ? count : 0;
}

/// The value at continuous node coordinates (x, y) (clamped to the grid of nx x ny
/// nodes) from the four nodes of its cell; `node(i, j, value)` gives a node's value
/// and returns false where there is none. False where the cell has no node.
template <class Node, class Value>
bool interpolateNodes(double x, double y, int nx, int ny, const Node& node, Value& result)
{
  std::array<Value, 4> values;
  std::array<NodeWeight, 4> nodes;
  int held = 0;
  double total = 0.0;
  const int count = nodeWeights(
    x, y, nx, ny, [&](int i, int j) { return node(i, j, values[held]) && (++held, true); }, nodes, total);
  if (count == 0)
    return false;
  result = Value{};
  for (int n = 0; n < count; ++n)
    for (std::size_t c = 0; c < result.size(); ++c)
      result[c] += nodes[n].weight * values[n][c];
  for (double& c : result)
    c /= total;
  return true;
}
} // namespace terralux
