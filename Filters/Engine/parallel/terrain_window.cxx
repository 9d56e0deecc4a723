#include "parallel/terrain_window.h"

#include "base/error.h"
#include "evaluation/post_lattice.h"
#include "parallel/held_posts.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

namespace terralux
{
namespace
{
constexpr int latticeCell = 2 * PostLattice::defaultStep;
}

int TerrainWindow::haloPosts(double detailDistance, double postSpacing)
{
  if (!(postSpacing > 0.0))
    return -1;
  const double posts = std::ceil(3.0 * detailDistance / postSpacing);
  return posts > 1e8 ? -1 : static_cast<int>(posts) + PostLattice::readReach + 3;
}

TerrainWindow::Extent TerrainWindow::requested(const Extent& whole, const Extent& piece, int halo)
{
  const int i0 = std::max(whole.i0, piece.i0 - halo), j0 = std::max(whole.j0, piece.j0 - halo);
  return Extent{ whole.i0 + (i0 - whole.i0) / latticeCell * latticeCell, std::min(whole.i1, piece.i1 + halo),
    whole.j0 + (j0 - whole.j0) / latticeCell * latticeCell, std::min(whole.j1, piece.j1 + halo) };
}

void TerrainWindow::checkHeld(
  const TerrainGrid& grid, double detailDistance, const Extent& whole, const Extent& held, const Extent& piece)
{
  // A window cut short (a source that gave less than asked, or a spacing it misjudged)
  // would give values that depend on the ranks.
  const int reach = HeldPosts::haloFor(grid, 3.0 * detailDistance);
  const int needed = reach < 0 ? INT_MAX : reach + PostLattice::readReach;
  const int heldLow[2] = { held.i0, held.j0 }, heldHigh[2] = { held.i1, held.j1 };
  const int wholeLow[2] = { whole.i0, whole.j0 }, wholeHigh[2] = { whole.i1, whole.j1 };
  const int pieceLow[2] = { piece.i0, piece.j0 }, pieceHigh[2] = { piece.i1, piece.j1 };
  for (int axis = 0; axis < 2; ++axis)
  {
    const bool lowShort = heldLow[axis] > wholeLow[axis] && pieceLow[axis] - heldLow[axis] < needed;
    const bool highShort = heldHigh[axis] < wholeHigh[axis] && heldHigh[axis] - pieceHigh[axis] < needed;
    if (lowShort || highShort || (heldLow[axis] - wholeLow[axis]) % latticeCell != 0)
      throw Error("the terrain's piece came with " +
        std::to_string(std::min(pieceLow[axis] - heldLow[axis], heldHigh[axis] - pieceHigh[axis])) +
        " posts around it where " + std::to_string(needed) + " (three DetailDistances and the lattice), from a " +
        "multiple of " + std::to_string(latticeCell) +
        ", are needed: connect vtkTerrainSource's output 0 to port 0 directly, or give the whole terrain");
  }
}
} // namespace terralux
