// Path metrics of SPEC sect. 6, computed by one implementation for CLI, GUI and exports.
#pragma once

#include "decomposition/Decomposition.h"
#include "model/CoveragePath.h"
#include "model/Plan.h"

#include <string>
#include <vector>

namespace fc {

struct Metrics {
    double length = 0.0;      // m
    double ideal = 0.0;       // sweepable area of the required rooms / W, m
    double extra = 0.0;       // length - ideal, m
    int turns = 0;            // heading changes >= 45 degrees
    double coverage = 0.0;    // 0..1
    double time = 0.0;        // s = length / speed + turns * turn time
    int cells = 0;            // required cells
    double graphCost = 0.0;   // from the solver's walk
    double lowerBound = -1.0; // proven bound on graphCost, < 0 unknown
    double seconds = 0.0;     // planning time
    // Areas over the free space of the required rooms (all of it, not only the cells that
    // were planned): required = sweepable + unreachable, sweepable = covered + uncovered.
    double requiredArea = 0.0;     // m^2, free area of the required rooms
    double sweepableArea = 0.0;    // m^2, what a disc of diameter L sweeps with a W-wide head
                                   // (its centre L/2 from walls); denominator of coverage
    double coveredArea = 0.0;      // m^2, numerator of coverage
    double uncoveredArea = 0.0;    // m^2, sweepable but missed by the path
    double unreachableArea = 0.0;  // m^2, required free area no robot position can sweep
    std::vector<Segment> overlaps; // world frame: path pieces over area already swept
    // World-frame sample points of sweepable area the path never swept (coverage gaps),
    // thinned to at most about 20,000 points.
    std::vector<Vec2> uncovered;
    // World-frame sample points of required free area no robot position can sweep
    // (unreachable), thinned the same way.
    std::vector<Vec2> unreachable;
};

struct MetricsInput {
    const Decomposition* decomposition = nullptr; // sweep frame, cells labelled by room
    RobotProfile robot;
    std::vector<char> requiredRooms; // per room of the decomposition
    CoveragePath path;               // world frame
    // Raster cell size in metres; 0 picks W/10, coarsened to keep the raster bounded.
    double resolution = 0.0;
    // False: Metrics::overlaps is left empty. They are only drawn, and walking the path for
    // them took a sixth of a big map's planning when every candidate path was measured.
    bool overlaps = true;
};

Metrics computeMetrics(const MetricsInput& input);

// Turns are counted by countTurns (geometry/Geometry.h).

} // namespace fc
