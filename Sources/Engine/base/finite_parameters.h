#pragma once
// Numeric parameters checked before use: vtkSetClampMacro lets NaN through (every
// comparison with NaN is false), so each adapter names its parameters here once.

#include "base/error.h"

#include <cmath>
#include <initializer_list>
#include <string>

namespace terralux
{
struct NamedParameter
{
  const char* name;
  double value;
};

/// Throws Error naming the first parameter that is NaN or infinite.
inline void requireFiniteParameters(std::initializer_list<NamedParameter> parameters)
{
  for (const NamedParameter& parameter : parameters)
    if (!std::isfinite(parameter.value))
    {
      throw Error(std::string(parameter.name) + " is " + (std::isnan(parameter.value) ? "NaN" : "infinite") +
        ": set it to a finite number (Set" + parameter.name + "())");
    }
}
} // namespace terralux
