#pragma once
// Geometry of a link, computed once when the link is made: the transport kernel
// (form factor for surfaces, R S Omega for sky patches, R S for the sun) and the
// visibility fraction from stratified, jittered rays seeded by the two element ids.
// External sources compute their own transport (paper section 5.3).

#include "emitters/external_source.h"
#include "hierarchy/helement.h"
#include "visibility/visibility.h"

namespace terralux
{
class Visibility;

/// Category of light a sender contributes.
int lightCategoryOf(const HElement& sender);

/// What transport (kernel x visibility) from a sky patch to a surface of unit normal n
/// adds to its sky view factor: the geometric share of it, over pi; 0 for other senders.
double skyViewOf(const HElement& sender, const Vec3& normal, double transport);

class PolygonElement;

/// Kernel of a surface or cluster sender at a surface receiver: the form factor
/// averaged over five points of the receiver (polygon senders) or the isotropic
/// cluster estimate; `spread` gets the variation over those points.
double surfaceKernel(const PolygonElement& receiver, const HElement& sender, double* spread = nullptr);

/// Kernel of any sender at a surface receiver, from the receiver's own geometry:
/// R for the sun, the projected solid angle for a sky patch, surfaceKernel otherwise.
double kernelAtSurface(const PolygonElement& receiver, HElement& sender);

/// Visibility fraction of `sender` from `receiver`: stratified, jittered rays seeded by
/// the two ids (directions jittered inside a sky patch, so partial sky occlusion is
/// sampled). A link's visibility and its re-sampling at a leaf both come from here.
double sampledVisibility(HElement& receiver, HElement& sender, const Visibility& visibility, int samples);

/// Transport kernel x visibility from `sender` to a point with a unit normal: the exact point form factor (or R for the sun, the projected solid angle
/// for a sky patch) and visibility sampled from that point (samples = 0: taken as
/// unoccluded, no rays). `seed` makes it repeatable.
double transportToPoint(const Vec3& point, const Vec3& normal, HElement& sender,
  const Visibility& visibility, int samples, std::uint64_t seed);

/// Suns already known seen or hidden from a point (bit s: suns[s]), which take no ray.
struct SunsProven
{
  unsigned seen = 0, hidden = 0;
  /// Whether sun s (of the suns in order) is proven seen, or hidden; suns past the
  /// mask's bits are proven neither.
  bool seenAt(std::size_t s) const { return s < 32 && (this->seen >> s & 1u); }
  bool hiddenAt(std::size_t s) const { return s < 32 && (this->hidden >> s & 1u); }
};

/// Direct sunlight at a point with a unit normal from every sun: normal irradiance x
/// cosine where one ray from just above the point reaches the sun (or `proven` says it
/// is seen), else 0. With `sunlitHours`, also the durations of the suns that reach the
/// point (sunshine).
Spectrum directSunlight(const Vec3& point, const Vec3& normal, const std::vector<HElement*>& suns,
  const Visibility& visibility, double* sunlitHours = nullptr, const SunsProven& proven = {});
/// One sun's part of that: `transport` (its kernel where it is seen, else 0) x its flux,
/// and its duration where it is seen.
inline void addSunlight(double transport, const Spectrum& flux, double duration, Spectrum& result, double* sunlitHours)
{
  for (int band = 0; band < maxBands; ++band)
    result[band] += transport * flux[band];
  if (sunlitHours && transport > 0.0)
    *sunlitHours += duration;
}

/// Kernel, visibility and direction of the link receiver <- sender.
Link evaluateLink(HElement& receiver, HElement& sender, const Visibility& visibility, int samples);
} // namespace terralux
