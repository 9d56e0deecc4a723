#include "evaluation/post_lattice.h"

#include "base/error.h"
#include "terrain/grid_interpolation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace terralux
{
namespace
{
/// Lattice posts a process holds beyond its window: those within `postsHalo` posts,
/// and the cells read there (a coarse cell is two lattice cells a side, and its
/// corners decide whether it is refined).
int latticeHalo(int postsHalo, int step)
{
  return postsHalo < 0 ? -1 : (postsHalo + step - 1) / step + 3;
}
} // namespace

PostLattice::PostLattice(int postsX, int postsY, int step, const WorkSplit* split, int postsHalo)
  : Step(std::max(1, step))
  , Nx((std::max(1, postsX) - 1) / Step + 1)
  , Ny((std::max(1, postsY) - 1) / Step + 1)
  , CoarseX(std::max(1, Nx / 2))
  , CoarseY(std::max(1, Ny / 2))
  , Held(Nx, Ny, split, latticeHalo(postsHalo, Step), Step)
{
  const WorkSplit::Window own = this->Held.own();
  if (!own.empty())
    this->HeldCells = WorkSplit::Window{ own.i0 / 2, own.i1 / 2, own.j0 / 2, own.j1 / 2 }.clampedTo(CoarseX, CoarseY);
  const std::size_t posts = this->Held.count();
  this->Variance.assign(posts, -1.0);
  this->Found.resize(posts);
  this->Ranges.assign(posts, { 0.0, 0.0, 0.0, 0.0, 0.0 });
  this->Received.assign(posts, 0.0);
  this->MapExcess.assign(posts, 0.0);
  this->ExcessBasis.assign(posts, 0.0);
  this->Edge.assign(posts, 0);
  const std::size_t cells = this->HeldCells.empty() ? 0
    : static_cast<std::size_t>(this->HeldCells.i1 - this->HeldCells.i0 + 1) * (this->HeldCells.j1 - this->HeldCells.j0 + 1);
  this->Refined.assign(cells, CellRefined); // every cell fine until refine decides
}

std::size_t PostLattice::coarseCell(int li, int lj) const
{
  const int ci = std::min(li / 2, this->CoarseX - 1), cj = std::min(lj / 2, this->CoarseY - 1);
  if (!this->HeldCells.holds(ci, cj))
    throw Error("a gather ray read the lattice's light beyond what this process holds: its detail distance's "
                "halo is too narrow for this grid");
  return static_cast<std::size_t>(cj - this->HeldCells.j0) * (this->HeldCells.i1 - this->HeldCells.i0 + 1) +
    (ci - this->HeldCells.i0);
}

bool PostLattice::gatheredInPass(int i, int j, bool first) const
{
  if (!this->onLattice(i, j))
    return false;
  const int li = i / this->Step, lj = j / this->Step;
  const bool coarse = li % 2 == 0 && lj % 2 == 0;
  if (first || coarse)
    return first && coarse;
  // A corner of a lattice cell (li - 1 or li, lj - 1 or lj) of a refined coarse cell.
  for (int b = std::max(0, lj - 1); b <= std::min(lj, this->Ny - 2); ++b)
    for (int a = std::max(0, li - 1); a <= std::min(li, this->Nx - 2); ++a)
      if (this->Refined[this->coarseCell(a, b)] != CellCoarse)
        return true;
  return false;
}

bool PostLattice::seesTerrain(std::size_t k) const
{
  return this->terrainSeen(k) > minimumTerrainSeen;
}

double PostLattice::perTerrainSeenIn(const double* part)
{
  return *std::max_element(part, part + maxBands) / part[terrainSeenSlot];
}

PostLattice::Slots PostLattice::partOf(std::size_t k, int part) const
{
  const Beyond& found = this->Found[k];
  const int q = part / 2;
  if (part % 2 == 0)
    return nearSlots(&found[sectorStart(q)], &found[farStart(q)]);
  Slots result;
  std::copy_n(&found[farStart(q)], slots, result.begin());
  return result;
}

PostLattice::Slots PostLattice::nearSlots(const double* sector, const double* far)
{
  Slots result;
  for (std::size_t slot = 0; slot < slots; ++slot)
    result[slot] = sector[slot] - far[slot];
  if (!(result[terrainSeenSlot] > 1e-9 * sector[terrainSeenSlot]))
    result = Slots{};
  return result;
}

PostLattice::Slots PostLattice::meanOver(
  const WeightedCorner* corners, int count, double total, std::size_t start) const
{
  Slots result{};
  for (int n = 0; n < count; ++n)
    for (std::size_t slot = 0; slot < slots; ++slot)
      result[slot] += corners[n].weight * this->Found[corners[n].k][start + slot];
  for (double& value : result)
    value /= total;
  return result;
}

void PostLattice::refine(double allowedSpread, double allowedFloor)
{
  const WorkSplit::Window& cells = this->HeldCells;
  for (int cj = cells.j0; cj <= cells.j1; ++cj)
    for (int ci = cells.i0; ci <= cells.i1; ++ci)
    {
      const Cell coarse{ 2 * ci, 2 * cj, 2 };
      std::uint8_t& refined = this->Refined[this->coarseCell(coarse.li, coarse.lj)];
      refined = CellCoarse;
      if (2 * ci + 2 > this->Nx - 1 || 2 * cj + 2 > this->Ny - 1) // no coarse corner at the far side
        refined = CellRefined;
      else if (!this->Held.holds(2 * ci, 2 * cj) || !this->Held.holds(2 * ci + 2, 2 * cj + 2))
        refined = CellUndecided;
      else
      {
        const Around corners = this->aroundCell(coarse);
        this->forEachCorner(coarse, [&](std::size_t k) {
          if (this->Variance[k] < 0.0 ||
            this->terrainSeen(k) * (corners.largestPerTerrainSeen - corners.leastPerTerrainSeen) >
              std::max(allowedSpread * this->Received[k], allowedFloor))
            refined = CellRefined;
        });
      }
    }
}

PostLattice::Cell PostLattice::cellAt(double u, double v) const
{
  const int li = std::clamp(static_cast<int>(std::floor(u / this->Step)), 0, std::max(0, this->Nx - 2));
  const int lj = std::clamp(static_cast<int>(std::floor(v / this->Step)), 0, std::max(0, this->Ny - 2));
  switch (this->Refined[this->coarseCell(li, lj)])
  {
    case CellCoarse:
      return { li - li % 2, lj - lj % 2, 2 };
    case CellRefined:
      return { li, lj, 1 };
    default:
      throw Error("a gather ray read the lattice's light where this process does not hold the corners that "
                  "decide it: its detail distance's halo is too narrow for this grid");
  }
}

PostLattice::NodeGrid PostLattice::nodeGridAt(double u, double v) const
{
  // The cell's own lattice: every post, or every second.
  const Cell cell = this->cellAt(u, v);
  const double size = static_cast<double>(this->Step * cell.side);
  return { cell.side, u / size, v / size, cell.side == 1 ? this->Nx : (this->Nx - 1) / 2 + 1,
    cell.side == 1 ? this->Ny : (this->Ny - 1) / 2 + 1 };
}

int PostLattice::cornersAt(double u, double v, std::array<WeightedCorner, 4>& corners, double& total) const
{
  const NodeGrid grid = this->nodeGridAt(u, v);
  std::array<NodeWeight, 4> nodes;
  const int count = nodeWeights(grid.x, grid.y, grid.nodesX, grid.nodesY,
    [&](int a, int b) { return this->Variance[this->index(a * grid.side, b * grid.side)] >= 0.0; }, nodes, total);
  for (int n = 0; n < count; ++n)
    corners[n] = { this->index(nodes[n].i * grid.side, nodes[n].j * grid.side), nodes[n].weight };
  return count;
}

int PostLattice::widerCornersAt(double u, double v, std::array<WeightedCorner, 16>& corners, double& total) const
{
  const NodeGrid grid = this->nodeGridAt(u, v);
  const int i0 = static_cast<int>(std::floor(grid.x)), j0 = static_cast<int>(std::floor(grid.y));
  int count = 0;
  total = 0.0;
  for (int b = std::max(0, j0 - 1); b <= std::min(grid.nodesY - 1, j0 + 2); ++b)
    for (int a = std::max(0, i0 - 1); a <= std::min(grid.nodesX - 1, i0 + 2); ++a)
    {
      const double w = std::max(0.0, 1.0 - 0.5 * std::abs(grid.x - a)) * std::max(0.0, 1.0 - 0.5 * std::abs(grid.y - b));
      if (!(w > 0.0) || !this->Held.holds(a * grid.side, b * grid.side))
        continue;
      const std::size_t k = this->index(a * grid.side, b * grid.side);
      if (this->Variance[k] < 0.0)
        continue;
      corners[count++] = { k, w };
      total += w;
    }
  return count;
}

template <class Value, class NodeValue>
bool PostLattice::interpolate(double u, double v, const NodeValue& nodeValue, Value& result) const
{
  // Bilinear between the gathered corners.
  const NodeGrid grid = this->nodeGridAt(u, v);
  return interpolateNodes(grid.x, grid.y, grid.nodesX, grid.nodesY,
    [&](int a, int b, Value& value) {
      const std::size_t k = this->index(a * grid.side, b * grid.side);
      if (this->Variance[k] < 0.0)
        return false;
      value = nodeValue(k);
      return true;
    },
    result);
}

void PostLattice::set(int i, int j, const Gathered& gathered)
{
  const std::size_t k = this->index(i / this->Step, j / this->Step);
  this->Variance[k] = std::max(0.0, gathered.variance);
  Beyond& found = this->Found[k];
  for (int band = 0; band < maxBands; ++band)
    found[band] = gathered.reflected[band];
  // Per terrain the rays met: the light is theirs, and a reading post takes the map's
  // excess off its own terrain seen (mapExcessAt).
  double met = 0.0;
  for (const double seen : gathered.terrainByPart)
    met += std::max(0.0, seen);
  found[terrainSeenSlot] = met;
  this->MapExcess[k] = std::max(0.0, gathered.terrainSeen) - met;
  this->ExcessBasis[k] = excessBasisOf(gathered.terrainSeen, gathered.voidSeen);
  for (int q = 0; q < viewSectors; ++q)
  {
    const int near = viewPartOf(q, false), far = viewPartOf(q, true);
    for (int band = 0; band < maxBands; ++band)
    {
      found[sectorStart(q) + band] = gathered.reflectedByPart[near][band] + gathered.reflectedByPart[far][band];
      found[farStart(q) + band] = gathered.reflectedByPart[far][band];
    }
    const double nearSeen = std::max(0.0, gathered.terrainByPart[near]), farSeen = std::max(0.0, gathered.terrainByPart[far]);
    found[sectorStart(q) + terrainSeenSlot] = nearSeen + farSeen;
    found[farStart(q) + terrainSeenSlot] = farSeen;
  }
  this->Received[k] = gathered.received;
  this->Edge[k] = gathered.edge ? 1 : 0;
  this->findRanges(k);
}

void PostLattice::findRanges(std::size_t k)
{
  // Over every part (and sector) that met terrain, however little: a post's read by
  // part and its whole's are both weighted means of these.
  const Beyond& found = this->Found[k];
  const double infinity = std::numeric_limits<double>::infinity();
  std::array<double, 5> range{ infinity, -infinity, infinity, -infinity, 0.0 };
  auto widen = [&](double* leastAndLargest, double perTerrainSeen) {
    leastAndLargest[0] = std::min(leastAndLargest[0], perTerrainSeen);
    leastAndLargest[1] = std::max(leastAndLargest[1], perTerrainSeen);
  };
  for (int q = 0; q < viewSectors; ++q)
  {
    if (!(found[sectorStart(q) + terrainSeenSlot] > 0.0))
      continue;
    widen(&range[2], perTerrainSeenIn(&found[sectorStart(q)]));
    std::array<double, 2> byDistance{ -1.0, -1.0 };
    for (const bool beyond : { false, true })
    {
      const Slots part = this->partOf(k, viewPartOf(q, beyond));
      if (!(part[terrainSeenSlot] > 0.0))
        continue;
      byDistance[beyond ? 1 : 0] = perTerrainSeenIn(part.data());
      widen(&range[0], byDistance[beyond ? 1 : 0]);
    }
    if (byDistance[0] >= 0.0 && byDistance[1] >= 0.0)
      range[4] = std::max(range[4], std::abs(byDistance[1] - byDistance[0]));
  }
  for (int r = 0; r < 4; r += 2)
    if (!(range[r + 1] >= range[r]))
      range[r] = range[r + 1] = 0.0;
  this->Ranges[k] = range;
}

void PostLattice::share()
{
  constexpr int latticeTag = 903; // after the posts' skies' and suns' (post_sky.cxx, post_sunlight.cxx)
  this->Held.share(this->Variance, latticeTag);
  this->Held.share(this->Found, latticeTag + 1);
  this->Held.share(this->Received, latticeTag + 2);
  this->Held.share(this->Edge, latticeTag + 3);
  this->Held.share(this->MapExcess, latticeTag + 4);
  this->Held.share(this->ExcessBasis, latticeTag + 5);
  for (std::size_t k = 0; k < this->Found.size(); ++k)
    this->findRanges(k);
}

template <class Corner>
void PostLattice::forEachCorner(const Cell& cell, const Corner& corner) const
{
  for (int dj = 0; dj < 2 && cell.lj + dj * cell.side < this->Ny; ++dj)
    for (int di = 0; di < 2 && cell.li + di * cell.side < this->Nx; ++di)
      corner(this->index(cell.li + di * cell.side, cell.lj + dj * cell.side));
}

PostLattice::Around PostLattice::aroundCell(const Cell& cell) const
{
  Around result;
  result.leastPerTerrainSeen = std::numeric_limits<double>::infinity();
  const double infinity = std::numeric_limits<double>::infinity();
  std::array<double, 4> ranges{ infinity, -infinity, infinity, -infinity };
  double distanceWidth = 0.0;
  this->forEachCorner(cell, [&](std::size_t k) {
    if (this->Variance[k] < 0.0)
      return;
    result.variance = std::max(result.variance, this->Variance[k]);
    result.edgeCorner = result.edgeCorner || this->Edge[k] != 0;
    if (!this->seesTerrain(k))
      return; // tells nothing per terrain seen
    const double largest = perTerrainSeenIn(this->Found[k].data());
    result.largestPerTerrainSeen = std::max(result.largestPerTerrainSeen, largest);
    result.leastPerTerrainSeen = std::min(result.leastPerTerrainSeen, largest);
    for (int r = 0; r < 4; r += 2)
      ranges[r] = std::min(ranges[r], this->Ranges[k][r]), ranges[r + 1] = std::max(ranges[r + 1], this->Ranges[k][r + 1]);
    distanceWidth = std::max(distanceWidth, this->Ranges[k][4]);
  });
  result.distanceWidth = distanceWidth;
  result.partWidth = ranges[1] >= ranges[0] ? ranges[1] - ranges[0] : 0.0;
  result.sectorWidth = ranges[3] >= ranges[2] ? ranges[3] - ranges[2] : 0.0;
  if (result.leastPerTerrainSeen > result.largestPerTerrainSeen) // no corner sees terrain
    result.leastPerTerrainSeen = result.largestPerTerrainSeen = 0.0;
  return result;
}

PostLattice::Around PostLattice::around(int i, int j) const
{
  return this->aroundCell(this->cellAt(i, j));
}

bool PostLattice::reflectedAt(double u, double v, Spectrum& reflected) const
{
  return this->interpolate(
    u, v,
    [&](std::size_t k) {
      Spectrum found;
      std::copy_n(this->Found[k].begin(), maxBands, found.begin());
      return found;
    },
    reflected);
}

bool PostLattice::mapExcessAt(double u, double v, double terrainSeen, double voidSeen, double& excess) const
{
  std::array<WeightedCorner, 16> wider;
  double total = 0.0;
  const int count = this->widerCornersAt(u, v, wider, total);
  if (count == 0)
    return false;
  // A ratio of sums: the noise of a post's rays that met little terrain weighs little.
  double excessSum = 0.0, basisSum = 0.0;
  for (int n = 0; n < count; ++n)
  {
    excessSum += wider[n].weight * this->MapExcess[wider[n].k];
    basisSum += wider[n].weight * this->ExcessBasis[wider[n].k];
  }
  excess = basisSum > 0.0 ? excessSum / basisSum * excessBasisOf(terrainSeen, voidSeen) : 0.0;
  return true;
}

bool PostLattice::perTerrainSeenAt(double u, double v, Spectrum& reflected) const
{
  PartRead read;
  if (!this->readByPart(u, v, PerViewPart<double>{}, false, read))
    return false;
  reflected = read.whole;
  return true;
}

bool PostLattice::readByPart(
  double u, double v, const PerViewPart<double>& shares, bool byDistance, PartRead& read) const
{
  // The whole's: a ratio of the corners' sums (each weighted by the terrain it sees)
  // rather than a mean of their ratios: a corner that sees next to no terrain (an open
  // ridge between valleys) tells next to nothing of what terrain sends, and counting
  // its ratio as 0 read too little light from surfaces on gentle terrain
  // (docs/tuning.md). Then only the parts the post sees terrain in, from the corners'
  // values in place (every post of a DEM takes one).
  std::array<WeightedCorner, 4> corners;
  double total = 0.0;
  const int count = this->cornersAt(u, v, corners, total);
  if (count == 0)
    return false;
  const Slots whole = this->meanOver(corners.data(), count, total, 0);
  const double terrainSeen = whole[terrainSeenSlot];
  if (!(terrainSeen > minimumTerrainSeen))
    return false;
  read = PartRead{};
  for (int band = 0; band < maxBands; ++band)
    read.whole[band] = whole[band] / terrainSeen;
  // The far parts of a view are much the same for the lattice's posts around: read
  // from 4 x 4 of them, their noise (few of a post's rays go far) is a quarter.
  std::array<WeightedCorner, 16> wider;
  double widerTotal = 0.0;
  bool seesFar = false;
  for (int q = 0; q < viewSectors && byDistance; ++q)
    seesFar = seesFar || shares[viewPartOf(q, true)] > 0.0;
  const int widerCount = seesFar ? this->widerCornersAt(u, v, wider, widerTotal) : 0;
  for (int q = 0; q < viewSectors; ++q)
  {
    const int nearPart = viewPartOf(q, false);
    if (!(shares[nearPart] > 0.0 || shares[nearPart + 1] > 0.0))
      continue;
    Slots sector = this->meanOver(corners.data(), count, total, sectorStart(q)), near{}, far{};
    if (byDistance)
    {
      // The near part: the sector's less the far, both between the corners; the far
      // part over the wider lattice posts where there are any; the sector, as read,
      // both.
      far = this->meanOver(corners.data(), count, total, farStart(q));
      near = nearSlots(sector.data(), far.data());
      if (widerCount > 0)
        far = this->meanOver(wider.data(), widerCount, widerTotal, farStart(q));
      for (std::size_t slot = 0; slot < slots; ++slot)
        sector[slot] = near[slot] + far[slot];
    }
    // Each part by its own light per terrain seen where a corner met terrain there,
    // else its sector's, else the whole's; without the distance, the sector's.
    for (const bool beyond : { false, true })
    {
      const double share = shares[nearPart + (beyond ? 1 : 0)];
      if (!(share > 0.0))
        continue;
      const Slots& own = !byDistance ? sector : beyond ? far : near;
      for (int band = 0; band < maxBands; ++band)
        read.perTerrainSeen[band] += share *
          (own[terrainSeenSlot] > minimumTerrainSeen          ? own[band] / own[terrainSeenSlot]
              : sector[terrainSeenSlot] > minimumTerrainSeen ? sector[band] / sector[terrainSeenSlot]
                                                             : read.whole[band]);
      // The spread between the corners that met terrain there.
      double largest = -std::numeric_limits<double>::infinity(), least = std::numeric_limits<double>::infinity();
      for (int n = 0; n < count; ++n)
      {
        const Slots part = byDistance ? this->partOf(corners[n].k, nearPart + (beyond ? 1 : 0)) : Slots{};
        const double* values = byDistance ? part.data() : &this->Found[corners[n].k][sectorStart(q)];
        if (!(values[terrainSeenSlot] > minimumTerrainSeen))
          continue;
        const double perTerrainSeen = perTerrainSeenIn(values);
        largest = std::max(largest, perTerrainSeen);
        least = std::min(least, perTerrainSeen);
      }
      if (largest >= least)
        read.spread += share * (largest - least);
    }
  }
  return true;
}
} // namespace terralux
