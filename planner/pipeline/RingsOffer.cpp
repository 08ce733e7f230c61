#include "pipeline/RingsOffer.h"

#include "decomposition/WallFollowing.h"
#include "model/Validation.h"
#include "pipeline/FloorTransits.h"
#include "pipeline/LayoutOffers.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fc::detail {
namespace {

struct Piece {
    Ring outline;
    std::vector<Ring> holes;
};

struct RingsContext {
    const FloorField& floor;
    const SolveControl& control;
    double width = 1.0;
    double minPieceArea = 0.0;
};

void throwIfStopped(const SolveControl& control) {
    if (control.cancelled && control.cancelled())
        throw SolverError("rings: cancelled");
}

double distanceTo(const Ring& ring, Vec2 p) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec2& q : ring)
        nearest = std::min(nearest, norm(q - p));
    return nearest;
}

// A piece's outline is the edge of the band its parent loop swept, W/2 from that loop: its
// own loop runs W/2 inside it, W from its parent's. Where the robot no longer fits there (the
// middle of a corridor narrower than the next ring), a loop nearer the edge sweeps what is
// left, if it keeps L/2 from the walls as drawn (the edge itself is no wall).
std::optional<WallLoop> loopInside(const RingsContext& context, const Piece& piece, Vec2 near) {
    Plan plan;
    plan.boundary = piece.outline;
    plan.obstacles = piece.holes;
    for (const double share : {0.5, 0.25, 0.05}) {
        std::optional<WallLoop> walls = wallLoop(plan, share * context.width, context.width, near,
                                                 context.minPieceArea, 0.0, true);
        if (!walls || walls->loop.size() < 4 || !context.floor.isClear(walls->loop))
            continue;
        bool clear = true;
        for (const Ring& round : walls->holeLoops)
            clear = clear && context.floor.isClear(round);
        if (clear)
            return walls;
    }
    return std::nullopt;
}

void driveRings(const RingsContext& context, const Piece& piece, WallLoopDraft& draft);

// Drives a closed loop from its vertex nearest the path's end, after a transit there; nothing
// where there is no transit (the touch-ups sweep round that obstacle).
void driveClosed(const RingsContext& context, const Ring& loop, WallLoopDraft& draft) {
    const size_t n = loop.size() - 1; // closed: the first point repeated
    size_t first = 0;
    for (size_t i = 1; i < n; ++i)
        if (norm(loop[i] - draft.path.points.back()) < norm(loop[first] - draft.path.points.back()))
            first = i;
    if (!tryAppendTransit(context.floor, draft.path, loop[first]))
        return;
    for (size_t k = 1; k <= n; ++k) {
        draft.path.points.push_back(loop[(first + k) % n]);
        draft.path.kinds.push_back(SegmentKind::Contour);
    }
    ++draft.cells;
}

// Calls visit(k) for each of the rings, the one nearest the path's end each time.
template <typename Visit>
void nearestFirst(const std::vector<Ring>& rings, const WallLoopDraft& draft, Visit visit) {
    std::vector<bool> done(rings.size(), false);
    for (size_t visited = 0; visited < rings.size(); ++visited) {
        size_t next = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < rings.size(); ++k) {
            const double d = done[k] ? nearest : distanceTo(rings[k], draft.path.points.back());
            if (d < nearest) {
                nearest = d;
                next = k;
            }
        }
        done[next] = true;
        visit(next);
    }
}

// Drives the loop (the path is at its first point) and the loops round the obstacles inside
// it, then the pieces they left, nearest first, each with the loops inside it before the next.
void driveLoopAndInside(const RingsContext& context, WallLoop walls, WallLoopDraft& draft) {
    for (size_t i = 1; i < walls.loop.size(); ++i) {
        draft.path.points.push_back(walls.loop[i]);
        draft.path.kinds.push_back(SegmentKind::Contour);
    }
    ++draft.cells;
    nearestFirst(walls.holeLoops, draft,
                 [&](size_t k) { driveClosed(context, walls.holeLoops[k], draft); });
    nearestFirst(walls.rest, draft, [&](size_t k) {
        driveRings(context, Piece{std::move(walls.rest[k]), std::move(walls.restHoles[k])}, draft);
    });
}

