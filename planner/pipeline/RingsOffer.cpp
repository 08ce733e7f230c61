#include "pipeline/RingsOffer.h"

#include "decomposition/WallFollowing.h"
#include "geometry/SkeletonSpine.h"
#include "geometry/SwathReach.h"
#include "model/Validation.h"
#include "pipeline/FloorTransits.h"
#include "pipeline/LayoutOffers.h"
#include "pipeline/RingTour.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <future>
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
    const RobotProfile& robot;
    bool spines = true; // pieces may be swept along their spines (driveRings)
    bool tours = false; // stops in tourOrder, else nearest first each time
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

// Drives the loop (the path is at its first point), then the loops round the obstacles
// inside it and the pieces the loops left, each piece with the loops inside it before the
// next: in one tour (tourOrder, the last stop's gap measured to `then`), or without tours the
// obstacles' loops and then the pieces, nearest first.
void driveLoopAndInside(const RingsContext& context, WallLoop walls, WallLoopDraft& draft,
                        std::optional<Vec2> then = std::nullopt) {
    for (size_t i = 1; i < walls.loop.size(); ++i) {
        draft.path.points.push_back(walls.loop[i]);
        draft.path.kinds.push_back(SegmentKind::Contour);
    }
    ++draft.cells;
    if (!context.tours) {
        nearestFirst(walls.holeLoops, draft,
                     [&](size_t k) { driveClosed(context, walls.holeLoops[k], draft); });
        nearestFirst(walls.rest, draft, [&](size_t k) {
            driveRings(context, Piece{std::move(walls.rest[k]), std::move(walls.restHoles[k])},
                       draft);
        });
        return;
    }
    std::vector<Ring> stops = walls.holeLoops;
    stops.insert(stops.end(), walls.rest.begin(), walls.rest.end());
    const size_t holes = walls.holeLoops.size();
    for (const size_t k : tourOrder(stops, draft.path.points.back(), then)) {
        if (k < holes)
            driveClosed(context, walls.holeLoops[k], draft);
        else
            driveRings(
                context,
                Piece{std::move(walls.rest[k - holes]), std::move(walls.restHoles[k - holes])},
                draft);
    }
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

// Where a spine's swath leaves parts of its piece, the robot sweeps each where the spine
// passes nearest it and comes back there.
struct SpineStop {
    std::size_t segment = 0; // of the spine
    double along = 0.0;      // from that segment's start
    Vec2 at;
    std::size_t part = 0;
};

SpineStop nearestOnSpine(const Polyline& spine, const Ring& outline) {
    SpineStop best;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec2& p : outline)
        for (std::size_t i = 1; i < spine.size(); ++i) {
            const Vec2 a = spine[i - 1], d = spine[i] - a;
            const double span = dot(d, d);
            const double t = span > 0.0 ? std::clamp(dot(p - a, d) / span, 0.0, 1.0) : 0.0;
            const Vec2 q = a + d * t;
            if (norm(p - q) < nearest) {
                nearest = norm(p - q);
                best.segment = i - 1;
                best.along = t * std::sqrt(span);
                best.at = q;
            }
        }
    return best;
}

// A piece narrower than the robot's head is swept in one pass along its spine (the middle
// of a corridor between the loops along its two walls, which loops W/4 or W/20 inside its
// edge swept out and back, bulge by bulge). Taken where the spine keeps L/2 from the walls
// and its swath leaves at most kRingsSpineMissShare of the piece; the parts it leaves are
// swept from where the spine passes them. False elsewhere, the draft unchanged or, where a
// part left it where no transit leads back, to be dropped.
bool driveSpine(const RingsContext& context, const Piece& piece, WallLoopDraft& draft) {
    // Its mean width (twice its area over its perimeter) first: a piece wider than that
    // leaves more than a tenth of itself to any one pass, and the skeleton of a large piece
    // is what costs (a hall of 950 m^2 drafted its rings for 7 s instead of 1).
    Ring closed = piece.outline;
    closed.push_back(closed.front());
    if (!piece.holes.empty() || 2.0 * ringArea(piece.outline) > kRingsSpineMaxMeanWidth *
                                                                    context.width *
                                                                    polylineLength(closed))
        return false;
    Polyline spine = skeletonSpine(piece.outline);
    if (spine.size() < 2)
        return false;
    const Vec2 here = draft.path.points.back();
    if (norm(spine.back() - here) < norm(spine.front() - here))
        std::reverse(spine.begin(), spine.end());
    const SwathLeftovers left = swathLeftovers(piece.outline, piece.holes, spine,
                                               0.5 * context.width, context.minPieceArea);
    if (!context.floor.isClear(spine) || left.area < 0.0 ||
        left.area > kRingsSpineMissShare * ringArea(piece.outline))
        return false;
    if (!tryAppendTransit(context.floor, draft.path, spine.front()))
        return false;
    std::vector<SpineStop> stops;
    for (std::size_t k = 0; k < left.parts.size(); ++k) {
        stops.push_back(nearestOnSpine(spine, left.parts[k].outline));
        stops.back().part = k;
    }
    std::sort(stops.begin(), stops.end(), [](const SpineStop& a, const SpineStop& b) {
        return a.segment != b.segment ? a.segment < b.segment : a.along < b.along;
    });
    ++draft.cells;
    std::size_t next = 0;
    for (std::size_t i = 1; i < spine.size(); ++i) {
        for (; next < stops.size() && stops[next].segment + 1 == i; ++next) {
            const SpineStop& stop = stops[next];
            if (norm(stop.at - draft.path.points.back()) > 1e-9) {
                draft.path.points.push_back(stop.at);
                draft.path.kinds.push_back(SegmentKind::Stripe);
            }
            const FloorPart& part = left.parts[stop.part];
            driveRings(context, Piece{part.outline, part.holes}, draft);
            if (!tryAppendTransit(context.floor, draft.path, stop.at))
                return false; // the caller drops this draft of the piece
        }
        draft.path.points.push_back(spine[i]);
        draft.path.kinds.push_back(SegmentKind::Stripe);
    }
    return true;
}

