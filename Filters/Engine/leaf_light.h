#pragma once
// The sky and the light from surfaces at each leaf, gathered from the leaf itself.
//
// A final-gather ray's hit sends its reflectance times what its leaf receives. From the
// hierarchy, that is the sum of the links that reach the leaf, each bounded against a
// threshold: between the facing walls of an urban canyon the shaded wall received 60 %
// too little reflected light, the street 11 % too much sky, whatever the tolerance, and
// the posts of the street read those errors back as +-1.5 W/m^2 of reflected light (7 %)
// that more rays never lowered. A short gather from each leaf (rays of its own over the
// hierarchy's values) makes what a hit sends one bounce more exact, as PostSky and
// PostLattice do for the posts of a height field; its noise averages out over the many
// leaves one point's rays meet.

#include "radiosity_types.h"

#include <vector>

namespace terralux
{
class LeafLight
{
public:
  explicit LeafLight(std::size_t elements);

  /// Records what leaf `id` receives from the sky and from surfaces (any thread, each
  /// leaf once).
  void set(std::uint64_t id, const Spectrum& sky, const Spectrum& reflected);
  /// What it recorded for leaf `id`; false for a leaf it did not gather.
  bool at(std::uint64_t id, Spectrum& sky, Spectrum& reflected) const;

private:
  std::vector<Spectrum> Sky, Reflected;
  std::vector<std::uint8_t> Known;
};
} // namespace terralux