// Whether driving `line` sweeps the piece (its swath W wide), up to kRingsHalfMissInWidths2;
// judged on a grid of W/8.
bool sweepsPiece(const Piece& piece, const Polyline& line, double width) {
    const BoundingBox box = boundsOf(piece.outline);
    const double step = width / 8.0, reach = 0.5 * width;
    int missed = 0;
    const int allowed = static_cast<int>(kRingsHalfMissInWidths2 * 64.0);
    for (double y = box.minY + 0.5 * step; y < box.maxY; y += step)
        for (double x = box.minX + 0.5 * step; x < box.maxX; x += step) {
            const Vec2 p{x, y};
            if (!pointInRing(piece.outline, p) ||
                std::any_of(piece.holes.begin(), piece.holes.end(),
                            [&](const Ring& hole) { return pointInRing(hole, p); }))
                continue;
            bool reached = false;
            for (size_t i = 1; i < line.size() && !reached; ++i)
                reached = pointSegmentDistance(p, line[i - 1], line[i]) <= reach;
            if (!reached && ++missed > allowed)
                return false;
        }
    return true;
}

// A loop round a thin piece with nothing inside it goes out along one side of the piece and
// back along the other, each side sweeping the whole piece: the robot drives one side, from
// the loop's point nearest it to the point farthest from there, and goes on from the far end
// (the corridor map's middle, a row of such pieces, was driven out and back piece by piece).
// The loop (closed, starting at its point nearest the robot) is replaced by that half where
// it sweeps the piece.
void halveThinLeaf(const Piece& piece, double width, Ring& loop) {
    const size_t n = loop.size() - 1;
    size_t far = 0;
    for (size_t i = 1; i < n; ++i)
        if (norm(loop[i] - loop[0]) > norm(loop[far] - loop[0]))
            far = i;
    if (far == 0)
        return;
    Polyline out(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(far) + 1);
    Polyline back(loop.rbegin(), loop.rend() - static_cast<std::ptrdiff_t>(far));
    if (polylineLength(back) < polylineLength(out))
        std::swap(out, back);
    for (Polyline* half : {&out, &back})
        if (sweepsPiece(piece, *half, width)) {
            loop = *half;
            return;
        }
}

void driveRings(const RingsContext& context, const Piece& piece, WallLoopDraft& draft) {
    throwIfStopped(context.control);
    std::optional<WallLoop> walls = loopInside(context, piece, draft.path.points.back());
    if (!walls || !tryAppendTransit(context.floor, draft.path, walls->loop.front()))
        return; // left to the touch-ups
    if (walls->rest.empty() && walls->holeLoops.empty())
        halveThinLeaf(piece, context.width, walls->loop);
    driveLoopAndInside(context, std::move(*walls), draft);
}

} // namespace

bool wantsRings(const PlanRequest& request) {
    const double width = request.robot.coverageWidth;
    std::size_t corners = request.plan.boundary.size();
    for (const Ring& obstacle : request.plan.obstacles)
        corners += obstacle.size();
    // Stripes at an angle the user fixed (the paper's 90 degrees, a room's own) are what was
    // asked for.
    const SweepOptions& sweep = request.sweep;
    const bool anglesFree = sweep.automatic || (sweep.perRoom && sweep.roomAngles.empty());
    return request.wallLoop && request.rings && anglesFree && everyRoomAsked(request) &&
           plansAnyGraph(request.solver) && request.solver != "exact" &&
           corners <= kRingsMaxCorners &&
           freeAreaOf(request.plan) <= kRingsMaxAreaInWidths2 * width * width;
}

std::optional<WallLoopDraft> draftRings(const PlanRequest& request, const SolveControl& control) {
    const RobotProfile& robot = request.robot;
    const double width = robot.coverageWidth, radius = 0.5 * robot.robotDiameter;
    const Plan plan = normalizedPlan(request.plan);
    const double minPieceArea = kEdgeMinPieceInWidths2 * width * width;
    std::optional<WallLoop> walls =
        wallLoop(plan, radius, width, request.start, minPieceArea, 0.0, true);
    if (!walls || walls->loop.size() < 4)
        return std::nullopt;
    const FloorField floor(plan, radius);
    const RingsContext context{floor, control, width, minPieceArea};
    const Vec2 start = request.start.value_or(walls->loop.front());
    WallLoopDraft draft;
    draft.lowerBound = -1.0;
    draft.path.points.push_back(start);
    if (!tryAppendTransit(floor, draft.path, walls->loop.front()))
        return std::nullopt;
    driveLoopAndInside(context, std::move(*walls), draft);
    if (!tryAppendTransit(floor, draft.path, request.end.value_or(start)))
        return std::nullopt;
    draft.graphCost = polylineLength(draft.path.points);
    return draft;
}

} // namespace fc::detail
