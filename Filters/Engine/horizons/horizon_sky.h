#pragma once
// The sky a height field hides from a point, from its horizon (r.horizon; Dozier &
// Marks 1987; HORAYZON): over a height field, a direction that is blocked blocks every
// lower direction of the same azimuth, so what the terrain hides in one azimuth is the
// sky between the point's lower bound (its plane's horizon or the world's) and the
// horizon elevation, found by bisection with occlusion rays or, at the posts of one
// terrain, read from the horizons found for all of them at once (horizon_map.h). That
// band is integrated exactly in elevation against the sky's cells. A final gather's
// cosine-weighted rays estimate the same hidden part with binomial noise (a post whose
// horizon hides 2 % of its sky gets a 1.7 % standard error from 64 rays); here only the
// azimuths are sampled, evenly, and the horizon between them is interpolated and
// integrated.
// Only for scenes that are height fields (terrains whose cells all face up, no
// polygons): under a roof or a tree crown the lower directions of an azimuth can be
// open again, and rays must sample them.

#include "base/angles.h"
#include "horizons/horizon_map.h"
#include "hierarchy/radiosity_types.h"
#include "terrain/view_sectors.h"

#include <array>
#include <cstdint>
#include <vector>

namespace terralux
{
class OpenSky;
class Visibility;

struct HiddenSky
{
  Spectrum irradiance{};           ///< W/m^2 the horizon hides from the point's plane
  double projectedSolidAngle = 0.0; ///< sr, of the hidden sky (the view factor's pi x its loss)
  int rays = 0;
  /// From a coarse map's horizons (16 azimuths), where asked: the sky between the
  /// horizon interpolated linearly between them and by a cubic through their
  /// neighbours, how far the interpolation may be off where the horizon bends between
  /// azimuths (W/m^2, and its projected solid angle, sr). Zero otherwise.
  Spectrum betweenAzimuths{};
  double betweenAzimuthsSolidAngle = 0.0;
  /// From a map's horizons: the projected solid angle (sr) of the void, HorizonSky::voidAt.
  double voidSolidAngle = 0.0;
};

class HorizonSky
{
public:
  /// Azimuths per point (evenly spaced, turned at random per point). A blocked azimuth's
  /// horizon is bisected until the band it may still lie in holds at most
  /// bandTolerance of the sector's share of the sky's projected solid angle (the band
  /// counts half: an error of at most half that, of either sign), or for
  /// maximumBisections steps (90 deg / 2^10: 0.09 deg).
  static constexpr int sectors = 32;
  /// Pieces between two sampled azimuths, over which the horizon is interpolated.
  static constexpr int piecesPerSector = 2;
  static constexpr double bandTolerance = 0.002;
  /// At a map's post, a sector whose horizons both stay this low (radians, 11.5 deg) is
  /// taken as one piece: its hidden band is thin and nearly linear (docs/tuning.md).
  static constexpr double lowSector = 0.2;
  static constexpr int maximumBisections = 10;

  /// `map`, where given, holds the horizons of the terrain's posts (may be null).
  HorizonSky(const Visibility& rays, const OpenSky& sky, const HorizonMap* map = nullptr);

  /// The sky hidden from a point (rays start there, lifted along the unit normal by
  /// the visibility's offset) on a plane of unit normal n; `seed` turns the azimuths.
  HiddenSky hiddenAt(const Vec3& point, const Vec3& normal, std::uint64_t seed) const;
  /// The sky hidden from a post of the map's terrain on a plane of unit normal n, from
  /// the map's horizons (no rays); with `betweenAzimuths`, from a coarse map, also the
  /// band between them (HiddenSky::betweenAzimuths).
  HiddenSky hiddenAt(const HorizonMap::Post& post, const Vec3& normal, bool betweenAzimuths = false) const;
  /// The share of a post's view (projected solid angle / pi) above its plane and below
  /// the horizontal whose directions leave the terrain without meeting it: where the
  /// terrain ahead falls away (the map's horizon lies below the horizontal) or ends.
  /// Neither sky nor terrain, it sends nothing: the post sees 1 - its sky view factor
  /// - this of terrain. The map's horizons interpolated over its sectors, as hiddenAt
  /// takes low ones (hiddenAt at a post gives it too, as HiddenSky::voidSolidAngle / pi).
  double voidAt(const HorizonMap::Post& post, const Vec3& normal) const;
  /// The projected solid angle (sr) of the terrain a post sees in each part of its
  /// view (view_sectors.h): toward each of the map's azimuths, between its plane and the
  /// map's true horizon (below the horizontal too), near up to the highest elevation of
  /// the terrain within nearViewPosts posts (HorizonMap::nearTangent) and beyond above
  /// it; each azimuth's wedge, half-way to its neighbours, in the sectors it lies in.
  /// Without `nearAndFar`, each sector's whole in its near part (no terrain walked).
  /// Which way and how far a post sees its terrain, for the lattice's reads
  /// (PostLattice::readByPart).
  PerViewPart<double> terrainByPart(const HorizonMap::Post& post, const Vec3& normal, bool nearAndFar = true) const;
  const HorizonMap* map() const { return this->Map; }

