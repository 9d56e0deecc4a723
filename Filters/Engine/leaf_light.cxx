#include "leaf_light.h"

namespace terralux
{
LeafLight::LeafLight(std::size_t elements)
  : Sky(elements)
  , Reflected(elements)
  , Known(elements, 0)
{
}

void LeafLight::set(std::uint64_t id, const Spectrum& sky, const Spectrum& reflected)
{
  this->Sky[id] = sky;
  this->Reflected[id] = reflected;
  this->Known[id] = 1;
}

bool LeafLight::at(std::uint64_t id, Spectrum& sky, Spectrum& reflected) const
{
  if (id >= this->Known.size() || !this->Known[id])
    return false;
  sky = this->Sky[id];
  reflected = this->Reflected[id];
  return true;
}
} // namespace terralux
