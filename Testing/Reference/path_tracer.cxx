#include "path_tracer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace terralux_reference
{
namespace
{
constexpr double pi = 3.14159265358979323846;

// An orthonormal frame with `n` as its third axis.
void frameOf(const Vec3& n, Vec3& t, Vec3& b)
{
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  t = glm::normalize(glm::cross(a, n));
  b = glm::cross(n, t);
}

// Cosine-weighted direction about n from (x, y) in [0, 1)^2 (Malley: a uniform point
// on the disc lifted to the hemisphere).
Vec3 cosineDirection(const Vec3& n, double x, double y)
{
  Vec3 t, b;
  frameOf(n, t, b);
  const double r = std::sqrt(x), phi = 2.0 * pi * y;
  return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - x)) * n);
}
} // namespace

class PathTracer::Random
{
public:
  explicit Random(std::uint64_t seed)
    : State(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull)
  {
  }
  double uniform()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return ((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
  }

private:
  std::uint64_t State;
};

PathTracer::PathTracer(const ReferenceScene& scene, const terralux::SkyHierarchy* sky, std::vector<ReferenceSun> suns)
  : Scene(scene)
  , Sky(sky)
  , Suns(std::move(suns))
{
  if (!sky)
    return;
  const int level = sky->finestLevel(), side = terralux::SkyHierarchy::cellsPerSide(level);
  for (int iu = 0; iu < side; ++iu)
    for (int iv = 0; iv < side; ++iv)
    {
      const terralux::SkyPatch cell{ level, iu, iv };
      const terralux::Direction w = cell.vectorSolidAngle();
      SkyCell c{ sky->radiance(cell, 0), Vec3(w[0], w[1], w[2]), cell.u0(), cell.u1(), cell.v0(), cell.v1(), {} };
      int k = 0;
      for (double u : { c.u0, c.u1 })
        for (double v : { c.v0, 0.5 * (c.v0 + c.v1), c.v1 })
          c.edges[k++] = Vec3(-std::sin(v) * std::cos(u), -std::cos(v) * std::cos(u), std::sin(u));
      this->Cells.push_back(c);
    }
}

double PathTracer::unoccludedSky(const Vec3& n) const
{
  auto direction = [](double u, double v) {
    return Vec3(-std::sin(v) * std::cos(u), -std::cos(v) * std::cos(u), std::sin(u));
  };
  double sum = 0.0;
  for (const SkyCell& c : this->Cells)
  {
    double low = 1.0, high = -1.0;
    for (const Vec3& d : c.edges)
    {
      const double cosine = glm::dot(n, d);
      low = std::min(low, cosine);
      high = std::max(high, cosine);
    }
    if (high <= 0.0)
      continue;
    if (low >= 0.0)
    {
      sum += c.radiance * glm::dot(n, c.vectorSolidAngle);
      continue;
    }
    constexpr int parts = 4;
    const double s0 = std::sin(c.u0), s1 = std::sin(c.u1);
    for (int a = 0; a < parts; ++a)
      for (int b = 0; b < parts; ++b)
      {
        const double sinU = s0 + (a + 0.5) * (s1 - s0) / parts, v = c.v0 + (b + 0.5) * (c.v1 - c.v0) / parts;
        const double omega = (s1 - s0) * (c.v1 - c.v0) / (parts * parts);
        sum += c.radiance * omega * std::max(0.0, glm::dot(n, direction(std::asin(sinU), v)));
      }
  }
  return sum;
}

double PathTracer::skyRadiance(const Vec3& d) const
{
  if (!this->Sky || !(d.z > 0.0))
    return 0.0;
  // Altitude u and azimuth v (west from south) of d = (-sin v cos u, -cos v cos u, sin u).
  const double u = std::asin(std::min(1.0, d.z));
  double v = std::atan2(-d.x, -d.y);
  if (v < 0.0)
    v += 2.0 * pi;
  const int level = this->Sky->finestLevel(), side = terralux::SkyHierarchy::cellsPerSide(level);
  const int iu = std::min(side - 1, static_cast<int>(u / (0.5 * pi) * side));
  const int iv = std::min(side - 1, static_cast<int>(v / (2.0 * pi) * side));
  return this->Sky->radiance(terralux::SkyPatch{ level, iu, iv }, 0);
}

double PathTracer::directSun(const Vec3& point, const Vec3& normal) const
{
  double sum = 0.0;
  const double offset = this->Scene.offsetAt(point);
  for (const ReferenceSun& sun : this->Suns)
  {
    const double cosine = glm::dot(normal, sun.direction);
    if (cosine > 0.0 && sun.normalIrradiance > 0.0 &&
      !this->Scene.occluded(point + offset * normal, sun.direction, offset, std::numeric_limits<float>::infinity()))
      sum += sun.normalIrradiance * cosine;
  }
  return sum;
}

double PathTracer::radiosityAt(const Hit& hit, int depth, Random& random) const
{
  const double rho = hit.reflectance[0];
  double b = hit.emission[0];
  if (!(rho > 0.0))
    return b;
  // Russian roulette after the second bounce, survival in proportion to reflectance.
  double weight = 1.0;
  if (depth >= 2)
  {
    if (random.uniform() >= rho)
      return b;
    weight = 1.0 / rho;
  }
  return b + weight * rho * this->incidentAt(hit.position, hit.normal, depth + 1, random);
}

double PathTracer::incidentAt(const Vec3& point, const Vec3& normal, int depth, Random& random) const
{
  double e = this->directSun(point, normal);
  const Vec3 d = cosineDirection(normal, random.uniform(), random.uniform());
  const double offset = this->Scene.offsetAt(point);
  Hit hit;
  if (!this->Scene.intersect(point + offset * normal, d, 0.0, hit))
    return e + pi * this->skyRadiance(d);
  if (glm::dot(hit.normal, d) >= 0.0)
    return e; // the back of a one-sided surface sends nothing
  return e + this->radiosityAt(hit, depth, random);
}

Vec3 PathTracer::openSideOf(const Vec3& point, const Vec3& normal, Random& random) const
{
  const double offset = this->Scene.offsetAt(point);
  // Probe rays that escape or meet a front: what an open side sees.
  auto openness = [&](const Vec3& p) {
    constexpr int strata = 6;
    int open = 0;
    for (int a = 0; a < strata; ++a)
      for (int c = 0; c < strata; ++c)
      {
        const Vec3 d = cosineDirection(normal, (a + random.uniform()) / strata, (c + random.uniform()) / strata);
        Hit hit;
        if (!this->Scene.intersect(p + offset * normal, d, 0.0, hit) || glm::dot(hit.normal, d) < 0.0)
          ++open;
      }
    return open;
  };
  Vec3 t, b;
  frameOf(normal, t, b);
  Vec3 best = point;
  int most = openness(point);
  for (const Vec3& along : { t + b, t - b, -t + b, -t - b })
  {
    const Vec3 candidate = point + 2.0 * offset * glm::normalize(along);
    const int open = openness(candidate);
    if (open > most + 3) // clearly more open, not noise
    {
      best = candidate;
      most = open;
    }
  }
  return best;
}

ReferenceIrradiance PathTracer::irradianceAt(const Vec3& at, const Vec3& normal, int samples, std::uint64_t seed) const
{
  Random random(seed);
  const Vec3 point = this->openSideOf(at, normal, random);
  const int strata = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(samples)))));
  const int n = strata * strata;
  const double offset = this->Scene.offsetAt(point);
  double hidden = 0.0, hidden2 = 0.0, reflected = 0.0, reflected2 = 0.0, sum = 0.0, sum2 = 0.0;
  for (int a = 0; a < strata; ++a)
    for (int c = 0; c < strata; ++c)
    {
      const Vec3 d = cosineDirection(normal, (a + random.uniform()) / strata, (c + random.uniform()) / strata);
      double hiddenValue = 0.0, reflectedValue = 0.0;
      Hit hit;
      if (this->Scene.intersect(point + offset * normal, d, 0.0, hit))
      {
        hiddenValue = pi * this->skyRadiance(d); // sky the scene hides in this direction
        if (glm::dot(hit.normal, d) < 0.0)
          reflectedValue = this->radiosityAt(hit, 1, random);
      }
      hidden += hiddenValue;
      hidden2 += hiddenValue * hiddenValue;
      reflected += reflectedValue;
      reflected2 += reflectedValue * reflectedValue;
      sum += reflectedValue - hiddenValue;
      sum2 += (reflectedValue - hiddenValue) * (reflectedValue - hiddenValue);
    }
  // Standard errors as for independent samples: stratification only lowers them.
  auto estimate = [n](double s, double s2) {
    const double mean = s / n;
    const double variance = std::max(0.0, s2 / n - mean * mean);
    return Estimate{ mean, std::sqrt(variance / std::max(1, n - 1)) };
  };
  ReferenceIrradiance result;
  const double open = this->unoccludedSky(normal);
  result.sun = { this->directSun(at, normal), 0.0 };
  result.sky = estimate(hidden, hidden2);
  result.sky.mean = std::max(0.0, open - result.sky.mean);
  result.reflected = estimate(reflected, reflected2);
  result.global = estimate(sum, sum2);
  result.global.mean += result.sun.mean + open;
  return result;
}

std::vector<ReferenceIrradiance> PathTracer::irradianceAt(
  const std::vector<Vec3>& points, const std::vector<Vec3>& normals, int samples, std::uint64_t firstSeed) const
{
  std::vector<ReferenceIrradiance> results(points.size());
  tbb::parallel_for(std::size_t(0), points.size(),
    [&](std::size_t k) { results[k] = this->irradianceAt(points[k], normals[k], samples, firstSeed + k); });
  return results;
}
} // namespace terralux_reference
