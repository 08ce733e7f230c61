#include "pipeline/EdgePass.h"

#include "decomposition/IslandDetours.h"
#include "decomposition/WallFollowing.h"
#include "geometry/Clearance.h"
#include "model/Validation.h"
#include "pipeline/LayoutOffers.h"
#include "pipeline/PerRoomSweep.h"
#include "pipeline/PreparedPlans.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace fc::detail {
namespace {

// The floor's walls as the planner's clearance field sees them, in a frame at the plan's
// first corner (UTM-sized coordinates keep their digits; 90 degrees: not turned).
struct FloorField {
    FloorField(const Plan& plan, double radius)
        : frame(plan.boundary.front(), 90.0), field(ringsOf(plan, frame), radius) {}

    static std::vector<Ring> ringsOf(const Plan& plan, const Frame& frame) {
        std::vector<Ring> rings{frame.toLocal(plan.boundary)};
        if (signedArea(rings.front()) < 0.0)
            std::reverse(rings.front().begin(), rings.front().end());
        for (const Ring& obstacle : plan.obstacles) {
            rings.push_back(frame.toLocal(obstacle));
            if (signedArea(rings.back()) > 0.0)
                std::reverse(rings.back().begin(), rings.back().end());
        }
        return rings;
    }

    Frame frame;
    ClearanceField field;
};

// Appends a collision-free transit from the path's last point to `to` (nothing when there);
// false, and the path unchanged, where there is none.
bool tryAppendTransit(const FloorField& floor, CoveragePath& path, Vec2 to) {
    const Vec2 from = path.points.back();
    if (norm(to - from) < 1e-9)
        return true;
    const Vec2 a = floor.frame.toLocal(from), b = floor.frame.toLocal(to);
    // Provably apart (a pocket behind a gap narrower than the robot): no search, which
    // would test every pair of wall corners on the floor before it gave up.
    const int regionA = floor.field.openRegionOf(a), regionB = floor.field.openRegionOf(b);
    if (regionA >= 0 && regionB >= 0 && regionA != regionB)
        return false;
    const Polyline local = floor.field.findPath(a, b);
    if (local.size() < 2)
        return false;
    const Polyline world = floor.frame.toWorld(local);
    for (size_t i = 1; i < world.size(); ++i) {
        path.points.push_back(i + 1 == world.size() ? to : world[i]);
        path.kinds.push_back(SegmentKind::Transit);
    }
    return true;
}

void appendTransit(const FloorField& floor, CoveragePath& path, Vec2 to) {
    if (!tryAppendTransit(floor, path, to))
        throw InputError("the wall loop's pieces cannot be joined without collision");
}

void append(CoveragePath& path, const CoveragePath& more) {
    for (size_t i = 1; i < more.points.size(); ++i) {
        path.points.push_back(more.points[i]);
        path.kinds.push_back(more.kinds[i - 1]);
    }
}

void throwIfStopped(const SolveControl& control) {
    if (control.cancelled && control.cancelled())
        throw SolverError("wall loop: cancelled");
}

// The stripe angle the user fixed for a piece of the rest: the whole floor's (`--angle DEG`,
// the editor's fixed sweep angle) or that of the piece's room (the editor's per-room "Fixed");
// none where the angle is the planner's to choose.
std::optional<double> fixedAngleOfPiece(const PlanRequest& request, int room) {
    const SweepOptions& sweep = request.sweep;
    if (sweep.automatic)
        return std::nullopt;
    if (!sweep.perRoom)
        return sweep.angleDeg;
    const std::string name =
        room >= 0 ? request.plan.rooms[static_cast<size_t>(room)].name
                  : (request.plan.rooms.empty() ? std::string("Floor") : std::string());
    if (auto it = sweep.roomAngles.find(name); !name.empty() && it != sweep.roomAngles.end())
        return it->second;
    return std::nullopt;
}

// Plans one piece of the rest as a floor of its own, from the point of it nearest `from`
// to the point nearest `towards`. Empty where the robot fits nowhere in it.
std::optional<PlanResult> planPiece(const PlanRequest& request, const WallLoop& walls, size_t index,
                                    Vec2 from, Vec2 towards, const SolveControl& control) {
    PlanRequest piece;
    piece.plan.boundary = walls.rest[index];
    piece.plan.obstacles = walls.restHoles[index];
    const double width = request.robot.coverageWidth, radius = 0.5 * request.robot.robotDiameter;
    const IslandDetours islands = islandDetours(piece.plan.boundary, piece.plan.obstacles, radius,
                                                kEdgeIslandInWidths2 * width * width);
    piece.plan.name = request.plan.name;
    piece.robot = request.robot;
    piece.sweep = request.sweep;
    piece.sweep.roomAngles.clear();
    piece.solver = request.solver;
    piece.seed = request.seed;
    piece.modelPath = request.modelPath;
    piece.transitionCells = request.transitionCells;
    piece.wallLoop = false;
    piece.start = clearPointNear(piece.plan.boundary, piece.plan.obstacles, radius, from);
    piece.end = clearPointNear(piece.plan.boundary, piece.plan.obstacles, radius, towards);
    if (!piece.start || !piece.end)
        return std::nullopt;
    const std::optional<double> fixed = fixedAngleOfPiece(request, walls.restRoom[index]);
    auto plan = [&](const PlanRequest& floor, const PreparedPlans& prepared) {
        return fixed ? planOneAngle(floor, *fixed, control, &prepared)
                     : planPerRoom(floor, control, &prepared);
    };
    try {
        // Small islands (traced furniture) out of the way of the stripes, which then drive
        // round them; where that cannot be (a path that would start beside one), the piece
        // is planned with every hole.
        if (!islands.zones.empty()) {
            PlanRequest open = piece;
            open.plan.obstacles = islands.keptHoles;
            const PreparedPlans prepared(open.plan, open.robot, open.transitionCells);
            PlanResult planned = plan(open, prepared);
            std::optional<CoveragePath> round = detouredPath(planned.path, islands.zones);
            if (round && !round->empty()) {
                planned.path = std::move(*round);
                return planned;
            }
        }
        const PreparedPlans prepared(piece.plan, piece.robot, piece.transitionCells);
        PlanResult planned = plan(piece, prepared);
        if (planned.path.empty())
            return std::nullopt;
        return planned;
    } catch (const InputError&) {
        // Smaller than a coverage square, or a pocket the robot cannot turn in: left to the
        // touch-ups, and measured with the whole path.
        return std::nullopt;
    } catch (const SolverError&) {
        throwIfStopped(control);
        return std::nullopt;
    }
}

// Straight-line distance from p to the nearest corner of the rest's pieces.
double distanceToRest(const WallLoop& walls, Vec2 p) {
    double nearest = INFINITY;
    for (const Ring& piece : walls.rest)
        for (const Vec2& q : piece)
            nearest = std::min(nearest, norm(q - p));
    return nearest;
}

// Where the loop breaks off for the rest (index into walls.loop; its last index: after
// the whole loop). The rest's tour leaves the loop and comes back to it there, and the
// loop then goes on to its end. Driving the whole loop first sends the tour to the rest
// from the loop's end and back to `end` from it: where the loop starts in a dead end (a
// corridor to a room, the start beside a door), that drives the dead end twice more.
// Chosen by straight-line estimates: out and back from the split point, against out from
// the loop's end and back to `end`; the earliest of equally good split points, and only
// where it saves kEdgeSplitMinGainInWidths W.
size_t loopSplit(const WallLoop& walls, Vec2 end, double width) {
    const size_t last = walls.loop.size() - 1;
    if (walls.rest.empty())
        return last;
    const double afterLoop = distanceToRest(walls, walls.loop[last]) + distanceToRest(walls, end);
    const double toEnd = norm(end - walls.loop[last]);
    size_t best = last;
    double bestCost = afterLoop;
    for (size_t i = 0; i < last; ++i) {
        const double cost = 2.0 * distanceToRest(walls, walls.loop[i]) + toEnd;
        if (cost < bestCost - 1e-3) {
            best = i;
            bestCost = cost;
        }
    }
    // A small estimated gain is noise: the rest's pieces are then toured from elsewhere, in
    // another order (the faculty map: 1.2 m estimated, 11 m lost).
    return bestCost < afterLoop - kEdgeSplitMinGainInWidths * width ? best : last;
}

} // namespace

