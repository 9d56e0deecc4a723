#pragma once
// What the horizon sweeps share (horizon_map.cxx, horizon_window.cxx,
// horizon_handoff.cxx): where a line of
// posts crosses its grid's cells, and a fast arctangent for the horizons they find (and
// for the planes' elevations HorizonSky compares them with).

#include "base/angles.h"
#include "base/floor_divide.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace terralux
{
namespace horizon_lines
{
/// Where a line of step g crosses a cell edge or diagonal between two of its posts, as
/// offsets from the step's first post: at fraction t of the step, on the edge from post
/// (a0, b0) to (a1, b1) at fraction f, between cells c and d (the same for a diagonal).
struct Crossing
{
  double t, f;
  int a0, b0, a1, b1;
  int ci, cj, di, dj;
};

inline std::vector<Crossing> crossingsOf(int q, int p)
{
  std::vector<Crossing> crossings;
  const int aq = std::abs(q), ap = std::abs(p), as = std::abs(q + p);
  // Columns u = U between rows B and B + 1.
  for (int k = 1; k < aq; ++k)
  {
    const int U = q > 0 ? k : -k, B = floorDivide(p * k, aq);
    crossings.push_back({ static_cast<double>(k) / aq, static_cast<double>(p * k - B * aq) / aq, U, B, U, B + 1,
      U - 1, B, U, B });
  }
  // Rows v = V between columns A and A + 1.
  for (int k = 1; k < ap; ++k)
  {
    const int V = p > 0 ? k : -k, A = floorDivide(q * k, ap);
    crossings.push_back({ static_cast<double>(k) / ap, static_cast<double>(q * k - A * ap) / ap, A, V, A + 1, V,
      A, V - 1, A, V });
  }
  // Diagonals u + v = n inside cell (A, B), from (A + 1, B) to (A, B + 1): never at a
  // post or an edge when q and p have no common factor.
  for (int m = 1; m < as; ++m)
  {
    const int A = floorDivide(q * m, as), B = floorDivide(p * m, as);
    crossings.push_back({ static_cast<double>(m) / as, static_cast<double>(p * m - B * as) / as, A + 1, B, A, B + 1,
      A, B, A, B });
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
  return crossings;
}

/// atan of t >= 0 to 5e-8 rad (the map keeps 2.4e-5): reduced to |x| <= tan(pi / 12)
/// by atan t = pi / 2 - atan(1 / t) and atan t = pi / 6 + atan((sqrt 3 t - 1) / (sqrt 3
/// + t)), then its series to x^9 (the next term 3e-8). A quarter of libm's time, and the
/// sweep takes one per post and azimuth.
inline double atanOfPositive(double t)
{
  const bool inverted = t > 1.0;
  double x = inverted ? 1.0 / t : t;
  constexpr double sqrt3 = 1.7320508075688772, tanPiOver12 = 0.2679491924311227;
  const bool shifted = x > tanPiOver12;
  if (shifted)
    x = (sqrt3 * x - 1.0) / (sqrt3 + x);
  const double x2 = x * x;
  double a = x * (1.0 + x2 * (-1.0 / 3.0 + x2 * (1.0 / 5.0 + x2 * (-1.0 / 7.0 + x2 * (1.0 / 9.0)))));
  if (shifted)
    a += pi / 6.0;
  return inverted ? 0.5 * pi - a : a;
}

/// atan of any t, as atanOfPositive.
inline double atanOf(double t)
{
  return std::copysign(atanOfPositive(std::abs(t)), t);
}

} // namespace horizon_lines
} // namespace terralux
