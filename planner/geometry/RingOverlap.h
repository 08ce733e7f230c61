// The area two rings share (Boost.Geometry), e.g. two buildings of a site drawn overlapping.
#pragma once

#include "geometry/Geometry.h"

namespace fc {

// m^2 (the rings' units squared); 0 where they do not overlap or either is not a valid
// polygon (its own checks name that).
double ringOverlapArea(const Ring& a, const Ring& b);

} // namespace fc