  struct SinCos
  {
    double sin, cos;
  };
  /// A map piece's sky, summed over the sky's columns it crosses: per row boundary the
  /// radiance-weighted terms from the horizon up (s, c: along-terms times the changes
  /// of sin and cos of the azimuth; w: up-terms times the widths) and the row's own
  /// radiance in those terms, for the part of a row. A band then costs its two ends.
  struct PieceRow
  {
    Spectrum s, c, w, rowS, rowC, rowW;
  };
  /// A piece of azimuth between two of the map's azimuths (piecesPerSector after each),
  /// over which the map's horizon is interpolated linearly, at its middle.
  struct MapPiece
  {
    double phi0, phi1; ///< radians counter-clockwise from +x
    SinCos start, end, middle;
    double dSin = 0.0, dCos = 0.0, width = 0.0; // over its sky columns
    std::vector<PieceRow> rows;                 // Side + 1
  };
  /// The map's pieces, azimuth by azimuth (empty without a map).
  const std::vector<MapPiece>& mapPieces() const { return this->MapTable.pieces; }
  using MapElevations = std::array<double, HorizonMap::maximumAzimuths>;
  /// A post's horizon at each of the map's azimuths as the hidden sky takes it: never
  /// below the lowest elevation whose sky can be hidden (the plane's own horizon or the
  /// world's); `rises`: whether terrain stands above that bound there; `falls`, where
  /// given: the horizon where below the horizontal, else 0 (HorizonMap::trueElevation).
  void mapHorizons(const HorizonMap::Post& post, const Vec3& normal, MapElevations& elevations,
    std::array<bool, HorizonMap::maximumAzimuths>& rises, MapElevations* falls = nullptr) const;

private:
  struct ElevationTerms
  {
    double along, up; // antiderivatives of cos^2 u and of sin u cos u
  };
  static ElevationTerms elevationTerms(double u, double sinU, double cosU);
  /// The lowest elevation toward azimuth a whose sky can be hidden: the plane's own
  /// horizon or the world's.
  static double lowerBound(const Vec3& normal, const SinCos& a);
  /// A sky azimuth cell clipped to a range: the changes of sin and cos of the azimuth
  /// over it (the cosine's terms across it), its width, its index.
  struct Column
  {
    double dSin, dCos, width;
    int iv;
  };
  int columnsOf(double phi0, double phi1, const SinCos& start, const SinCos& end, std::array<Column, 16>& columns) const;
  void hideBand(double phi0, double phi1, const SinCos& start, const SinCos& end, double u0, double u1, double share,
    const Vec3& normal, HiddenSky& result) const;
  ElevationTerms termsAt(double u) const; // from the table Terms
  /// The terms at any u in [-pi/2, pi/2] (along is odd, up even), by series near the
  /// horizontal.
  ElevationTerms lowTerms(double u) const;
  /// voidAt's projected solid angle (sr), from the map's horizons below the horizontal.
  double voidOf(const MapElevations& falls, const Vec3& normal) const;
  /// Entries of Terms; a multiple of every sky's cells per side (at most 2^10).
  static constexpr int fineTerms = 4096;
  static constexpr double termsPerRadian = fineTerms / (0.5 * pi);
  /// Where elevation u lies in Terms: the entry at or below it and the fraction of a
  /// step past it.
  struct TermsEntry
  {
    int k;
    double fraction;
  };
  static TermsEntry termsEntry(double u);

  /// Bands past the sky's own repeat its last: found once, at the end.
  void repeatLastBand(HiddenSky& result) const;
  const Visibility& Rays;
  const OpenSky& Sky;
  int Bands; // the sky's
  const HorizonMap* Map;
  int Side;                 // the sky's finest cells per parameter
  double RowsPerRadian = 0.0; // the sky's rows per radian of elevation
  double CellWidth = 0.0;   // radians of azimuth per cell
  double CellStart = 0.0;   // the first azimuth cell boundary
  int FirstColumn = 0;      // the sky's azimuth index of the cell before CellStart, + 1
  std::vector<ElevationTerms> Terms;         // at fineTerms + 1 elevations, 0 to pi / 2
  /// Column by column of the sky, the radiance-weighted elevation terms summed from the
  /// horizon up to each row boundary (Side + 1 per column): a band of any height costs
  /// its two ends, not a cell per row.
  struct RadianceTerms
  {
    Spectrum along, up;
  };
  std::vector<RadianceTerms> ColumnSums;
  RadianceTerms columnSumAt(int iv, double u, const ElevationTerms& terms) const;
  std::vector<SinCos> ColumnBoundaries;      // at each azimuth cell boundary
  std::vector<SinCos> PieceBoundaries, PieceMiddles; // of the pieces, before a point's turn
  void sumPiece(MapPiece& piece) const;
  void hidePiece(const MapPiece& piece, double u0, double u1, const Vec3& normal, HiddenSky& result) const;
  /// The same for a band `height` high about elevation u, from the piece's rate there.
  void hideThinBand(const MapPiece& piece, double u, double height, const Vec3& normal, HiddenSky& result) const;
  struct MapAzimuths
  {
    std::vector<SinCos> directions;
    std::vector<MapPiece> pieces; // piecesPerSector after each azimuth
    std::vector<MapPiece> sectors; // each azimuth to the next, whole
    /// Each azimuth's wedge, half-way to its neighbours: its halves' widths (radians)
    /// and the sectors of the view they lie in (terrainByPart).
    struct Wedge
    {
      double before, after;
      int sectorBefore, sectorAfter;
    };
    std::vector<Wedge> wedges;
  };
  MapAzimuths MapTable; // of the map's azimuths, where there is a map
};
} // namespace terralux
