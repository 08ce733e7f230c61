#include "decomposition/WallFollowing.h"

#include "geometry/BoostGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace fc {
namespace {

using namespace bgeo;

// Points per full circle of the round joins: a chord of a 0.3 m arc then cuts it by 1.4 mm.
constexpr int kCirclePoints = 32;
// Added to the clearance so that those chords keep it (see the header).
constexpr double kChordMargin = 0.005;
// The band the loop's head sweeps is taken this much narrower than the head, so that what
// stripes must cover overlaps it rather than leaving a hairline between.
constexpr double kBandOverlap = 0.02;

template <typename Geometry> BMulti buffered(const Geometry& geometry, double distance) {
    return roundBuffer(geometry, distance, kCirclePoints);
}

// Douglas-Peucker keeps a closed ring's first vertex and splits from there, so what it keeps
// depends on where the ring starts, and Boost starts the rings it computes at a vertex that
// depends on how the plan is turned. Each ring starts at its vertex farthest from the
// polygon's centroid instead, the same vertex at any rotation of the plan: the faculty map
// turned by 90 degrees planned 5,703 s against 5,100 s turned by 180 (the same stripes), its
// main piece simplified into another outline that left 22 m^2 instead of 14 to touch-ups.
void startAtFarthestVertex(BRing& ring, const BPoint& centre) {
    if (ring.size() < 4)
        return;
    ring.pop_back(); // closed: the first vertex repeated
    size_t farthest = 0;
    for (size_t i = 1; i < ring.size(); ++i)
        if (bg::comparable_distance(ring[i], centre) >
            bg::comparable_distance(ring[farthest], centre))
            farthest = i;
    std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(farthest), ring.end());
    ring.push_back(ring.front());
}

// A piece's outline is mostly the band's edge, a line the robot need not follow: simplified
// (its arcs and the loop's wiggles would each start cells), then cut back to the free floor.
BMulti simplified(const BMulti& pieces, const BPolygon& free, double tolerance) {
    if (tolerance <= 0.0)
        return pieces;
    BMulti out;
    for (const BPolygon& piece : pieces) {
        // Grown first, so that the simplified outline never cuts into the piece: floor
        // between the band and the stripes would go unswept.
        BMulti grown;
        bg::buffer(piece, grown, bg::strategy::buffer::distance_symmetric<double>(tolerance),
                   bg::strategy::buffer::side_straight(), bg::strategy::buffer::join_miter(),
                   bg::strategy::buffer::end_flat(), bg::strategy::buffer::point_square());
        for (BPolygon part : grown) {
            BPoint centre;
            bg::centroid(part, centre);
            startAtFarthestVertex(part.outer(), centre);
            for (BRing& inner : part.inners())
                startAtFarthestVertex(inner, centre);
            BPolygon simple;
            bg::simplify(part, simple, tolerance);
            bg::correct(simple);
            BMulti inFree;
            bg::intersection(simple, free, inFree);
            for (BPolygon& kept : inFree)
                out.push_back(std::move(kept));
        }
    }
    return out;
}

// A piece with a waist narrower than the robot is several floors to it: split there (each
// part grown back from where the robot centre may be, within the piece).
BMulti robotParts(const BMulti& pieces, double clearance) {
    BMulti out;
    for (const BPolygon& piece : pieces) {
        const BMulti centres = buffered(piece, -(clearance + kChordMargin));
        if (centres.size() <= 1) {
            out.push_back(piece);
            continue;
        }
        for (const BPolygon& centre : centres) {
            BMulti part;
            bg::intersection(buffered(centre, clearance + 2 * kChordMargin), piece, part);
            for (BPolygon& kept : part)
                out.push_back(std::move(kept));
        }
    }
    return out;
}

void keepPieces(const BMulti& pieces, int room, Vec2 origin, double minPieceArea, WallLoop& out) {
    for (const BPolygon& piece : pieces) {
        const double area = bg::area(piece);
        if (area < minPieceArea) {
            out.droppedArea += area;
            continue;
        }
        out.rest.push_back(toRing(piece.outer(), origin));
        out.restHoles.emplace_back();
        for (const auto& inner : piece.inners())
            out.restHoles.back().push_back(toRing(inner, origin));
        out.restRoom.push_back(room);
        out.restArea += area;
    }
}

} // namespace

