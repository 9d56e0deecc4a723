#pragma once
// A raster's coordinate reference system and its transformation to and from
// WGS84 geographic longitude/latitude (GDAL/OSR, i.e. PROJ). Heights are not
// transformed: DEM values are taken as heights above the ellipsoid.

#include <array>
#include <cstddef>
#include <memory>
#include <string>

namespace terralux
{
class MapProjection
{
public:
  /// crsDefinition: WKT, PROJ string or "EPSG:n". Throws Error when it cannot be
  /// parsed or no transformation to WGS84 exists.
  explicit MapProjection(const std::string& crsDefinition);
  ~MapProjection();
  MapProjection(const MapProjection&) = delete;
  MapProjection& operator=(const MapProjection&) = delete;

  /// An independent copy for use on another thread (transforms keep state).
  std::unique_ptr<MapProjection> clone() const;

  /// The CRS as WKT (OGC WKT2 2019 where the CRS needs it, else WKT1).
  const std::string& wkt() const { return this->Wkt; }
  bool isGeographic() const;

  /// In place: map x, y -> longitude, latitude in degrees. Throws Error if any
  /// point cannot be transformed.
  void toGeographic(std::size_t count, double* x, double* y);
  /// In place: longitude, latitude in degrees -> map x, y.
  void fromGeographic(std::size_t count, double* x, double* y);

  /// Map-coordinate bounds (xmin, ymin, xmax, ymax) enclosing a WGS84 box, with
  /// densified edges so curved images of the box edges are enclosed too.
  std::array<double, 4> boundsFromGeographic(
    double southDeg, double northDeg, double westDeg, double eastDeg);

private:
  MapProjection() = default;
  struct Impl;
  std::unique_ptr<Impl> State;
  std::string Wkt;
};
} // namespace terralux
