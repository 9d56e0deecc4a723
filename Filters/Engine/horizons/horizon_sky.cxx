#include "horizons/horizon_sky.h"

#include "base/angles.h"
#include "horizons/horizon_lines.h"
#include "horizons/horizon_map.h"
#include "evaluation/open_sky.h"
#include "visibility/sampling.h"
#include "visibility/visibility.h"

#include <algorithm>
#include <array>
#include <cmath>

// Directions are d(u, phi) = cos u (cos phi, sin phi, 0) + sin u (0, 0, 1), u the
// elevation. Toward a plane of unit normal n, n . d = cos u (nx cos phi + ny sin phi) +
// sin u nz, so the projected solid angle of the sky between elevations u0, u1 and
// azimuths phi0, phi1, the integral of (n . d) cos u du dphi, separates:
//   [across(phi1) - across(phi0)] [along(u1) - along(u0)] + nz (phi1 - phi0) [up(u1) - up(u0)]
// with across = nx sin phi - ny cos phi, along = u / 2 + sin u cos u / 2 (of cos^2 u) and
// up = sin^2 u / 2 (of sin u cos u). The sines and cosines of the sky's cell boundaries
// and of the sectors' pieces are tabulated once: they are most of the work otherwise.
namespace terralux
{
HorizonSky::ElevationTerms HorizonSky::elevationTerms(double u, double sinU, double cosU)
{
  return { 0.5 * u + 0.5 * sinU * cosU, 0.5 * sinU * sinU };
}

HorizonSky::HorizonSky(const Visibility& rays, const OpenSky& sky, const HorizonMap* map)
  : Rays(rays)
  , Sky(sky)
  , Bands(sky.bands())
  , Map(map)
  , Side(sky.cellsPerSide())
{
  this->RowsPerRadian = this->Side / (0.5 * pi);
  this->CellWidth = 2.0 * pi / this->Side;
  // Azimuth cell boundaries sit at CellStart + m CellWidth (the sky's azimuth v runs
  // west from south: v = 3 pi / 2 - phi); the cell between boundaries m and m + 1 has
  // v index FirstColumn - m - 1 (mod Side).
  this->CellStart = std::fmod(1.5 * pi, this->CellWidth);
  this->FirstColumn = static_cast<int>(std::lround((1.5 * pi - this->CellStart) / this->CellWidth));
  for (int k = 0; k <= fineTerms; ++k)
  {
    const double u = k * 0.5 * pi / fineTerms;
    this->Terms.push_back(elevationTerms(u, std::sin(u), std::cos(u)));
  }
  this->ColumnSums.resize(static_cast<std::size_t>(this->Side) * (this->Side + 1));
  for (int iv = 0; iv < this->Side; ++iv)
  {
    RadianceTerms sum{};
    RadianceTerms* column = &this->ColumnSums[static_cast<std::size_t>(iv) * (this->Side + 1)];
    column[0] = sum;
    for (int row = 0; row < this->Side; ++row)
    {
      const ElevationTerms& low = this->Terms[row * (fineTerms / this->Side)];
      const ElevationTerms& high = this->Terms[(row + 1) * (fineTerms / this->Side)];
      const Spectrum& l = sky.cellRadiance(row, iv);
      for (int band = 0; band < maxBands; ++band)
      {
        sum.along[band] += l[band] * (high.along - low.along);
        sum.up[band] += l[band] * (high.up - low.up);
      }
      column[row + 1] = sum;
    }
  }
  for (int m = 0; m < this->Side; ++m)
  {
    const double phi = this->CellStart + m * this->CellWidth;
    this->ColumnBoundaries.push_back({ std::sin(phi), std::cos(phi) });
  }
  const double piece = 2.0 * pi / (sectors * piecesPerSector);
  for (int p = 0; p <= sectors * piecesPerSector; ++p)
  {
    this->PieceBoundaries.push_back({ std::sin(p * piece), std::cos(p * piece) });
    this->PieceMiddles.push_back({ std::sin((p + 0.5) * piece), std::cos((p + 0.5) * piece) });
  }
  auto sinCos = [](double phi) { return SinCos{ std::sin(phi), std::cos(phi) }; };
  if (map)
  {
    MapAzimuths& table = this->MapTable;
    const std::vector<double>& azimuths = map->azimuths();
    for (std::size_t a = 0; a < azimuths.size(); ++a)
    {
      table.directions.push_back(sinCos(azimuths[a]));
      const double from = azimuths[a];
      const double to = a + 1 < azimuths.size() ? azimuths[a + 1] : azimuths[0] + 2.0 * pi;
      const double width = (to - from) / piecesPerSector;
      for (int j = 0; j < piecesPerSector; ++j)
      {
        const double phi0 = from + j * width;
        MapPiece mapPiece{ phi0, phi0 + width, sinCos(phi0), sinCos(phi0 + width), sinCos(phi0 + 0.5 * width), 0.0, 0.0, 0.0, {} };
        this->sumPiece(mapPiece);
        table.pieces.push_back(std::move(mapPiece));
      }
      MapPiece sector{ from, to, sinCos(from), sinCos(to), sinCos(0.5 * (from + to)), 0.0, 0.0, 0.0, {} };
      this->sumPiece(sector);
      table.sectors.push_back(std::move(sector));
    }
    const std::size_t count = table.sectors.size();
    for (std::size_t a = 0; a < count; ++a)
    {
      const MapPiece& before = table.sectors[(a + count - 1) % count];
      const MapPiece& after = table.sectors[a];
      table.wedges.push_back({ 0.5 * (before.phi1 - before.phi0), 0.5 * (after.phi1 - after.phi0),
        sectorOf(before.middle.cos, before.middle.sin), sectorOf(after.middle.cos, after.middle.sin) });
    }
  }
}

HorizonSky::ElevationTerms HorizonSky::termsAt(double u) const
{
  // Linear between the table's entries: within 1e-7 of the exact terms (they are
  // smooth, their second derivatives at most 1), for a lookup instead of a sine. Half
  // of a post's pieces start at the horizontal (its plane faces them): both terms 0.
  if (!(u > 0.0))
    return { 0.0, 0.0 };
  const auto [k, f] = termsEntry(u);
  const ElevationTerms& a = this->Terms[k];
  const ElevationTerms& b = this->Terms[k + 1];
  return { a.along + f * (b.along - a.along), a.up + f * (b.up - a.up) };
}

HorizonSky::TermsEntry HorizonSky::termsEntry(double u)
{
  const double x = std::clamp(u * termsPerRadian, 0.0, static_cast<double>(fineTerms));
  const int k = std::min(static_cast<int>(x), fineTerms - 1);
  return { k, x - k };
}

HiddenSky HorizonSky::hiddenAt(const Vec3& point, const Vec3& normal, std::uint64_t seed) const
{
  HiddenSky result;
  constexpr int azimuths = sectors, pieces = piecesPerSector;
  const double halfPi = 0.5 * pi, sector = 2.0 * pi / azimuths, piece = sector / pieces;
  // Evenly spaced azimuths, turned by a random angle per point so that neighbouring
  // posts' small errors do not line up.
  const double turn = sector * SampleGenerator(seed).uniform();
  const SinCos turned{ std::sin(turn), std::cos(turn) };
  auto rotate = [&](const SinCos& a) {
    return SinCos{ turned.sin * a.cos + turned.cos * a.sin, turned.cos * a.cos - turned.sin * a.sin };
  };
  auto lowerAt = [&](const SinCos& a) { return lowerBound(normal, a); };

  // Each sampled azimuth's horizon lies between the highest elevation found blocked and
  // the lowest found open (both the lower bound where that is open).
  struct Horizon
  {
    double blocked, open;
  };
  std::array<Horizon, sectors> horizons; // the first `azimuths` used
  // The search starts at the previous azimuth's horizon: neighbouring azimuths have
  // similar horizons, so a few rays bracket the new one.
  double previous = -1.0;
  for (int k = 0; k < azimuths; ++k)
  {
    const SinCos azimuth = rotate(this->PieceBoundaries[k * pieces]);
    const double lower = lowerAt(azimuth);
    Horizon& horizon = horizons[k];
    horizon = { lower, lower };
    if (!(lower < halfPi - 1e-9))
      continue;
    // A ray toward elevation u; `terms` receives the elevation's terms of
    // projectedBand from the same sine and cosine.
    auto occluded = [&](double u, ElevationTerms& terms) {
      ++result.rays;
      const double s = std::sin(u), c = std::cos(u);
      terms = elevationTerms(u, s, c);
      return this->Rays.occludedToward(point, normal, Vec3(c * azimuth.cos, c * azimuth.sin, s));
    };
    const double hint = previous;
    previous = lower;
    ElevationTerms blockedTerms{}, openTerms{}, terms{};
    if (!occluded(lower + 1e-4, terms))
      continue; // open down to the lower bound
    double blocked = lower, open = halfPi;
    if (hint > blocked + 1e-3 && hint < open)
      (occluded(hint, terms) ? blocked : open) = hint;
    // Still no upper bracket: upward in doubling steps (most horizons are low).
    if (open == halfPi)
      for (double step = 2.0 * degree; blocked + step < open; step *= 2.0)
      {
        if (!occluded(blocked + step, terms))
        {
          open = blocked + step;
          break;
        }
        blocked += step;
      }
    blockedTerms = this->termsAt(blocked);
    openTerms = this->termsAt(open);
    // Bisection until the band left holds at most bandTolerance of the sector's share
    // of the whole sky's projected solid angle (pi / azimuths): bands near the plane's
    // own horizon, where the cosine vanishes, end early.
    const double across = normal.x * azimuth.cos + normal.y * azimuth.sin;
    const double bandLimit = bandTolerance * pi / azimuths;
    for (int step = 0; step < maximumBisections &&
         sector * (across * (openTerms.along - blockedTerms.along) + normal.z * (openTerms.up - blockedTerms.up)) >
           bandLimit;
         ++step)
    {
      const double middle = 0.5 * (blocked + open);
      if (occluded(middle, terms))
        blocked = middle, blockedTerms = terms;
      else
        open = middle, openTerms = terms;
    }
    horizon = { blocked, open };
    previous = 0.5 * (blocked + open);
  }

  auto hide = [&](int p, double u0, double u1, double share) {
    const double phi0 = turn + p * piece;
    this->hideBand(phi0, phi0 + piece, rotate(this->PieceBoundaries[p]), rotate(this->PieceBoundaries[p + 1]), u0, u1,
      share, normal, result);
  };
  // Between two sampled azimuths the horizon's bounds are interpolated linearly, over
  // pieces narrow enough for that to hold (the midpoint rule of a linear horizon).
  for (int k = 0; k < azimuths; ++k)
  {
    const Horizon& from = horizons[k];
    const Horizon& to = horizons[(k + 1) % azimuths];
    if (from.open == from.blocked && to.open == to.blocked)
      continue; // both azimuths open down to their lower bounds: so is the sky between
    for (int j = 0; j < pieces; ++j)
    {
      const int p = k * pieces + j;
      const double t = (j + 0.5) / pieces;
      const double lower = lowerAt(rotate(this->PieceMiddles[p]));
      const double blocked = std::max(lower, (1.0 - t) * from.blocked + t * to.blocked);
      const double open = std::max(blocked, (1.0 - t) * from.open + t * to.open);
      // Below the horizon all is hidden, the band where it lies half (the mean of the
      // two bounds, whatever the band's shape).
      hide(p, lower, blocked, 1.0);
      hide(p, blocked, open, 0.5);
    }
  }
  this->repeatLastBand(result);
  return result;
}

void HorizonSky::repeatLastBand(HiddenSky& result) const
{
  for (int band = this->Bands; band < maxBands; ++band)
    result.irradiance[band] = result.irradiance[this->Bands - 1];
}

double HorizonSky::lowerBound(const Vec3& normal, const SinCos& a)
{
  // Below the plane's own horizon the plane receives nothing, below the world's the
  // sky sends nothing.
  const double toward = normal.x * a.cos + normal.y * a.sin;
  if (toward >= 0.0 && normal.z > 0.0)
    return 0.0;
  // The plane's elevation there, atan(-toward / nz) (within 5e-8 rad: a post's sky takes
  // about a hundred of these).
  return normal.z > 0.0 ? horizon_lines::atanOfPositive(-toward / normal.z)
                        : std::max(0.0, std::atan2(-toward, normal.z));
}

void HorizonSky::sumPiece(MapPiece& piece) const
{
  std::array<Column, 16> columns;
  const int count = this->columnsOf(piece.phi0, piece.phi1, piece.start, piece.end, columns);
  piece.rows.assign(this->Side + 1, PieceRow{});
  for (int c = 0; c < count; ++c)
  {
    const Column& column = columns[c];
    piece.dSin += column.dSin;
    piece.dCos += column.dCos;
    piece.width += column.width;
    const RadianceTerms* sums = &this->ColumnSums[static_cast<std::size_t>(column.iv) * (this->Side + 1)];
    for (int row = 0; row <= this->Side; ++row)
    {
      PieceRow& r = piece.rows[row];
      const Spectrum* l = row < this->Side ? &this->Sky.cellRadiance(row, column.iv) : nullptr;
      for (int band = 0; band < maxBands; ++band)
      {
        r.s[band] += column.dSin * sums[row].along[band];
        r.c[band] += column.dCos * sums[row].along[band];
        r.w[band] += column.width * sums[row].up[band];
        if (l)
        {
          r.rowS[band] += column.dSin * (*l)[band];
          r.rowC[band] += column.dCos * (*l)[band];
          r.rowW[band] += column.width * (*l)[band];
        }
      }
    }
  }
}

void HorizonSky::hidePiece(const MapPiece& piece, double u0, double u1, const Vec3& normal, HiddenSky& result) const
{
  // As hideBand, over the piece's columns at once (a piece behind the plane on balance
  // counts nothing).
  if (!(u0 < u1))
    return;
  const ElevationTerms low = this->termsAt(u0), high = this->termsAt(u1);
  const double weight = (normal.x * piece.dSin - normal.y * piece.dCos) * (high.along - low.along) +
    normal.z * piece.width * (high.up - low.up);
  if (!(weight > 0.0))
    return;
  // Each end's row and its terms from the row's lower boundary, found once for every band.
  struct End
  {
    const PieceRow* row;
    double along, up;
  };
  auto endAt = [&](double u, const ElevationTerms& terms) {
    const int row = std::clamp(static_cast<int>(u * this->RowsPerRadian), 0, this->Side - 1);
    const ElevationTerms& boundary = this->Terms[row * (fineTerms / this->Side)];
    return End{ &piece.rows[row], terms.along - boundary.along, terms.up - boundary.up };
  };
  auto sumAt = [&](const End& end, int band) {
    const PieceRow& r = *end.row;
    return normal.x * (r.s[band] + r.rowS[band] * end.along) - normal.y * (r.c[band] + r.rowC[band] * end.along) +
      normal.z * (r.w[band] + r.rowW[band] * end.up);
  };
  const End top = endAt(u1, high), bottom = endAt(u0, low);
  result.projectedSolidAngle += weight;
  for (int band = 0; band < this->Bands; ++band)
    result.irradiance[band] += std::max(0.0, sumAt(top, band) - sumAt(bottom, band));
}

void HorizonSky::hideThinBand(const MapPiece& piece, double u, double height, const Vec3& normal, HiddenSky& result) const
{
  // The band's height times the piece's rate at u: its terms' slopes (cos^2 u and
  // sin u cos u, from the table's differences) times its row's radiance.
  const int k = termsEntry(u).k;
  const double perStep = termsPerRadian * height;
  const double along = (this->Terms[k + 1].along - this->Terms[k].along) * perStep;
  const double up = (this->Terms[k + 1].up - this->Terms[k].up) * perStep;
  const double weight = (normal.x * piece.dSin - normal.y * piece.dCos) * along + normal.z * piece.width * up;
  if (!(weight > 0.0))
    return;
  const PieceRow& row = piece.rows[std::clamp(static_cast<int>(u * this->RowsPerRadian), 0, this->Side - 1)];
  result.projectedSolidAngle += weight;
  for (int band = 0; band < this->Bands; ++band)
    result.irradiance[band] += std::max(0.0,
      normal.x * row.rowS[band] * along - normal.y * row.rowC[band] * along + normal.z * row.rowW[band] * up);
}

int HorizonSky::columnsOf(
  double phi0, double phi1, const SinCos& start, const SinCos& end, std::array<Column, 16>& columns) const
{
  // The sky's azimuth cells the range crosses, each clipped to it.
  int count = 0;
  int m = static_cast<int>(std::floor((phi0 - this->CellStart) / this->CellWidth)) + 1;
  double b = phi0;
  SinCos at = start;
  while (b < phi1 && count < static_cast<int>(columns.size()))
  {
    const double boundary = this->CellStart + m * this->CellWidth;
    const bool last = boundary >= phi1;
    const SinCos next = last ? end : this->ColumnBoundaries[((m % this->Side) + this->Side) % this->Side];
    const double bEnd = last ? phi1 : boundary;
    const int iv = (((this->FirstColumn - m) % this->Side) + this->Side) % this->Side;
    columns[count++] = { next.sin - at.sin, next.cos - at.cos, bEnd - b, iv };
    b = bEnd;
    at = next;
    ++m;
  }
  return count;
}

void HorizonSky::hideBand(double phi0, double phi1, const SinCos& start, const SinCos& end, double u0, double u1,
  double share, const Vec3& normal, HiddenSky& result) const
{
  // The sky between azimuths phi0 and phi1 and elevations u0 and u1 taken as hidden,
  // with weight `share`, column by column of the sky.
  if (!(u0 < u1))
    return;
  std::array<Column, 16> columns;
  const int count = this->columnsOf(phi0, phi1, start, end, columns);
  // Each column at once, from the running sums of its radiance-weighted terms (the
  // cosine is linear in them, so it needs no cell-by-cell loop). A column whose band
  // lies behind the plane on balance counts nothing.
  const ElevationTerms low = this->termsAt(u0), high = this->termsAt(u1);
  for (int c = 0; c < count; ++c)
  {
    const Column& column = columns[c];
    const double across = normal.x * column.dSin - normal.y * column.dCos;
    const double weight = share *
      (across * (high.along - low.along) + normal.z * column.width * (high.up - low.up));
    if (!(weight > 0.0))
      continue;
    const RadianceTerms bottom = this->columnSumAt(column.iv, u0, low);
    const RadianceTerms top = this->columnSumAt(column.iv, u1, high);
    result.projectedSolidAngle += weight;
    for (int band = 0; band < this->Bands; ++band)
      result.irradiance[band] += std::max(0.0, share *
        (across * (top.along[band] - bottom.along[band]) +
          normal.z * column.width * (top.up[band] - bottom.up[band])));
  }
}

HorizonSky::RadianceTerms HorizonSky::columnSumAt(int iv, double u, const ElevationTerms& terms) const
{
  // The sums up to the row boundary below u, and the part of u's row up to u.
  const int row = std::clamp(static_cast<int>(u * this->RowsPerRadian), 0, this->Side - 1);
  RadianceTerms sum = this->ColumnSums[static_cast<std::size_t>(iv) * (this->Side + 1) + row];
  const ElevationTerms& boundary = this->Terms[row * (fineTerms / this->Side)];
  const Spectrum& l = this->Sky.cellRadiance(row, iv);
  for (int band = 0; band < maxBands; ++band)
  {
    sum.along[band] += l[band] * (terms.along - boundary.along);
    sum.up[band] += l[band] * (terms.up - boundary.up);
  }
  return sum;
}

void HorizonSky::mapHorizons(const HorizonMap::Post& post, const Vec3& normal, MapElevations& elevations,
  std::array<bool, HorizonMap::maximumAzimuths>& rises, MapElevations* falls) const
{
  const std::vector<SinCos>& directions = this->MapTable.directions;
  const std::size_t cell = this->Map->cellOf(post);
  for (std::size_t a = 0; a < directions.size(); ++a)
  {
    const double lower = lowerBound(normal, directions[a]);
    const double trueHorizon = this->Map->trueElevationAt(cell, static_cast<int>(a));
    const double horizon = std::max(0.0, trueHorizon);
    rises[a] = horizon > lower;
    elevations[a] = std::max(lower, horizon);
    if (falls)
      (*falls)[a] = std::min(0.0, trueHorizon);
  }
}

double HorizonSky::voidAt(const HorizonMap::Post& post, const Vec3& normal) const
{
  if (this->MapTable.directions.empty())
    return 0.0;
  MapElevations elevations, falls;
  std::array<bool, HorizonMap::maximumAzimuths> rises;
  this->mapHorizons(post, normal, elevations, rises, &falls);
  return this->voidOf(falls, normal) / pi;
}

double HorizonSky::voidOf(const MapElevations& falls, const Vec3& normal) const
{
  const MapAzimuths& table = this->MapTable;
  const int count = static_cast<int>(table.directions.size());
  if (!(normal.z > 0.0) || std::none_of(falls.begin(), falls.begin() + count, [](double f) { return f < 0.0; }))
    return 0.0;
  // Per sector, at its middle (a band below the horizontal is low: one piece, as the
  // hidden sky takes a low sector): from the higher of the plane's horizon and the
  // map's up to the horizontal, the integral of (n . d) cos u du dphi (its terms as
  // hidePiece's).
  double projected = 0.0;
  for (int a = 0; a < count; ++a)
  {
    const int b = (a + 1) % count;
    if (falls[a] == 0.0 && falls[b] == 0.0)
      continue;
    const MapPiece& sector = table.sectors[a];
    const double toward = normal.x * sector.middle.cos + normal.y * sector.middle.sin;
    if (toward <= 0.0)
      continue; // the plane stays above the horizontal there
    // From the higher of the plane's elevation and the map's, with its tangent (sin u
    // cos u and sin^2 u from it).
    const double planeTangent = -toward / normal.z, plane = -horizon_lines::atanOfPositive(toward / normal.z);
    const double from = std::max(plane, 0.5 * (falls[a] + falls[b]));
    if (from >= 0.0)
      continue;
    const double tangent = from == plane ? planeTangent : std::tan(from);
    const double cos2 = 1.0 / (1.0 + tangent * tangent);
    const double across = normal.x * (sector.end.sin - sector.start.sin) - normal.y * (sector.end.cos - sector.start.cos);
    projected -= across * 0.5 * (from + tangent * cos2) + normal.z * (sector.phi1 - sector.phi0) * 0.5 * tangent * tangent * cos2;
  }
  return std::max(0.0, projected);
}

HorizonSky::ElevationTerms HorizonSky::lowTerms(double u) const
{
  // along = u / 2 + sin 2u / 4 and up = (1 - cos 2u) / 4, by their series in x = 2u to
  // within 2e-9 below 0.35 rad (most horizons of gentle terrain), else from the table.
  if (!(std::abs(u) < 0.35))
  {
    const ElevationTerms terms = this->termsAt(std::abs(u));
    return { std::copysign(terms.along, u), terms.up };
  }
  const double x = 2.0 * u, x2 = x * x;
  const double sine = x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0))));
  const double versine = x2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0 * (1.0 - x2 / 90.0))));
  return { 0.5 * u + 0.25 * sine, 0.25 * versine };
}

