#include "geodesy/map_projection.h"

#include "base/error.h"
#include "raster/gdal_messages.h"

#include <ogr_spatialref.h>

#include <vector>

namespace terralux
{
struct MapProjection::Impl
{
  OGRSpatialReference source;
  OGRSpatialReference wgs84;
  std::unique_ptr<OGRCoordinateTransformation> toGeographic;
  std::unique_ptr<OGRCoordinateTransformation> fromGeographic;
};

namespace
{
void transformOrThrow(OGRCoordinateTransformation& transformation, std::size_t count, double* x,
  double* y, const char* what)
{
  std::vector<int> success(count, 0);
  const QuietGdalErrors quiet;
  const bool ok =
    transformation.Transform(static_cast<int>(count), x, y, nullptr, success.data()) != 0;
  for (std::size_t i = 0; ok && i < count; ++i)
  {
    if (!success[i])
    {
      throw Error(std::string("cannot transform ") + what +
        ": the point lies outside the CRS's domain of validity");
    }
  }
  if (!ok)
  {
    throw Error(std::string("cannot transform ") + what + ": " + quiet.lastMessage());
  }
}
} // namespace

MapProjection::MapProjection(const std::string& crsDefinition)
  : State(std::make_unique<Impl>())
{
  const QuietGdalErrors quiet;
  if (this->State->source.SetFromUserInput(crsDefinition.c_str()) != OGRERR_NONE)
  {
    throw Error("cannot parse the raster's coordinate reference system (" + quiet.lastMessage() +
      "); assign a valid CRS, e.g. gdal_edit.py -a_srs EPSG:32725");
  }
  this->State->wgs84.SetWellKnownGeogCS("WGS84");
  // Longitude first, latitude second, whatever the CRS's official axis order.
  this->State->source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  this->State->wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  this->State->toGeographic.reset(
    OGRCreateCoordinateTransformation(&this->State->source, &this->State->wgs84));
  this->State->fromGeographic.reset(
    OGRCreateCoordinateTransformation(&this->State->wgs84, &this->State->source));
  if (!this->State->toGeographic || !this->State->fromGeographic)
  {
    throw Error("the raster's coordinate reference system cannot be transformed to WGS84 (" +
      quiet.lastMessage() + "); reproject the DEM with gdalwarp -t_srs EPSG:4326");
  }
  char* wkt = nullptr;
  const char* options[] = { "FORMAT=WKT2_2019", nullptr };
  if (this->State->source.exportToWkt(&wkt, options) == OGRERR_NONE && wkt)
  {
    this->Wkt = wkt;
  }
  CPLFree(wkt);
}

MapProjection::~MapProjection() = default;

std::unique_ptr<MapProjection> MapProjection::clone() const
{
  std::unique_ptr<MapProjection> copy(new MapProjection());
  copy->State = std::make_unique<Impl>();
  copy->State->source = this->State->source;
  copy->State->wgs84 = this->State->wgs84;
  copy->State->toGeographic.reset(this->State->toGeographic->Clone());
  copy->State->fromGeographic.reset(this->State->fromGeographic->Clone());
  copy->Wkt = this->Wkt;
  return copy;
}

bool MapProjection::isGeographic() const
{
  return this->State->source.IsGeographic() != 0;
}

void MapProjection::toGeographic(std::size_t count, double* x, double* y)
{
  transformOrThrow(*this->State->toGeographic, count, x, y, "raster coordinates to WGS84");
}

void MapProjection::fromGeographic(std::size_t count, double* x, double* y)
{
  transformOrThrow(*this->State->fromGeographic, count, x, y, "WGS84 coordinates to the raster CRS");
}

std::array<double, 4> MapProjection::boundsFromGeographic(
  double southDeg, double northDeg, double westDeg, double eastDeg)
{
  std::array<double, 4> bounds{};
  const QuietGdalErrors quiet;
  constexpr int densifyPoints = 21;
  if (!this->State->fromGeographic->TransformBounds(westDeg, southDeg, eastDeg, northDeg,
        &bounds[0], &bounds[1], &bounds[2], &bounds[3], densifyPoints))
  {
    throw Error("cannot transform the geographic bounds to the raster CRS: " + quiet.lastMessage());
  }
  return bounds;
}
} // namespace terralux
