#include "visibility/visibility.h"

#include "base/error.h"
#include "terrain/terrain_grid.h"

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>
#include <utility>
#include <vector>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace terralux
{
struct Visibility::RayCounters
{
  tbb::enumerable_thread_specific<std::uint64_t> perThread{ 0 };
};

std::uint64_t Visibility::raysCast() const
{
  std::uint64_t total = 0;
  for (std::uint64_t count : this->Rays->perThread)
    total += count;
  return total;
}

namespace
{
// Ray ends are pulled in by 1e-5 of the scene's bounding diagonal.
double offsetOf(const Vec3& low, const Vec3& high)
{
  return std::max(1e-9, 1e-5 * glm::length(high - low));
}

// The parameters (fu, fv) within cell (i, j) of a point on (or within rounding of) its
// lower or upper triangle (TerrainGrid::cellTriangles), by least squares in 3-D: the
// two triangles agree on their shared diagonal, and neighbouring cells on their edge.
std::array<double, 2> cellParameters(
  const TerrainGrid& terrain, int i, int j, const Vec3& origin, const Vec3& d, const Vec3& hitPoint, bool upper)
{
  // Lower: p00 + fu (p10 - p00) + fv (p01 - p00); upper: p11 + (1 - fu)(p01 - p11)
  // + (1 - fv)(p10 - p11).
  const Vec3 base = upper ? terrain.post(i + 1, j + 1) : terrain.post(i, j);
  const Vec3 a = upper ? terrain.post(i, j + 1) - base : terrain.post(i + 1, j) - base;
  const Vec3 b = upper ? terrain.post(i + 1, j) - base : terrain.post(i, j + 1) - base;
  // Where the ray meets the triangle's plane, in double (Embree's float distance
  // leaves the point 1e-7 of the ray's length off the plane); the hit point itself
  // for rays that graze it.
  const Vec3 normal = glm::cross(a, b);
  const double across = glm::dot(normal, d);
  const double length = glm::dot(normal, base - origin) / across;
  const Vec3 point = std::abs(across) > 1e-3 * glm::length(normal) && std::isfinite(length) ? origin + length * d : hitPoint;
  const Vec3 r = point - base;
  const double aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
  const double ra = glm::dot(r, a), rb = glm::dot(r, b);
  const double det = aa * bb - ab * ab;
  if (!(det > 0.0))
    return { 0.0, 0.0 };
  const double x = (ra * bb - rb * ab) / det, y = (rb * aa - ra * ab) / det;
  // Upper: x runs along -u from p11, y along -v.
  return upper ? std::array<double, 2>{ 1.0 - x, 1.0 - y } : std::array<double, 2>{ x, y };
}

double offsetFor(const TerrainGrid& terrain)
{
  Vec3 low, high;
  return terrain.validBounds(low, high) ? offsetOf(low, high) : 1e-9;
}

// One Embree device for the process, created on first use and never released. A
// Visibility may outlive main (a filter keeping its geometry, destroyed with ParaView's
// process module among the static destructors at exit); releasing a device then waits
// forever on Embree's global state, already torn down. Scenes are released as usual.
RTCDevice processDevice()
{
  static RTCDevice device = rtcNewDevice("verbose=0");
  return device;
}
} // namespace

Visibility::Visibility(const RadiosityScene& scene, const FarSight& far)
  : Rays(std::make_shared<RayCounters>())
{
  this->build(scene);
  this->Coarse = FarTerrain::of(scene, far);
  if (this->Coarse)
  {
    // A window of the grid takes its ray offset from the far terrain, the whole grid's
    // box: every process's rays then start alike, whatever window it holds.
    if (scene.farTerrain.grid)
      this->Offset = offsetFor(this->Coarse->grid());
    this->Far = std::unique_ptr<Visibility>(new Visibility(*this->Coarse, this->Offset, this->Rays));
    this->DetailDistance = far.detailDistance;
  }
}

Visibility::Visibility(const FarTerrain& far, double sceneOffset, std::shared_ptr<RayCounters> counters)
  : MapsTo(&far)
  , Rays(std::move(counters))
{
  RadiosityScene scene;
  scene.terrains.push_back(&far.grid());
  this->build(scene);
  this->Offset = sceneOffset; // the fine scene's: the far grid's box is the same but for a few posts
}

void Visibility::build(const RadiosityScene& scene)
{
  this->Device = processDevice();
  if (!this->Device)
  {
    throw Error("Embree could not create a device");
  }
  this->Grids = scene.terrains;
  this->Scene = rtcNewScene(this->Device);
  rtcSetSceneBuildQuality(this->Scene, RTC_BUILD_QUALITY_HIGH);
  // Watertight intersection: rays must not slip between triangles that share an edge.
  rtcSetSceneFlags(this->Scene, RTC_SCENE_FLAG_ROBUST);

  // Vertices relative to the scene's centre keep float precision for large coordinates;
  // with terrains, the first one's origin, so its vertices are shared as they are.
  Vec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
  for (const Vec3& p : scene.points)
  {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  for (const TerrainGrid* terrain : scene.terrains)
  {
    Vec3 terrainLow, terrainHigh;
    if (terrain->validBounds(terrainLow, terrainHigh))
    {
      low = glm::min(low, terrainLow);
      high = glm::max(high, terrainHigh);
    }
  }
  this->Offset = offsetOf(low, high);
  this->Centre = scene.terrains.empty() ? 0.5 * (low + high) : scene.terrains.front()->origin();
  for (std::size_t t = 0; t < scene.terrains.size(); ++t)
  {
    this->addTerrain(*scene.terrains[t], static_cast<int>(t));
  }
  if (!scene.polygons.empty())
  {
    this->addPolygons(scene);
  }
  rtcCommitScene(this->Scene);
  if (rtcGetDeviceError(this->Device) != RTC_ERROR_NONE)
  {
    throw Error("Embree failed to build the visibility structure (out of memory?)");
  }
}

void Visibility::addTerrain(const TerrainGrid& terrain, int terrainIndex)
{
  // Rectangles of valid cells, merged greedily: runs of valid cells in a row grow down
  // the rows while the next row has the same run. Embree limits a grid to 32767 posts a side.
  constexpr int largest = 32766;
  struct Rectangle
  {
    int i0, j0, i1, j1;
  };
  std::vector<Rectangle> rectangles;
  std::map<std::pair<int, int>, int> open; // run (i0, i1) -> first row
  const int cx = terrain.cellsX(), cy = terrain.cellsY();
  for (int j = 0; j <= cy; ++j)
  {
    std::map<std::pair<int, int>, int> next;
    for (int i = 0; j < cy && i < cx;)
    {
      if (!terrain.cellValid(i, j))
      {
        ++i;
        continue;
      }
      int end = i;
      while (end < cx && end - i < largest && terrain.cellValid(end, j))
        ++end;
      const auto run = std::make_pair(i, end);
      const auto it = open.find(run);
      if (it != open.end() && j - it->second < largest)
      {
        next[run] = it->second;
        open.erase(it);
      }
      else
      {
        next[run] = j;
      }
      i = end;
    }
    for (const auto& [run, first] : open) // runs that stop at this row
      rectangles.push_back({ run.first, first, run.second, j });
    open.swap(next);
  }
  if (rectangles.empty())
  {
    return;
  }
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_GRID);
  const std::size_t posts = static_cast<std::size_t>(terrain.postsX()) * terrain.postsY();
  if (terrain.origin() == this->Centre)
  {
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, terrain.vertices(), 0,
      3 * sizeof(float), posts);
  }
  else
  {
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), posts));
    if (!vertices)
    {
      rtcReleaseGeometry(geometry);
      throw Error("Embree could not allocate a terrain's vertices (out of memory?)");
    }
    const Vec3 shift = terrain.origin() - this->Centre;
    for (std::size_t k = 0; k < posts; ++k)
      for (int c = 0; c < 3; ++c)
        vertices[3 * k + c] = static_cast<float>(terrain.vertices()[3 * k + c] + shift[c]);
  }
  GeometryOrigin origin;
  origin.terrain = terrainIndex;
  auto* grids = static_cast<RTCGrid*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_GRID, 0, RTC_FORMAT_GRID, sizeof(RTCGrid), rectangles.size()));
  if (!grids)
  {
    rtcReleaseGeometry(geometry);
    throw Error("Embree could not allocate a terrain's grids (out of memory?)");
  }
  for (std::size_t k = 0; k < rectangles.size(); ++k)
  {
    const Rectangle& r = rectangles[k];
    grids[k].startVertexID = static_cast<unsigned>(r.j0 * static_cast<std::size_t>(terrain.postsX()) + r.i0);
    grids[k].stride = static_cast<unsigned>(terrain.postsX());
    grids[k].width = static_cast<unsigned short>(r.i1 - r.i0 + 1);
    grids[k].height = static_cast<unsigned short>(r.j1 - r.j0 + 1);
    origin.gridStarts.emplace_back(r.i0, r.j0);
    origin.gridSizes.emplace_back(r.i1 - r.i0, r.j1 - r.j0);
  }
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(this->Scene, geometry);
  if (this->Origins.size() <= id)
    this->Origins.resize(id + 1);
  this->Origins[id] = std::move(origin);
  rtcReleaseGeometry(geometry);
}

