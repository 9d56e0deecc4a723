#include "hierarchy/helement.h"

namespace terralux
{
void HElement::resetSolution()
{
  this->Radiosity = {};
  this->Gathered = {};
  this->GatheredPartial = 0.0;
  this->GatheredSkyView = 0.0;
  this->Incoming = {}; // its memory too: a kept hierarchy holds no links between solves
}

void ElementStore::restore(std::size_t count)
{
  count = std::min(count, this->Elements.size());
  for (std::size_t k = 0; k < count; ++k)
  {
    this->Elements[k]->forgetChildrenFrom(this->FirstId + count);
    this->Elements[k]->resetSolution();
  }
  this->Elements.resize(count);
}
} // namespace terralux
