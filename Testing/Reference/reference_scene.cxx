#include "reference_scene.h"

#include "terrain/terrain_grid.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace terralux_reference
{
ReferenceScene::ReferenceScene(const terralux::RadiosityScene& scene)
{
  std::vector<std::array<Vec3, 3>> corners;
  auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c, const Spectrum& reflectance, const Spectrum& emission) {
    const Vec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (!(length > 0.0))
      return;
    corners.push_back({ a, b, c });
    this->Triangles.push_back({ n / length, reflectance, emission });
  };
  for (const terralux::ScenePolygon& polygon : scene.polygons)
    for (int k = 1; k + 1 < polygon.vertexCount; ++k)
      add(scene.points[polygon.vertices[0]], scene.points[polygon.vertices[k]],
        scene.points[polygon.vertices[k + 1]], polygon.reflectance, polygon.emission);
  for (const terralux::TerrainGrid* terrain : scene.terrains)
    for (int j = 0; j < terrain->cellsY(); ++j)
      for (int i = 0; i < terrain->cellsX(); ++i)
        if (terrain->cellValid(i, j))
          for (const auto& t : terrain->cellTriangles(i, j))
            add(t[0], t[1], t[2], terrain->cellReflectance(i, j), terrain->cellEmission(i, j));
  if (corners.empty())
    throw std::runtime_error("reference scene: no triangle of non-zero area");
  Vec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
  for (const auto& t : corners)
    for (const Vec3& p : t)
    {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  this->Centre = 0.5 * (low + high);
  this->Offset = std::max(1e-9, 1e-5 * glm::length(high - low));

  this->Device = rtcNewDevice("verbose=0");
  this->Scene = rtcNewScene(this->Device);
  rtcSetSceneBuildQuality(this->Scene, RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(this->Scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * corners.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), corners.size()));
  for (std::size_t t = 0; t < corners.size(); ++t)
    for (int c = 0; c < 3; ++c)
    {
      indices[3 * t + c] = static_cast<unsigned>(3 * t + c);
      for (int axis = 0; axis < 3; ++axis)
        vertices[3 * (3 * t + c) + axis] = static_cast<float>(corners[t][c][axis] - this->Centre[axis]);
    }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(this->Scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(this->Scene);
}

ReferenceScene::~ReferenceScene()
{
  rtcReleaseScene(this->Scene);
  rtcReleaseDevice(this->Device);
}

double ReferenceScene::offsetAt(const Vec3&) const
{
  return this->Offset;
}

bool ReferenceScene::intersect(const Vec3& origin, const Vec3& direction, double tnear, Hit& hit) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  const Vec3 o = origin - this->Centre;
  query.ray.org_x = static_cast<float>(o.x);
  query.ray.org_y = static_cast<float>(o.y);
  query.ray.org_z = static_cast<float>(o.z);
  query.ray.dir_x = static_cast<float>(direction.x);
  query.ray.dir_y = static_cast<float>(direction.y);
  query.ray.dir_z = static_cast<float>(direction.z);
  query.ray.tnear = static_cast<float>(tnear);
  query.ray.tfar = std::numeric_limits<float>::infinity();
  query.ray.mask = 0xFFFFFFFFu;
  query.ray.flags = 0;
  query.ray.time = 0.0f;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(this->Scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID)
    return false;
  const Triangle& t = this->Triangles[query.hit.primID];
  hit.position = origin + static_cast<double>(query.ray.tfar) * direction;
  hit.normal = t.normal;
  hit.reflectance = t.reflectance;
  hit.emission = t.emission;
  return true;
}

bool ReferenceScene::occluded(const Vec3& origin, const Vec3& direction, double tnear, double tfar) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  const Vec3 o = origin - this->Centre;
  ray.org_x = static_cast<float>(o.x);
  ray.org_y = static_cast<float>(o.y);
  ray.org_z = static_cast<float>(o.z);
  ray.dir_x = static_cast<float>(direction.x);
  ray.dir_y = static_cast<float>(direction.y);
  ray.dir_z = static_cast<float>(direction.z);
  ray.tnear = static_cast<float>(tnear);
  ray.tfar = static_cast<float>(tfar);
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  ray.time = 0.0f;
  rtcOccluded1(this->Scene, &context, &ray);
  return ray.tfar < 0.0f;
}
} // namespace terralux_reference