double averageWallPiece(const Plan& plan) {
    constexpr double kStraight = 1e-3; // sine of the turn below which a corner is no corner
    double length = 0.0;
    size_t pieces = 0;
    auto add = [&](const Ring& ring) {
        const size_t n = ring.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 in = ring[i] - ring[(i + n - 1) % n], out = ring[(i + 1) % n] - ring[i];
            length += norm(out);
            const double lengths = norm(in) * norm(out);
            if (lengths > 0.0 &&
                (dot(in, out) < 0.0 || std::abs(cross(in, out)) > kStraight * lengths))
                ++pieces;
        }
    };
    add(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        add(obstacle);
    return pieces ? length / static_cast<double>(pieces) : 0.0;
}

bool everyRoomAsked(const PlanRequest& request) {
    if (request.rooms.empty())
        return true;
    const double floor = freeAreaOf(request.plan);
    double rooms = 0.0;
    for (const Room& room : request.plan.rooms) {
        if (std::find(request.rooms.begin(), request.rooms.end(), room.name) == request.rooms.end())
            return false;
        rooms += std::abs(signedArea(room.outline));
    }
    // A name that is no room is the planner's to report.
    for (const std::string& name : request.rooms)
        if (std::none_of(request.plan.rooms.begin(), request.plan.rooms.end(),
                         [&](const Room& room) { return room.name == name; }))
            return false;
    return rooms >= (1.0 - kEdgeRoomsCoverFloorSlack) * floor;
}