void Visibility::addPolygons(const RadiosityScene& scene)
{
  std::size_t triangleCount = 0;
  for (const ScenePolygon& polygon : scene.polygons)
  {
    triangleCount += polygon.vertexCount - 2;
  }
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
    RTC_FORMAT_FLOAT3, 3 * sizeof(float), scene.points.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangleCount));
  if (!vertices || !indices)
  {
    rtcReleaseGeometry(geometry);
    throw Error("Embree could not allocate the scene's buffers (out of memory?)");
  }
  for (std::size_t k = 0; k < scene.points.size(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      vertices[3 * k + c] = static_cast<float>(scene.points[k][c] - this->Centre[c]);
    }
  }
  std::size_t t = 0;
  this->TrianglePolygon.resize(triangleCount);
  for (std::size_t p = 0; p < scene.polygons.size(); ++p)
  {
    const ScenePolygon& polygon = scene.polygons[p];
    for (int k = 1; k + 1 < polygon.vertexCount; ++k, ++t)
    {
      this->TrianglePolygon[t] = static_cast<int>(p);
      indices[3 * t + 0] = static_cast<unsigned>(polygon.vertices[0]);
      indices[3 * t + 1] = static_cast<unsigned>(polygon.vertices[k]);
      indices[3 * t + 2] = static_cast<unsigned>(polygon.vertices[k + 1]);
    }
  }
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(this->Scene, geometry);
  if (this->Origins.size() <= id)
    this->Origins.resize(id + 1);
  this->Origins[id] = GeometryOrigin{};
  rtcReleaseGeometry(geometry);
}

