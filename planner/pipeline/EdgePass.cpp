#include "pipeline/EdgePass.h"

#include "decomposition/IslandDetours.h"
#include "decomposition/WallFollowing.h"
#include "geometry/Clearance.h"
#include "model/Validation.h"
#include "pipeline/FloorTransits.h"
#include "pipeline/LayoutOffers.h"
#include "pipeline/PerRoomSweep.h"
#include "pipeline/PreparedPlans.h"
#include "pipeline/RestPieces.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <string>

namespace fc::detail {
namespace {

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

struct LoopContext {
    const PlanRequest& request;
    const WallLoop& walls;
    const std::vector<PreparedPiece>& pieces;
    const FloorField& floor;
    const SolveControl& control;
};

// The piece's plan appended after a transit to it; false where it has none or cannot be got
// to from here (on a map imported without cleaning, a pocket behind specks: left out, as the
// stripes' plan leaves out the cells its start cannot reach; the measure counts it unswept).
bool appendPiece(const LoopContext& context, size_t index, Vec2 towards, WallLoopDraft& draft) {
    CoveragePath& path = draft.path;
    const std::optional<PlanResult> planned =
        planPiece(context.request, context.walls, context.pieces[index], index, path.points.back(),
                  towards, context.control);
    if (!planned || !tryAppendTransit(context.floor, path, planned->path.points.front()))
        return false;
    append(path, planned->path);
    draft.graphCost += planned->metrics.graphCost;
    draft.cells += planned->metrics.cells;
    draft.lowerBound = draft.lowerBound >= 0.0 && planned->metrics.lowerBound >= 0.0
                           ? draft.lowerBound + planned->metrics.lowerBound
                           : -1.0;
    return true;
}

WallLoopDraft draftFrom(const LoopContext& context, Vec2 start) {
    WallLoopDraft draft;
    draft.path.points.push_back(start);
    appendTransit(context.floor, draft.path, context.walls.loop.front());
    return draft;
}

void driveLoop(const WallLoop& walls, size_t from, size_t to, CoveragePath& path) {
    for (size_t i = from + 1; i <= to; ++i) {
        path.points.push_back(walls.loop[i]);
        path.kinds.push_back(SegmentKind::Contour);
    }
}

// Each piece of the rest as an excursion from the loop where the loop passes nearest it, back
// to that point: every piece borders the loop's band, so the robot leaves the loop beside it.
// Touring all pieces from one point of the loop (tourDraft) crosses the floor between
// pieces (the faculty map 1,747 m against 1,726 m), excursions turn more where the rest is
// many small pieces in a row (the corridor map: 404 turns against 311, 1,573 s against
// 1,415 s): both are drafted.
WallLoopDraft excursionDraft(const LoopContext& context, Vec2 start, Vec2 end) {
    const WallLoop& walls = context.walls;
    const size_t last = walls.loop.size() - 1;
    std::vector<std::vector<size_t>> piecesAt(last);
    for (size_t k = 0; k < walls.rest.size(); ++k) {
        size_t nearestAt = 0;
        double nearest = INFINITY;
        for (size_t i = 0; i < last; ++i)
            for (const Vec2& q : walls.rest[k])
                if (norm(q - walls.loop[i]) < nearest) {
                    nearest = norm(q - walls.loop[i]);
                    nearestAt = i;
                }
        piecesAt[nearestAt].push_back(k);
    }
    WallLoopDraft draft = draftFrom(context, start);
    for (size_t i = 0; i < last; ++i) {
        for (const size_t piece : piecesAt[i]) {
            throwIfStopped(context.control);
            if (appendPiece(context, piece, walls.loop[i], draft))
                appendTransit(context.floor, draft.path, walls.loop[i]);
        }
        driveLoop(walls, i, i + 1, draft.path);
    }
    appendTransit(context.floor, draft.path, end);
    return draft;
}

// An order of the rest's pieces (their indices) from `from` to `to` by cheapest insertion, where
// its straight-line estimate saves kEdgeSplitMinGainInWidths W over taking the nearest piece next;
// else empty (the nearest next, as it always was). The nearest next ignores where the path must
// end: on a corridor map ended at its far end it swept the middle to that end, then drove 37 m back
// to the one room it had passed and 42 m to the end again.
std::vector<size_t> insertionOrder(const WallLoop& walls, Vec2 from, Vec2 to, double width) {
    const size_t count = walls.rest.size();
    std::vector<std::vector<Vec2>> points(count); // each piece's outline, 64 points at most
    for (size_t i = 0; i < count; ++i) {
        const Ring& ring = walls.rest[i];
        const size_t step = std::max<size_t>(1, ring.size() / 64);
        for (size_t k = 0; k < ring.size(); k += step)
            points[i].push_back(ring[k]);
    }
    auto gap = [](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
        double nearest = INFINITY;
        for (const Vec2& p : a)
            for (const Vec2& q : b)
                nearest = std::min(nearest, norm(p - q));
        return nearest;
    };
    // Stops: `from`, the pieces, `to`.
    std::vector<std::vector<Vec2>> stops{{from}};
    stops.insert(stops.end(), points.begin(), points.end());
    stops.push_back({to});
    const size_t n = stops.size();
    std::vector<double> d(n * n, 0.0);
    for (size_t a = 0; a < n; ++a)
        for (size_t b = a + 1; b < n; ++b)
            d[a * n + b] = d[b * n + a] = gap(stops[a], stops[b]);
    auto cost = [&](const std::vector<size_t>& tour) {
        double sum = 0.0;
        for (size_t k = 0; k + 1 < tour.size(); ++k)
            sum += d[tour[k] * n + tour[k + 1]];
        return sum;
    };
    std::vector<size_t> nearestNext{0}; // stop indices
    std::vector<char> taken(n, 0);
    for (size_t k = 0; k < count; ++k) {
        size_t next = 0;
        for (size_t i = 1; i <= count; ++i)
            if (!taken[i] &&
                (next == 0 || d[nearestNext.back() * n + i] < d[nearestNext.back() * n + next]))
                next = i;
        taken[next] = 1;
        nearestNext.push_back(next);
    }
    nearestNext.push_back(n - 1);
    std::vector<size_t> inserted{0, n - 1};
    for (size_t k = 1; k <= count; ++k) {
        const size_t piece = nearestNext[k];
        size_t at = 1;
        double added = INFINITY;
        for (size_t i = 0; i + 1 < inserted.size(); ++i) {
            const size_t a = inserted[i], b = inserted[i + 1];
            const double extra = d[a * n + piece] + d[piece * n + b] - d[a * n + b];
            if (extra < added) {
                added = extra;
                at = i + 1;
            }
        }
        inserted.insert(inserted.begin() + static_cast<std::ptrdiff_t>(at), piece);
    }
    if (!(cost(inserted) < cost(nearestNext) - kEdgeSplitMinGainInWidths * width))
        return {};
    std::vector<size_t> pieces; // stop i is piece i - 1
    for (size_t k = 1; k + 1 < inserted.size(); ++k)
        pieces.push_back(inserted[k] - 1);
    return pieces;
}

// The whole rest toured from one point of the loop (loopSplit), piece by piece, the nearest
// next, or in `order` (piece indices, as insertionOrder gives them); each ends where
// the piece after it is nearest (the last one where the tour rejoins the loop, or where the
// path ends).
WallLoopDraft tourDraft(const LoopContext& context, Vec2 start, Vec2 end,
                        const std::vector<size_t>& order = {}) {
    const WallLoop& walls = context.walls;
    WallLoopDraft draft = draftFrom(context, start);
    CoveragePath& path = draft.path;
    const size_t split = loopSplit(walls, end, context.request.robot.coverageWidth);
    driveLoop(walls, 0, split, path);
    const Vec2 restEnd = split + 1 < walls.loop.size() ? walls.loop[split] : end;
    const size_t count = walls.rest.size();
    std::vector<char> done(count, 0);
    for (size_t k = 0; k < count; ++k) {
        throwIfStopped(context.control);
        const Vec2 at = path.points.back();
        size_t next = count;
        double nearest = INFINITY;
        if (!order.empty())
            next = order[k];
        else
            for (size_t i = 0; i < count; ++i)
                for (const Vec2& p : walls.rest[i])
                    if (!done[i] && norm(p - at) < nearest) {
                        nearest = norm(p - at);
                        next = i;
                    }
        done[next] = 1;
        Vec2 towards = restEnd;
        double after = INFINITY;
        for (size_t i = 0; i < count; ++i)
            for (const Vec2& p : walls.rest[i])
                for (const Vec2& q : walls.rest[next])
                    if (!done[i] && (order.empty() || (k + 1 < count && i == order[k + 1])) &&
                        norm(p - q) < after) {
                        after = norm(p - q);
                        towards = p;
                    }
        appendPiece(context, next, towards, draft);
    }
    if (split + 1 < walls.loop.size()) {
        appendTransit(context.floor, path, walls.loop[split]);
        driveLoop(walls, split, walls.loop.size() - 1, path);
    }
    appendTransit(context.floor, path, end);
    return draft;
}

double estimatedTime(const CoveragePath& path, const RobotProfile& robot) {
    const double length = polylineLength(path.points);
    return (robot.speed > 0.0 ? length / robot.speed : 0.0) +
           countTurns(path.points) * robot.turnTime;
}

} // namespace

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
    const std::vector<PreparedPiece> pieces = preparedPieces(request, *walls);
    const LoopContext context{request, *walls, pieces, floor, control};
    // Both orders drafted, the faster kept: excursions drive less between pieces, the tour
    // turns less where the rest is many small pieces in a row (the middle of a corridor).
    std::future<WallLoopDraft> touring =
        std::async(std::launch::async, [&] { return tourDraft(context, start, end); });
    // Where the path ends away from its start, also the rest in an order by cheapest
    // insertion, where that is estimated shorter than the nearest piece next.
    std::vector<size_t> inserted;
    if (norm(end - start) > width) {
        const size_t split = loopSplit(*walls, end, width);
        inserted = insertionOrder(*walls, walls->loop[split],
                                  split + 1 < walls->loop.size() ? walls->loop[split] : end, width);
    }
    std::future<WallLoopDraft> insertion;
    if (!inserted.empty())
        insertion = std::async(std::launch::async,
                               [&] { return tourDraft(context, start, end, inserted); });
    WallLoopDraft draft = excursionDraft(context, start, end);
    for (std::future<WallLoopDraft>* other : {&touring, &insertion}) {
        if (!other->valid())
            continue;
        WallLoopDraft tour = other->get();
        if (estimatedTime(tour.path, robot) < estimatedTime(draft.path, robot))
            draft = std::move(tour);
    }
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
