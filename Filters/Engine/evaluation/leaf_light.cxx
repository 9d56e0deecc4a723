#include "evaluation/leaf_light.h"

#include <algorithm>
#include <cmath>

namespace terralux
{
LeafLight::LeafLight(std::size_t elements, const std::vector<std::uint64_t>& leaves)
  : Slot(elements, -1)
  , Fits(leaves.size())
{
  for (std::size_t k = 0; k < leaves.size(); ++k)
    this->Slot[leaves[k]] = static_cast<std::int32_t>(k);
}

double LeafLight::Plane::at(int band, const Vec3& offset) const
{
  return std::clamp(this->mean[band] + glm::dot(this->slope[band], offset), this->low[band], this->high[band]);
}

void LeafLight::set(std::size_t k, const Vec3& normal, const std::vector<Sample>& samples)
{
  if (samples.empty())
    return;
  Fit& fit = this->Fits[k];
  const double n = static_cast<double>(samples.size());
  for (const Sample& s : samples)
    fit.centre += s.point / n;
  // Coordinates in the leaf's plane; the normal equations of a plane through the mean.
  Vec3 u, v;
  tangentsOf(normal, u, v);
  std::vector<double> xs, ys; // each point's coordinates, once
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (const Sample& s : samples)
  {
    const double x = glm::dot(s.point - fit.centre, u), y = glm::dot(s.point - fit.centre, v);
    xs.push_back(x), ys.push_back(y);
    xx += x * x, xy += x * y, yy += y * y;
  }
  const double determinant = xx * yy - xy * xy;
  // Fewer than three points, or all on a line: the mean alone.
  const bool sloped = samples.size() >= 3 && determinant > 1e-6 * (xx + yy) * (xx + yy);
  auto fitPlane = [&](Plane& plane, auto value) {
    for (int band = 0; band < maxBands; ++band)
    {
      double mean = 0.0, xf = 0.0, yf = 0.0, low = value(samples[0], band), high = low;
      for (const Sample& s : samples)
        mean += value(s, band) / n;
      for (std::size_t k = 0; k < samples.size(); ++k)
      {
        const double f = value(samples[k], band) - mean;
        xf += xs[k] * f, yf += ys[k] * f;
        low = std::min(low, value(samples[k], band)), high = std::max(high, value(samples[k], band));
      }
      plane.mean[band] = mean, plane.low[band] = low, plane.high[band] = high;
      if (sloped)
        plane.slope[band] = ((yy * xf - xy * yf) / determinant) * u + ((xx * yf - xy * xf) / determinant) * v;
    }
  };
  fitPlane(fit.sky, [](const Sample& s, int band) { return s.sky[band]; });
  fitPlane(fit.reflected, [](const Sample& s, int band) { return s.reflected[band]; });
  fit.known = true;
}

const LeafLight::Fit* LeafLight::fitOf(std::uint64_t id) const
{
  if (id >= this->Slot.size() || this->Slot[id] < 0)
    return nullptr;
  const Fit& fit = this->Fits[static_cast<std::size_t>(this->Slot[id])];
  return fit.known ? &fit : nullptr;
}

bool LeafLight::mean(std::uint64_t id, Spectrum& sky, Spectrum& reflected) const
{
  const Fit* fit = this->fitOf(id);
  if (!fit)
    return false;
  sky = fit->sky.mean;
  reflected = fit->reflected.mean;
  return true;
}

bool LeafLight::at(std::uint64_t id, const Vec3& point, Spectrum& sky, Spectrum& reflected) const
{
  const Fit* found = this->fitOf(id);
  if (!found)
    return false;
  const Fit& fit = *found;
  const Vec3 offset = point - fit.centre;
  for (int band = 0; band < maxBands; ++band)
  {
    sky[band] = fit.sky.at(band, offset);
    reflected[band] = fit.reflected.at(band, offset);
  }
  return true;
}
} // namespace terralux
