#pragma once
// The circle's constants, written once for the engines and the adapters.

namespace terralux
{
constexpr double pi = 3.14159265358979323846;
constexpr double twoPi = 2.0 * pi;
/// One degree in radians: angleDeg * degree is the angle in radians.
constexpr double degree = pi / 180.0;
} // namespace terralux
