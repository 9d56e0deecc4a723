#include "cumulative_sky.h"

#include "error.h"

namespace terralux
{
CumulativeSky::CumulativeSky(int finestLevel, int bands)
  : Level(finestLevel)
  , Bands(bands)
{
  const std::size_t side = static_cast<std::size_t>(SkyHierarchy::cellsPerSide(finestLevel));
  this->Sums.assign(side * side * static_cast<std::size_t>(bands), 0.0);
}

void CumulativeSky::add(const SkyHierarchy& sky, double hours)
{
  if (sky.finestLevel() != this->Level || sky.bands() != this->Bands)
    throw Error("a cumulative sky sums skies of one level and number of bands");
  const int side = SkyHierarchy::cellsPerSide(this->Level);
  for (int iu = 0; iu < side; ++iu)
    for (int iv = 0; iv < side; ++iv)
      for (int band = 0; band < this->Bands; ++band)
        this->Sums[(static_cast<std::size_t>(iu) * side + iv) * this->Bands + band] +=
          hours * sky.radiance(SkyPatch{ this->Level, iu, iv }, band);
  ++this->Steps;
}

std::unique_ptr<SkyHierarchy> CumulativeSky::hierarchy() const
{
  if (this->Steps == 0)
    return nullptr;
  return std::make_unique<SkyHierarchy>(SkyHierarchy::fromCellAverages(this->Level, this->Bands, this->Sums));
}
} // namespace terralux
