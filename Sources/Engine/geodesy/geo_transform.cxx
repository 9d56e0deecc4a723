#include "geodesy/geo_transform.h"

#include "base/error.h"

#include <cmath>

namespace terralux
{
void GeoTransform::pixelToMap(double col, double row, double& x, double& y) const
{
  const auto& c = this->coefficients;
  x = c[0] + col * c[1] + row * c[2];
  y = c[3] + col * c[4] + row * c[5];
}

bool GeoTransform::isValid() const
{
  for (double value : this->coefficients)
  {
    if (!std::isfinite(value))
    {
      return false;
    }
  }
  const auto& c = this->coefficients;
  return c[1] * c[5] - c[2] * c[4] != 0.0;
}

void GeoTransform::mapToPixel(double x, double y, double& col, double& row) const
{
  const auto& c = this->coefficients;
  const double determinant = c[1] * c[5] - c[2] * c[4];
  if (determinant == 0.0 || !std::isfinite(determinant))
  {
    throw Error("the raster's geotransform is singular: pixel size must be non-zero");
  }
  const double dx = x - c[0];
  const double dy = y - c[3];
  col = (c[5] * dx - c[2] * dy) / determinant;
  row = (-c[4] * dx + c[1] * dy) / determinant;
}

GeoTransform GeoTransform::window(int col0, int row0, int stride) const
{
  // Corner of the new grid: the old pixel centre (col0 + 0.5, row0 + 0.5) minus
  // half a new pixel (stride / 2 old pixels).
  const double shift = 0.5 - 0.5 * stride;
  GeoTransform result;
  auto& r = result.coefficients;
  const auto& c = this->coefficients;
  this->pixelToMap(col0 + shift, row0 + shift, r[0], r[3]);
  r[1] = c[1] * stride;
  r[2] = c[2] * stride;
  r[4] = c[4] * stride;
  r[5] = c[5] * stride;
  return result;
}
} // namespace terralux
