// Internal: the vertical-slab sweep behind the Boustrophedon decomposition.
// Between consecutive event x's the free space is a stack of trapezoids; room borders
// split them further. Merging trapezoids whose slice connectivity does not change gives
// the Boustrophedon cells (see Decompose.cpp).
#pragma once

#include "geometry/Geometry.h"

#include <vector>

namespace fc::detail {

struct Trapezoid {
    int slab = -1;
    double xa = 0, xb = 0;
    double fa = 0, fb = 0; // floor y at xa, xb
    double ca = 0, cb = 0; // ceiling y at xa, xb
    int room = -1;         // -1: free space outside every room (assigned later)
};

// Two trapezoids of neighbouring slabs that touch along the slab border x.
struct TrapezoidLink {
    int left = -1, right = -1;
    double x = 0, y0 = 0, y1 = 0; // the shared vertical piece
};

// Two trapezoids of one slab separated only by a room border (no wall between them).
struct TrapezoidStack {
    int lower = -1, upper = -1;
};

struct SlabSweep {
    std::vector<double> xs;                    // event x's, sorted and unique
    std::vector<Trapezoid> trapezoids;         // grouped by slab, sorted by y in a slab
    std::vector<std::vector<int>> slabMembers; // slab -> trapezoid ids (bottom to top)
    std::vector<TrapezoidLink> links;
    std::vector<TrapezoidStack> stacks;
    std::vector<std::vector<int>> linksOfTrapezoid; // trapezoid -> link ids
};

// freeRings: boundary then holes (any orientation); rooms: outlines. All vertices must
// already be snapped so that equal x's are bit-identical. epsY: the smallest interval
// height kept. Throws InputError if a slice crosses an odd number of walls.
SlabSweep sweepSlabs(const std::vector<Ring>& freeRings, const std::vector<Ring>& rooms,
                     double epsY);

// Gives every trapezoid outside all rooms to the room its connected leftover region shares
// the longest border with (SPEC sect. 1); regions touching no room get a new room index
// starting at roomCount. Returns the number of rooms after assignment.
int assignLeftovers(SlabSweep& sweep, int roomCount);

// Recomputes links from the trapezoids (after trapezoids changed).
void computeLinks(SlabSweep& sweep, double epsY);
// Fuses trapezoids stacked on a room border with the same room on both sides; relinks.
void fuseSameRoomStacks(SlabSweep& sweep, double epsY);

// Headlands: in every trapezoid of room r (0 <= r < roomCount) taller than the bands need,
// the band of height w above a floor wall (with floors) and below a ceiling wall (with
// ceilings) becomes its own piece,
// labelled roomCount + r, so that it forms cells of its own, swept along the wall by one
// pass, where the stripes of the rest end (a field's headland). Only walls at most
// maxSlope steep (in the sweep frame) get a band; room borders (doorways) get none.
// Relinks.
// Returns the number of bands.
int splitHeadlands(SlabSweep& sweep, int roomCount, double w, bool floors, bool ceilings,
                   double maxSlope, double epsY);

} // namespace fc::detail
