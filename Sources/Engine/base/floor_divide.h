#pragma once
// Integer division rounded down (toward minus infinity) for a positive divisor: grid
// indices of lines, cells and nodes that may lie before index 0.

namespace terralux
{
template <typename Integer>
inline Integer floorDivide(Integer a, Integer b)
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
} // namespace terralux
