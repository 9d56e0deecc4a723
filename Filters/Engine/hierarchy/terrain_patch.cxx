#include "hierarchy/terrain_patch.h"

#include "base/angles.h"
#include "evaluation/point_form_factor.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
namespace
{
// Sub-cell ranges stop at 1/256 of a cell: far below any DEM's accuracy.
constexpr double smallestWidth = 1.0 / 256.0;

bool wholeCells(const ParameterRange& r)
{
  return r.width() >= 1.0 && r.height() >= 1.0 && r.u0 == std::floor(r.u0) && r.v0 == std::floor(r.v0) &&
    r.u1 == std::floor(r.u1) && r.v1 == std::floor(r.v1);
}

std::array<Vec3, 4> cornersOf(const TerrainGrid& grid, const ParameterRange& r)
{
  return { grid.surfacePoint(r.u0, r.v0).position, grid.surfacePoint(r.u1, r.v0).position,
    grid.surfacePoint(r.u1, r.v1).position, grid.surfacePoint(r.u0, r.v1).position };
}

// What a sub-cell range holds: its corner quad, with the material of its cell.
TerrainRangeSummary subCellSummary(const TerrainGrid& grid, const ParameterRange& r)
{
  const int i = std::min(static_cast<int>(std::floor(r.u0)), grid.cellsX() - 1);
  const int j = std::min(static_cast<int>(std::floor(r.v0)), grid.cellsY() - 1);
  TerrainRangeSummary s;
  const auto c = cornersOf(grid, r);
  s.areaVector = 0.5 * glm::cross(c[2] - c[0], c[3] - c[1]);
  s.area = glm::length(s.areaVector);
  s.low = glm::min(glm::min(c[0], c[1]), glm::min(c[2], c[3]));
  s.high = glm::max(glm::max(c[0], c[1]), glm::max(c[2], c[3]));
  s.cells = s.validCells = 1;
  s.reflectance = grid.cellReflectance(i, j);
  s.emission = grid.cellEmission(i, j);
  return s;
}

TerrainRangeSummary summaryOf(const TerrainBlockSums& sums, const ParameterRange& r)
{
  if (wholeCells(r))
  {
    return sums.summarize(static_cast<int>(r.u0), static_cast<int>(r.v0), static_cast<int>(r.u1),
      static_cast<int>(r.v1));
  }
  return subCellSummary(sums.grid(), r);
}
} // namespace

