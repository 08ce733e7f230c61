#include "pipeline/Planner.h"

#include "model/Validation.h"
#include "path/PathBuilder.h"
#include "pipeline/SolverRegistry.h"
#include "solvers/Baselines.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <queue>
#include <sstream>

namespace fc {

PreparedPlan preparePlan(const Plan& plan, const RobotProfile& robot, double stripeAngleDeg,
                         bool transitionCells) {
    PreparedPlan prepared;
    prepared.plan = normalizedPlan(plan);
    prepared.robot = robot;
    validatePlan(prepared.plan, robot);
    if (!std::isfinite(stripeAngleDeg))
        throw InputError("the sweep angle must be a finite number of degrees");
    DecompositionOptions options;
    options.coverageWidth = robot.coverageWidth;
    options.stripeAngleDeg = stripeAngleDeg;
    options.transitionCells = transitionCells;
    prepared.decomposition = decompose(prepared.plan, options);
    prepared.graph = buildCornerGraph(prepared.decomposition);
    return prepared;
}

namespace {

std::vector<int> componentOf(const CornerGraph& g) {
    std::vector<int> comp(g.nodes.size(), -1);
    int next = 0;
    for (size_t s = 0; s < g.nodes.size(); ++s) {
        if (comp[s] >= 0)
            continue;
        std::queue<int> q;
        q.push(static_cast<int>(s));
        comp[s] = next;
        while (!q.empty()) {
            const int u = q.front();
            q.pop();
            for (int e : g.incident[u]) {
                const int v = g.edges[e].other(u);
                if (comp[v] < 0) {
                    comp[v] = next;
                    q.push(v);
                }
            }
        }
        ++next;
    }
    return comp;
}

} // namespace

Query makeQuery(const PreparedPlan& prepared, const std::vector<std::string>& rooms,
                std::optional<Vec2> start, std::optional<Vec2> end, std::uint64_t seed,
                std::vector<std::string>& warnings) {
    const Decomposition& dec = prepared.decomposition;
    const CornerGraph& g = prepared.graph;
    std::vector<char> roomSelected(dec.roomNames.size(), rooms.empty() ? 1 : 0);
    for (const std::string& name : rooms) {
        auto it = std::find(dec.roomNames.begin(), dec.roomNames.end(), name);
        if (it == dec.roomNames.end()) {
            std::ostringstream msg;
            msg << "unknown room \"" << name << "\" (rooms:";
            for (const std::string& n : dec.roomNames)
                msg << ' ' << n;
            msg << ")";
            throw InputError(msg.str());
        }
        roomSelected[it - dec.roomNames.begin()] = 1;
    }
    Query q;
    q.seed = seed;
    q.required.assign(g.cells.size(), 0);
    for (const GraphCell& c : g.cells)
        q.required[c.id] = roomSelected[c.room] && c.reachable;
    if (std::none_of(q.required.begin(), q.required.end(), [](char r) { return r != 0; }))
        throw InputError("the selected rooms contain no area the robot can sweep");

    if (start) {
        q.startNode = nearestNode(g, dec.frame.toLocal(*start));
    } else {
        // Default: the lower-left corner of the leftmost required cell.
        int best = -1;
        for (const GraphCell& c : g.cells)
            if (q.required[c.id] && (best < 0 || dec.cells[c.id].x0 < dec.cells[best].x0))
                best = c.id;
        q.startNode = g.cells[best].nodes.front();
    }
    q.endNode = end ? nearestNode(g, dec.frame.toLocal(*end)) : q.startNode;

    const std::vector<int> comp = componentOf(g);
    if (comp[q.endNode] != comp[q.startNode])
        throw InputError("the end point cannot be reached from the start point");
    int dropped = 0;
    double droppedArea = 0;
    for (const GraphCell& c : g.cells) {
        if (q.required[c.id] && comp[c.nodes.front()] != comp[q.startNode]) {
            q.required[c.id] = 0;
            ++dropped;
            droppedArea += dec.cells[c.id].area();
        }
    }
    if (dropped > 0) {
        std::ostringstream msg;
        msg.precision(3);
        msg << dropped << " cells (" << droppedArea
            << " m^2) cannot be reached from the start and are left out";
        warnings.push_back(msg.str());
    }
    if (std::none_of(q.required.begin(), q.required.end(), [](char r) { return r != 0; }))
        throw InputError("no selected area can be reached from the start point");
    return q;
}

PlanRequest planRequestFor(const Project& project) {
    PlanRequest request;
    request.plan = project.plan;
    request.robot = project.robot;
    request.sweep = project.sweep;
    request.solver = project.solver;
    request.rooms = project.selectedRooms;
    if (project.hasStart)
        request.start = project.start;
    if (project.hasEnd)
        request.end = project.end;
    return request;
}

std::vector<std::string> solverNames() {
    std::vector<std::string> names{"exact", "heuristic", "greedy", "reeb-cpp", "adjacency-ga"};
    for (const std::string& name : registeredSolverNames())
        if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    return names;
}

Solution runSolver(const std::string& name, const PreparedPlan& prepared, const Query& query,
                   const std::string& modelPath, const SolveControl& control) {
    if (std::optional<RegisteredSolver> registered = findRegisteredSolver(name))
        return registered->solve(prepared, query, modelPath, control);
    if (name == "exact")
        return solveExact(prepared.graph, query, {}, control);
    if (name == "heuristic")
        return solveHeuristic(prepared.graph, query, control);
    if (name == "greedy")
        return solveGreedy(prepared.graph, query);
    if (name == "reeb-cpp" || name == "adjacency-ga") {
        const BaselineQuery baseline =
            makeBaselineQuery(prepared.plan, prepared.decomposition, prepared.graph, query);
        return name == "reeb-cpp" ? solveReebPostman(baseline) : solveAdjacencyGa(baseline);
    }
    std::ostringstream msg;
    msg << "unknown solver \"" << name << "\" (available:";
    for (const std::string& n : solverNames())
        msg << ' ' << n;
    msg << ")";
    throw InputError(msg.str());
}

std::vector<double> candidateAngles(const Plan& plan) {
    // Wall length per direction (mod 180, whole degrees): the two longest families.
    std::map<int, double> byDirection;
    const Ring& b = plan.boundary;
    for (size_t i = 0; i < b.size(); ++i) {
        const Vec2 d = b[(i + 1) % b.size()] - b[i];
        double deg = std::atan2(d.y, d.x) * 180.0 / M_PI;
        deg = std::fmod(deg + 360.0, 180.0);
        byDirection[static_cast<int>(std::lround(deg)) % 180] += norm(d);
    }
    std::vector<std::pair<double, int>> ranked;
    for (const auto& [deg, len] : byDirection)
        ranked.push_back({-len, deg});
    std::sort(ranked.begin(), ranked.end());
    std::vector<double> out{90.0, 0.0};
    for (size_t i = 0; i < ranked.size() && i < 2; ++i)
        for (double a : {double(ranked[i].second), double((ranked[i].second + 90) % 180)})
            if (std::none_of(out.begin(), out.end(),
                             [a](double o) { return std::abs(o - a) < 1.0; }))
                out.push_back(a);
    return out;
}

namespace {

PlanResult planAtAngle(const PlanRequest& request, double angle, const SolveControl& control) {
    const auto t0 = std::chrono::steady_clock::now();
    PlanResult result;
    result.stripeAngleDeg = angle;
    result.prepared = preparePlan(request.plan, request.robot, angle, request.transitionCells);
    result.query = makeQuery(result.prepared, request.rooms, request.start, request.end,
                             request.seed, result.warnings);
    result.solution =
        runSolver(request.solver, result.prepared, result.query, request.modelPath, control);
    result.path = buildCoveragePath(result.prepared.decomposition, result.prepared.graph,
                                    result.solution, request.start, request.end);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    MetricsInput in;
    in.decomposition = &result.prepared.decomposition;
    in.robot = request.robot;
    in.path = result.path;
    in.requiredRooms.assign(result.prepared.decomposition.roomNames.size(), 0);
    for (const GraphCell& c : result.prepared.graph.cells)
        if (result.query.required[c.id])
            in.requiredRooms[c.room] = 1;
    result.metrics = computeMetrics(in);
    result.metrics.graphCost = result.solution.graphCost;
    result.metrics.lowerBound = result.solution.lowerBound;
    result.metrics.seconds = seconds;
    result.metrics.cells =
        static_cast<int>(std::count(result.query.required.begin(), result.query.required.end(), 1));
    return result;
}

} // namespace

PlanResult planCoverage(const PlanRequest& request, const SolveControl& control) {
    request.robot.validate();
    if (!request.sweep.automatic)
        return planAtAngle(request, request.sweep.angleDeg, control);
    // A solver bound to one graph (a trained model) plans at the angle it was trained at.
    if (std::optional<RegisteredSolver> registered = findRegisteredSolver(request.solver))
        if (registered->sweepAngle)
            if (std::optional<double> angle = registered->sweepAngle(request.modelPath))
                return planAtAngle(request, *angle, control);
    const auto t0 = std::chrono::steady_clock::now();
    std::optional<PlanResult> best;
    for (double angle : candidateAngles(request.plan)) {
        PlanResult r = planAtAngle(request, angle, control);
        if (!best || r.metrics.length < best->metrics.length - 1e-9 ||
            (std::abs(r.metrics.length - best->metrics.length) <= 1e-9 &&
             r.metrics.turns < best->metrics.turns))
            best = std::move(r);
    }
    best->metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return std::move(*best);
}

} // namespace fc