Visibility::~Visibility()
{
  if (this->Scene)
    rtcReleaseScene(this->Scene);
}

namespace
{
// A ray of Embree's single-ray API from scene-relative double values.
RTCRay embreeRay(const Vec3& origin, const Vec3& direction, double tnear, double tfar)
{
  RTCRay ray;
  ray.org_x = static_cast<float>(origin.x);
  ray.org_y = static_cast<float>(origin.y);
  ray.org_z = static_cast<float>(origin.z);
  ray.dir_x = static_cast<float>(direction.x);
  ray.dir_y = static_cast<float>(direction.y);
  ray.dir_z = static_cast<float>(direction.z);
  ray.tnear = static_cast<float>(tnear);
  ray.tfar = static_cast<float>(tfar);
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

bool castOcclusion(RTCScene scene, const Vec3& origin, const Vec3& direction, double tnear, double tfar)
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = embreeRay(origin, direction, tnear, tfar);
  rtcOccluded1(scene, &context, &ray);
  return ray.tfar < 0.0f; // Embree marks a hit by tfar = -inf
}
} // namespace

double Visibility::detailEnd(const Vec3& d) const
{
  // A ray within 1e-9 rad of the vertical leaves it hundreds of thousands of km away,
  // past anything (and past the coordinates Embree takes): never.
  const double across = std::hypot(d.x, d.y);
  return this->Far && across > 1e-9 ? this->DetailDistance / across : std::numeric_limits<double>::infinity();
}

bool Visibility::blocked(const Vec3& origin, const Vec3& d, double tnear, double tfar) const
{
  if (!(tnear < tfar))
    return false;
  return castOcclusion(this->Scene, origin - this->Centre, d, tnear, tfar);
}

bool Visibility::under(const Vec3& point, SurfaceHit& hit) const
{
  // Straight up from a point under a height field, the first surface met is a back face.
  return this->intersect(point, Vec3(0.0, 0.0, 1.0), 0.0, std::numeric_limits<double>::infinity(), hit);
}

