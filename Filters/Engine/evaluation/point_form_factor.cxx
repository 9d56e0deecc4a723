#include "evaluation/point_form_factor.h"

#include "base/angles.h"

#include <cmath>

namespace terralux
{
double pointToPolygonFormFactor(
  const Vec3& x, const Vec3& n, const Vec3* polygon, int count, const Vec3& senderNormal)
{
  // One-sided emitters: x must be in front of the sender.
  if (glm::dot(senderNormal, x - polygon[0]) <= 0.0)
  {
    return 0.0;
  }
  // Clip to the half-space in front of x (Sutherland-Hodgman against one plane).
  Vec3 clipped[8];
  int clippedCount = 0;
  const double eps = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % count];
    const double da = glm::dot(n, a - x), db = glm::dot(n, b - x);
    if (da > eps)
    {
      clipped[clippedCount++] = a;
    }
    if ((da > eps) != (db > eps))
    {
      const double t = da / (da - db);
      clipped[clippedCount++] = a + t * (b - a);
    }
  }
  if (clippedCount < 3)
  {
    return 0.0;
  }
  double sum = 0.0;
  for (int i = 0; i < clippedCount; ++i)
  {
    const Vec3 a = glm::normalize(clipped[i] - x);
    const Vec3 b = glm::normalize(clipped[(i + 1) % clippedCount] - x);
    const Vec3 c = glm::cross(a, b);
    const double length = glm::length(c);
    if (length < 1e-300)
    {
      continue;
    }
    const double angle = std::atan2(length, glm::dot(a, b));
    sum += angle * glm::dot(n, c) / length;
  }
  return std::abs(sum) / (2.0 * pi);
}
} // namespace terralux
