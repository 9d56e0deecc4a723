#include "sky_patch_element.h"

namespace terralux
{
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
  for (int band = 0; band < maxBands; ++band)
  {
    // A one-band sky lights every band alike.
    this->Radiance[band] = sky->radiance(patch, sky->bands() == 1 ? 0 : std::min(band, sky->bands() - 1));
  }
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
