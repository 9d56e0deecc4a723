#include "emitters/sky_patch_element.h"

#include "base/angles.h"

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

// Integral of max(0, a - b cos w) over w in [w0, w1], b >= 0: a - b cos w > 0 where
// cos w < a / b, i.e. on [alpha, 2 pi - alpha] + 2 pi k with alpha = acos(a / b).
// sinW0 and sinW1 are sin w0 and sin w1, the same for every row of a patch.
double positiveCosineIntegral(double a, double b, double w0, double w1, double sinW0, double sinW1)
{
  auto sine = [&](double w) { return w == w0 ? sinW0 : (w == w1 ? sinW1 : std::sin(w)); };
  auto piece = [&](double lo, double hi) { return hi > lo ? a * (hi - lo) - b * (sine(hi) - sine(lo)) : 0.0; };
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
  : ExternalSource(id, level)
  , Store(store)
  , Sky(sky)
  , Patch(patch)
  , SolidAngle(patch.solidAngle())
{
  const terralux::Direction d = patch.direction();
  this->Direction = Vec3(d[0], d[1], d[2]);
  const double u0 = patch.u0(), u1 = patch.u1(), v0 = patch.v0(), v1 = patch.v1();
  this->Range = { u0, u1, v0, v1, std::sin(u0), std::cos(u0), std::sin(u1), std::cos(u1), std::sin(v0), std::cos(v0),
    std::sin(v1), std::cos(v1) };

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

  const int finest = sky->finestLevel();
  if (patch.level < finest)
  {
    const int per = 1 << (finest - patch.level);
    this->CellsPerSide = per;
    this->CellCdf.resize(static_cast<std::size_t>(per) * per);
    double sum = 0.0;
    for (int a = 0; a < per; ++a)
    {
      const SkyPatch row{ finest, patch.iu * per + a, 0 };
      const double weight = 0.5 * (std::pow(std::sin(row.u1()), 2) - std::pow(std::sin(row.u0()), 2));
      for (int b = 0; b < per; ++b)
      {
        const SkyPatch cell{ finest, patch.iu * per + a, patch.iv * per + b };
        double l = 0.0;
        for (int band = 0; band < sky->bands(); ++band)
          l += sky->radiance(cell, band);
        sum += l * weight;
        this->CellCdf[static_cast<std::size_t>(a) * per + b] = static_cast<float>(sum);
      }
    }
    if (sum > 0.0)
      for (float& c : this->CellCdf)
        c = static_cast<float>(c / sum);
    else
      this->CellCdf.clear();
  }
}

Vec3 SkyPatchElement::uniformDirection(double u0, double u1, double v0, double v1, SampleGenerator& random)
{
  const double s0 = std::sin(u0), s1 = std::sin(u1);
  const double s = std::min(1.0, std::sqrt(s0 * s0 + random.uniform() * (s1 * s1 - s0 * s0)));
  const double v = v0 + random.uniform() * (v1 - v0);
  const double c = std::sqrt(1.0 - s * s); // cos u
  return Vec3(-std::sin(v) * c, -std::cos(v) * c, s); // as directionFromSkyParameters
}

Vec3 SkyPatchElement::sampleDirection(SampleGenerator& random) const
{
  const SkyPatch& p = this->Patch;
  if (this->CellCdf.empty())
    return uniformDirection(p.u0(), p.u1(), p.v0(), p.v1(), random);
  const float x = static_cast<float>(random.uniform());
  const std::size_t k = std::min<std::size_t>(
    std::lower_bound(this->CellCdf.begin(), this->CellCdf.end(), x) - this->CellCdf.begin(), this->CellCdf.size() - 1);
  const int per = this->CellsPerSide, a = static_cast<int>(k) / per, b = static_cast<int>(k) % per;
  const double du = (p.u1() - p.u0()) / per, dv = (p.v1() - p.v0()) / per;
  return uniformDirection(p.u0() + a * du, p.u0() + (a + 1) * du, p.v0() + b * dv, p.v0() + (b + 1) * dv, random);
}

SkyPatchElement::PlaneTerms::PlaneTerms(const Vec3& normal)
  : horizontal(std::hypot(normal.x, normal.y))
  , phi(std::atan2(normal.x, normal.y))
{
}

int SkyPatchElement::sideOf(const Vec3& n, const PlaneTerms& plane) const
{
  // n . d = n_z sin u - cos u g(v), g(v) = n_x sin v + n_y cos v = h cos(v - phi).
  const Bounds& r = this->Range;
  auto g = [&](double v) { return n.x * std::sin(v) + n.y * std::cos(v); };
  const double g0 = n.x * r.sinV0 + n.y * r.cosV0, g1 = n.x * r.sinV1 + n.y * r.cosV1;
  double gLow = std::min(g0, g1), gHigh = std::max(g0, g1);
  for (int k = -2; k <= 3; ++k) // the extremes of g at phi + k pi inside [v0, v1]
  {
    const double v = plane.phi + k * pi;
    if (v > r.v0 && v < r.v1)
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
    auto extend = [&](double f) {
      low = std::min(low, f);
      high = std::max(high, f);
    };
    extend(n.z * r.sinU0 - gv * r.cosU0);
    extend(n.z * r.sinU1 - gv * r.cosU1);
    const double stationary = std::atan2(-n.z, gv); // tan u = -n_z / g
    for (double u : { stationary, stationary + pi, stationary - pi })
      if (u >= r.u0 && u <= r.u1)
        extend(n.z * std::sin(u) - gv * std::cos(u));
  }
  constexpr double grazing = 1e-12;
  return low >= -grazing ? 1 : (high <= grazing ? -1 : 0);
}

double SkyPatchElement::kernel(const Vec3& normal) const
{
  double kernel = 0.0, projected = 0.0;
  this->kernelAndProjection(normal, kernel, projected);
  return kernel;
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
  double kernel = 0.0, projected = 0.0;
  this->kernelAndProjection(normal, kernel, projected);
  return projected;
}

void SkyPatchElement::kernelAndProjection(const Vec3& normal, double& kernel, double& projected) const
{
  const PlaneTerms plane(normal);
  this->kernelAndProjection(normal, plane, this->sideOf(normal, plane), kernel, projected);
}

void SkyPatchElement::kernelAndProjection(
  const Vec3& normal, const PlaneTerms& plane, int side, double& kernel, double& projected) const
{
  if (side > 0)
  {
    kernel = std::max(0.0, glm::dot(normal, this->RadianceVector));
    projected = std::max(0.0, glm::dot(normal, this->VectorSolidAngle));
  }
  else
    kernel = projected = side < 0 ? 0.0 : this->straddlingProjection(normal, plane);
}

double SkyPatchElement::straddlingProjection(const Vec3& normal, const PlaneTerms& plane) const
{
  // The surface's horizon crosses the patch. With s = sin u (dOmega = ds dv) and
  // n . d = n_z s - sqrt(1 - s^2) h cos(v - phi), each row of constant s integrates
  // max(0, n . d) over v in closed form; the rows are summed by Gauss-Legendre over s,
  // split where a row turns wholly lit or wholly dark (the kinks in s).
  const double h = plane.horizontal;
  const double w0 = this->Range.v0 - plane.phi, w1 = this->Range.v1 - plane.phi;
  const double sinW0 = std::sin(w0), sinW1 = std::sin(w1);
  auto row = [&](double sinU) {
    const double a = normal.z * sinU, b = std::sqrt(std::max(0.0, 1.0 - sinU * sinU)) * h;
    return positiveCosineIntegral(a, b, w0, w1, sinW0, sinW1);
  };
  const double s0 = this->Range.sinU0, s1 = this->Range.sinU1;
  // a = +-b where n_z s = +-h sqrt(1 - s^2): s = h / sqrt(n_z^2 + h^2) = h (unit normal).
  std::array<double, 3> breaks{ s0, s1, s1 };
  std::size_t count = 2;
  if (h > s0 && h < s1)
    breaks[1] = h, count = 3;
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < count; ++k)
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