// The estimated time of the path from its point `from` on (as Metrics::time).
double timeFrom(const RingsContext& context, const CoveragePath& path, std::size_t from) {
    const Polyline tail(path.points.begin() + static_cast<std::ptrdiff_t>(from), path.points.end());
    return polylineLength(tail) / context.robot.speed + countTurns(tail) * context.robot.turnTime;
}

void driveLoops(const RingsContext& context, const Piece& piece, WallLoopDraft& draft) {
    std::optional<WallLoop> walls = loopInside(context, piece, draft.path.points.back());
    if (!walls || !tryAppendTransit(context.floor, draft.path, walls->loop.front()))
        return; // left to the touch-ups
    if (walls->rest.empty() && walls->holeLoops.empty())
        halveThinLeaf(piece, context.width, walls->loop);
    driveLoopAndInside(context, std::move(*walls), draft);
}

// The piece swept by loops inside its edge or along its spine, whichever is estimated
// faster (a spine's bulges may cost more excursions than a loop round them).
void driveRings(const RingsContext& context, const Piece& piece, WallLoopDraft& draft) {
    throwIfStopped(context.control);
    if (!context.spines) {
        driveLoops(context, piece, draft);
        return;
    }
    const std::size_t from = draft.path.points.size() - 1;
    WallLoopDraft spined = draft;
    const bool spine = driveSpine(context, piece, spined);
    driveLoops(context, piece, draft);
    if (spine && timeFrom(context, spined.path, from) < timeFrom(context, draft.path, from))
        draft = std::move(spined);
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

static std::optional<WallLoopDraft>
ringsDraft(const PlanRequest& request, const SolveControl& control, bool spines, bool tours) {
    const RobotProfile& robot = request.robot;
    const double width = robot.coverageWidth, radius = 0.5 * robot.robotDiameter;
    const Plan plan = normalizedPlan(request.plan);
    const double minPieceArea = kEdgeMinPieceInWidths2 * width * width;
    std::optional<WallLoop> walls =
        wallLoop(plan, radius, width, request.start, minPieceArea, 0.0, true);
    if (!walls || walls->loop.size() < 4)
        return std::nullopt;
    const FloorField floor(plan, radius);
    const RingsContext context{floor, control, width, minPieceArea, robot, spines, tours};
    const Vec2 start = request.start.value_or(walls->loop.front());
    WallLoopDraft draft;
    draft.lowerBound = -1.0;
    draft.path.points.push_back(start);
    if (!tryAppendTransit(floor, draft.path, walls->loop.front()))
        return std::nullopt;
    driveLoopAndInside(context, std::move(*walls), draft, request.end.value_or(start));
    if (!tryAppendTransit(floor, draft.path, request.end.value_or(start)))
        return std::nullopt;
    draft.graphCost = polylineLength(draft.path.points);
    return draft;
}

std::vector<WallLoopDraft> draftRings(const PlanRequest& request, const SolveControl& control) {
    // Three variants, each on a thread of its own, all weighed by the planner: each piece
    // takes its spine or its loops by the time of that piece alone, and a tour's order is
    // judged on straight gaps between the rings, either of which can cost more later in the
    // path or in the touch-ups after it (with spines alone a round hall of the property bench
    // was 3% slower; with tours alone star rooms up to 12%, where nearest first follows the
    // robot's true position after each piece).
    const auto drafted = [&](bool spines, bool tours) {
        return std::async(std::launch::async, [&request, &control, spines, tours] {
            return ringsDraft(request, control, spines, tours);
        });
    };
    std::future<std::optional<WallLoopDraft>> spined = drafted(true, false);
    std::future<std::optional<WallLoopDraft>> toured = drafted(true, true);
    std::vector<WallLoopDraft> drafts;
    if (std::optional<WallLoopDraft> loops = ringsDraft(request, control, false, false))
        drafts.push_back(std::move(*loops));
    for (std::future<std::optional<WallLoopDraft>>* variant : {&spined, &toured}) {
        std::optional<WallLoopDraft> other;
        try {
            other = variant->get();
        } catch (const std::exception&) {
            if (control.cancelled && control.cancelled())
                throw;
            // Geometry the spines cannot be built on: the loops stand.
        }
        if (other && std::none_of(drafts.begin(), drafts.end(), [&](const WallLoopDraft& d) {
                return d.path.points == other->path.points;
            }))
            drafts.push_back(std::move(*other));
    }
    return drafts;
}

} // namespace fc::detail
