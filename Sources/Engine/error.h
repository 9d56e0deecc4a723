#pragma once
// Errors of the TerraLux engines: one exception type whose message names the
// problem and, where there is one, the fix. The VTK adapters turn it into
// vtkErrorMacro and an empty output.

#include <stdexcept>
#include <string>

namespace terralux
{
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& message)
    : std::runtime_error(message)
  {
  }
};
} // namespace terralux