bool wantsWallLoop(const PlanRequest& request) {
    const double width = request.robot.coverageWidth;
    const bool ragged = averageWallPiece(request.plan) < kEdgeRaggedWallInWidths * width;
    // Pillars and furniture small enough to be driven round (IslandDetours.h) in a hall: the
    // first plan parts its stripes at each one, whatever its walls. Not on floors of several
    // rooms, each a piece of its own: the ward's beds drafted a loop that never won, and its
    // 0.8 s of planning became 2.2 s.
    const bool islands = request.plan.rooms.size() <= 1 &&
                         std::any_of(request.plan.obstacles.begin(), request.plan.obstacles.end(),
                                     [&](const Ring& obstacle) {
                                         return std::abs(signedArea(obstacle)) <=
                                                kEdgeIslandInWidths2 * width * width;
                                     });
    return request.wallLoop && everyRoomAsked(request) && plansAnyGraph(request.solver) &&
           request.solver != "exact" && (ragged || islands);
}

WallLoopDraft draftWallLoop(const PlanRequest& request, const SolveControl& control,
                            std::promise<double>& estimate) {
    const RobotProfile& robot = request.robot;
    const double width = robot.coverageWidth, radius = 0.5 * robot.robotDiameter;
    // The estimate is promised whatever happens before it is known: the caller waits on it.
    std::optional<WallLoop> walls;
    Plan plan;
    try {
        plan = normalizedPlan(request.plan);
        walls = wallLoop(plan, radius, width, request.start, kEdgeMinPieceInWidths2 * width * width,
                         kEdgeSimplifyInWidths * width);
    } catch (...) {
        estimate.set_value(std::numeric_limits<double>::infinity());
        throw;
    }
    if (!walls || walls->loop.size() < 4) {
        estimate.set_value(std::numeric_limits<double>::infinity());
        throw InputError("the robot fits nowhere along the walls");
    }
    const Vec2 start = request.start.value_or(walls->loop.front());
    const Vec2 end = request.end.value_or(start);
    estimate.set_value(norm(walls->loop.front() - start) + walls->length +
                       kEdgeStripeFactor * walls->restArea / width);

    const FloorField floor(plan, radius);
    WallLoopDraft draft;
    CoveragePath& path = draft.path;
    path.points.push_back(start);
    appendTransit(floor, path, walls->loop.front());
    const size_t split = loopSplit(*walls, end, width);
    auto driveLoop = [&](size_t from, size_t to) {
        for (size_t i = from + 1; i <= to; ++i) {
            path.points.push_back(walls->loop[i]);
            path.kinds.push_back(SegmentKind::Contour);
        }
    };
    driveLoop(0, split);
    const Vec2 restEnd = split + 1 < walls->loop.size() ? walls->loop[split] : end;
    // The rest piece by piece, the nearest next; each ends where the piece after it is
    // nearest (the last one where the tour rejoins the loop, or where the path ends).
    const size_t count = walls->rest.size();
    std::vector<char> done(count, 0);
    for (size_t k = 0; k < count; ++k) {
        throwIfStopped(control);
        const Vec2 at = path.points.back();
        size_t next = count;
        double nearest = INFINITY;
        for (size_t i = 0; i < count; ++i)
            for (const Vec2& p : walls->rest[i])
                if (!done[i] && norm(p - at) < nearest) {
                    nearest = norm(p - at);
                    next = i;
                }
        done[next] = 1;
        Vec2 towards = restEnd;
        double after = INFINITY;
        for (size_t i = 0; i < count; ++i)
            for (const Vec2& p : walls->rest[i])
                for (const Vec2& q : walls->rest[next])
                    if (!done[i] && norm(p - q) < after) {
                        after = norm(p - q);
                        towards = p;
                    }
        const std::optional<PlanResult> planned =
            planPiece(request, *walls, next, at, towards, control);
        // A piece the robot cannot get to from here (on a map imported without cleaning, a
        // pocket behind specks) is left out, as the stripes' plan leaves out the cells its
        // start cannot reach; the measure counts it unswept. It used to stop the whole loop.
        if (!planned || !tryAppendTransit(floor, path, planned->path.points.front()))
            continue;
        append(path, planned->path);
        draft.graphCost += planned->metrics.graphCost;
        draft.cells += planned->metrics.cells;
        draft.lowerBound = draft.lowerBound >= 0.0 && planned->metrics.lowerBound >= 0.0
                               ? draft.lowerBound + planned->metrics.lowerBound
                               : -1.0;
    }
    if (split + 1 < walls->loop.size()) {
        appendTransit(floor, path, walls->loop[split]);
        driveLoop(split, walls->loop.size() - 1);
    }
    appendTransit(floor, path, end);
    return draft;
}

