#pragma once
// The sky a plane would receive with nothing in the way, exact for any normal, and the
// sky's radiance toward a direction: what a final gather needs to take the sky at a
// point as "open sky minus what the scene hides" (a control variate: the rays then only
// estimate the hidden part, which is 0 on open ground and small on most slopes).

#include "emitters/sky_patch_element.h"
#include "hierarchy/radiosity_types.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace terralux
{
class SkyHierarchy;

class OpenSky
{
public:
  explicit OpenSky(const SkyHierarchy& sky);
  ~OpenSky();

  /// Irradiance on an unobstructed plane of unit normal n, per band, and the projected
  /// solid angle of the sky above both the plane and the horizon (pi x the sky view
  /// factor of an open plane): patches wholly in front of the plane exactly through
  /// their irradiance vectors, those its horizon crosses split (to level 3 at least, on
  /// toward the sky map's finest level, at most 5, while one gives anything) and
  /// integrated exactly in solid angle there.
  /// With a table (tabulate), normals above the horizon are read from it instead.
  void irradiance(const Vec3& n, Spectrum& irradiance, double& projectedSolidAngle) const;
  /// Tabulates irradiance() over the upper hemisphere of normals (an octahedral map of
  /// (side + 1)^2 vertices, read bilinearly): the open sky as a function of the normal
  /// is smooth (a radiance integrated against a clamped cosine), so at side 128 the
  /// table is within about 1e-5 of the exact value, for a few look-ups instead of a
  /// recursion over the sky. Worth it for many points (a terrain of a million posts).
  /// Each vertex is computed when first read, by one thread, exactly: a terrain's
  /// normals fill part of the hemisphere, and the values never depend on the order.
  void tabulate(int side);
  /// Radiance (W/m^2/sr) of the finest sky cell holding unit direction d; 0 below the horizon.
  Spectrum radiance(const Vec3& d) const;
  /// Cells of the finest sky level across each of its parameters: altitude u in
  /// [0, pi / 2] and azimuth v (west from south) in [0, 2 pi), so that radiance() is
  /// constant over cells of (pi / 2) / cellsPerSide() by 2 pi / cellsPerSide().
  int cellsPerSide() const { return this->Side; }
  /// The sky's own bands; the bands past them repeat its last (Spectrum has maxBands).
  int bands() const { return this->Bands; }
  /// Radiance (W/m^2/sr) of finest cell (iu, iv), iu from the horizon, iv from the south.
  const Spectrum& cellRadiance(int iu, int iv) const
  {
    return this->Finest[static_cast<std::size_t>(iu) * this->cellsPerSide() + iv];
  }

private:
  void exactIrradiance(const Vec3& n, Spectrum& irradiance, double& projectedSolidAngle) const;
  void accumulate(int level, int iu, int iv, const Vec3& n, const SkyPatchElement::PlaneTerms& plane, Spectrum& e,
    double& omega) const;

  int Deepest = 0;
  std::vector<std::vector<std::unique_ptr<SkyPatchElement>>> Levels; // [level][iu * side + iv]
  std::vector<std::vector<double>> Radii; // the same: largest |d - centre| over each patch
  int Side = 0;                 // the finest level's cells per parameter
  int Bands = 1;
  std::vector<Spectrum> Finest; // their radiance, row by row of altitude
  /// Vertex (row, column) of the table, computed if it is not yet.
  const double* tableVertex(int row, int column) const;

  int TableSide = 0;
  mutable std::vector<double> Table; // per vertex: the bands' irradiance, then the projected solid angle
  mutable std::unique_ptr<std::atomic<std::uint8_t>[]> TableState; // per vertex: see tableVertex
};
} // namespace terralux
