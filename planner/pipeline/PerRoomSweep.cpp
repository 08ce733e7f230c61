#include "pipeline/PerRoomSweep.h"

#include "graph/ComponentBridges.h"
#include "pipeline/LayoutOffers.h"
#include "pipeline/PathChoice.h"
#include "pipeline/PreparedPlans.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <future>
#include <limits>
#include <memory>
#include <sstream>

namespace fc {
namespace {

// Angle groups the per-room search turns (each try plans the whole floor once), and the
// largest floor (in rooms) it searches at all; larger floors plan once.
constexpr size_t kPerRoomSearchLimit = 4;
constexpr size_t kPerRoomSearchMaxRooms = 60;
// Nor on floors of more obstacles than this: each one's corners are joined by path searches
// at every angle planned (a laser map imported without cleaning, 1,360 specks: 22.8 s with
// the search, 12.7 s and the same path with the family alone). Cleaned maps have a few
// dozen, drawings rarely hundreds.
constexpr size_t kPerRoomSearchMaxObstacles = 500;
// Rooms tried one at a time along their second wall family (roomSecondAngles).
constexpr size_t kSecondFamilyCandidates = 3;
// Screened candidates planned again with the requested solver (besides the family plan), and
// of those along rooms' second families.
constexpr size_t kPerRoomReplans = 2;
constexpr size_t kSecondFamilyReplans = 1;
// Distances closer than this (m) are ties: a rotated plan must choose as the upright one.
constexpr double kTieTolerance = 1e-6;
// Screened candidates that miss at most this share of the floor (before touch-ups) rank by
// estimated time.
constexpr double kScreenedLoss = 0.02;
// On floors of many cells, a complete screened candidate this much slower than the best
// complete one is not planned again: there greedy's ranking holds (ward, 132 cells, and
// office: the requested solver gains 6-8% over greedy on every candidate), and each finalist
// costs a whole solve (on the ward a third of its planning time). On small floors greedy
// ranks poorly (generated star rooms and slanted rooms: winners screened up to 25% slower)
// and every solve is quick, so all finalists are planned.
constexpr double kFinalistSlack = 1.15;
constexpr int kFinalistSlackMinCells = 100;

// Computed relative to the first vertex: with UTM-sized coordinates the cross products of
// raw coordinates cancel catastrophically.
Vec2 centroidOf(const Ring& ring) {
    if (ring.empty())
        return {};
    const Vec2 origin = ring.front();
    double area = 0.0;
    Vec2 sum;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i] - origin, b = ring[(i + 1) % ring.size()] - origin;
        const double c = cross(a, b);
        area += c;
        sum = sum + (a + b) * c;
    }
    if (std::abs(area) < 1e-12) {
        Vec2 mean;
        for (const Vec2& p : ring)
            mean = mean + (p - origin) * (1.0 / ring.size());
        return origin + mean;
    }
    return origin + sum * (1.0 / (3.0 * area));
}

struct Group {
    double angle = 90.0;
    std::vector<std::string> rooms; // decomposition room names
    Vec2 centre;                    // world frame
    PreparedPlan prepared;
};

// Position of a node in the world frame.
// Whether any cell of `rooms` lies in the part of the graph holding the point `at`.
bool reachesAny(const PreparedPlan& prepared, const std::vector<std::string>& rooms, Vec2 at) {
    const CornerGraph& g = prepared.graph;
    const Decomposition& dec = prepared.decomposition;
    int count = 0;
    const std::vector<int> comp = graphComponents(g, count);
    const int main = comp[joinableNode(prepared, dec.frame.toLocal(at))];
    for (const GraphCell& c : g.cells) {
        const std::string& room = dec.roomNames[c.room];
        if (c.reachable && !c.nodes.empty() && comp[c.nodes.front()] == main &&
            std::find(rooms.begin(), rooms.end(), room) != rooms.end())
            return true;
    }
    return false;
}

Vec2 worldOf(const PreparedPlan& prepared, int node) {
    return prepared.decomposition.frame.toWorld(prepared.graph.nodes[node].position);
}

