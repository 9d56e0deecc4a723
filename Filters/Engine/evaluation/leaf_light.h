#pragma once
// The sky and the light from surfaces at each leaf, gathered from the leaf itself.
//
// A final-gather ray's hit sends its reflectance times what its leaf receives. From the
// hierarchy, that is the sum of the links that reach the leaf, each bounded against a
// threshold: between the facing walls of an urban canyon the shaded wall received 60 %
// too little reflected light, the street 11 % too much sky, whatever the tolerance. A
// short gather from a few points of each leaf (rays of their own over the hierarchy's
// values) makes what a hit sends one bounce more exact, as PostSky and PostLattice do
// for the posts of a height field; its noise averages out over the many leaves one
// point's rays meet.
//
// What a leaf receives varies across it, most at a concave junction: the foot of a
// shaded wall receives a third of what its leaf does on average. So each leaf keeps a
// plane fitted to its points' values (least squares in the leaf's plane), read at the
// hit and kept within the range of those values, instead of one mean.

#include "hierarchy/radiosity_types.h"

#include <vector>

namespace terralux
{
class LeafLight
{
public:
  /// What one point of a leaf received.
  struct Sample
  {
    Vec3 point{ 0.0 };
    Spectrum sky{}, reflected{};
  };
  /// For a store of `elements` elements, of which `leaves` (ids) are gathered.
  LeafLight(std::size_t elements, const std::vector<std::uint64_t>& leaves);

  /// Records what the points of the k-th leaf of the constructor's list received (any
  /// thread, each leaf once; none: the leaf keeps the hierarchy's values).
  void set(std::size_t k, const Vec3& normal, const std::vector<Sample>& samples);
  /// What leaf `id` receives at `point` (of its plane); false for a leaf without values.
  bool at(std::uint64_t id, const Vec3& point, Spectrum& sky, Spectrum& reflected) const;
  /// Its mean over the leaf's points; false for a leaf without values.
  bool mean(std::uint64_t id, Spectrum& sky, Spectrum& reflected) const;

private:
  /// value(p) = mean + slope . (p - centre), within [low, high].
  struct Plane
  {
    Spectrum mean{}, low{}, high{};
    std::array<Vec3, maxBands> slope{};
    double at(int band, const Vec3& offset) const;
  };
  struct Fit
  {
    bool known = false;
    Vec3 centre{ 0.0 };
    Plane sky, reflected;
  };
  const Fit* fitOf(std::uint64_t id) const; // null: no values
  std::vector<std::int32_t> Slot; // by element id; -1: not gathered
  std::vector<Fit> Fits;
};
} // namespace terralux
