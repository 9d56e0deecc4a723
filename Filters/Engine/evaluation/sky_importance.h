#pragma once
// Directions drawn in proportion to the sky's radiance, for the sky a point does not
// see where the scene is not a height field (buildings, vegetation). Cosine-weighted
// rays find that hidden sky with the noise of the sky's contrast: under a clear sky
// the few degrees around the sun are twenty times brighter than the rest, so a house
// that hides them from a post is seen by one ray of 64, or none (posts 10 % off
// either way). Drawn by radiance (the sky map's cells by radiance x solid angle, then
// uniformly in solid angle inside the cell, Pharr, Jakob & Humphreys, PBR 4th ed.
// 13.6.7), every direction carries the same share of the sky's flux, so what a point
// does not see is estimated with the noise of a fraction only.

#include "hierarchy/radiosity_types.h"

#include <vector>

namespace terralux
{
class OpenSky;

class SkyImportance
{
public:
  explicit SkyImportance(const OpenSky& sky);

  struct Sample
  {
    Vec3 direction{ 0.0, 0.0, 1.0 };
    /// Per band, the sky's radiance toward `direction` over the density of drawing
    /// it (W/m^2): the mean of weight x max(0, n . d) over the samples a plane of
    /// normal n does not see is the irradiance it misses.
    Spectrum weight{};
    /// One over the density of drawing `direction` (sr): the same mean with this
    /// weight is the projected solid angle the plane does not see.
    double solidAngleWeight = 0.0;
  };
  /// The direction for the point (s, t) of the unit square (stratified points give
  /// stratified directions). False when the sky is black.
  bool sample(double s, double t, Sample& out) const;

private:
  const OpenSky& Sky;
  int Side = 0;
  double CellWidth = 0.0;          // radians of azimuth per cell
  std::vector<double> RowSines;    // sin u at each altitude boundary, Side + 1 values
  double Flux = 0.0;              // sum of radiance x solid angle over the cells (largest band)
  std::vector<double> Rows;       // cumulative flux of the altitude rows, Side + 1 values
  std::vector<double> Columns;    // per row, cumulative flux of its cells, Side + 1 values each
};
} // namespace terralux