// The corner of a required cell of `group` nearest to `target` (world frame).
// Equally near corners (a symmetric building) go to the one nearest to `away` (where
// this part starts), so that the choice is the same at any rotation of the plan.
Vec2 entryPoint(const Group& group, Vec2 target, Vec2 away) {
    const Decomposition& dec = group.prepared.decomposition;
    const CornerGraph& g = group.prepared.graph;
    double best = INFINITY;
    Vec2 out = group.centre;
    for (const GraphCell& cell : g.cells) {
        const std::string& room = dec.roomNames[cell.room];
        if (!cell.reachable ||
            std::find(group.rooms.begin(), group.rooms.end(), room) == group.rooms.end())
            continue;
        for (int node : cell.nodes) {
            const Vec2 p = worldOf(group.prepared, node);
            const double d = distance(p, target);
            if (d < best - kTieTolerance ||
                (d <= best + kTieTolerance &&
                 distance(p, away) < distance(out, away) - kTieTolerance))
                best = std::min(best, d), out = p;
        }
    }
    return out;
}

} // namespace

namespace {

void throwIfCancelled(const SolveControl& control) {
    if (control.cancelled && control.cancelled())
        throw SolverError("cancelled");
}

} // namespace

PlanResult planWithRoomAngles(const PlanRequest& request,
                              const std::map<std::string, double>& angles,
                              const SolveControl& control, const PreparedPlans& prepared) {
    // The angles of the selected rooms; one angle is an ordinary plan.
    std::vector<double> distinct;
    auto addAngle = [&](double a) {
        if (std::none_of(distinct.begin(), distinct.end(),
                         [a](double d) { return angleDistance(a, d) < 0.5; }))
            distinct.push_back(a);
    };
    if (request.rooms.empty()) {
        for (const auto& entry : angles)
            addAngle(entry.second);
    } else {
        for (const std::string& room : request.rooms)
            addAngle(sweepAngleOfRoom(angles, room));
    }
    if (distinct.size() == 1)
        return detail::planOneAngle(request, distinct.front(), control, &prepared);
    const auto t0 = std::chrono::steady_clock::now();

    // Each group decomposes the whole floor at its angle (other rooms' cells carry its
    // transits) and requires only its own rooms.
    // They are prepared side by side: on a large floor each takes seconds (a laser map
    // imported without cleaning: 2.6 and 3.0 s for its two angles, one after the other).
    const bool classic = solverNeedsClassicStages(request.solver);
    std::vector<std::future<std::shared_ptr<const PreparedPlan>>> preparing;
    for (size_t i = 1; i < distinct.size(); ++i)
        preparing.push_back(
            std::async(std::launch::async, [&prepared, classic, &control, a = distinct[i]] {
                throwIfCancelled(control);
                return prepared.shared(PreparedPlans::roundedAngle(a), classic);
            }));
    std::vector<Group> groups;
    for (size_t i = 0; i < distinct.size(); ++i) {
        Group group;
        group.angle = PreparedPlans::roundedAngle(distinct[i]);
        throwIfCancelled(control); // each decomposition takes a while on large floors
        group.prepared = i == 0 ? prepared.at(group.angle, classic) : *preparing[i - 1].get();
        double area = 0.0;
        Vec2 weighted;
        for (const std::string& name : group.prepared.decomposition.roomNames) {
            const bool selected =
                request.rooms.empty() ||
                std::find(request.rooms.begin(), request.rooms.end(), name) != request.rooms.end();
            if (!selected || angleDistance(sweepAngleOfRoom(angles, name), distinct[i]) >= 0.5)
                continue;
            group.rooms.push_back(name);
            for (const Room& room : request.plan.rooms)
                if (room.name == name) {
                    const double a = ringArea(room.outline);
                    area += a;
                    weighted = weighted + centroidOf(room.outline) * a;
                }
        }
        group.centre = area > 0.0 ? weighted * (1.0 / area) : centroidOf(request.plan.boundary);
        if (!group.rooms.empty())
            groups.push_back(std::move(group));
    }
    if (groups.empty())
        throw InputError("the selected rooms contain no area the robot can sweep");

    // Order: the start's group first (else the largest), then the nearest remaining group.
    std::vector<int> order;
    {
        int first = 0;
        if (request.start) {
            for (const Room& room : request.plan.rooms)
                if (pointInRing(room.outline, *request.start))
                    for (size_t g = 0; g < groups.size(); ++g)
                        if (std::find(groups[g].rooms.begin(), groups[g].rooms.end(), room.name) !=
                            groups[g].rooms.end())
                            first = static_cast<int>(g);
        } else {
            first = static_cast<int>(std::max_element(groups.begin(), groups.end(),
                                                      [](const Group& a, const Group& b) {
                                                          return a.rooms.size() < b.rooms.size();
                                                      }) -
                                     groups.begin());
        }
        std::vector<char> used(groups.size(), 0);
        order.push_back(first);
        used[first] = 1;
        while (order.size() < groups.size()) {
            const Vec2 from = groups[order.back()].centre;
            int next = -1;
            for (size_t g = 0; g < groups.size(); ++g)
                if (!used[g] &&
                    (next < 0 || distance(groups[g].centre, from) <
                                     distance(groups[next].centre, from) - kTieTolerance))
                    next = static_cast<int>(g);
            order.push_back(next);
            used[next] = 1;
        }
    }

    PlanResult result;
    double lowerBound = 0.0;
    std::optional<Vec2> start = request.start, home = request.end;
    // The floor's main part (where the robot reaches the most of the selected rooms): the
    // parts hand over inside it, so a room's pocket behind a gap narrower than the robot
    // does not strand the rooms after it.
    std::optional<Vec2> mainRegionAt = request.start;
    if (!mainRegionAt) {
        std::vector<std::string> allRooms, ignored;
        for (const Group& group : groups)
            allRooms.insert(allRooms.end(), group.rooms.begin(), group.rooms.end());
        const PreparedPlan& any = groups[order.front()].prepared;
        mainRegionAt = worldOf(
            any,
            makeQuery(any, allRooms, std::nullopt, std::nullopt, request.seed, ignored).startNode);
    }
    for (size_t k = 0; k < order.size(); ++k) {
        Group& group = groups[order[k]];
        PlanPart part;
        part.stripeAngleDeg = group.angle;
        part.prepared = std::move(group.prepared);
        part.rooms = group.rooms;
        // Each part ends at the next group's nearest corner; the last one at the end point,
        // or back where the first part started.
        Vec2 from;
        // A room wholly in a pocket the robot cannot get into is left out, loudly.
        if (!reachesAny(part.prepared, part.rooms, *mainRegionAt)) {
            std::ostringstream msg;
            msg << "room";
            for (const std::string& room : part.rooms)
                msg << (&room == &part.rooms.front() ? " " : ", ") << room;
            msg << " cannot be reached from the start and is left out";
            result.warnings.push_back(msg.str());
            continue;
        }
        if (start) {
            from = *start;
        } else { // the default start corner, found before the end is known
            std::vector<std::string> ignored;
            from = worldOf(part.prepared, makeQuery(part.prepared, part.rooms, start, std::nullopt,
                                                    request.seed, ignored, mainRegionAt)
                                              .startNode);
        }
        const std::optional<Vec2> end =
            k + 1 < order.size()
                ? std::optional<Vec2>(entryPoint(groups[order[k + 1]], group.centre, from))
                : home;
        // Hand-over points are the planner's own: they may move to where the robot gets.
        part.query = makeQuery(part.prepared, part.rooms, start, end, request.seed, result.warnings,
                               mainRegionAt, k + 1 < order.size() || !request.end);
        if (!request.previousPath.empty())
            part.query.orderHint = orderHintFrom(part.prepared, request.previousPath);
        if (!home)
            home = worldOf(part.prepared, part.query.startNode);
        // A hand-over point the query moved (it lay in a pocket of this part's graph): the
        // path joins the moved corner, and reaches it from the previous part by a transit.
        const Decomposition& dec = part.prepared.decomposition;
        std::optional<Vec2> pathStart = start, pathEnd = end;
        Polyline handOver;
        if (k > 0 && start &&
            part.query.startNode != joinableNode(part.prepared, dec.frame.toLocal(*start))) {
            pathStart = worldOf(part.prepared, part.query.startNode);
            handOver =
                dec.clearance().findPath(dec.frame.toLocal(*start), dec.frame.toLocal(*pathStart));
            if (handOver.empty())
                throw SolverError("the rooms cannot be joined: no collision-free way from " +
                                  group.rooms.front() + "'s neighbour into it");
        }
        if (end && part.query.endNode != joinableNode(part.prepared, dec.frame.toLocal(*end)))
            pathEnd = worldOf(part.prepared, part.query.endNode);
        ChosenPath chosen = choosePathByTime(
            part.prepared, part.query,
            runSolver(request.solver, part.prepared, part.query, request.modelPath, control),
            pathStart, pathEnd, part.rooms);
        if (handOver.size() > 1) {
            CoveragePath joined;
            for (const Vec2& p : handOver) {
                if (!joined.points.empty())
                    joined.kinds.push_back(SegmentKind::Transit);
                joined.points.push_back(dec.frame.toWorld(p));
            }
            for (size_t i = 1; i < chosen.path.points.size(); ++i) {
                joined.kinds.push_back(chosen.path.kinds[i - 1]);
                joined.points.push_back(chosen.path.points[i]);
            }
            chosen.path = std::move(joined);
        }
        part.solution = std::move(chosen.solution);
        part.path = std::move(chosen.path);
        // The next part starts where this one ended.
        start = part.path.empty() ? end : std::optional<Vec2>(part.path.points.back());
        for (size_t i = 0; i < part.path.points.size(); ++i) {
            const Vec2 p = part.path.points[i];
            if (!result.path.points.empty()) {
                if (i == 0 && distance(result.path.points.back(), p) < 1e-9)
                    continue; // the parts meet here
                result.path.kinds.push_back(i == 0 ? SegmentKind::Transit : part.path.kinds[i - 1]);
            }
            result.path.points.push_back(p);
        }
        result.metrics.graphCost += part.solution.graphCost;
        // The parts' bounds add up: each bounds its own part of the walk.
        lowerBound = lowerBound >= 0.0 && part.solution.lowerBound >= 0.0
                         ? lowerBound + part.solution.lowerBound
                         : -1.0;
        result.metrics.cells +=
            static_cast<int>(std::count(part.query.required.begin(), part.query.required.end(), 1));
        result.parts.push_back(std::move(part));
    }

    throwIfCancelled(control); // before measuring the path
    if (result.parts.empty())
        throw InputError("no selected room can be reached from the start point");
    const PlanPart& first = result.parts.front();
    (void)t0;
    result.prepared = first.prepared;
    result.query = first.query;
    result.solution = first.solution;
    result.stripeAngleDeg = first.stripeAngleDeg;
    const double graphCost = result.metrics.graphCost;
    const int cells = result.metrics.cells;
    // Measured over every selected room, the left-out ones too (SPEC: coverage over all the
    // required rooms): a room a part's graph left out (cut off from its start, rightly or
    // wrongly: a start joined to a corner beyond a door narrower than the robot) counts
    // against coverage, so that such a plan never looks complete or wins on time.
    std::vector<std::string> selected;
    for (const Group& group : groups)
        selected.insert(selected.end(), group.rooms.begin(), group.rooms.end());
    result.metrics = measurePath(first.prepared, selected, result.path);
    result.metrics.graphCost = graphCost;
    result.metrics.lowerBound = lowerBound;
    result.metrics.cells = cells;
    result.metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const std::string& loss : coverageLossWarnings(result.metrics))
        result.warnings.push_back(loss);
    return result;
}

