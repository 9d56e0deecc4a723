// Large arrays on huge pages (large_arrays.h): aligned to a huge page from the threshold
// on, the heap's own below it, and vectors of them behave as std::vector does.
#include "base/large_arrays.h"
#include "base/uninitialized_vector.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

using namespace terralux;

TEST(LargeArrays, LargeVectorsAreAlignedToAHugePageAndKeepTheirValues)
{
  LargeVector<double> values(large_arrays::threshold / sizeof(double) + 7);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % large_arrays::hugePage, 0u);
  std::iota(values.begin(), values.end(), 0.0);
  values.resize(3 * values.size()); // moved to a larger huge-page block
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % large_arrays::hugePage, 0u);
  EXPECT_EQ(values[12345], 12345.0);
  EXPECT_EQ(values[large_arrays::threshold / sizeof(double) + 6], static_cast<double>(large_arrays::threshold / sizeof(double) + 6));
  values.resize(10);
  values.shrink_to_fit(); // back to the heap's own memory
  EXPECT_EQ(values[9], 9.0);
  LargeVector<float> small(100, 1.5f);
  EXPECT_EQ(small[99], 1.5f);
}

TEST(LargeArrays, UninitializedVectorsTakeHugePagesToo)
{
  UninitializedVector<std::uint16_t> elevations;
  elevations.resize(large_arrays::threshold); // 8 MiB of uint16
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(elevations.data()) % large_arrays::hugePage, 0u);
  elevations.back() = 7;
  EXPECT_EQ(elevations.back(), 7);
}
