#pragma once
// A terrain as the engine sees it (paper section 4): a regular grid of nx x ny posts
// in 3-D with cells that may be missing (no data). Between posts the surface is two
// triangles per cell, split along the (i+1, j)-(i, j+1) diagonal as Embree's grid
// geometry splits its quads, so points sampled here lie exactly on what rays hit.
// Parameters (u, v) are continuous post coordinates: u in [0, nx-1], v in [0, ny-1].

#include "base/large_arrays.h"
#include "hierarchy/radiosity_types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace terralux
{
/// What a parameter range of the grid holds, summed over its whole cells.
struct TerrainRangeSummary
{
  double area = 0.0;          ///< true surface area of the valid cells, m^2
  Vec3 areaVector{ 0.0 };     ///< sum of area x unit normal over the triangles
  Vec3 low{ 0.0 }, high{ 0.0 }; ///< bounding box of the valid cells' posts
  std::size_t validCells = 0;
  std::size_t cells = 0;
  Spectrum reflectance{};     ///< area-weighted mean
  Spectrum emission{};        ///< area-weighted mean
};

/// A point on the terrain surface with the normal of the triangle it lies on.
struct TerrainPoint
{
  Vec3 position;
  Vec3 normal;
};

class TerrainGrid
{
public:
  /// Posts are set afterwards with setPost (from any thread, each post once); every
  /// cell starts valid. `origin`: positions are stored as floats relative to it.
  TerrainGrid(int nx, int ny, const Vec3& origin);

  int postsX() const { return this->Nx; }
  int postsY() const { return this->Ny; }
  int cellsX() const { return this->Nx - 1; }
  int cellsY() const { return this->Ny - 1; }
  const Vec3& origin() const { return this->Origin; }

  void setPost(int i, int j, const Vec3& position);
  Vec3 post(int i, int j) const;
  void setCellValid(int i, int j, bool valid) { this->Valid[this->cellIndex(i, j)] = valid; }
  bool cellValid(int i, int j) const { return this->Valid[this->cellIndex(i, j)] != 0; }
  /// Per-cell materials (optional; a uniform value otherwise).
  void setUniformMaterial(const Spectrum& reflectance, const Spectrum& emission);
  void setCellMaterial(int i, int j, const Spectrum& reflectance, const Spectrum& emission);
  Spectrum cellReflectance(int i, int j) const;
  /// Whether materials were set per cell (else every cell has the uniform ones).
  bool hasCellMaterials() const { return !this->CellReflectance.empty(); }
  Spectrum cellEmission(int i, int j) const;

  using Triangle = std::array<Vec3, 3>;
  /// The two triangles of cell (i, j), split as Embree splits its grids: lower
  /// (p00, p10, p01) and upper (p11, p01, p10), counter-clockwise seen from above. Every
  /// use of the cell's surface goes through here, so all agree with what rays hit.
  std::array<Triangle, 2> cellTriangles(int i, int j) const;
  /// The same split of any cell given its corners (a grid's points in double, before
  /// they become a TerrainGrid's floats).
  static std::array<Triangle, 2> cellTriangles(const Vec3& p00, const Vec3& p10, const Vec3& p01, const Vec3& p11)
  {
    const Vec3 p[4] = { p00, p10, p01, p11 };
    const auto& c = cellTriangleCorners;
    return { Triangle{ p[c[0][0]], p[c[0][1]], p[c[0][2]] }, Triangle{ p[c[1][0]], p[c[1][1]], p[c[1][2]] } };
  }
  /// That split as corner numbers, corner c = (i + c % 2, j + c / 2): for meshes that
  /// take a grid's cells as triangles of point ids.
  static constexpr std::array<std::array<int, 3>, 2> cellTriangleCorners{ { { 0, 1, 2 }, { 3, 2, 1 } } };
  /// Area x unit normal of a triangle.
  static Vec3 areaVector(const Triangle& t) { return 0.5 * glm::cross(t[1] - t[0], t[2] - t[0]); }

  /// The surface at parameter (u, v) inside a valid cell (clamped to the grid).
  TerrainPoint surfacePoint(double u, double v) const;
  /// The point of cell (i, j) at fractions (s, t) of its sides, on the triangle rays
  /// meet there (cellTriangles' split), relative to origin(): from the stored floats
  /// alone, for walks that take many.
  Vec3 onCellTriangles(int i, int j, double s, double t) const
  {
    auto corner = [&](int di, int dj) {
      const float* c = &this->Xyz[3 * this->postIndex(i + di, j + dj)];
      return Vec3(c[0], c[1], c[2]);
    };
    const Vec3 p10 = corner(1, 0), p01 = corner(0, 1);
    return s + t <= 1.0 ? corner(0, 0) + s * (p10 - corner(0, 0)) + t * (p01 - corner(0, 0))
                        : corner(1, 1) + (1.0 - s) * (p01 - corner(1, 1)) + (1.0 - t) * (p10 - corner(1, 1));
  }
  /// Area vector (area x unit normal) of cell (i, j): both triangles.
  Vec3 cellAreaVector(int i, int j) const;
  /// Sum over the whole cells of [i0, i1) x [j0, j1) (parallel for large ranges).
  TerrainRangeSummary summarize(int i0, int j0, int i1, int j1) const { return finished(this->sumCells(i0, j0, i1, j1)); }
  /// The same before its materials are divided by the area (area-weighted sums), so
  /// that sums of ranges join (TerrainBlockSums); `finished` divides them.
  TerrainRangeSummary sumCells(int i0, int j0, int i1, int j1) const;
  /// The sums of no cell (bounds inverted, so that any post widens them).
  static TerrainRangeSummary emptySum();
  static TerrainRangeSummary joined(TerrainRangeSummary a, const TerrainRangeSummary& b);
  static TerrainRangeSummary finished(TerrainRangeSummary sum);
  /// The bounding box of the valid cells' posts (as summarize's low and high, without
  /// its areas); false where no cell is valid.
  bool validBounds(Vec3& low, Vec3& high) const;
  /// Area-weighted mean of max(0, n . d) over the triangles of the whole cells of
  /// [i0, i1) x [j0, j1): the cosine factor of a rough surface toward direction d. Large
  /// ranges are estimated from at most about 64 x 64 evenly strided cells.
  double meanCosine(int i0, int j0, int i1, int j1, const Vec3& d) const;
  /// Area-weighted unit normal of the valid triangles around post (i, j) (+z if none).
  Vec3 postNormal(int i, int j) const;
  /// Horn's (1981) 3 x 3 normal at post (i, j), the convention of r.slope.aspect and
  /// gdaldem: tangents from the weighted (1, 2, 1) differences of the neighbouring rows
  /// and columns of posts (in 3-D, so curved and rotated grids are handled), normal =
  /// their cross product. Where a neighbour is missing (border, no data) the post's
  /// area-weighted normal instead.
  Vec3 hornNormal(int i, int j) const;
  /// The normal of post (i, j) by either convention (the outputs' choice, see the
  /// filter's PostNormals): Horn's where `horn`, the area-weighted one otherwise.
  Vec3 normalAt(int i, int j, bool horn) const { return horn ? this->hornNormal(i, j) : this->postNormal(i, j); }
  /// Whether post (i, j) lies inside the grid with all four cells around it valid.
  bool surroundedByCells(int i, int j) const;
  /// True when every triangle of the valid cells faces up (+z): the surface is then a
  /// height field over the ground plane, as a DEM is, and not a folded grid.
  bool facesUp() const;
  /// True when post (i, j) is a corner of a valid cell.
  bool postUsed(int i, int j) const;

  /// Whether `other` has the same posts and valid cells (materials aside): rays and
  /// horizons built on one hold for the other.
  bool sameSurface(const TerrainGrid& other) const
  {
    return this->Nx == other.Nx && this->Ny == other.Ny && this->Origin == other.Origin && this->Xyz == other.Xyz &&
      this->Valid == other.Valid;
  }

  /// Whether `other` has the same materials in every cell.
  bool sameMaterials(const TerrainGrid& other) const
  {
    return this->UniformReflectance == other.UniformReflectance && this->UniformEmission == other.UniformEmission &&
      this->CellReflectance == other.CellReflectance && this->CellEmission == other.CellEmission;
  }

  /// Float xyz relative to origin(), nx*ny posts row by row (i fastest), padded for
  /// Embree's 16-byte loads: share it with the ray tracer instead of copying.
  const float* vertices() const { return this->Xyz.data(); }

private:
  std::size_t cellIndex(int i, int j) const { return static_cast<std::size_t>(j) * (this->Nx - 1) + i; }
  std::size_t postIndex(int i, int j) const { return static_cast<std::size_t>(j) * this->Nx + i; }

  int Nx, Ny;
  Vec3 Origin;
  LargeVector<float> Xyz; // huge pages: 12 MB a 1025^2 grid
  std::vector<std::uint8_t> Valid;
  Spectrum UniformReflectance{};
  Spectrum UniformEmission{};
  std::vector<Spectrum> CellReflectance; // empty: uniform
  std::vector<Spectrum> CellEmission;
};
} // namespace terralux
