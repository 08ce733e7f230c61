// Internal to the occupancy-map importer: traced outlines straightened along the map's two
// dominant wall directions. A ragged laser wall traces as dozens of tiny steps, and every
// step that folds against the sweep starts a Boustrophedon cell; a wall fitted as one line
// (within a cell of every traced point) starts none. Include only from the importers.
#pragma once

#include "importers/OgrSupport.h"

#include <cmath>
#include <optional>

namespace fc::importing {

// The dominant wall direction of the traced outlines in degrees in [0, 90) (the other family
// is at +90), when walls along it hold at least a third of the outline's length (a round or
// irregular building has none). `fine`: the same outlines simplified within half a cell; the
// direction is refined to the one along which most of it runs as walls within `band`.
std::optional<double> dominantWallDirection(const OGRGeometry& traced,
                                            const OGRGeometry* fine = nullptr, double band = 1.0);

struct StraightenOptions {
    double angleDeg = 0;    // wall direction (see dominantWallDirection)
    double band = 1.0;      // a run's points lie within 2 bands across; its wall within 2 bands
                            // of each of them (at their length-weighted median)
    double minRun = 4.0;    // shortest wall fitted as a line
    double notchDepth = 0;  // notches into a wall this shallow are filled (floor lost)
    double cornerShift = 3; // a corner moves at most this far to meet two fitted walls
    // ... and this far between walls at least chamferMinWall long, also across a few traced
    // points between them (a corner the tracing cut or the opening rounded)
    double chamferShift = 3;
    double chamferMinWall = INFINITY;
};

struct StraightenStats {
    int walls = 0;         // lines fitted
    int notchesFilled = 0; // excursions deeper than `band` into a wall, filled
};

// One ring straightened (same units as the options). freeInside: the floor lies inside the
// ring (an outline) rather than outside it (an obstacle); it decides which excursions are
// notches. The ring has no repeated closing point.
Ring straightenRing(const Ring& ring, bool freeInside, const StraightenOptions& options,
                    StraightenStats& stats);

// Every polygon of `outlines` straightened; a polygon whose straightened form is not valid
// (rings crossing) is kept as it was. Floor areas in the units squared.
struct StraightenResult {
    GeometryPtr geometry;
    StraightenStats stats;
    double floorAdded = 0;   // teeth within `band` that became floor
    double floorRemoved = 0; // notches and wall offsets that became wall
};
StraightenResult straightenOutlines(const OGRGeometry& outlines, const StraightenOptions& options,
                                    bool freeInside = true);

} // namespace fc::importing