PlanResult wallLoopPlan(const PlanRequest& request, const PlanResult& first, WallLoopDraft draft) {
    PlanResult result;
    result.prepared = first.prepared;
    result.query = first.query;
    result.solution.solver = request.solver;
    result.solution.graphCost = draft.graphCost;
    result.solution.lowerBound = draft.lowerBound;
    result.stripeAngleDeg = first.stripeAngleDeg;
    const std::vector<std::string>& required = first.prepared.decomposition.roomNames;
    result.path = std::move(draft.path);
    result.metrics = measurePath(first.prepared, required, result.path);
    if (result.metrics.uncoveredArea > kTouchUpFraction * result.metrics.requiredArea)
        touchUpCoverage(first.prepared, required, result.path, result.metrics);
    result.touchedUp = true;
    result.metrics.graphCost = draft.graphCost;
    result.metrics.lowerBound = draft.lowerBound;
    result.metrics.cells = draft.cells;
    const std::vector<std::string> firstLosses = coverageLossWarnings(first.metrics);
    for (const std::string& warning : first.warnings)
        if (std::find(firstLosses.begin(), firstLosses.end(), warning) == firstLosses.end())
            result.warnings.push_back(warning);
    for (const std::string& loss : coverageLossWarnings(result.metrics))
        result.warnings.push_back(loss);
    return result;
}

} // namespace fc::detail
