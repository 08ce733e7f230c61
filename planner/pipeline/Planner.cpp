#include "pipeline/Planner.h"

#include "graph/ComponentBridges.h"
#include "model/Validation.h"
#include "path/CoverageRepair.h"
#include "pipeline/EdgePass.h"
#include "pipeline/LayoutOffers.h"
#include "pipeline/PathChoice.h"
#include "pipeline/PerRoomSweep.h"
#include "pipeline/PreparedPlans.h"
#include "pipeline/RingsOffer.h"
#include "pipeline/ShavedTeethOffer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <iomanip>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <sstream>

namespace fc {

namespace {

// The classic stages exactly as the baselines made them for themselves: at the prepared
// decomposition's angle, for its W and L.
void addClassicStages(PreparedPlan& prepared, const std::shared_ptr<FloorCache>& floorCache) {
    prepared.classic = std::make_shared<const PlanStages>(
        buildPlanStages(prepared.plan, prepared.decomposition.robot,
                        prepared.decomposition.frame.stripeAngleDeg(), false, floorCache));
}

} // namespace

PreparedPlan preparePlan(const Plan& plan, const RobotProfile& robot, double stripeAngleDeg,
                         bool transitionCells, bool classicStages,
                         const std::shared_ptr<FloorCache>& floorCache, LatticeMode stripeLattice,
                         Headland headland) {
    PreparedPlan prepared;
    prepared.plan = normalizedPlan(plan);
    prepared.robot = robot;
    validatePlan(prepared.plan, robot);
    if (!std::isfinite(stripeAngleDeg))
        throw InputError("the sweep angle must be a finite number of degrees");
    PlanStages stages = buildPlanStages(prepared.plan, robot, stripeAngleDeg, transitionCells,
                                        floorCache, stripeLattice, headland);
    prepared.decomposition = std::move(stages.decomposition);
    prepared.graph = std::move(stages.graph);
    if (classicStages)
        addClassicStages(prepared, floorCache);
    return prepared;
}

bool solverNeedsClassicStages(const std::string& name) {
    const std::optional<RegisteredSolver> solver = findRegisteredSolver(name);
    return solver && solver->classicStages;
}

int defaultStartNode(const PreparedPlan& prepared, const std::vector<char>& allRequired,
                     int inPart) {
    // Where the robot reaches the most floor: the part of the corner graph holding the most
    // required area (a SLAM map's pockets behind gaps narrower than the robot are parts of
    // their own). In it, the corner of a required cell farthest from the centre of the
    // required area: a corner of the floor, as a person would start, and the same corner
    // whatever the plan's rotation or sweep frame (equally far corners are mirror images,
    // which plan alike).
    const Decomposition& dec = prepared.decomposition;
    const CornerGraph& g = prepared.graph;
    int componentCount = 0;
    const std::vector<int> comp = graphComponents(g, componentCount);
    std::vector<double> componentArea(componentCount, 0.0);
    for (const GraphCell& c : g.cells)
        if (allRequired[c.id] && !c.nodes.empty())
            componentArea[comp[c.nodes.front()]] += dec.cells[c.id].area();
    const int largest =
        inPart >= 0
            ? inPart
            : static_cast<int>(std::max_element(componentArea.begin(), componentArea.end()) -
                               componentArea.begin());
    std::vector<char> required(allRequired.size(), 0);
    for (const GraphCell& c : g.cells)
        required[c.id] = allRequired[c.id] && !c.nodes.empty() && comp[c.nodes.front()] == largest;
    double area = 0.0;
    Vec2 centre;
    for (const GraphCell& c : g.cells) {
        if (!required[c.id])
            continue;
        const Ring outline = dec.cells[c.id].outline();
        const double a = ringArea(outline);
        Vec2 mean;
        for (const Vec2& p : outline)
            mean = mean + p * (1.0 / outline.size());
        centre = centre + mean * a;
        area += a;
    }
    if (area > 0.0)
        centre = centre * (1.0 / area);
    int best = -1;
    double farthest = -1.0;
    const double tie = 1e-6 * std::max(1.0, std::sqrt(area));
    for (const GraphCell& c : g.cells) {
        if (!required[c.id])
            continue;
        for (int node : c.nodes) {
            const double d = distance(g.nodes[node].position, centre);
            if (d > farthest + tie)
                farthest = d, best = node;
        }
    }
    return best;
}

std::vector<double> orderHintFrom(const PreparedPlan& prepared, const CoveragePath& previous) {
    const Decomposition& dec = prepared.decomposition;
    // Midpoints of the covering segments in order, sweep frame, sorted by x for the search.
    std::vector<std::pair<Vec2, double>> marks;
    for (size_t i = 0; i + 1 < previous.points.size() && i < previous.kinds.size(); ++i)
        if (previous.kinds[i] != SegmentKind::Transit)
            marks.push_back({dec.frame.toLocal((previous.points[i] + previous.points[i + 1]) * 0.5),
                             static_cast<double>(marks.size())});
    std::sort(marks.begin(), marks.end(),
              [](const auto& a, const auto& b) { return a.first.x < b.first.x; });
    const double none = std::numeric_limits<double>::infinity();
    std::vector<double> rank(dec.cells.size(), none);
    bool any = false;
    for (const Cell& cell : dec.cells) {
        auto it = std::lower_bound(marks.begin(), marks.end(), cell.x0,
                                   [](const auto& m, double x) { return m.first.x < x; });
        for (; it != marks.end() && it->first.x <= cell.x1; ++it) {
            const Vec2 p = it->first;
            if (p.y >= cell.floorAt(p.x) && p.y <= cell.ceilingAt(p.x))
                rank[cell.id] = std::min(rank[cell.id], it->second);
        }
        any = any || rank[cell.id] < none;
    }
    if (!any)
        return {};
    std::vector<Vec2> centre(dec.cells.size());
    for (const Cell& cell : dec.cells)
        centre[cell.id] = {0.5 * (cell.x0 + cell.x1),
                           0.5 * (cell.floorAt(0.5 * (cell.x0 + cell.x1)) +
                                  cell.ceilingAt(0.5 * (cell.x0 + cell.x1)))};
    const std::vector<double> swept = rank;
    for (const Cell& cell : dec.cells) {
        if (swept[cell.id] < none)
            continue;
        int nearest = -1;
        double nearestDistance = none;
        for (const Cell& other : dec.cells) {
            const double d = distance(centre[other.id], centre[cell.id]);
            if (swept[other.id] < none && d < nearestDistance)
                nearest = other.id, nearestDistance = d;
        }
        rank[cell.id] = swept[nearest] + 0.5;
    }
    return rank;
}

int joinableNode(const PreparedPlan& prepared, Vec2 p, const std::vector<int>* components,
                 int only) {
    const CornerGraph& g = prepared.graph;
    const ClearanceField& field = prepared.decomposition.clearance();
    auto allowed = [&](const GraphNode& node) {
        return only < 0 || components == nullptr || (*components)[node.id] == only;
    };
    // Nearest first among corners of cells the robot sweeps: a cell without stripes (too
    // narrow, or swept by its neighbours on the dense lattice) keeps a corner at its middle
    // that nothing joins. region >= 0: only corners in that open region.
    auto nearest = [&](int region) {
        int best = -1;
        for (int pass = 0; pass < 2 && best < 0; ++pass) {
            double bestDistance = INFINITY;
            for (const GraphNode& node : g.nodes)
                if ((pass == 1 || g.cells[node.cell].reachable) && allowed(node) &&
                    distance(node.position, p) < bestDistance &&
                    (region < 0 || field.openRegionOf(node.position) == region))
                    bestDistance = distance(node.position, p), best = node.id;
        }
        return best;
    };
    const int closest = nearest(-1);
    if (closest < 0 || field.segmentIsClear(p, g.nodes[closest].position))
        return closest;
    const int region = field.openRegionOf(p);
    const int inRegion = region >= 0 ? nearest(region) : -1;
    return inRegion >= 0 ? inRegion : closest;
}

namespace {
// The error for a room name that is none of `rooms` (the editor matches its wording).
InputError unknownRoom(const std::string& name, const std::vector<std::string>& rooms) {
    std::ostringstream msg;
    msg << "unknown room \"" << name << "\" (rooms:";
    for (const std::string& room : rooms)
        msg << ' ' << room;
    msg << ")";
    return InputError(msg.str());
}
} // namespace

Query makeQuery(const PreparedPlan& prepared, const std::vector<std::string>& rooms,
                std::optional<Vec2> start, std::optional<Vec2> end, std::uint64_t seed,
                std::vector<std::string>& warnings, std::optional<Vec2> mainRegionAt,
                bool endMayMove) {
    const Decomposition& dec = prepared.decomposition;
    const CornerGraph& g = prepared.graph;
    std::vector<char> roomSelected(dec.roomNames.size(), rooms.empty() ? 1 : 0);
    for (const std::string& name : rooms) {
        auto it = std::find(dec.roomNames.begin(), dec.roomNames.end(), name);
        if (it == dec.roomNames.end())
            throw unknownRoom(name, dec.roomNames);
        roomSelected[it - dec.roomNames.begin()] = 1;
    }
    Query q;
    q.seed = seed;
    q.required.assign(g.cells.size(), 0);
    for (const GraphCell& c : g.cells)
        q.required[c.id] = roomSelected[c.room] && c.reachable;
    if (std::none_of(q.required.begin(), q.required.end(), [](char r) { return r != 0; }))
        throw InputError("the selected rooms contain no area the robot can sweep");

    int componentCount = 0;
    const std::vector<int> comp = graphComponents(g, componentCount);
    auto joinableIn = [&](Vec2 p, int only) {
        return joinableNode(prepared, p, only >= 0 ? &comp : nullptr, only);
    };
    const int mainPart = mainRegionAt ? comp[joinableIn(dec.frame.toLocal(*mainRegionAt), -1)] : -1;
    if (start)
        q.startNode = joinableIn(dec.frame.toLocal(*start), mainPart);
    else
        q.startNode = defaultStartNode(prepared, q.required, mainPart);
    if (q.startNode < 0)
        throw InputError("no selected area can be reached from the start point");
    q.endNode = end ? joinableIn(dec.frame.toLocal(*end), endMayMove ? comp[q.startNode] : -1)
                    : q.startNode;

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
    return registeredSolverNames();
}

Solution runSolver(const std::string& name, const PreparedPlan& prepared, const Query& query,
                   const std::string& modelPath, const SolveControl& control) {
    const std::optional<RegisteredSolver> solver = findRegisteredSolver(name);
    if (solver && solver->classicStages && !prepared.classic) {
        PreparedPlan withClassic = prepared;
        addClassicStages(withClassic, nullptr);
        return solver->solve(withClassic, query, modelPath, control);
    }
    if (solver)
        return solver->solve(prepared, query, modelPath, control);
    std::ostringstream msg;
    msg << "unknown solver \"" << name << "\" (available:";
    for (const std::string& n : solverNames())
        msg << ' ' << n;
    msg << ")";
    throw InputError(msg.str());
}

namespace {

// Up to kTouchUpRounds rounds of touch-ups, each within a TouchUpBudget where `budgeted`.
void touchUpRounds(const PreparedPlan& prepared, const std::vector<std::string>& requiredRooms,
                   CoveragePath& path, Metrics& metrics, bool budgeted) {
    // A second round reaches what the first round's strokes uncovered only in part.
    for (int round = 0; round < kTouchUpRounds; ++round) {
        if (metrics.uncovered.empty() || metrics.uncoveredArea <= 0.0)
            return;
        TouchUpBudget budget;
        budget.pointArea = metrics.uncoveredArea / static_cast<double>(metrics.uncovered.size());
        budget.missedArea = metrics.uncoveredArea;
        budget.keepMissed = kTouchUpKeepShare * kTouchUpFraction * metrics.requiredArea;
        budget.speed = prepared.robot.speed;
        budget.turnTime = prepared.robot.turnTime;
        budget.minRate = kTouchUpMinRateShare * prepared.robot.coverageWidth * budget.speed;
        CoveragePath repaired = path;
        const CoverageRepairStats stats =
            repairCoverage(prepared.decomposition, repaired, metrics.uncovered,
                           kTouchUpReachInWidths * prepared.robot.coverageWidth, true,
                           budgeted ? &budget : nullptr);
        if (stats.touchUps == 0)
            return;
        Metrics after = measurePath(prepared, requiredRooms, repaired);
        // Chained strokes end differently from lone ones: the lone ones, where they plan
        // better (complete first, then faster).
        if (stats.chains > 0) {
            CoveragePath lone = path;
            repairCoverage(prepared.decomposition, lone, metrics.uncovered,
                           kTouchUpReachInWidths * prepared.robot.coverageWidth, false,
                           budgeted ? &budget : nullptr);
            Metrics loneAfter = measurePath(prepared, requiredRooms, lone);
            if (betterPlanChoice(loneAfter, after)) {
                repaired = std::move(lone);
                after = std::move(loneAfter);
            }
        }
        if (!(after.coveredArea > metrics.coveredArea))
            return;
        path = std::move(repaired);
        metrics = std::move(after);
    }
}

} // namespace

void touchUpCoverage(const PreparedPlan& prepared, const std::vector<std::string>& requiredRooms,
                     CoveragePath& path, Metrics& metrics) {
    const CoveragePath drafted = path;
    const Metrics draftedMetrics = metrics;
    touchUpRounds(prepared, requiredRooms, path, metrics, true);
    // The budget's sweep is an estimate, and a stroke from a corner of the path can cost that
    // corner's turn its swept wedge: where the budgeted rounds leave more than
    // kTouchUpFraction missed, every stroke is tried too and kept if it covers more (a door
    // room missed 0.44% by the raster measure and 0.66% by the exact one).
    if (!(metrics.uncoveredArea > kTouchUpFraction * metrics.requiredArea))
        return;
    CoveragePath every = drafted;
    Metrics everyMetrics = draftedMetrics;
    touchUpRounds(prepared, requiredRooms, every, everyMetrics, false);
    if (everyMetrics.coveredArea > metrics.coveredArea) {
        path = std::move(every);
        metrics = std::move(everyMetrics);
    }
}

Metrics measurePath(const PreparedPlan& prepared, const std::vector<std::string>& requiredRooms,
                    const CoveragePath& path) {
    const Decomposition& dec = prepared.decomposition;
    MetricsInput in;
    in.decomposition = &dec;
    in.robot = prepared.robot;
    in.path = path;
    in.requiredRooms.assign(dec.roomNames.size(), requiredRooms.empty() ? 1 : 0);
    for (const std::string& name : requiredRooms) {
        auto it = std::find(dec.roomNames.begin(), dec.roomNames.end(), name);
        if (it != dec.roomNames.end())
            in.requiredRooms[static_cast<size_t>(it - dec.roomNames.begin())] = 1;
    }
    in.overlaps = false;
    return computeMetrics(in);
}

void withOverlaps(PlanResult& result) {
    // The overlap pieces depend on the path and the raster only, not on the rooms required.
    MetricsInput in;
    in.decomposition = &result.prepared.decomposition;
    in.robot = result.prepared.robot;
    in.path = result.path;
    result.metrics.overlaps = computeMetrics(in).overlaps;
}

namespace detail {

PlanResult planOneAngle(const PlanRequest& request, double angle, const SolveControl& control,
                        const PreparedPlans* prepared) {
    const auto t0 = std::chrono::steady_clock::now();
    PlanResult result;
    const bool classic = solverNeedsClassicStages(request.solver);
    if (prepared) {
        angle = PreparedPlans::roundedAngle(angle);
        result.prepared = prepared->at(angle, classic);
    } else {
        result.prepared =
            preparePlan(request.plan, request.robot, angle, request.transitionCells, classic);
    }
    result.stripeAngleDeg = angle;
    result.query = makeQuery(result.prepared, request.rooms, request.start, request.end,
                             request.seed, result.warnings);
    if (!request.previousPath.empty())
        result.query.orderHint = orderHintFrom(result.prepared, request.previousPath);
    // Every selected room counts, also cells the start could not reach (no silent loss).
    std::vector<std::string> required = request.rooms;
    if (required.empty())
        required = result.prepared.decomposition.roomNames;
    ChosenPath chosen = choosePathByTime(
        result.prepared, result.query,
        runSolver(request.solver, result.prepared, result.query, request.modelPath, control),
        request.start, request.end, required);
    result.solution = std::move(chosen.solution);
    result.path = std::move(chosen.path);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    result.metrics = chosen.metrics ? std::move(*chosen.metrics)
                                    : measurePath(result.prepared, required, result.path);
    result.metrics.graphCost = result.solution.graphCost;
    result.metrics.lowerBound = result.solution.lowerBound;
    result.metrics.seconds = seconds;
    result.metrics.cells =
        static_cast<int>(std::count(result.query.required.begin(), result.query.required.end(), 1));
    for (const std::string& loss : coverageLossWarnings(result.metrics))
        result.warnings.push_back(loss);
    return result;
}

} // namespace detail

bool completePlan(const Metrics& metrics) {
    return metrics.uncoveredArea <= kReportedLossFraction * metrics.requiredArea;
}

namespace {
// Plans are ranked by coverage in steps of kReportedLossFraction of the floor, 0 for a
// complete plan: within a step, time decides. A ragged map's plans all miss a little
// (pockets the disc barely reaches); ranking them by every 0.1% lost chose, on a lab's
// map, a plan 43% slower that swept 0.27 m^2 more of its 141 m^2.
long coverageStep(const Metrics& m) {
    if (completePlan(m))
        return 0;
    if (!(m.requiredArea > 0.0))
        return 1;
    return static_cast<long>(
               std::ceil(m.uncoveredArea / (kReportedLossFraction * m.requiredArea))) -
           1;
}
} // namespace

bool betterPlanChoice(const Metrics& candidate, const Metrics& best) {
    const long c = coverageStep(candidate), b = coverageStep(best);
    if (c != b)
        return c < b;
    if (std::abs(candidate.time - best.time) > 1e-9 * std::max(1.0, best.time))
        return candidate.time < best.time;
    return candidate.length < best.length;
}

namespace {

// Whether `c` covers as much as the best plan `b` and is within kTimeTie of its time: one
// choosePlan may take for being shorter.
bool tiesWith(const Metrics& c, const Metrics& b) {
    const bool coversAsMuch =
        completePlan(c) == completePlan(b) &&
        (completePlan(b) || std::abs(c.uncoveredArea - b.uncoveredArea) <= 1e-3 * b.requiredArea);
    return coversAsMuch && c.time <= b.time * (1 + kTimeTie);
}

size_t bestByTime(const std::vector<const Metrics*>& candidates) {
    size_t best = 0;
    for (size_t i = 1; i < candidates.size(); ++i)
        if (betterPlanChoice(*candidates[i], *candidates[best]))
            best = i;
    return best;
}

std::vector<const Metrics*> metricsOf(const std::vector<PlanResult>& plans) {
    std::vector<const Metrics*> metrics;
    for (const PlanResult& plan : plans)
        metrics.push_back(&plan.metrics);
    return metrics;
}

} // namespace

size_t choosePlan(const std::vector<const Metrics*>& candidates) {
    const size_t best = bestByTime(candidates);
    const Metrics& b = *candidates[best];
    size_t chosen = best;
    for (size_t i = 0; i < candidates.size(); ++i)
        if (tiesWith(*candidates[i], b) &&
            candidates[i]->length < candidates[chosen]->length - 1e-9 * std::max(1.0, b.length))
            chosen = i;
    return chosen;
}

void keepContenders(std::vector<PlanResult>& plans) {
    if (plans.empty())
        return;
    const std::vector<const Metrics*> metrics = metricsOf(plans);
    const Metrics best = *metrics[bestByTime(metrics)];
    std::vector<PlanResult> kept;
    for (PlanResult& plan : plans)
        if (tiesWith(plan.metrics, best))
            kept.push_back(std::move(plan));
    plans = std::move(kept);
}

size_t choosePlan(const std::vector<PlanResult>& plans) {
    return choosePlan(metricsOf(plans));
}

std::vector<std::string> coverageLossWarnings(const Metrics& metrics) {
    std::vector<std::string> out;
    const double floor = metrics.requiredArea;
    if (!(floor > 0.0))
        return out;
    auto describe = [&](double area, const char* what) {
        if (area <= kReportedLossFraction * floor)
            return;
        std::ostringstream msg;
        msg.setf(std::ios::fixed);
        msg.precision(2);
        msg << area << " m^2 (" << std::setprecision(1) << 100.0 * area / floor
            << "% of the selected floor) " << what;
        out.push_back(msg.str());
    };
    describe(metrics.uncoveredArea, "the robot could sweep but the path does not cover");
    describe(metrics.unreachableArea, "the robot cannot reach (gaps narrower than the robot, "
                                      "corners beyond its head)");
    return out;
}

PlanResult planAtAngle(const PlanRequest& request, double angleDeg, const SolveControl& control,
                       const PreparedPlans* prepared) {
    request.robot.validate();
    PlanResult result = detail::planOneAngle(request, angleDeg, control, prepared);
    withOverlaps(result);
    return result;
}

namespace {

PlanResult planWithoutTouchUps(const PlanRequest& request, const SolveControl& control,
                               const PreparedPlans* prepared) {
    request.robot.validate();
    if (!request.sweep.automatic && !request.sweep.perRoom)
        return detail::planOneAngle(request, request.sweep.angleDeg, control, prepared);
    // A solver bound to one graph (a trained model) plans at the angle it was trained at.
    if (std::optional<RegisteredSolver> registered = findRegisteredSolver(request.solver))
        if (registered->sweepAngle)
            if (std::optional<double> angle = registered->sweepAngle(request.modelPath))
                return detail::planOneAngle(request, *angle, control, prepared);
    if (!request.sweep.automatic)
        return planPerRoom(request, control, prepared);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<PlanResult> plans;
    std::string firstError;
    for (double angle : candidateAngles(request.plan)) {
        try {
            PlanResult r = detail::planOneAngle(request, angle, control, prepared);
            applyTouchUps(request, r);
            plans.push_back(std::move(r));
            keepContenders(plans); // a floor's graphs are large: only near-ties are kept
        } catch (const InputError& e) {
            // One angle may fail (e.g. the start cannot be joined at that angle) where
            // another succeeds; only when every angle fails is the request bad.
            if (firstError.empty())
                firstError = e.what();
        }
    }
    if (plans.empty())
        throw InputError(firstError);
    PlanResult best = std::move(plans[choosePlan(plans)]);
    best.metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return best;
}

} // namespace

void applyTouchUps(const PlanRequest& request, PlanResult& result) {
    // Only where the plan misses more than kTouchUpFraction of the floor: each touch-up adds
    // turns, so a plan that already covers 99.65% keeps its clean pattern.
    const Metrics before = result.metrics;
    if (result.touchedUp || !(before.uncoveredArea > kTouchUpFraction * before.requiredArea))
        return;
    result.touchedUp = true;
    std::vector<std::string> required = request.rooms;
    if (required.empty())
        required = result.prepared.decomposition.roomNames;
    touchUpCoverage(result.prepared, required, result.path, result.metrics);
    if (result.metrics.coveredArea > before.coveredArea) {
        result.metrics.graphCost = before.graphCost;
        result.metrics.lowerBound = before.lowerBound;
        result.metrics.cells = before.cells;
        const auto old = coverageLossWarnings(before);
        result.warnings.erase(std::remove_if(result.warnings.begin(), result.warnings.end(),
                                             [&](const std::string& w) {
                                                 return std::find(old.begin(), old.end(), w) !=
                                                        old.end();
                                             }),
                              result.warnings.end());
        for (const std::string& loss : coverageLossWarnings(result.metrics))
            result.warnings.push_back(loss);
    }
}

namespace detail {

bool plansAnyGraph(const std::string& solver) {
    return solver == "heuristic" || solver == "greedy" || solver == "exact";
}

} // namespace detail

LatticeMode firstLayoutFor(const PlanRequest& request) {
    return request.stripeLattice && detail::plansAnyGraph(request.solver) ? LatticeMode::Auto
                                                                          : LatticeMode::Own;
}

PlanResult planCoverage(const PlanRequest& request, const SolveControl& control,
                        const PreparedPlans* prepared) {
    // A name that is no room of the plan is refused here: a per-room plan takes its rooms
    // from each angle's decomposition and used to drop it without a word.
    if (!request.plan.rooms.empty()) {
        std::vector<std::string> names;
        for (const Room& room : request.plan.rooms)
            names.push_back(room.name);
        for (const std::string& name : request.rooms)
            if (std::find(names.begin(), names.end(), name) == names.end())
                throw unknownRoom(name, names);
    }
    // Every room named where the rooms cover the floor (the editor with every room picked)
    // is the whole floor: planned as with none named, the same path (the lab map's rooms
    // leave 0.14 m^2 of slivers out, and with them named it planned another path).
    if (!request.rooms.empty() && detail::everyRoomAsked(request)) {
        PlanRequest whole = request;
        whole.rooms.clear();
        return planCoverage(whole, control, prepared);
    }
    const auto t0 = std::chrono::steady_clock::now();
    // On ragged walls a loop along them first is drafted on another thread while the first
    // plan is made (pipeline/EdgePass.h); it is stopped as soon as its estimate shows it
    // cannot pay, and always before this returns.
    std::promise<double> loopEstimate;
    std::future<double> estimated = loopEstimate.get_future();
    std::atomic<bool> stopLoop{false};
    std::future<detail::WallLoopDraft> loop;
    if (detail::wantsWallLoop(request)) {
        SolveControl loopControl;
        loopControl.cancelled = [&stopLoop, cancelled = control.cancelled] {
            return stopLoop.load() || (cancelled && cancelled());
        };
        loop = std::async(std::launch::async, [&request, loopControl, &loopEstimate] {
            return detail::draftWallLoop(request, loopControl, loopEstimate);
        });
    }
    // The floor with its wall teeth cut back, planned beside (pipeline/ShavedTeethOffer.h).
    std::future<std::optional<PlanResult>> flat;
    if (std::optional<detail::ShavedTeethRequest> shaved = detail::shavedTeethRequest(request))
        flat = std::async(std::launch::async, [shaved = std::move(*shaved), control] {
            return detail::planShavedTeeth(shaved, control);
        });
    // Loops inside the wall loop, W apart (pipeline/RingsOffer.h).
    std::atomic<bool> stopRings{false};
    std::future<std::vector<detail::WallLoopDraft>> rings;
    if (detail::wantsRings(request)) {
        SolveControl ringsControl;
        ringsControl.cancelled = [&stopRings, cancelled = control.cancelled] {
            return stopRings.load() || (cancelled && cancelled());
        };
        rings = std::async(std::launch::async, [&request, ringsControl] {
            try {
                return detail::draftRings(request, ringsControl);
            } catch (const std::exception&) {
                // An offer: cancelled, or geometry the loops cannot be built on (Boost's
                // overlays throw on input they cannot handle); the other plans stand.
                return std::vector<detail::WallLoopDraft>();
            }
        });
    }
    struct StopOnExit {
        std::atomic<bool>& stop;
        std::atomic<bool>& stopRings;
        ~StopOnExit() { stop = stopRings = true; } // before the futures wait for the drafts
    } stopOnExit{stopLoop, stopRings};

    std::optional<PreparedPlans> own; // shared by the first plan and the lattice's check
    if (!prepared)
        prepared = &own.emplace(request.plan, request.robot, request.transitionCells, nullptr,
                                firstLayoutFor(request));
    else if (prepared->stripeLattice() != firstLayoutFor(request))
        prepared = &own.emplace(request.plan, request.robot, request.transitionCells,
                                prepared->floorCache(), firstLayoutFor(request));
    PlanRequest first = request;
    const double width = request.robot.coverageWidth;
    first.singleFinalist =
        loop.valid() && freeAreaOf(request.plan) > kSingleFinalistMinArea * width * width;
    PlanResult result = planWithoutTouchUps(first, control, prepared);
    // The candidates of a search over angles were compared with their touch-ups (a plan
    // that leaves wedges along slanted walls may be the best once they are swept); a plan of
    // one angle gets them here.
    applyTouchUps(request, result);
    std::vector<PlanResult> plans;
    try {
        plans = detail::planLayoutOffers(request, result, control, *prepared);
    } catch (const InputError&) {
        // The lattice is an offer: where it cannot be planned, the first plan stands.
    }
    if (loop.valid()) {
        if (estimated.get() / request.robot.speed <
            detail::kEdgeEstimateGain * result.metrics.time) {
            try {
                plans.push_back(detail::wallLoopPlan(request, result, loop.get()));
            } catch (const InputError&) {
                // An offer too: a floor whose pieces cannot be joined keeps the first plan.
            } catch (const SolverError&) {
                if (control.cancelled && control.cancelled())
                    throw;
            }
        } else {
            stopLoop = true;
        }
    }
    if (rings.valid())
        for (detail::WallLoopDraft& drafted : rings.get()) {
            if (control.cancelled && control.cancelled())
                throw SolverError("cancelled");
            PlanResult ringed = detail::wallLoopPlan(request, result, std::move(drafted));
            ringed.rings = true;
            plans.push_back(std::move(ringed));
        }
    if (flat.valid())
        if (std::optional<PlanResult> shaved = flat.get())
            if (detail::keepShavedTeethPlan(request, result, *shaved))
                plans.push_back(std::move(*shaved));
    if (!plans.empty()) {
        plans.insert(plans.begin(), std::move(result)); // the first of equals
        result = std::move(plans[choosePlan(plans)]);
    }
    withOverlaps(result);
    result.metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

PlanResult draftCoverage(const PlanRequest& request, const PreparedPlans& prepared,
                         const SolveControl& control) {
    request.robot.validate();
    const auto t0 = std::chrono::steady_clock::now();
    PlanRequest quick = request;
    quick.solver = "greedy";
    quick.modelPath.clear();
    PlanResult result;
    if (request.sweep.perRoom && !request.sweep.automatic) {
        std::map<std::string, double> angles = familyAngles(request.plan, request.sweep);
        for (auto& [room, angle] : angles) {
            auto it = request.previousAngles.find(room);
            if (it != request.previousAngles.end() && request.sweep.roomAngles.count(room) == 0)
                angle = it->second;
        }
        result = planWithRoomAngles(quick, angles, control, prepared);
    } else
        result =
            detail::planOneAngle(quick,
                                 request.sweep.automatic ? candidateAngles(request.plan).front()
                                                         : request.sweep.angleDeg,
                                 control, &prepared);
    withOverlaps(result);
    result.metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

} // namespace fc
