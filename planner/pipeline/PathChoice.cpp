#include "pipeline/PathChoice.h"

#include "path/PathBuilder.h"
#include "pipeline/Planner.h"

#include <algorithm>

namespace fc {
namespace {

double estimatedTime(const CoveragePath& path, const RobotProfile& robot) {
    // As Metrics::time (computeMetrics), without measuring coverage.
    const double length = polylineLength(path.points);
    return (robot.speed > 0.0 ? length / robot.speed : 0.0) +
           countTurns(path.points) * robot.turnTime;
}

} // namespace

ChosenPath choosePathByTime(const PreparedPlan& prepared, const Query& query, Solution solution,
                            std::optional<Vec2> start, std::optional<Vec2> end,
                            const std::vector<std::string>& requiredRooms) {
    const Decomposition& dec = prepared.decomposition;
    const CornerGraph& graph = prepared.graph;
    std::vector<Walk> alternatives = std::move(solution.alternatives);
    solution.alternatives.clear();
    ChosenPath chosen;
    chosen.path = buildCoveragePath(dec, graph, solution, start, end);
    const auto required = std::count(query.required.begin(), query.required.end(), 1);
    if (required > kPathChoiceMaxCells)
        alternatives.clear();
    chosen.candidates = 1 + static_cast<int>(alternatives.size());
    if (alternatives.empty()) {
        chosen.solution = std::move(solution);
        return chosen;
    }
    // The fastest alternative by its path's time; ties keep the solver's own best.
    const double bestTime = estimatedTime(chosen.path, prepared.robot);
    double fastest = bestTime;
    int fastestIndex = -1;
    CoveragePath fastestPath;
    WalkEvaluation fastestEvaluation;
    for (size_t i = 0; i < alternatives.size(); ++i) {
        WalkEvaluation check = evaluateWalk(graph, query, alternatives[i]);
        if (!check.connected || !check.coversAllRequired)
            continue; // never trusted blindly, as for the solver's own walk
        CoveragePath path = buildCoveragePath(dec, graph, alternatives[i], start, end);
        const double time = estimatedTime(path, prepared.robot);
        if (time < fastest - 1e-9 * std::max(1.0, fastest)) {
            fastest = time;
            fastestIndex = static_cast<int>(i);
            fastestPath = std::move(path);
            fastestEvaluation = std::move(check);
        }
    }
    if (fastestIndex < 0) {
        chosen.solution = std::move(solution);
        return chosen;
    }
    // Measured: a faster path must also cover everything reachable (seal excursions and
    // transits differ). A complete faster path wins outright (betterPlanChoice), so the
    // solver's own path is measured only when the faster one is not complete.
    Metrics faster = measurePath(prepared, requiredRooms, fastestPath);
    if (!completePlan(faster)) {
        Metrics own = measurePath(prepared, requiredRooms, chosen.path);
        if (!betterPlanChoice(faster, own)) {
            chosen.solution = std::move(solution);
            chosen.metrics = std::move(own);
            return chosen;
        }
    }
    solution.walk = std::move(alternatives[static_cast<size_t>(fastestIndex)]);
    solution.cellOrder = std::move(fastestEvaluation.cellOrder);
    solution.graphCost = fastestEvaluation.graphCost;
    // The bound still holds for every walk; optimality is the chosen walk's own.
    solution.provenOptimal =
        solution.lowerBound >= 0.0 && !(solution.lowerBound < solution.graphCost - 1e-9);
    chosen.solution = std::move(solution);
    chosen.path = std::move(fastestPath);
    chosen.metrics = std::move(faster);
    return chosen;
}

} // namespace fc
