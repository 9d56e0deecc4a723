#pragma once
// Deterministic stratified sampling: every link draws its jitter from a generator
// seeded by the ids of its two elements, so results do not depend on thread order.

#include <cstdint>

namespace terralux
{
/// SplitMix64: small, fast, good enough for jitter.
class SampleGenerator
{
public:
  explicit SampleGenerator(std::uint64_t seed)
    : State(seed)
  {
  }
  std::uint64_t next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double uniform() { return (this->next() >> 11) * (1.0 / 9007199254740992.0); }

private:
  std::uint64_t State;
};

inline std::uint64_t linkSeed(std::uint64_t receiverId, std::uint64_t senderId)
{
  return receiverId * 0x9E3779B97F4A7C15ull ^ (senderId + 0x632BE59BD9B4E019ull);
}

/// A point's or leaf's seed drawn again under a user's random seed (the same where that
/// is 0, the default).
inline std::uint64_t reseeded(std::uint64_t seed, std::uint64_t randomSeed)
{
  if (randomSeed == 0)
    return seed;
  // SplitMix64's finaliser of the user's seed: neighbouring seeds draw unrelated rays.
  std::uint64_t z = randomSeed * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return seed ^ (z ^ (z >> 31));
}

/// The k-th of n stratified, jittered points of the unit square.
inline void stratifiedPoint(int k, int n, SampleGenerator& random, double& s, double& t)
{
  int columns = 1;
  while (columns * columns < n)
    ++columns;
  const int rows = (n + columns - 1) / columns;
  s = ((k % columns) + random.uniform()) / columns;
  t = ((k / columns) + random.uniform()) / rows;
}
} // namespace terralux
