#include "sky_patch_element.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace terralux
{
namespace
{
// 8-point Gauss-Legendre on [-1, 1].
const double gauss8Nodes[8] = { -0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
  -0.1834346424956498, 0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363 };
const double gauss8Weights[8] = { 0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
  0.3626837833783620, 0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763 };
constexpr double twoPi = 6.28318530717958647692;

// Integral of max(0, a - b cos w) over w in [w0, w1], b >= 0: a - b cos w > 0 where
// cos w < a / b, i.e. on [alpha, 2 pi - alpha] + 2 pi k with alpha = acos(a / b).
double positiveCosineIntegral(double a, double b, double w0, double w1)
{
  auto piece = [&](double lo, double hi) { return hi > lo ? a * (hi - lo) - b * (std::sin(hi) - std::sin(lo)) : 0.0; };
  if (b <= 1e-15 * std::abs(a) || a >= b)
    return b <= 1e-15 * std::abs(a) ? std::max(0.0, a) * (w1 - w0) : piece(w0, w1);
  if (a <= -b)
    return 0.0;
  const double alpha = std::acos(a / b);
  double sum = 0.0;
  for (double k = std::floor((w0 - twoPi) / twoPi); k <= std::ceil(w1 / twoPi); k += 1.0)
    sum += piece(std::max(w0, alpha + twoPi * k), std::min(w1, twoPi - alpha + twoPi * k));
  return sum;
}
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
  // The surface's horizon crosses the patch. With s = sin u (dOmega = ds dv) and
  // n . d = n_z s - sqrt(1 - s^2) h cos(v - phi), each row of constant s integrates
  // max(0, n . d) over v in closed form; the rows are summed by Gauss-Legendre over s,
  // split where a row turns wholly lit or wholly dark (the kinks in s).
  const double h = std::hypot(normal.x, normal.y), phi = std::atan2(normal.x, normal.y);
  const double w0 = this->Patch.v0() - phi, w1 = this->Patch.v1() - phi;
  auto row = [&](double sinU) {
    const double a = normal.z * sinU, b = std::sqrt(std::max(0.0, 1.0 - sinU * sinU)) * h;
    return positiveCosineIntegral(a, b, w0, w1);
  };
  const double s0 = std::sin(this->Patch.u0()), s1 = std::sin(this->Patch.u1());
  // a = +-b where n_z s = +-h sqrt(1 - s^2): s = h / sqrt(n_z^2 + h^2) = h (unit normal).
  std::vector<double> breaks{ s0, s1 };
  if (h > s0 && h < s1)
    breaks.push_back(h);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
  {
    const double lo = breaks[k], hi = breaks[k + 1];
    for (int g = 0; g < 8; ++g)
      sum += 0.5 * (hi - lo) * gauss8Weights[g] * row(0.5 * (lo + hi) + 0.5 * (hi - lo) * gauss8Nodes[g]);
  }
  return sum;
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
