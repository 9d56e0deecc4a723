#pragma once
// The horizon of every post of a height-field terrain grid toward 32 azimuths, found
// for all posts at once (a scene of one terrain: several grids would hide each other).
// Toward an azimuth whose step in the grid is a whole number of posts, g = (q, p)
// (slopes 0, 1/5, 2/5, 2/3, 1 and their mirrors: azimuths 10.5 to 11.9 deg apart on
// square cells), the posts lie on lines that repeat g, and the
// terrain along a line is linear between its crossings of cell edges and diagonals,
// whose pattern is the same on every step. Swept from its far end, a line keeps the
// upper convex hull of the crossings ahead; the horizon of each post is its tangent to
// that hull (Dozier, Bruno & Downey 1981; Stewart 1998 for the sectors): amortised
// constant work per crossing, a few per post and azimuth, instead of a search per post.
// The horizons are those of the grid's own triangles, as rays see them, at the post
// itself. Each line is placed by the grid's mean map from parameters to positions: on
// a grid bent by the Earth's curvature its azimuth is the mean one, to a small fraction
// of a degree.

#include "radiosity_types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace terralux
{
class TerrainGrid;

class HorizonMap
{
public:
  /// A grid whose cells all face up (TerrainGrid::facesUp), alone in its scene; it
  /// must outlive this.
  explicit HorizonMap(const TerrainGrid& terrain);
  static constexpr int azimuthCount = 32;
  /// Whether the map of `terrain` fits the 2 GiB it may take (64 bytes a post: grids up
  /// to about 5,800^2 posts); beyond, posts keep the rays' horizons.
  static bool fits(const TerrainGrid& terrain);

  /// A post of the grid.
  struct Post
  {
    bool found = false;
    std::size_t index = 0; ///< j * postsX + i
    explicit operator bool() const { return this->found; }
  };
  /// The post at `point` (within a hundredth of a cell), or none.
  Post find(const Vec3& point) const;

  /// The azimuths: radians counter-clockwise from +x, increasing, in [0, 2 pi).
  const std::vector<double>& azimuths() const { return this->Azimuths; }
  /// The horizon's elevation at a post toward azimuth a (radians, 0 where nothing
  /// rises above the horizontal), to 2.4e-5 rad.
  double elevation(const Post& post, int a) const;

  /// A direction between two of the map's azimuths: the one below it (k) and how far
  /// it lies from it and from the next (radians).
  struct Bearing
  {
    int k = 0;
    double fromBelow = 0.0, toAbove = 0.0;
  };
  Bearing bearing(double azimuth) const;
  /// What the horizon between the map's azimuths can be proven not to reach, by two
  /// bounds (Lipschitz, as horizon sectors are bounded; Stewart 1998):
  /// - terrain within the post's distance to the grid's edge, R: a point's elevation
  ///   seen from the post turns with the azimuth at most as fast as the steepest
  ///   triangle's slope S (d/da atan((z(r, a) - z0) / r) <= |grad z|), so the horizon
  ///   of those points at a lies below min(H_k + S da_k, H_k+1 + S da_k+1);
  /// - terrain farther: below atan((highest height - z0) / R).
  /// farBound is the second. R is the least distance from the post to the grid's edge
  /// between the azimuths k and k + 1 (the arcs of points nearer stay on the grid);
  /// without k, in any direction.
  double farBound(const Post& post, int k) const;
  double farBound(const Post& post) const;
  /// Whether the terrain's own triangles (what rays meet) leave the direction of
  /// `bearing` at `elevation` (radians) open from the post, proven by those bounds with
  /// a margin for the map's quantisation and mean directions; false where only a ray
  /// can tell. Only for grids without missing cells (holes have no such bound).
  bool clearlyAbove(const Post& post, const Bearing& bearing, double elevation, double farBound) const;
  /// Whether they hide that direction, proven from a mapped neighbour's horizon: the
  /// terrain point P that makes horizon H_k at azimuth k lies at some distance d, and
  /// the point Q at the same distance along the bearing is at most the chord
  /// d 2 sin(da / 2) from it, so no lower than S times that below it: Q rises above the
  /// post at least atan(tan H_k - 2 S sin(da / 2)), and a ray below Q's elevation meets
  /// the terrain before Q. Only where H_k is above farBound (so d < R and the arc from
  /// P to Q stays on the grid), with the same margin.
  bool clearlyBelow(const Post& post, const Bearing& bearing, double elevation, double farBound) const;
  /// Whether every cell of the grid is valid (clearlyAbove and clearlyBelow need it).
  bool complete() const { return this->Complete; }
  /// The steepest slope (tan) of the grid's triangles: S above.
  double steepestSlope() const { return this->SteepestSlope; }

private:
  void fitMeanMap();
  void sweep(int q, int p, int slot);

  const TerrainGrid& Terrain;
  /// The mean affine map from parameters to xy: x = X0 + Ux u + Vx v, and so on.
  double X0 = 0.0, Y0 = 0.0, Ux = 1.0, Uy = 0.0, Vx = 0.0, Vy = 1.0;
  bool Complete = true; ///< no missing cells (from fitMeanMap)
  double SteepestSlope = 0.0, HighestZ = 0.0; // of the valid cells
  // Toward the edges u = 0, u = max, v = 0, v = max: the azimuth of the shortest way.
  std::array<double, 4> EdgeAzimuths{};
  double edgeDistance(int i, int j, int edge) const;
  /// Distance from post (i, j) to the grid's edge along map azimuth k.
  double exitDistance(int i, int j, int k) const;
  double farBoundAt(int i, int j, double distance) const;
  void measureRelief();
  /// What clearlyAbove and clearlyBelow allow for the map's quantisation and mean directions.
  double proofMargin() const { return 1e-3 + 2e-3 * this->SteepestSlope; }
  std::vector<double> Azimuths;
  /// A metre along each azimuth in grid parameters (the mean map inverted).
  std::vector<std::array<double, 2>> AzimuthSteps;
  /// Azimuth by azimuth, each azimuth's posts in order; elevation / (pi / 2) x 65535.
  std::vector<std::uint16_t> Elevations;
};
} // namespace terralux
