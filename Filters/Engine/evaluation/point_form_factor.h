#pragma once
// Analytic form factor from a differential area to a polygon (Lambert's contour
// integral; Baum, Rushmeier & Winget 1989): exact for any distance, so touching or
// close surfaces stay finite. The polygon is first clipped to the half-space in
// front of the differential area.

#include "hierarchy/radiosity_types.h"

namespace terralux
{
/// Form factor from a point x with unit normal n to the polygon (count 3 or 4
/// vertices); 0 when the polygon is behind x or seen from its back (senderNormal).
double pointToPolygonFormFactor(
  const Vec3& x, const Vec3& n, const Vec3* polygon, int count, const Vec3& senderNormal);
} // namespace terralux
