#pragma once
// Wall-clock seconds for the phase timings the engine reports.

#include <chrono>

namespace terralux
{
inline double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace terralux
