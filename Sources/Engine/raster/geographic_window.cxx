#include "raster/geographic_window.h"

#include "base/error.h"
#include "geodesy/map_projection.h"

#include <algorithm>
#include <sstream>

namespace terralux
{
namespace
{
std::string boxText(double south, double north, double west, double east)
{
  std::ostringstream text;
  text << "GeoBounds (" << south << ", " << north << ", " << west << ", " << east << ")";
  return text.str();
}
} // namespace

PixelWindow windowOfGeographicBox(
  const DemRaster& raster, MapProjection& projection, double south, double north, double west, double east)
{
  if (!(south >= -90.0 && north <= 90.0 && south < north && west < east && west >= -540.0 && east <= 540.0 &&
        east - west <= 360.0))
    throw Error(boxText(south, north, west, east) +
      " is not a geographic box: give south < north within [-90, 90] and west < east, at most 360 degrees apart");
  if (projection.isGeographic())
  {
    // The raster's longitudes: its corners' map x (GDAL's traditional order, x east).
    const RasterInfo& info = raster.info();
    double low = 1e300, high = -1e300;
    for (const double col : { 0.0, double(info.width) })
      for (const double row : { 0.0, double(info.height) })
      {
        double x, y;
        info.geoTransform.pixelToMap(col, row, x, y);
        low = std::min(low, x);
        high = std::max(high, x);
      }
    // The box, or the box a turn east or west, where it overlaps the raster.
    double shift = 0.0;
    int overlapping = 0;
    for (const double turn : { -720.0, -360.0, 0.0, 360.0, 720.0 })
      if (std::min(east + turn, high) > std::max(west + turn, low))
      {
        shift = turn;
        ++overlapping;
      }
    if (overlapping > 1)
      throw Error(boxText(south, north, west, east) + " wraps around the raster's edge at longitude " +
        std::to_string(high) + " (the raster spans the globe from " + std::to_string(low) +
        "): read each side of that meridian with a GeoBounds of its own");
    west += shift;
    east += shift;
  }
  std::array<double, 4> map = projection.boundsFromGeographic(south, north, west, east);
  // A geographic CRS may give a box across the antimeridian as xmin > xmax.
  if (projection.isGeographic() && map[2] < map[0])
    map[2] += 360.0;
  return raster.windowCovering(map[0], map[1], map[2], map[3]);
}
} // namespace terralux
