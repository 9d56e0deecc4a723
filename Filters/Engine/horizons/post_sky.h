#pragma once
// The sky each post of a height-field terrain receives, found once from the horizons'
// map, and read between posts where a final gather's ray meets the terrain. What a hit
// sends is its reflectance times what it receives; taken from its leaf, the sky part is
// the leaf's average, and a leaf that holds a pit or the foot of a slope averages the
// open sky of its rims into the shadowed bottom (on a rough fractal DEM, posts in pits
// then gathered 2 to 4 times the reference's reflected light from their walls).
// Between posts the sky is interpolated bilinearly from the posts of the hit's cell.

#include "parallel/held_posts.h"
#include "horizons/horizon_map.h"
#include "hierarchy/radiosity_types.h"
#include "base/uninitialized_vector.h"

#include <algorithm>
#include <array>
#include <vector>

namespace terralux
{
class HorizonSky;
class OpenSky;
class TerrainGrid;
class WorkSplit;

class PostSky
{
public:
  /// Every used post of the map's terrain, on its normal (Horn's where `hornNormals`,
  /// the area-weighted one otherwise: the outputs' choice), in parallel; with `split`,
  /// each process its window's posts, then the others' it holds received: every post,
  /// or with a `halo` >= 0 (HeldPosts::haloFor a detail distance) those within it of
  /// its window.
  PostSky(const TerrainGrid& terrain, const HorizonSky& horizons, const OpenSky& sky, bool hornNormals = false,
    const WorkSplit* split = nullptr, int halo = -1);

  /// Finds again the skies of the posts of this process's window that `again` flags
  /// (one flag per post of the window, row by row: a refined map's exact posts), from
  /// `horizons`, and shares them as the constructor does (every process calls it).
  void findAgain(const std::vector<std::uint8_t>& again, const HorizonSky& horizons, const OpenSky& sky,
    bool hornNormals = false, const WorkSplit* split = nullptr);

  struct Value
  {
    Spectrum irradiance{};
    double skyViewFactor = 0.0;
    /// The open sky on the same plane (OpenSky::irradiance): its largest band and its
    /// projected solid angle, kept so that the sky's error (the share the horizons
    /// hide) needs no second evaluation of it, exact on small terrains.
    double openLargestBand = 0.0, openProjectedSolidAngle = 0.0;
    /// The share of the view that meets neither sky nor terrain (HorizonSky::voidAt).
    double voidViewFactor = 0.0;
    /// The share that meets terrain: where the light from surfaces comes from.
    double terrainSeen() const { return std::max(0.0, 1.0 - this->skyViewFactor - this->voidViewFactor); }
  };
  /// The sky a post receives on a plane of unit normal n: the open sky less what its
  /// horizon hides (as the final gather takes it at a post).
  static Value at(const HorizonMap::Post& post, const Vec3& normal, const HorizonSky& horizons, const OpenSky& sky);

  /// The sky found for a post, when `normal` is the one it was found on; false
  /// otherwise.
  bool found(const HorizonMap::Post& post, const Vec3& normal, Value& value) const;
  /// The sky found for post (i, j) and the normal it was found on (to 6e-8); false
  /// where this process holds none.
  bool foundAt(int i, int j, Value& value, Vec3& normal) const;

  /// The sky irradiance at grid parameters (u, v), between the used posts of its cell;
  /// false where the cell has none. Throws where this process does not hold them.
  bool interpolate(double u, double v, Spectrum& irradiance) const;

private:
  /// The skies of this process's window's posts (those `again` flags, where given),
  /// then the others' it holds from their processes.
  void findOwn(const HorizonSky& horizons, const OpenSky& sky, bool hornNormals, const WorkSplit* split,
    const std::vector<std::uint8_t>* again);
  const TerrainGrid& Terrain;
  HeldPosts Held;
  // Per held post, row by row: irradiance (its bands first), sky view factor, the open
  // sky's largest band and projected solid angle, the void, and the normal it was found on, each
  // written by a parallel loop or a share without a serial zeroing first (read only
  // where Used).
  static constexpr int skyViewSlot = maxBands, openBandSlot = maxBands + 1, openSolidAngleSlot = maxBands + 2,
                       voidSlot = maxBands + 3, normalSlot = maxBands + 4;
  static constexpr int valueSize = normalSlot + 3;
  static Value valueOf(const std::array<float, valueSize>& held);
  static Vec3 normalOf(const std::array<float, valueSize>& held);
  /// Post (i, j)'s held values; null where this process does not hold it or it is unused.
  const std::array<float, valueSize>* heldAt(int i, int j) const;
  UninitializedVector<std::array<float, valueSize>> Values;
  std::vector<std::uint8_t> Used;
};
} // namespace terralux
