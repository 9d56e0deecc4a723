#pragma once
// The hierarchical sky of paper section 5.1: a quadtree over the hemisphere in
// altitude u in [0, pi/2] and azimuth v in [0, 2 pi) (measured westward from
// south, the paper's parameter), with a pyramid of cell-averaged radiances.
// Level k has 2^k x 2^k cells. Below the finest level radiance is subsampled
// (bilinear between finest-level averages).
//   Solid angle of [u0,u1] x [v0,v1]:  Omega = (v1 - v0)(sin u1 - sin u0)
//   Irradiance from a patch:           dE = R S Omega L

#include "sky/sky_model.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace terralux
{
/// An optional multiplier of the sky radiance over (compass azimuth, altitude):
/// clouds or colour. values[(j * width + i) * components + band] is the sample at
/// azimuth 360 i / (width - 1) degrees and altitude 90 j / (height - 1) degrees.
struct SkyTexture
{
  int width = 0;
  int height = 0;
  int components = 1; ///< 1 or 3
  std::vector<double> values;

  /// Bilinear sample; azimuth wraps, altitude is clamped.
  double sample(double compassAzimuthRad, double altitudeRad, int band) const;
};

/// One patch of the sky quadtree: level and cell indices (iu along altitude from the
/// horizon, iv along v from south).
struct SkyPatch
{
  int level = 0;
  int iu = 0;
  int iv = 0;

  double u0() const;
  double u1() const;
  double v0() const;
  double v1() const;
  /// Omega = (v1 - v0)(sin u1 - sin u0), steradians.
  double solidAngle() const;
  /// Vector solid angle: the integral of the unit direction d dOmega over the patch, in
  /// closed form; n . it is the patch's projected solid angle for a plane of normal n
  /// that sees all of the patch.
  Direction vectorSolidAngle() const;
  /// Unit ENU vector toward the patch centre (mid altitude, mid azimuth).
  Direction direction() const;
  /// The four children at level + 1.
  void children(SkyPatch out[4]) const;
};

/// Unit ENU vector toward altitude u and azimuth v (westward from south), radians.
Direction directionFromSkyParameters(double u, double v);

/// The sky map users see (vtkSkySource's radiance image and dome): at a level, n = 2^level
/// columns of compass azimuth (clockwise from north) by n rows of altitude. The pyramid
/// cell at map column i, row j (the pyramid's azimuth runs westward from south).
SkyPatch skyMapCell(int level, int i, int j);
/// Unit ENU vector toward corner (i, j) of the map: compass azimuth 360 i / n degrees,
/// altitude 90 j / n degrees (i, j in [0, n]).
Direction skyMapCorner(int level, int i, int j);

/// Calls f(direction, weight, s, u, v) at the 3 x 3 Gauss-Legendre points of a cell over
/// (s = sin u, v), where dOmega = ds dv: the weights sum to the cell's solid angle, and
/// the rule is exact for radiance polynomial of degree 5 in s and v.
template <class F>
void forCellGaussPoints(const SkyPatch& cell, F&& f)
{
  constexpr double nodes[3] = { -0.7745966692414834, 0.0, 0.7745966692414834 };
  constexpr double weights[3] = { 5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0 };
  const double s0 = std::sin(cell.u0()), s1 = std::sin(cell.u1()), v0 = cell.v0(), v1 = cell.v1();
  // The points' directions as directionFromSkyParameters gives them, from one sine and
  // cosine per altitude and per azimuth rather than one of each per point.
  double v[3], sinV[3], cosV[3];
  for (int b = 0; b < 3; ++b)
  {
    v[b] = 0.5 * (v0 + v1) + 0.5 * (v1 - v0) * nodes[b];
    sinV[b] = std::sin(v[b]);
    cosV[b] = std::cos(v[b]);
  }
  for (int a = 0; a < 3; ++a)
  {
    const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * nodes[a];
    const double u = std::asin(std::min(1.0, std::max(0.0, s)));
    const double sinU = std::sin(u), cosU = std::cos(u);
    for (int b = 0; b < 3; ++b)
      f(Direction{ -sinV[b] * cosU, -cosV[b] * cosU, sinU }, 0.25 * (s1 - s0) * (v1 - v0) * weights[a] * weights[b], s,
        u, v[b]);
  }
}

/// dE = R S Omega L: receiver factor R (cosine for a surface, 1 for a cluster) and
/// scale factor S (1 for a surface, 1/4 for a cluster), paper sections 3 and 5.1.
inline double skyIrradianceContribution(
  double receiverFactor, double scaleFactor, double solidAngle, double radiance)
{
  return receiverFactor * scaleFactor * solidAngle * radiance;
}

class SkyHierarchy
{
public:
  /// Samples `model` into 2^finestLevel x 2^finestLevel cell averages (Gauss-Legendre
  /// quadrature inside each cell, so peaks are integrated, not point-sampled), scaled
  /// so that the untextured sky gives diffuseHorizontalWm2 on a horizontal plane, then
  /// multiplied by the texture if one is given (bands = its components).
  /// Throws Error for finestLevel outside 1..10 or a negative or non-finite irradiance.
  SkyHierarchy(const SkyModel& model, double diffuseHorizontalWm2, int finestLevel,
    const SkyTexture* texture = nullptr);

  /// A hierarchy over given finest-level cell averages (W/m^2/sr), e.g. a radiance map
  /// read back from vtkSkySource: averages[(iu * side + iv) * bands + band] with
  /// side = 2^finestLevel. Throws Error on a size mismatch or a negative value.
  static SkyHierarchy fromCellAverages(int finestLevel, int bands, const std::vector<double>& averages);

  int finestLevel() const { return this->FinestLevel; }
  int bands() const { return this->Bands; }
  /// Cells per side at a level.
  static int cellsPerSide(int level) { return 1 << level; }

  /// Cell-averaged radiance (W/m^2/sr) of a patch; below the finest level, subsampled.
  double radiance(const SkyPatch& patch, int band) const;
  /// Irradiance vector of a patch: the integral of L d dOmega (W/m^2), summed up the
  /// pyramid from the finest cells (radiance constant in each), so n . it is the exact
  /// irradiance the patch gives a plane of normal n that sees all of it, at every level
  /// (mean radiance x projected solid angle is not, where radiance varies with
  /// altitude). Below the finest level: the subsampled radiance x vectorSolidAngle().
  Direction irradianceVector(const SkyPatch& patch, int band) const;
  /// Radiance scale: W/m^2/sr per unit of the model's relative radiance.
  double radianceScale() const { return this->Scale; }
  /// Irradiance on a horizontal plane from the whole sky (W/m^2), per band.
  double horizontalIrradiance(int band) const { return this->Horizontal[band]; }

  /// Irradiance on a plane with unit normal `normal` from all patches of a level:
  /// sum of R S Omega L with R = max(0, n . d) at each patch centre, S = 1.
  double planeIrradiance(const Direction& normal, int level, int band) const;

private:
  SkyHierarchy(int finestLevel, int bands);
  void buildPyramid();
  double finestAverage(int iu, int iv, int band) const;

  int FinestLevel;
  int Bands;
  double Scale = 0.0;
  std::vector<double> Horizontal;
  std::vector<std::vector<double>> Pyramid; // [level][(iu * side + iv) * bands + band]
  std::vector<std::vector<double>> VectorPyramid; // [level][((iu * side + iv) * bands + band) * 3 + axis]
};
} // namespace terralux
