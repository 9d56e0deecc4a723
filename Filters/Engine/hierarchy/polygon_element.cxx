#include "hierarchy/polygon_element.h"

#include "evaluation/point_form_factor.h"

#include <algorithm>
#include <limits>

namespace terralux
{
double PolygonElement::areaAndNormal(const Vec3* corners, int count, Vec3& normal)
{
  Vec3 sum(0.0);
  for (int k = 1; k + 1 < count; ++k)
  {
    sum += glm::cross(corners[k] - corners[0], corners[k + 1] - corners[0]);
  }
  const double length = glm::length(sum);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    normal = Vec3(0.0, 0.0, 1.0);
    return 0.0;
  }
  normal = sum / length;
  return 0.5 * length;
}

PolygonElement::PolygonElement(std::uint64_t id, int level, ElementStore* store, const Vec3* corners,
  int count, const Spectrum& reflectance, const Spectrum& emission, int rootPolygon)
  : HElement(id, level)
  , Store(store)
  , Count(count)
  , Reflectance(reflectance)
  , Emission(emission)
  , RootPolygon(rootPolygon)
{
  for (int k = 0; k < count; ++k)
  {
    this->Corners[k] = corners[k];
    this->Centre += corners[k];
  }
  this->Centre /= static_cast<double>(count);
  this->Area = areaAndNormal(corners, count, this->Normal);
  this->Radiosity = emission;
}

const std::vector<HElement*>& PolygonElement::children()
{
  if (!this->Children.empty() || !this->canSplit())
  {
    return this->Children;
  }
  const Vec3* c = this->Corners;
  auto child = [&](std::initializer_list<Vec3> corners) {
    this->Children.push_back(this->Store->make<PolygonElement>(this->level() + 1, this->Store,
      corners.begin(), static_cast<int>(corners.size()), this->Reflectance, this->Emission,
      this->RootPolygon));
  };
  if (this->Count == 3)
  {
    const Vec3 ab = 0.5 * (c[0] + c[1]), bc = 0.5 * (c[1] + c[2]), ca = 0.5 * (c[2] + c[0]);
    child({ c[0], ab, ca });
    child({ ab, c[1], bc });
    child({ ca, bc, c[2] });
    child({ ab, bc, ca });
  }
  else
  {
    const Vec3 ab = 0.5 * (c[0] + c[1]), bc = 0.5 * (c[1] + c[2]), cd = 0.5 * (c[2] + c[3]),
               da = 0.5 * (c[3] + c[0]), o = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    child({ c[0], ab, o, da });
    child({ ab, c[1], bc, o });
    child({ o, bc, c[2], cd });
    child({ da, o, cd, c[3] });
  }
  for (HElement* kid : this->Children)
  {
    kid->Radiosity = this->Radiosity;
    kid->Parent = this;
  }
  return this->Children;
}

void PolygonElement::resetSolution()
{
  HElement::resetSolution();
  this->Radiosity = this->Emission;
  this->Irradiance = {};
  this->SkyViewFactor = 0.0;
  this->LeafKernels = {};
  this->LeafKernelKeys = {};
  this->LeafKernelPartial = {};
  this->LeafKernelSignature = 0;
  this->PartialIrradiance = 0.0;
  this->DeferredPartial = 0.0;
  this->DeferredSkyView = 0.0;
}

void PolygonElement::forgetChildrenFrom(std::uint64_t firstId)
{
  // Siblings are made together: all by refinement, or all (a terrain's structural
  // patches around missing cells) when the hierarchy was built.
  if (!this->Children.empty() && this->Children.front()->id() >= firstId)
    this->Children.clear();
}

double PolygonElement::receivedIrradiance() const
{
  double total = 0.0;
  for (const Spectrum& category : this->Irradiance)
    total += largestBand(category);
  return total;
}

const PolygonElement* PolygonElement::leafHolding(const Vec3& p) const
{
  const PolygonElement* element = this;
  while (!element->Children.empty())
  {
    const PolygonElement* deepest = nullptr;
    double best = -std::numeric_limits<double>::infinity();
    for (const HElement* child : element->Children)
    {
      const auto* part = static_cast<const PolygonElement*>(child);
      // Smallest signed distance of p inside the part's edges (all corners share the plane).
      double margin = std::numeric_limits<double>::infinity();
      for (int k = 0; k < part->Count; ++k)
      {
        const Vec3& a = part->Corners[k];
        const Vec3 edge = part->Corners[(k + 1) % part->Count] - a;
        const double length = glm::length(edge);
        if (length > 0.0)
          margin = std::min(margin, glm::dot(glm::cross(edge, p - a), part->Normal) / length);
      }
      if (margin > best)
      {
        best = margin;
        deepest = part;
      }
    }
    if (!deepest)
      break;
    element = deepest;
  }
  return element;
}

SurfaceSample PolygonElement::sample(int k, int n, SampleGenerator& random) const
{
  double s, t;
  stratifiedPoint(k, n, random, s, t);
  const Vec3* c = this->Corners;
  Vec3 p;
  if (this->Count == 3)
  {
    if (s + t > 1.0)
    {
      s = 1.0 - s;
      t = 1.0 - t;
    }
    p = c[0] + s * (c[1] - c[0]) + t * (c[2] - c[0]);
  }
  else
  {
    p = (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + s * t * c[2] + (1 - s) * t * c[3];
  }
  return { p, this->Normal };
}

double PolygonElement::formFactorFrom(const Vec3& x, const Vec3& n) const
{
  return pointToPolygonFormFactor(x, n, this->Corners, this->Count, this->Normal);
}

void PolygonElement::bounds(Vec3& low, Vec3& high) const
{
  low = high = this->Corners[0];
  for (int k = 1; k < this->Count; ++k)
  {
    low = glm::min(low, this->Corners[k]);
    high = glm::max(high, this->Corners[k]);
  }
}

double PolygonElement::receiverFactor(const Vec3& towardSender) const
{
  return std::max(0.0, glm::dot(this->Normal, towardSender));
}
} // namespace terralux
