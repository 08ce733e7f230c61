// Wall touch-ups (SPEC sect. 6, issue 13 item 4): where the stripes and their seals leave
// sweepable floor unswept (wedges under slanted walls, around round pillars, in star-shaped
// rooms), the robot leaves its path for a short stroke along the wall, as a robot vacuum's
// edge mode does, and comes back the same way.
#pragma once

#include "decomposition/Decomposition.h"
#include "model/CoveragePath.h"

#include <vector>

namespace fc {

struct CoverageRepairStats {
    int gaps = 0;       // groups of missed floor found
    int touchUps = 0;   // strokes added
    double added = 0.0; // path length added, m
    int chains = 0;     // groups of touch-ups driven as one chain
    int skipped = 0;    // touch-ups the budget left out
};

// Which touch-ups are worth adding (nullptr: every one that can be driven). Each one's worth
// is the missed floor its stroke sweeps, its price the time of its detour alone (there and
// back, the turns included). They are taken best rate first: as long as the missed floor
// still exceeds `keepMissed` (m^2), and after that only where they sweep at least `minRate`
// (m^2 per second); a stroke that sweeps nothing the better-paying ones leave is never
// taken. So a plan that misses a little more than it may gets the few strokes that bring it
// back, not a hundred turns for the last square metre.
struct TouchUpBudget {
    double pointArea = 0.0;  // m^2 each missed point stands for
    double missedArea = 0.0; // m^2 missed now
    double keepMissed = 0.0; // m^2 that may stay missed
    double minRate = 0.0;    // m^2/s a touch-up beyond that must sweep
    double speed = 0.5;      // m/s
    double turnTime = 2.0;   // s per turn
};

// Adds a touch-up for each group of `missed` points (world frame, e.g. Metrics::uncovered)
// that a clear stroke within `maxDetour` of the path can sweep. Every added piece keeps the
// robot L/2 from walls. The path stays a valid world-frame path; its metrics must be
// computed again.
// chainNearby: touch-ups that leave from nearly the same place are driven as one chain
// where that is shorter (CoverageRepair.cpp); a chain turns where a lone stroke turns back, so
// the head's square ends sweep a little differently: the caller measures both.
CoverageRepairStats repairCoverage(const Decomposition& dec, CoveragePath& path,
                                   const std::vector<Vec2>& missed, double maxDetour,
                                   bool chainNearby = true, const TouchUpBudget* budget = nullptr);

} // namespace fc
