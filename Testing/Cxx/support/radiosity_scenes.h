#pragma once
// Test scenes for the radiosity engine, built in code: squares, boxes, spheres, pits,
// walls. Polygons face the side their right-handed corner order gives.

#include "hierarchy/radiosity_types.h"

#include <cmath>

namespace terralux_test
{
using terralux::RadiosityScene;
using terralux::ScenePolygon;
using terralux::Spectrum;
using terralux::Vec3;

inline int addPoint(RadiosityScene& scene, const Vec3& p)
{
  scene.points.push_back(p);
  return static_cast<int>(scene.points.size()) - 1;
}

inline void addPolygon(RadiosityScene& scene, std::initializer_list<Vec3> corners, double reflectance,
  double emission = 0.0, int owner = 0)
{
  ScenePolygon polygon;
  polygon.vertexCount = static_cast<int>(corners.size());
  int k = 0;
  for (const Vec3& c : corners)
    polygon.vertices[k++] = addPoint(scene, c);
  polygon.reflectance = terralux::uniformSpectrum(reflectance);
  polygon.emission = terralux::uniformSpectrum(emission);
  polygon.owner = owner;
  polygon.cell = static_cast<std::int64_t>(scene.polygons.size());
  scene.polygons.push_back(polygon);
}

/// Closed axis-aligned cube [0, size]^3 with inward-facing faces.
inline void addInwardCube(RadiosityScene& scene, double size, double reflectance, double emission)
{
  const double s = size;
  addPolygon(scene, { { 0, 0, 0 }, { s, 0, 0 }, { s, s, 0 }, { 0, s, 0 } }, reflectance, emission); // floor, up
  addPolygon(scene, { { 0, 0, s }, { 0, s, s }, { s, s, s }, { s, 0, s } }, reflectance, emission); // ceiling, down
  addPolygon(scene, { { 0, 0, 0 }, { 0, s, 0 }, { 0, s, s }, { 0, 0, s } }, reflectance, emission); // x = 0, +x
  addPolygon(scene, { { s, 0, 0 }, { s, 0, s }, { s, s, s }, { s, s, 0 } }, reflectance, emission); // x = s, -x
  addPolygon(scene, { { 0, 0, 0 }, { 0, 0, s }, { s, 0, s }, { s, 0, 0 } }, reflectance, emission); // y = 0, +y
  addPolygon(scene, { { 0, s, 0 }, { s, s, 0 }, { s, s, s }, { 0, s, s } }, reflectance, emission); // y = s, -y
}

/// Closed UV sphere of radius r with inward-facing quads (triangles at the poles).
inline void addInwardSphere(RadiosityScene& scene, double r, int rings, int segments, double reflectance,
  double emission)
{
  auto at = [&](int i, int j) {
    const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments;
    return Vec3(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
    {
      const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      // Outward order would be a, b, c, d; inward reverses it.
      if (i == 0)
        addPolygon(scene, { a, c, b }, reflectance, emission);
      else if (i == rings - 1)
        addPolygon(scene, { a, d, b }, reflectance, emission);
      else
        addPolygon(scene, { a, d, c, b }, reflectance, emission);
    }
}
} // namespace terralux_test

namespace terralux_test
{
/// A cylindrical pit of radius r and depth h: floor disc (fan of `segments` triangles,
/// facing up) and wall (quads facing inward), open to the sky.
inline void addPit(RadiosityScene& scene, double r, double h, int segments, double reflectance)
{
  for (int j = 0; j < segments; ++j)
  {
    const double a0 = 2 * M_PI * j / segments, a1 = 2 * M_PI * (j + 1) / segments;
    const Vec3 p0(r * std::cos(a0), r * std::sin(a0), -h), p1(r * std::cos(a1), r * std::sin(a1), -h);
    addPolygon(scene, { Vec3(0, 0, -h), p0, p1 }, reflectance);
    const Vec3 q0(p0.x, p0.y, 0.0), q1(p1.x, p1.y, 0.0);
    addPolygon(scene, { p0, q0, q1, p1 }, reflectance); // faces the axis
  }
}

/// Ground square [-half, half]^2 at z = 0 facing up, and a wall along the x axis from
/// x = -length/2 to length/2, `height` tall, facing north (+y).
inline void addWallOnGround(RadiosityScene& scene, double half, double length, double height, double reflectance)
{
  addPolygon(scene, { { -half, -half, 0 }, { half, -half, 0 }, { half, half, 0 }, { -half, half, 0 } }, reflectance);
  const double l = 0.5 * length;
  addPolygon(scene, { { l, 0, 0 }, { -l, 0, 0 }, { -l, 0, height }, { l, 0, height } }, reflectance, 0.0, 1);
}
} // namespace terralux_test
