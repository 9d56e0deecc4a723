#include "sky_patch_element.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace terralux
{
namespace
{
// 3-point Gauss-Legendre on [-1, 1].
const double nodes[3] = { -0.7745966692414834, 0.0, 0.7745966692414834 };
const double weights[3] = { 5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0 };
} // namespace

SkyPatchElement::SkyPatchElement(
  std::uint64_t id, int level, ElementStore* store, const SkyHierarchy* sky, SkyPatch patch)
  : HElement(id, level)
  , Store(store)
  , Sky(sky)
  , Patch(patch)
  , SolidAngle(patch.solidAngle())
{
  const terralux::Direction d = patch.direction();
  this->Direction = Vec3(d[0], d[1], d[2]);

  const terralux::Direction vector = patch.vectorSolidAngle();
  this->VectorSolidAngle = Vec3(vector[0], vector[1], vector[2]);
  const double u0 = patch.u0(), u1 = patch.u1(), v0 = patch.v0(), v1 = patch.v1();
  const double us[2] = { u0, u1 }, vs[2] = { v0, v1 };
  for (int k = 0; k < 4; ++k)
  {
    const terralux::Direction c = directionFromSkyParameters(us[k / 2], vs[k % 2]);
    this->CornerDirections[k] = Vec3(c[0], c[1], c[2]);
  }
  const double s0 = std::sin(u0), s1 = std::sin(u1);
  for (int a = 0; a < 3; ++a)
  {
    const double sinU = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * nodes[a];
    const double u = std::asin(std::min(1.0, std::max(0.0, sinU)));
    for (int b = 0; b < 3; ++b)
    {
      const double v = 0.5 * (v0 + v1) + 0.5 * (v1 - v0) * nodes[b];
      const terralux::Direction q = directionFromSkyParameters(u, v);
      this->QuadratureDirections[3 * a + b] = Vec3(q[0], q[1], q[2]);
      this->QuadratureWeights[3 * a + b] = 0.25 * (s1 - s0) * (v1 - v0) * weights[a] * weights[b];
    }
  }
  for (int band = 0; band < maxBands; ++band)
  {
    // A one-band sky lights every band alike.
    this->Radiance[band] = sky->radiance(patch, sky->bands() == 1 ? 0 : std::min(band, sky->bands() - 1));
  }
  // The radiance-weighted direction, over the sky's bands (exact for one band, and for
  // bands in proportion).
  Vec3 weighted(0.0);
  double radiance = 0.0;
  for (int band = 0; band < sky->bands(); ++band)
  {
    const terralux::Direction w = sky->irradianceVector(patch, band);
    weighted += Vec3(w[0], w[1], w[2]);
    radiance += sky->radiance(patch, band);
  }
  this->RadianceVector = radiance > 0.0 ? weighted / radiance : this->VectorSolidAngle;
}

int SkyPatchElement::sideOf(const Vec3& n) const
{
  // n . d = n_z sin u - cos u g(v), g(v) = n_x sin v + n_y cos v = h cos(v - phi).
  const double v0 = this->Patch.v0(), v1 = this->Patch.v1(), u0 = this->Patch.u0(), u1 = this->Patch.u1();
  auto g = [&](double v) { return n.x * std::sin(v) + n.y * std::cos(v); };
  double gLow = std::min(g(v0), g(v1)), gHigh = std::max(g(v0), g(v1));
  const double phi = std::atan2(n.x, n.y);
  constexpr double pi = 3.14159265358979323846;
  for (int k = -2; k <= 3; ++k) // the extremes of g at phi + k pi inside [v0, v1]
  {
    const double v = phi + k * pi;
    if (v > v0 && v < v1)
    {
      gLow = std::min(gLow, g(v));
      gHigh = std::max(gHigh, g(v));
    }
  }
  // For a fixed g, f(u) = n_z sin u - g cos u has its extremes at u0, u1 or where
  // f'(u) = n_z cos u + g sin u = 0; f is linear in g, so g's extremes suffice.
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (double gv : { gLow, gHigh })
  {
    auto f = [&](double u) { return n.z * std::sin(u) - gv * std::cos(u); };
    const double stationary = std::atan2(-n.z, gv); // tan u = -n_z / g
    for (double u : { u0, u1, stationary, stationary + pi, stationary - pi })
      if (u >= u0 && u <= u1)
      {
        low = std::min(low, f(u));
        high = std::max(high, f(u));
      }
  }
  constexpr double grazing = 1e-12;
  return low >= -grazing ? 1 : (high <= grazing ? -1 : 0);
}

double SkyPatchElement::kernel(const Vec3& normal) const
{
  if (this->sideOf(normal) > 0)
    return std::max(0.0, glm::dot(normal, this->RadianceVector));
  return this->projectedSolidAngle(normal);
}

double SkyPatchElement::geometricShare(const Vec3& normal) const
{
  if (this->sideOf(normal) <= 0)
    return 1.0;
  const double weighted = glm::dot(normal, this->RadianceVector);
  return weighted > 0.0 ? std::max(0.0, glm::dot(normal, this->VectorSolidAngle)) / weighted : 1.0;
}

double SkyPatchElement::projectedSolidAngle(const Vec3& normal) const
{
  const int side = this->sideOf(normal);
  if (side > 0)
    return std::max(0.0, glm::dot(normal, this->VectorSolidAngle));
  if (side < 0)
    return 0.0;
  double sum = 0.0;
  bool straddles = false;
  for (int k = 0; k < 9; ++k)
  {
    const double cosine = glm::dot(normal, this->QuadratureDirections[k]);
    straddles = straddles || cosine <= 0.0;
    sum += this->QuadratureWeights[k] * std::max(0.0, cosine);
  }
  for (const Vec3& corner : this->CornerDirections)
    straddles = straddles || glm::dot(normal, corner) <= 0.0;
  if (!straddles || sum == 0.0)
  {
    return sum;
  }
  // The surface's horizon crosses the patch: the kink of max(0, cos) needs finer
  // quadrature, 3 x 3 Gauss points in each of 8 x 8 sub-ranges; the 24 altitudes and 24
  // azimuths are shared, so this costs 48 sines and cosines, not one per point.
  constexpr int parts = 8, points = 3 * parts;
  const double s0 = std::sin(this->Patch.u0()), s1 = std::sin(this->Patch.u1());
  const double v0 = this->Patch.v0(), v1 = this->Patch.v1();
  const double ds = (s1 - s0) / parts, dv = (v1 - v0) / parts;
  double sinU[points], cosU[points], sinV[points], cosV[points], weight[points];
  for (int i = 0; i < parts; ++i)
    for (int a = 0; a < 3; ++a)
    {
      const int k = 3 * i + a;
      sinU[k] = s0 + ds * (i + 0.5 + 0.5 * nodes[a]);
      cosU[k] = std::sqrt(std::max(0.0, 1.0 - sinU[k] * sinU[k]));
      const double v = v0 + dv * (i + 0.5 + 0.5 * nodes[a]);
      sinV[k] = std::sin(v);
      cosV[k] = std::cos(v);
      weight[k] = weights[a];
    }
  sum = 0.0;
  for (int i = 0; i < points; ++i)
  {
    // directionFromSkyParameters: (-sin v cos u, -cos v cos u, sin u)
    const double up = normal.z * sinU[i];
    double row = 0.0;
    for (int j = 0; j < points; ++j)
    {
      const double cosine = up - cosU[i] * (normal.x * sinV[j] + normal.y * cosV[j]);
      row += weight[j] * std::max(0.0, cosine);
    }
    sum += weight[i] * row;
  }
  return 0.25 * ds * dv * sum;
}

const std::vector<HElement*>& SkyPatchElement::children()
{
  if (this->Children.empty() && this->canSplit())
  {
    SkyPatch kids[4];
    this->Patch.children(kids);
    for (const SkyPatch& kid : kids)
    {
      this->Children.push_back(this->Store->make<SkyPatchElement>(this->level() + 1, this->Store, this->Sky, kid));
      this->Children.back()->Parent = this;
    }
  }
  return this->Children;
}
} // namespace terralux
