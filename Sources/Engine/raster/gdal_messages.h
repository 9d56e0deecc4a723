#pragma once
// While alive, GDAL/OSR errors on this thread are recorded instead of printed,
// so the engine can put GDAL's own words into its exception messages.

#include <cpl_error.h>

#include <string>

namespace terralux
{
class QuietGdalErrors
{
public:
  QuietGdalErrors()
  {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdalErrors() { CPLPopErrorHandler(); }
  QuietGdalErrors(const QuietGdalErrors&) = delete;
  QuietGdalErrors& operator=(const QuietGdalErrors&) = delete;

  std::string lastMessage() const
  {
    const char* message = CPLGetLastErrorMsg();
    return (message && *message) ? message : "no details from GDAL";
  }
};
} // namespace terralux
