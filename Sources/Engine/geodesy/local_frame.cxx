#include "geodesy/local_frame.h"

#include "base/error.h"

#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <sstream>

namespace terralux
{
struct LocalFrame::Impl
{
  GeographicLib::LocalCartesian cartesian;
};

LocalFrame::LocalFrame(const GeodeticPoint& origin)
  : Origin(origin)
{
  if (!std::isfinite(origin.latitudeDeg) || !std::isfinite(origin.longitudeDeg) ||
    !std::isfinite(origin.heightM) || std::abs(origin.latitudeDeg) > 90.0)
  {
    std::ostringstream message;
    message << "invalid geographic origin (lat " << origin.latitudeDeg << ", lon "
            << origin.longitudeDeg << ", height " << origin.heightM
            << "): give a finite latitude in [-90, 90] degrees, longitude in degrees and "
               "height in metres";
    throw Error(message.str());
  }
  this->Cartesian = std::make_unique<Impl>(
    Impl{ GeographicLib::LocalCartesian(origin.latitudeDeg, origin.longitudeDeg, origin.heightM) });
}

LocalFrame::LocalFrame(const LocalFrame& other)
  : Origin(other.Origin)
  , Cartesian(std::make_unique<Impl>(*other.Cartesian))
{
}

LocalFrame& LocalFrame::operator=(const LocalFrame& other)
{
  if (this != &other)
  {
    this->Origin = other.Origin;
    this->Cartesian = std::make_unique<Impl>(*other.Cartesian);
  }
  return *this;
}

LocalFrame::~LocalFrame() = default;

LocalPoint LocalFrame::toLocal(const GeodeticPoint& point) const
{
  LocalPoint local;
  this->Cartesian->cartesian.Forward(
    point.latitudeDeg, point.longitudeDeg, point.heightM, local[0], local[1], local[2]);
  return local;
}

GeodeticPoint LocalFrame::toGeodetic(const LocalPoint& local) const
{
  GeodeticPoint point;
  this->Cartesian->cartesian.Reverse(
    local[0], local[1], local[2], point.latitudeDeg, point.longitudeDeg, point.heightM);
  return point;
}
} // namespace terralux
