#pragma once
// Errors of the TerraLux engines: one exception type whose message names the
// problem and, where there is one, the fix. The VTK adapters turn it into
// vtkErrorMacro and an empty output.

#include <sstream>
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

/// A number as a message shows it: shortest form, no trailing zeros (0.5, not 0.500000).
inline std::string numberText(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}
} // namespace terralux