PerViewPart<double> HorizonSky::terrainByPart(const HorizonMap::Post& post, const Vec3& normal, bool nearAndFar) const
{
  PerViewPart<double> result{};
  const MapAzimuths& table = this->MapTable;
  const int count = static_cast<int>(table.directions.size());
  if (count == 0 || !(normal.z > 0.0))
    return result;
  const std::size_t cell = this->Map->cellOf(post);
  const double nearDistance = nearViewPosts * this->Map->postSpacing();
  // Each azimuth's band from the plane, elevation p, up to elevation h: the integral of
  // (n . d) cos u du dphi, with n . d = t cos u + nz sin u (t: the normal's part along
  // the azimuth), is the wedge's width times t (h / 2 + sin h cos h / 2) + nz sin^2 h
  // / 2 - t p / 2 (at the plane the rest cancels, tan p = -t / nz).
  const double invNz = 1.0 / normal.z;
  std::array<double, HorizonMap::maximumAzimuths> nearBands, farBands;
  for (int a = 0; a < count; ++a)
  {
    const double toward = normal.x * table.directions[a].cos + normal.y * table.directions[a].sin;
    const double horizon = this->Map->trueElevationAt(cell, a);
    const double plane = horizon_lines::atanOf(-toward * invNz);
    auto band = [&](double top) {
      if (!(top > plane))
        return 0.0;
      const ElevationTerms terms = lowTerms(top);
      return toward * (terms.along - 0.5 * plane) + normal.z * terms.up;
    };
    const double whole = band(horizon);
    nearBands[a] = std::max(0.0, whole);
    if (!nearAndFar)
      continue;
    farBands[a] = 0.0;
    if (!(whole > 0.0))
      continue;
    // Near up to the highest terrain within the near distance, unless that reaches the
    // horizon (the walk then stops).
    const double horizonTangent = std::tan(horizon);
    const double nearTangent = this->Map->nearTangent(post, a, nearDistance, horizonTangent);
    if (nearTangent >= horizonTangent)
      continue;
    const double nearTop = nearTangent > -1e300 ? horizon_lines::atanOf(nearTangent) : plane;
    nearBands[a] = nearTop > plane ? std::min(whole, band(nearTop)) : 0.0;
    farBands[a] = whole - nearBands[a];
  }
  for (int a = 0; a < count; ++a)
  {
    const MapAzimuths::Wedge& wedge = table.wedges[a];
    result[viewPartOf(wedge.sectorBefore, false)] += wedge.before * nearBands[a];
    result[viewPartOf(wedge.sectorAfter, false)] += wedge.after * nearBands[a];
    if (!nearAndFar)
      continue;
    result[viewPartOf(wedge.sectorBefore, true)] += wedge.before * farBands[a];
    result[viewPartOf(wedge.sectorAfter, true)] += wedge.after * farBands[a];
  }
  for (double& part : result)
    part = std::max(0.0, part);
  return result;
}

