// Internal to the 3D importer: the exact planar section (CGAL arrangement of segments with
// exact constructions). Each segment carries the id of the closed solid it was cut from; a
// face of the arrangement is inside solid k when crossing from the unbounded face to it
// crosses an odd number of k's segments (solids may overlap: parity is kept per solid).
#pragma once

#include "geometry/Geometry.h"

#include <vector>

namespace fc::building {

// The section is snap-rounded to a grid of 1 / kGridPerMetre before the exact arrangement.
constexpr double kGridPerMetre = 1e4; // a pixel of 0.1 mm
// Corners where rings of the free region touch are cut back by this much (see the .cpp).
constexpr double kChamfer = 1e-3; // m

struct SectionSegment {
    Segment segment;
    int solid = 0; // index into the `isDoor` vector below
};

struct Region {
    Ring outer;              // counter-clockwise
    std::vector<Ring> holes; // clockwise
    double area = 0;         // outer minus holes, m^2
};

struct FreeSpace {
    Region region;               // the largest enclosed free region
    int otherRegions = 0;        // smaller enclosed free regions left out
    double otherRegionsArea = 0; // their total area
};

// The free floor region enclosed by the solids. Door leaves (isDoor[solid]) always close the
// building off from the outside; with doorsAreFloor their footprint inside the building counts
// as floor, so rooms joined by a door leaf become one region. Throws InputError when nothing
// is enclosed (message names the reason).
FreeSpace enclosedFreeSpace(const std::vector<SectionSegment>& segments,
                            const std::vector<bool>& isDoor, bool doorsAreFloor);

// The outer rings of the union of the solids' sections (counter-clockwise), largest first.
std::vector<Ring> solidOutlines(const std::vector<SectionSegment>& segments);

} // namespace fc::building
