// The solver's final choice judged on the true objective: the graph cost only approximates
// what a robot takes (it ignores turns and the seals the path builder drops), so every walk
// the solver offers (its best and its alternatives) is built as a path and the one with the
// least estimated time (length / speed + turns x turn time) is kept.
#pragma once

#include "graph/PreparedPlan.h"
#include "metrics/Metrics.h"
#include "model/CoveragePath.h"
#include "solvers/Solver.h"

#include <optional>
#include <string>
#include <vector>

namespace fc {

struct ChosenPath {
    Solution solution; // the chosen walk, its graph cost recomputed; no alternatives left
    CoveragePath path;
    // Set when the choice measured the path (a finalist); else the caller measures it.
    std::optional<Metrics> metrics;
    int candidates = 1; // walks built and compared
};

// Queries of more required cells keep the solver's own walk: building and measuring each
// alternative path costs seconds there (a 1,000-room floor: about 4 s per alternative).
inline constexpr long kPathChoiceMaxCells = 1000;

// Builds `solution`'s walk and each alternative as a path from `start` to `end` (world
// frame), and keeps the fastest. An alternative replaces the solver's best only when its
// measured metrics are a better plan choice (betterPlanChoice: complete first, then time).
// Up to kPathChoiceMaxCells required cells.
ChosenPath choosePathByTime(const PreparedPlan& prepared, const Query& query, Solution solution,
                            std::optional<Vec2> start, std::optional<Vec2> end,
                            const std::vector<std::string>& requiredRooms);

} // namespace fc