PlanResult planPerRoom(const PlanRequest& request, const SolveControl& control,
                       const PreparedPlans* shared) {
    request.robot.validate();
    const auto t0 = std::chrono::steady_clock::now();
    const std::map<std::string, double> walls = roomSweepAngles(request.plan, request.sweep);
    std::optional<PreparedPlans> own;
    if (!shared)
        own.emplace(request.plan, request.robot, request.transitionCells, nullptr,
                    firstLayoutFor(request));
    const PreparedPlans& prepared = shared ? *shared : *own;
    const std::vector<std::pair<double, int>> groups = angleGroups(walls);
    const std::map<std::string, double> family = familyAngles(request.plan, request.sweep);
    auto free = [&](const std::string& room) { return request.sweep.roomAngles.count(room) == 0; };

    // First the building's family swept as one (familyAngles). Large or cluttered floors plan
    // the family alone; small ones search (below).
    if (request.plan.rooms.size() > kPerRoomSearchMaxRooms ||
        request.plan.obstacles.size() > kPerRoomSearchMaxObstacles) {
        PlanResult best = planWithRoomAngles(request, family, control, prepared);
        best.metrics.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return best;
    }

    // Then, on floors small enough to plan a few times over, each room along its own walls,
    // and each group of those turned by 90 degrees, keeping what plans better (complete
    // first, then faster): walls decide the family; whether stripes run along or across it
    // depends on obstacles and doors, which only planning sees.
    // Candidates are screened with the greedy solver (fast, and it ranks sweep directions
    // as the others do); the best is planned with the requested solver.
    PlanRequest screening = request;
    screening.solver = "greedy";
    struct Screened {
        std::map<std::string, double> angles;
        Metrics metrics;
        bool secondFamily = false; // a candidate of roomSecondAngles
    };
    std::vector<Screened> screened;
    // Progress: the screening is the first half, the finalists the second.
    auto report = [&control](double fraction) {
        if (control.progress)
            control.progress(fraction);
    };
    // The distinct candidates, screened side by side (each plan is independent; results are
    // kept in candidate order, so the choice does not depend on which finishes first).
    std::vector<std::map<std::string, double>> candidateAngles;
    auto addCandidate = [&](const std::map<std::string, double>& candidate) {
        for (const auto& previous : candidateAngles) {
            bool same = true;
            for (const auto& [room, angle] : candidate)
                same = same && angleDistance(angle, previous.at(room)) < 0.5;
            if (same)
                return;
        }
        candidateAngles.push_back(candidate);
    };
    addCandidate(family);
    addCandidate(walls);
    for (size_t g = 0; g < groups.size() && g < kPerRoomSearchLimit; ++g) {
        std::map<std::string, double> turned = walls;
        for (auto& [room, angle] : turned)
            if (free(room) && angleDistance(walls.at(room), groups[g].first) < 0.5)
                angle = normalizedAngle(angle + 90.0);
        addCandidate(turned);
    }
    // Rooms whose walls run two ways (a slanted side, a door wall across the long walls)
    // also along their second family: the largest few one at a time, along and across it,
    // then all at once.
    const size_t firstSecondFamily = candidateAngles.size();
    const std::map<std::string, double> second = request.secondFamilies
                                                     ? roomSecondAngles(request.plan, request.sweep)
                                                     : std::map<std::string, double>();
    std::vector<std::pair<double, std::string>> twoWay; // area, room ("": the floor)
    for (const auto& [name, angle] : second) {
        const auto room = std::find_if(request.plan.rooms.begin(), request.plan.rooms.end(),
                                       [&](const Room& r) { return r.name == name; });
        const Ring& outline =
            room != request.plan.rooms.end() ? room->outline : request.plan.boundary;
        twoWay.push_back({ringArea(outline), name});
    }
    std::stable_sort(twoWay.begin(), twoWay.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::map<std::string, double> allSecond = walls;
    for (size_t i = 0; i < twoWay.size(); ++i) {
        const std::string& name = twoWay[i].second;
        allSecond[name] = second.at(name);
        if (i < kSecondFamilyCandidates) { // along and across: such rooms are often squat
            std::map<std::string, double> one = walls;
            one[name] = second.at(name);
            addCandidate(one);
            one[name] = normalizedAngle(second.at(name) + 90.0);
            addCandidate(one);
        }
    }
    addCandidate(allSecond);
    throwIfCancelled(control);
    std::vector<std::future<std::optional<Metrics>>> screenings;
    SolveControl screeningControl;
    screeningControl.cancelled = control.cancelled;
    for (const auto& candidate : candidateAngles)
        screenings.push_back(std::async(std::launch::async, [&screening, &prepared, candidate,
                                                             screeningControl]() {
            try {
                return std::optional<Metrics>(
                    planWithRoomAngles(screening, candidate, screeningControl, prepared).metrics);
            } catch (const InputError&) {
                // e.g. one group's rooms cannot be reached from the start at its angle
                return std::optional<Metrics>();
            } catch (const SolverError&) {
                // A candidate whose parts cannot be joined (a 0.5 m corner room at its own
                // angle: the end point found no way out) is dropped, not the whole plan.
                if (screeningControl.cancelled && screeningControl.cancelled())
                    throw;
                return std::optional<Metrics>();
            }
        }));
    std::exception_ptr screeningFailure;
    for (size_t i = 0; i < screenings.size(); ++i) {
        try {
            if (std::optional<Metrics> metrics = screenings[i].get())
                screened.push_back({candidateAngles[i], *metrics, i >= firstSecondFamily});
        } catch (...) { // cancelled: every screening is waited for first
            if (!screeningFailure)
                screeningFailure = std::current_exception();
        }
        report(0.5 * static_cast<double>(i + 1) / static_cast<double>(screenings.size()));
    }
    if (screeningFailure)
        std::rethrow_exception(screeningFailure);
    // Screened without wall touch-ups (they take longer than the plan on ragged maps): what
    // they would sweep, wedges along walls the stripes miss, is no reason to drop a
    // candidate, so misses up to kScreenedLoss of the floor count as complete here. The
    // finalists are compared with their touch-ups.
    const auto complete = [](const Metrics& m) {
        return m.uncoveredArea <= kScreenedLoss * m.requiredArea;
    };
    std::stable_sort(screened.begin(), screened.end(), [&](const Screened& a, const Screened& b) {
        if (complete(a.metrics) != complete(b.metrics))
            return complete(a.metrics);
        if (!complete(a.metrics))
            return a.metrics.uncoveredArea < b.metrics.uncoveredArea;
        return a.metrics.time < b.metrics.time;
    });
    // The family and the best screened candidates, planned with the requested solver side
    // by side (each plan is independent; only cancellation is shared, and it is atomic).
    // The rooms' second families compete for a place of their own, so that the places of
    // the others go as they would without them (a round hall: a second family screened
    // first took the place of the plan that won).
    std::vector<std::map<std::string, double>> finalists{family};
    size_t others = 0, seconds = 0;
    for (size_t i = 0; i < screened.size(); ++i) {
        size_t& taken = screened[i].secondFamily ? seconds : others;
        if (taken >= (screened[i].secondFamily ? kSecondFamilyReplans : kPerRoomReplans))
            continue;
        bool isFamily = true;
        for (const auto& [room, angle] : screened[i].angles)
            isFamily = isFamily && angleDistance(angle, family.at(room)) < 0.5;
        const Metrics& best = screened.front().metrics;
        const bool hopeless = best.cells >= kFinalistSlackMinCells && complete(best) &&
                              complete(screened[i].metrics) &&
                              screened[i].metrics.time > kFinalistSlack * best.time;
        if (!isFamily && !hopeless)
            finalists.push_back(screened[i].angles), ++taken;
    }
    if (request.singleFinalist && !screened.empty()) // beside a wall loop on a large floor
        finalists = {screened.front().angles};
    SolveControl quiet;
    quiet.cancelled = control.cancelled;
    std::vector<std::future<PlanResult>> plans;
    for (const auto& finalist : finalists)
        plans.push_back(std::async(std::launch::async, [&request, &prepared, finalist, quiet]() {
            PlanResult plan = planWithRoomAngles(request, finalist, quiet, prepared);
            applyTouchUps(request, plan);
            return plan;
        }));
    std::vector<PlanResult> done;
    std::exception_ptr failure;
    report(0.5);
    for (auto& plan : plans) { // in order, so that ties go to the family plan
        report(0.5 +
               0.5 * static_cast<double>(&plan - plans.data()) / static_cast<double>(plans.size()));
        try {
            done.push_back(plan.get());
            keepContenders(done);
        } catch (...) {
            if (!failure)
                failure = std::current_exception();
        }
    }
    if (done.empty())
        std::rethrow_exception(failure);
    std::optional<PlanResult> best = std::move(done[choosePlan(done)]);
    best->metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return std::move(*best);
}

} // namespace fc
