#pragma once
// Terrain patch H-element (paper section 4.2): a parameter range of a TerrainGrid,
// approximated for form factors by the quad of its four corner posts but with the true
// area, mean normal and bounds of the cells it covers. Splitting uses finer posts
// (halving the range at a post); below one cell it goes on as a regular quadtree in
// parameter space with corners on the cell's triangles. Samples, and so visibility,
// always lie on the full-resolution surface, never on the coarse quad.
//
// Ranges holding missing cells are structural only: they split at construction until
// each part is complete or empty, and never take part in the solution.

#include "hierarchy/polygon_element.h"
#include "terrain/terrain_block_sums.h"
#include "terrain/terrain_grid.h"

#include <memory>

namespace terralux
{
/// A rectangle of the grid's parameter space, in post units.
struct ParameterRange
{
  double u0 = 0.0, v0 = 0.0, u1 = 0.0, v1 = 0.0;
  double width() const { return this->u1 - this->u0; }
  double height() const { return this->v1 - this->v0; }
  bool contains(double u, double v) const { return u >= this->u0 && u <= this->u1 && v >= this->v0 && v <= this->v1; }
};

class TerrainPatch : public PolygonElement
{
public:
  /// The tree over a grid: its root (null when no cell is valid) and, in `complete`,
  /// the largest patches without missing cells, which are what the solver works on.
  static TerrainPatch* buildTree(ElementStore& store, const TerrainGrid& grid, int terrainIndex,
    std::vector<TerrainPatch*>& complete);

  /// A patch of the grid whose block sums `sums` holds (shared by the tree's patches).
  TerrainPatch(std::uint64_t id, int level, ElementStore* store, std::shared_ptr<const TerrainBlockSums> sums,
    const ParameterRange& range, const TerrainRangeSummary& summary, TerrainPatch* up, int terrainIndex);

  const ParameterRange& range() const { return this->Range; }
  /// The patch whose range holds this one (null for the root of the grid).
  TerrainPatch* up() const { return this->Up; }
  /// Children that exist now, without creating any.
  const std::vector<HElement*>& existingChildren() const { return this->Children; }
  /// The leaf below this patch whose closed range holds parameter (u, v) (the first one
  /// found on shared borders), or null: outside the range, or in a hole.
  const TerrainPatch* leafHolding(double u, double v) const;
  /// Of the leaves that touch post (i, j) (those of the up to four cells around it),
  /// the one that receives the most light once solved: a post where the ground runs
  /// under a building takes the value seen from the open side, as points on polygons
  /// do. Null when no cell around it is valid.
  const TerrainPatch* mostLitLeafAt(int i, int j) const;
  /// False for structural patches that hold missing cells.
  bool complete() const { return this->Complete; }
  int terrain() const { return this->TerrainIndex; }
  const TerrainGrid& grid() const { return this->Sums->grid(); }

  const std::vector<HElement*>& children() override;
  bool canSplit() const override;
  SurfaceSample sample(int k, int n, SampleGenerator& random) const override;
  void bounds(Vec3& low, Vec3& high) const override;
  bool childrenShareNormal() const override { return false; }
  /// The mean cosine of the cells toward the sender, not the cosine of the mean normal:
  /// a patch facing away on average may hold slopes that face the sender.
  double receiverFactor(const Vec3& towardSender) const override;
  /// Over the true triangles for patches of up to exactTriangles / 2 cells (near a
  /// point the coarse quad can be far from the surface); the coarse quad beyond.
  double formFactorFrom(const Vec3& x, const Vec3& n) const override;
  static constexpr int exactTriangles = 32;
  /// True unless form factors to this patch use its true triangles.
  bool approximateShape() const override;
  /// More than one cell: its children use finer posts.
  bool refinesGeometry() const override { return this->Range.width() * this->Range.height() > 1.0; }


  /// The child ranges of a range: halved at a post along each side longer than one cell;
  /// a single cell or less is halved along both sides.
  static std::vector<ParameterRange> splitRange(const ParameterRange& range);

private:
  static TerrainPatch* buildNode(ElementStore& store, const std::shared_ptr<const TerrainBlockSums>& sums,
    int terrainIndex, const ParameterRange& range, TerrainPatch* up, int level, std::vector<TerrainPatch*>& complete);

  std::shared_ptr<const TerrainBlockSums> Sums; // and through it the grid
  ParameterRange Range;
  TerrainPatch* Up;
  int TerrainIndex;
  bool Complete = true;
  Vec3 Low{ 0.0 }, High{ 0.0 };
};
} // namespace terralux
