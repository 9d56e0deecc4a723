#pragma once
// Shared by the fuzz targets: reading fuzzed bytes as values, silencing VTK's
// messages, and the checks that turn a wrong answer into a crash libFuzzer reports.

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkObject.h"
#include "vtkPointData.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace terralux_fuzz
{
/// Reads values off the front of the input; past its end, zeros.
class ByteReader
{
public:
  ByteReader(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  template <typename T>
  T take()
  {
    T value{};
    const std::size_t n = std::min(sizeof(T), this->Size - this->Position);
    std::memcpy(&value, this->Data + this->Position, n);
    this->Position += n;
    return value;
  }
  /// An integer in [low, high].
  int between(int low, int high)
  {
    const unsigned span = static_cast<unsigned>(high - low) + 1u;
    return low + static_cast<int>(this->take<std::uint16_t>() % span);
  }
  /// A double: raw bits half of the time (NaN, infinities, denormals), else a value
  /// spread over [-scale, scale].
  double number(double scale)
  {
    if (this->take<std::uint8_t>() & 1u)
      return this->take<double>();
    return scale * (this->take<std::int16_t>() / 32768.0);
  }
  const std::uint8_t* rest() const { return this->Data + this->Position; }
  std::size_t remaining() const { return this->Size - this->Position; }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

/// Messages of bad input are expected: keep the fuzzer's output readable.
inline void silenceVtk()
{
  vtkObject::GlobalWarningDisplayOff();
}

/// A finding: print it and abort, so libFuzzer keeps the input as a crash.
[[noreturn]] inline void finding(const char* what)
{
  std::fprintf(stderr, "terralux fuzz finding: %s\n", what);
  std::abort();
}

/// Every point coordinate and every value of every point array is finite (at the
/// points `checked` says, or all).
inline void requireFiniteOutput(vtkDataSet* data, const char* what, const std::vector<bool>* checked = nullptr)
{
  if (!data)
    return;
  for (vtkIdType k = 0; k < data->GetNumberOfPoints(); ++k)
  {
    if (checked && !(*checked)[k])
      continue;
    double p[3];
    data->GetPoint(k, p);
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      std::fprintf(stderr, "point %lld: %g %g %g\n", static_cast<long long>(k), p[0], p[1], p[2]);
      finding(what);
    }
  }
  vtkPointData* pointData = data->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    // Elevation and SkyViewFactor hold NaN at no-data posts by design.
    if (!array || !array->GetName() || std::strcmp(array->GetName(), "Elevation") == 0 ||
      std::strcmp(array->GetName(), "SkyViewFactor") == 0)
      continue;
    for (vtkIdType k = 0; k < array->GetNumberOfValues(); ++k)
    {
      if (checked && !(*checked)[k / array->GetNumberOfComponents()])
        continue;
      const double v = array->GetComponent(k / array->GetNumberOfComponents(), k % array->GetNumberOfComponents());
      if (!std::isfinite(v))
      {
        std::fprintf(stderr, "array %s value %lld: %g\n", array->GetName(), static_cast<long long>(k), v);
        finding(what);
      }
    }
  }
}
} // namespace terralux_fuzz
