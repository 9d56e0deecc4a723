#pragma once
// The window of a raster that a geographic box covers, in the raster's CRS. A box may
// cross the antimeridian (west 179.9, east 180.2): in a geographic raster it is placed
// where the raster's longitudes hold it (a raster from 179 to 181 E, or from -181 to
// -179), or refused where it would wrap around the raster's own edge.

#include "raster/dem_raster.h"

namespace terralux
{
class MapProjection;

/// Throws Error naming the fix for a box that is not one (NaN, south >= north,
/// west >= east, beyond the poles, a longitude span over 360 deg) or that wraps around
/// the edge of a raster that spans the whole globe. An empty window: no overlap.
PixelWindow windowOfGeographicBox(
  const DemRaster& raster, MapProjection& projection, double south, double north, double west, double east);
} // namespace terralux