std::optional<WallLoop> wallLoop(const Plan& plan, double clearance, double headWidth,
                                 std::optional<Vec2> near, double minPieceArea,
                                 double simplifyTolerance, bool aroundHoles) {
    if (plan.boundary.size() < 3)
        return std::nullopt;
    const Vec2 origin = plan.boundary.front();
    BPolygon free;
    appendRing(plan.boundary, origin, free.outer());
    for (const Ring& obstacle : plan.obstacles) {
        free.inners().emplace_back();
        appendRing(obstacle, origin, free.inners().back());
    }
    bg::correct(free);
    const BMulti eroded = buffered(free, -(clearance + kChordMargin));
    // The part holding `near` (else nearest it), or the largest.
    const BPolygon* part = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (const BPolygon& candidate : eroded) {
        const double score =
            near ? bg::distance(BPoint(near->x - origin.x, near->y - origin.y), candidate)
                 : -bg::area(candidate);
        if (score < best) {
            best = score;
            part = &candidate;
        }
    }
    if (!part || part->outer().size() < 4)
        return std::nullopt;

    WallLoop out;
    const auto& outer = part->outer();
    // It starts nearest `near`, or farthest from the part's centre (the same point at any
    // rotation of the plan).
    BPoint at;
    if (near)
        at = BPoint(near->x - origin.x, near->y - origin.y);
    else
        bg::centroid(*part, at);
    size_t first = 0;
    for (size_t i = 0; i + 1 < outer.size(); ++i) {
        const double d = bg::comparable_distance(outer[i], at),
                     f = bg::comparable_distance(outer[first], at);
        if (near ? d < f : d > f)
            first = i;
    }
    BLine line;
    for (size_t k = 0; k + 1 < outer.size(); ++k)
        line.push_back(outer[(first + k) % (outer.size() - 1)]);
    line.push_back(line.front());
    // Rings feed the loops of their own pieces back in: no repeated points into the buffer.
    if (aroundHoles)
        bg::unique(line);
    for (const BPoint& p : line)
        out.loop.push_back({p.x() + origin.x, p.y() + origin.y});
    out.length = bg::length(line);

    const double halfBand = std::max(0.5 * headWidth - kBandOverlap, 0.0);
    BMulti band = buffered(line, halfBand);
    if (aroundHoles)
        for (const BRing& inner : part->inners()) {
            if (inner.size() < 4)
                continue;
            size_t nearest = 0;
            for (size_t i = 0; i + 1 < inner.size(); ++i)
                if (bg::comparable_distance(inner[i], at) <
                    bg::comparable_distance(inner[nearest], at))
                    nearest = i;
            BLine round;
            for (size_t k = 0; k + 1 < inner.size(); ++k)
                round.push_back(inner[(nearest + k) % (inner.size() - 1)]);
            round.push_back(round.front());
            bg::unique(round);
            Ring loop;
            for (const BPoint& p : round)
                loop.push_back({p.x() + origin.x, p.y() + origin.y});
            out.holeLoops.push_back(std::move(loop));
            BMulti both;
            bg::union_(band, buffered(round, halfBand), both);
            band = std::move(both);
        }
    BMulti rest;
    bg::difference(free, band, rest);
    rest = simplified(rest, free, simplifyTolerance);
    BMulti outside = rest;
    for (size_t r = 0; r < plan.rooms.size(); ++r) {
        BPolygon room;
        appendRing(plan.rooms[r].outline, origin, room.outer());
        bg::correct(room);
        BMulti inRoom, left;
        bg::intersection(rest, room, inRoom);
        keepPieces(robotParts(inRoom, clearance), static_cast<int>(r), origin, minPieceArea, out);
        bg::difference(outside, room, left);
        outside = std::move(left);
    }
    keepPieces(robotParts(outside, clearance), -1, origin, minPieceArea, out);
    return out;
}

std::optional<Vec2> clearPointNear(const Ring& outline, const std::vector<Ring>& holes,
                                   double clearance, Vec2 near) {
    if (outline.size() < 3)
        return std::nullopt;
    const Vec2 origin = outline.front();
    BPolygon floor;
    appendRing(outline, origin, floor.outer());
    for (const Ring& hole : holes) {
        floor.inners().emplace_back();
        appendRing(hole, origin, floor.inners().back());
    }
    bg::correct(floor);
    const BMulti inside = buffered(floor, -(clearance + 0.01));
    const BPoint at(near.x - origin.x, near.y - origin.y);
    std::optional<Vec2> best;
    double nearest = std::numeric_limits<double>::infinity();
    for (const BPolygon& part : inside)
        for (const BPoint& p : part.outer())
            if (bg::distance(p, at) < nearest) {
                nearest = bg::distance(p, at);
                best = Vec2{p.x() + origin.x, p.y() + origin.y};
            }
    return best;
}

} // namespace fc