bool Visibility::intersect(const Vec3& origin, const Vec3& d, double tnear, double tfar, SurfaceHit& hit) const
{
  if (!(tnear < tfar))
    return false;
  const Vec3 from = origin - this->Centre;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  query.ray = embreeRay(from, d, tnear, tfar);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(this->Scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID || query.hit.geomID >= this->Origins.size())
    return false;
  const GeometryOrigin& source = this->Origins[query.hit.geomID];
  hit = SurfaceHit{};
  hit.point = from + static_cast<double>(query.ray.tfar) * d + this->Centre;
  const Vec3 ng(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
  const double length = glm::length(ng);
  if (length > 0.0)
    hit.normal = ng / length;
  if (source.terrain >= 0)
  {
    // Grid u, v run over [0, 1] across the whole Embree grid, in float: they pick the
    // cell, and the parameters within it are found again in double from the hit point,
    // so that they do not depend on how the valid cells were cut into grids (a
    // window's cut differs from the whole grid's) nor lose precision on wide ones.
    const auto [i0, j0] = source.gridStarts[query.hit.primID];
    const auto [cellsU, cellsV] = source.gridSizes[query.hit.primID];
    hit.terrain = source.terrain;
    const double u = std::clamp(static_cast<double>(query.hit.u), 0.0, 1.0) * cellsU;
    const double v = std::clamp(static_cast<double>(query.hit.v), 0.0, 1.0) * cellsV;
    const int ci = std::min(static_cast<int>(u), cellsU - 1), cj = std::min(static_cast<int>(v), cellsV - 1);
    const std::array<double, 2> within =
      cellParameters(*this->Grids[static_cast<std::size_t>(source.terrain)], i0 + ci, j0 + cj, origin, d,
        hit.point, (u - ci) + (v - cj) > 1.0);
    hit.u = i0 + std::clamp(ci + within[0], 0.0, static_cast<double>(cellsU));
    hit.v = j0 + std::clamp(cj + within[1], 0.0, static_cast<double>(cellsV));
    if (this->MapsTo)
    {
      hit.u = this->MapsTo->fineU(hit.u);
      hit.v = this->MapsTo->fineV(hit.v);
      hit.far = true;
    }
  }
  else
  {
    hit.polygon = this->TrianglePolygon[query.hit.primID];
  }
  return true;
}

// A ray that reaches its detail distance below the far terrain's surface (where that
// spans a hollow the fine terrain dips into, or the ray runs along a valley the far
// terrain does not have) is inside the far terrain: it stops there, as a ray under a
// height field would, at the surface above it.
bool Visibility::farBlocked(const Vec3& origin, const Vec3& d, double detail, double tfar) const
{
  SurfaceHit above;
  return this->Far->under(origin + detail * d, above) || this->Far->blocked(origin, d, detail, tfar);
}

bool Visibility::farHit(const Vec3& origin, const Vec3& d, double detail, SurfaceHit& hit) const
{
  return this->Far->under(origin + detail * d, hit) ||
    this->Far->intersect(origin, d, detail, std::numeric_limits<double>::infinity(), hit);
}

bool Visibility::occluded(const Vec3& a, const Vec3& aNormal, const Vec3& b, const Vec3& bNormal) const
{
  ++this->Rays->perThread.local();
  const Vec3 from = a + this->Offset * aNormal;
  const Vec3 to = b + this->Offset * bNormal;
  const Vec3 d = to - from;
  const double length = glm::length(d);
  if (length <= 2.0 * this->Offset)
  {
    return false;
  }
  // The ray also starts one offset along itself: a point where two surfaces meet (the
  // foot of a wall) lifted off one of them may still lie on the other.
  const Vec3 unit = d / length;
  const double end = length - this->Offset, detail = this->detailEnd(unit);
  return this->blocked(from, unit, this->Offset, std::min(end, detail)) ||
    (detail < end && this->farBlocked(from, unit, detail, end));
}

bool Visibility::firstHit(const Vec3& a, const Vec3& aNormal, const Vec3& d, SurfaceHit& hit) const
{
  ++this->Rays->perThread.local();
  // From the lifted origin on: a scene-relative offset can exceed small objects (a 1 m
  // box on 100 km of ground lifts rays by 1.4 m), and skipping it would miss the
  // ground just below a wall.
  const Vec3 origin = a + this->Offset * aNormal;
  const double detail = this->detailEnd(d);
  return this->intersect(origin, d, 0.0, detail, hit) ||
    (detail < std::numeric_limits<double>::infinity() && this->farHit(origin, d, detail, hit));
}

std::uint64_t Visibility::seedOf(const Vec3& p) const
{
  const Vec3 cells = glm::round((p - this->Centre) / (1e-3 * this->Offset));
  return hashPosition(cells);
}

bool Visibility::occludedToward(const Vec3& a, const Vec3& aNormal, const Vec3& d) const
{
  ++this->Rays->perThread.local();
  const Vec3 origin = a + this->Offset * aNormal;
  const double detail = this->detailEnd(d), infinity = std::numeric_limits<double>::infinity();
  return this->blocked(origin, d, this->Offset, std::min(infinity, detail)) ||
    (detail < infinity && this->farBlocked(origin, d, detail, infinity));
}
} // namespace terralux