HiddenSky HorizonSky::hiddenAt(const HorizonMap::Post& post, const Vec3& normal, bool betweenAzimuths) const
{
  // The map's azimuths, each with its horizon, interpolated between them over pieces
  // as the sampled azimuths are.
  HiddenSky result, between;
  const MapAzimuths& table = this->MapTable;
  const int count = static_cast<int>(table.directions.size());
  const bool coarse = betweenAzimuths && count <= static_cast<int>(HorizonMap::Density::Coarse);
  MapElevations elevations, falls;
  std::array<bool, HorizonMap::maximumAzimuths> rises;
  this->mapHorizons(post, normal, elevations, rises, &falls);
  result.voidSolidAngle = this->voidOf(falls, normal);
  // A coarse map's piece also takes the band between its linear horizon and the
  // cubic's (Catmull-Rom through the sector's ends and their neighbours) at its middle.
  auto hide = [&](const MapPiece& piece, int a, int b, double t) {
    const double low = lowerBound(normal, piece.middle);
    const double linear = (1.0 - t) * elevations[a] + t * elevations[b];
    this->hidePiece(piece, low, linear, normal, result);
    if (!coarse)
      return;
    const double p0 = elevations[(a + count - 1) % count], p1 = elevations[a], p2 = elevations[b],
                 p3 = elevations[(b + 1) % count];
    const double t2 = t * t, t3 = t2 * t;
    const double cubic =
      0.5 * (2.0 * p1 + (p2 - p0) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2 + (3.0 * (p1 - p2) + p3 - p0) * t3);
    const double from = std::max(low, std::min(linear, cubic)), to = std::max(low, std::max(linear, cubic));
    if (to > from)
      this->hideThinBand(piece, 0.5 * (from + to), to - from, normal, between);
  };
  for (int a = 0; a < count; ++a)
  {
    const int b = (a + 1) % count;
    if (!rises[a] && !rises[b])
      continue;
    if (std::max(elevations[a], elevations[b]) <= lowSector)
    {
      hide(table.sectors[a], a, b, 0.5);
      continue;
    }
    for (int j = 0; j < piecesPerSector; ++j)
      hide(table.pieces[a * piecesPerSector + j], a, b, (j + 0.5) / piecesPerSector);
  }
  this->repeatLastBand(result);
  if (coarse)
  {
    this->repeatLastBand(between);
    result.betweenAzimuths = between.irradiance;
    result.betweenAzimuthsSolidAngle = between.projectedSolidAngle;
  }
  return result;
}
} // namespace terralux
