#pragma once
// The cumulative sky (Robinson & Stone 2004): the radiance of every sky cell summed
// over the steps of a range, each weighted by its hours. Light transport is linear in
// the sources, so one solve under this sky gives the sum of the solves under each
// step's sky (Wh/m^2 instead of W/m^2).

#include "sky_hierarchy.h"

#include <memory>
#include <vector>

namespace terralux
{
class CumulativeSky
{
public:
  /// Sums skies of this finest level and number of bands.
  CumulativeSky(int finestLevel, int bands);
  /// Adds `sky` (same level and bands) for `hours`. Throws Error on a mismatch.
  void add(const SkyHierarchy& sky, double hours);
  /// The sum as a sky hierarchy (radiance x hours, Wh/m^2/sr); null when nothing was added.
  std::unique_ptr<SkyHierarchy> hierarchy() const;
  int steps() const { return this->Steps; }

private:
  int Level;
  int Bands;
  int Steps = 0;
  std::vector<double> Sums; // finest cells, (iu * side + iv) * bands + band
};
} // namespace terralux
