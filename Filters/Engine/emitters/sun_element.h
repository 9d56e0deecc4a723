#pragma once
// The sun as a parallel source (paper section 5.2): one direction, never splits;
// dE = R S phi with R the receiver's cosine.

#include "emitters/external_source.h"

#include <algorithm>

namespace terralux
{
class SunElement : public ExternalSource
{
public:
  /// `flux`: normal irradiance (W/m^2 per band); `duration`: hours this sun stands for
  /// (a time series' step), 0 for an instant.
  SunElement(std::uint64_t id, int level, const Vec3& direction, const Spectrum& flux, double duration = 0.0)
    : ExternalSource(id, level)
    , Direction(glm::normalize(direction))
    , Flux(flux)
    , Duration(duration)
  {
  }
  Kind kind() const override { return Kind::Sun; }
  Spectrum emittance() const override { return this->Flux; }
  const std::vector<HElement*>& children() override { return this->None; }
  bool canSplit() const override { return false; }

  const Vec3& direction() const override { return this->Direction; }
  double kernel(const Vec3& normal) const override { return std::max(0.0, glm::dot(normal, this->Direction)); }
  double kernelToward(const HElement& receiver, const Vec3&) const override
  {
    return receiver.receiverFactor(this->Direction);
  }
  double directionalKernel() const override { return 1.0; }
  Vec3 sampleDirection(SampleGenerator&) const override { return this->Direction; }
  bool parallel() const override { return true; }
  LightCategory category() const override { return SunLight; }
  double hemisphereShare() const override { return 0.0; }
  double skyView(const Vec3&, double) const override { return 0.0; }
  double duration() const override { return this->Duration; }

private:
  Vec3 Direction;
  Spectrum Flux;
  double Duration;
  std::vector<HElement*> None;
};
} // namespace terralux
