#pragma once
// The cumulative sky (Robinson & Stone 2004): the radiance of every sky cell summed
// over the steps of a range, each weighted by its hours. Light transport is linear in
// the sources, so one solve under this sky gives the sum of the solves under each
// step's sky (Wh/m^2 instead of W/m^2).

#include "sky/sky_hierarchy.h"

#include <memory>
#include <vector>

namespace terralux
{
class CumulativeSky
{
public:
  /// Sums one-band skies of this finest level.
  explicit CumulativeSky(int finestLevel);
  /// Adds `model`, scaled to give diffuseHorizontalWm2 on a horizontal plane, for
  /// `hours`. Cell integrals take 3 x 3 Gauss points (as SkyHierarchy's) within 25
  /// degrees of `peak` (the sun: the circumsolar brightening) and the cell's centre
  /// elsewhere, where radiance varies slowly across a cell; a year of hourly skies
  /// costs seconds, not minutes. Rows of cells in parallel, summed in a fixed order.
  void add(const SkyModel& model, const Direction& peak, double diffuseHorizontalWm2, double hours);
  /// The sum as a sky hierarchy (radiance x hours, Wh/m^2/sr); null when nothing was added.
  std::unique_ptr<SkyHierarchy> hierarchy() const;
  int steps() const { return this->Steps; }

private:
  int Level;
  int Steps = 0;
  std::vector<double> Sums;      // finest cells, iu * side + iv
  std::vector<double> Integrals; // the current model's, same order
  std::vector<Direction> Centres; // each cell's centre (in s = sin u and v), same order
};
} // namespace terralux
