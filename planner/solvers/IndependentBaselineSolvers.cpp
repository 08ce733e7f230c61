// The solvers `adjacency-ga` and `reeb-cpp`: the corner-graph query handed to the
// independent baselines (baselines/IndependentBaselines.h) as what it is, rooms and points;
// their path comes back as the solution's direct path. Only this adapter knows both sides.
#include "baselines/IndependentBaselines.h"
#include "solvers/Baselines.h"

#include <algorithm>
#include <functional>

namespace fc {

namespace {

using Planner = std::function<baselines::Tour(const Plan&, const std::vector<std::string>&, Vec2,
                                              Vec2, const baselines::Options&)>;

Solution solveIndependently(const char* name, const Planner& plan, const PreparedPlan& prepared,
                            const Query& query, const SolveControl& control) {
    const Decomposition& dec = prepared.decomposition;
    const CornerGraph& graph = prepared.graph;
    std::vector<std::string> rooms;
    bool everyRoom = true;
    std::vector<char> roomRequired(dec.roomNames.size(), 0);
    for (std::size_t c = 0; c < dec.cells.size() && c < query.required.size(); ++c)
        if (query.required[c])
            roomRequired[dec.cells[c].room] = 1;
    for (std::size_t r = 0; r < dec.roomNames.size(); ++r) {
        if (roomRequired[r])
            rooms.push_back(dec.roomNames[r]);
        else
            everyRoom = false;
    }
    if (rooms.empty())
        throw SolverError(std::string(name) + ": no required cells");
    if (everyRoom || prepared.plan.rooms.empty())
        rooms.clear(); // the whole floor
    baselines::Options options;
    options.width = prepared.robot.coverageWidth;
    options.clearance = 0.5 * prepared.robot.robotDiameter;
    options.stripeAngleDeg = dec.frame.stripeAngleDeg();
    options.seed = query.seed;
    options.cancelled = control.cancelled;
    const Vec2 start = dec.frame.toWorld(graph.nodes[query.startNode].position);
    const Vec2 end = dec.frame.toWorld(graph.nodes[query.endNode].position);
    baselines::Tour tour;
    try {
        tour = plan(prepared.plan, rooms, start, end, options);
    } catch (const baselines::TourError& e) {
        throw SolverError(e.what());
    }
    DirectPath direct;
    for (const Vec2& p : tour.path.points)
        direct.path.points.push_back(dec.frame.toLocal(p));
    direct.path.kinds = tour.path.kinds;
    Solution s;
    s.solver = name;
    s.directPath = std::move(direct);
    return s;
}

} // namespace

Solution solveTungLiuGa(const PreparedPlan& prepared, const Query& query,
                        const SolveControl& control) {
    return solveIndependently("adjacency-ga", baselines::planTungLiuGa, prepared, query, control);
}

Solution solveReebPostman(const PreparedPlan& prepared, const Query& query,
                          const SolveControl& control) {
    return solveIndependently("reeb-cpp", baselines::planReebPostman, prepared, query, control);
}

} // namespace fc