std::vector<ParameterRange> TerrainPatch::splitRange(const ParameterRange& r)
{
  std::vector<double> us{ r.u0 }, vs{ r.v0 };
  if (r.width() > 1.0 || r.height() > 1.0)
  {
    if (r.width() > 1.0)
      us.push_back(r.u0 + std::floor(0.5 * r.width()));
    if (r.height() > 1.0)
      vs.push_back(r.v0 + std::floor(0.5 * r.height()));
  }
  else
  {
    us.push_back(0.5 * (r.u0 + r.u1));
    vs.push_back(0.5 * (r.v0 + r.v1));
  }
  us.push_back(r.u1);
  vs.push_back(r.v1);
  std::vector<ParameterRange> ranges;
  // Counter-clockwise from the low corner, as the corners of a patch.
  const int nu = static_cast<int>(us.size()) - 1, nv = static_cast<int>(vs.size()) - 1;
  const int order[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (const auto& o : order)
    if (o[0] < nu && o[1] < nv)
      ranges.push_back({ us[o[0]], vs[o[1]], us[o[0] + 1], vs[o[1] + 1] });
  return ranges;
}

TerrainPatch::TerrainPatch(std::uint64_t id, int level, ElementStore* store,
  std::shared_ptr<const TerrainBlockSums> sums, const ParameterRange& range, const TerrainRangeSummary& summary,
  TerrainPatch* up, int terrainIndex)
  : PolygonElement(id, level, store, cornersOf(sums->grid(), range).data(), 4, summary.reflectance, summary.emission, -1)
  , Sums(std::move(sums))
  , Range(range)
  , Up(up)
  , TerrainIndex(terrainIndex)
  , Complete(summary.validCells == summary.cells)
  , Low(summary.low)
  , High(summary.high)
{
  // True area and mean normal of the cells covered, not of the coarse quad.
  const double aligned = glm::length(summary.areaVector);
  if (summary.area > 0.0 && aligned > 0.0)
  {
    this->Area = summary.area;
    this->Normal = summary.areaVector / aligned;
    this->UnalignedArea = std::max(0.0, summary.area - aligned);
  }
  this->Centre = this->Sums->grid().surfacePoint(0.5 * (range.u0 + range.u1), 0.5 * (range.v0 + range.v1)).position;
}

TerrainPatch* TerrainPatch::buildNode(ElementStore& store, const std::shared_ptr<const TerrainBlockSums>& sums,
  int terrainIndex, const ParameterRange& range, TerrainPatch* up, int level, std::vector<TerrainPatch*>& complete)
{
  const TerrainRangeSummary summary = summaryOf(*sums, range);
  if (summary.validCells == 0 || !(summary.area > 0.0))
  {
    return nullptr; // a hole, or cells of zero area: nothing to light
  }
  TerrainPatch* patch = store.make<TerrainPatch>(level, &store, sums, range, summary, up, terrainIndex);
  if (patch->Complete)
  {
    complete.push_back(patch);
    return patch;
  }
  for (const ParameterRange& part : splitRange(range))
  {
    if (TerrainPatch* child = buildNode(store, sums, terrainIndex, part, patch, level + 1, complete))
    {
      patch->Children.push_back(child);
    }
  }
  return patch;
}

TerrainPatch* TerrainPatch::buildTree(
  ElementStore& store, const TerrainGrid& grid, int terrainIndex, std::vector<TerrainPatch*>& complete)
{
  const ParameterRange whole{ 0.0, 0.0, static_cast<double>(grid.cellsX()), static_cast<double>(grid.cellsY()) };
  return buildNode(store, std::make_shared<const TerrainBlockSums>(grid), terrainIndex, whole, nullptr, 0, complete);
}

const TerrainPatch* TerrainPatch::leafHolding(double u, double v) const
{
  if (!this->Range.contains(u, v))
    return nullptr;
  if (this->Children.empty())
    return this->Complete ? this : nullptr;
  for (const HElement* child : this->Children)
    if (const TerrainPatch* leaf = static_cast<const TerrainPatch*>(child)->leafHolding(u, v))
      return leaf;
  return nullptr;
}

const TerrainPatch* TerrainPatch::mostLitLeafAt(int i, int j) const
{
  const TerrainPatch* best = nullptr;
  double most = -1.0;
  for (const double du : { -0.5, 0.5 })
    for (const double dv : { -0.5, 0.5 })
    {
      const TerrainPatch* leaf = this->leafHolding(i + du, j + dv);
      if (!leaf)
        continue;
      const double received = leaf->receivedIrradiance();
      // Only a clearly brighter leaf: between leaves of one open slope the choice only
      // sets which way the point is nudged, and should not hop with noise.
      if (!best || received > 1.1 * most + 1e-9)
      {
        best = leaf;
        most = received;
      }
    }
  return best;
}

bool TerrainPatch::canSplit() const
{
  if (!this->Complete)
    return true;
  if (wholeCells(this->Range) && (this->Range.width() > 1.0 || this->Range.height() > 1.0))
    return true; // cells are never smaller than the DEM's posts allow
  return this->Range.width() > smallestWidth && this->Area >= 4.0 * this->Store->MinimumArea;
}

const std::vector<HElement*>& TerrainPatch::children()
{
  if (!this->Children.empty() || !this->canSplit())
  {
    return this->Children;
  }
  for (const ParameterRange& part : splitRange(this->Range))
  {
    const TerrainRangeSummary summary = summaryOf(*this->Sums, part);
    if (!(summary.area > 0.0))
      continue; // degenerate cells (zero area) carry no light
    auto* child = this->Store->make<TerrainPatch>(
      this->level() + 1, this->Store, this->Sums, part, summary, this, this->TerrainIndex);
    child->Radiosity = this->Radiosity;
    child->Parent = this;
    this->Children.push_back(child);
  }
  return this->Children;
}

SurfaceSample TerrainPatch::sample(int k, int n, SampleGenerator& random) const
{
  double s, t;
  stratifiedPoint(k, n, random, s, t);
  const TerrainPoint p = this->Sums->grid().surfacePoint(
    this->Range.u0 + s * this->Range.width(), this->Range.v0 + t * this->Range.height());
  return { p.position, p.normal };
}

double TerrainPatch::receiverFactor(const Vec3& towardSender) const
{
  if (!wholeCells(this->Range))
  {
    return PolygonElement::receiverFactor(towardSender); // within a cell: nearly planar
  }
  return this->Sums->grid().meanCosine(static_cast<int>(this->Range.u0), static_cast<int>(this->Range.v0),
    static_cast<int>(this->Range.u1), static_cast<int>(this->Range.v1), towardSender);
}

bool TerrainPatch::approximateShape() const
{
  return !(wholeCells(this->Range) && 2.0 * this->Range.width() * this->Range.height() <= exactTriangles);
}

double TerrainPatch::formFactorFrom(const Vec3& x, const Vec3& n) const
{
  if (this->approximateShape())
  {
    return PolygonElement::formFactorFrom(x, n);
  }
  // Far from the patch (beyond 8 bounding radii, where the exact sum differs from this
  // by about (r / d)^2 < 2 %): its area vector, plus a quarter of its unaligned area as
  // clusters count it, seen like a disc. The exact sum over up to 32 triangles was most
  // of the time of push on rough terrain.
  const Vec3 toPatch = this->Centre - x;
  const double d2 = glm::dot(toPatch, toPatch), radius = 0.5 * glm::length(this->High - this->Low);
  if (d2 > 64.0 * radius * radius)
  {
    const double d = std::sqrt(d2);
    const Vec3 dir = toPatch / d;
    const double cosine = glm::dot(n, dir);
    if (!(cosine > 0.0))
      return 0.0;
    const double aligned = this->Area - this->UnalignedArea;
    const double projected = std::max(0.0, -aligned * glm::dot(this->Normal, dir)) + 0.25 * this->UnalignedArea;
    return cosine * projected / (pi * d2 + projected);
  }
  double sum = 0.0;
  for (int j = static_cast<int>(this->Range.v0); j < this->Range.v1; ++j)
    for (int i = static_cast<int>(this->Range.u0); i < this->Range.u1; ++i)
    {
      for (const TerrainGrid::Triangle& triangle : this->Sums->grid().cellTriangles(i, j))
      {
        const Vec3 a = TerrainGrid::areaVector(triangle);
        const double length = glm::length(a);
        if (length > 0.0)
          sum += pointToPolygonFormFactor(x, n, triangle.data(), 3, a / length);
      }
    }
  return sum;
}

void TerrainPatch::bounds(Vec3& low, Vec3& high) const
{
  low = this->Low;
  high = this->High;
}
} // namespace terralux
