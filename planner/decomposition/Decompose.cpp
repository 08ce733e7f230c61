#include "decomposition/Decomposition.h"

#include "decomposition/FunctionClip.h"
#include "decomposition/SlabSweep.h"
#include "decomposition/StripePlanner.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fc {
namespace {

using detail::SlabSweep;
using detail::Trapezoid;

// Snaps x's closer than eps onto one value so that near-vertical edges of rotated
// rectilinear plans become exactly vertical and shared slices are bit-identical.
void snapXs(std::vector<Ring*>& rings, double eps) {
    std::vector<double> xs;
    for (Ring* r : rings)
        for (const Vec2& p : *r)
            xs.push_back(p.x);
    std::sort(xs.begin(), xs.end());
    std::vector<double> rep(xs.size());
    double start = xs.empty() ? 0 : xs[0];
    for (size_t i = 0; i < xs.size(); ++i) {
        if (xs[i] - start > eps)
            start = xs[i];
        rep[i] = start;
    }
    for (Ring* r : rings)
        for (Vec2& p : *r)
            p.x = rep[std::lower_bound(xs.begin(), xs.end(), p.x) - xs.begin()];
}

void orient(Ring& ring, bool counterClockwise) {
    if ((signedArea(ring) > 0) != counterClockwise)
        std::reverse(ring.begin(), ring.end());
}

struct RawCell {
    int room = 0;
    double x0 = 0, x1 = 0;
    Polyline floor, ceiling;
};

// One raw cell's share of the final cells: consecutive x-pieces.
struct Piece {
    int cell = -1; // final cell id
    double x0 = 0, x1 = 0;
};

struct RawAdjacency {
    Adjacency::Kind kind;
    int first, second;
    double x0, x1;   // along: shared x-range; across: x0 == x1 == x
    double y0, y1;   // across: shared y-range; along: border y at x0 and x1
};

std::vector<RawAdjacency> rawAdjacencies(const SlabSweep& sweep, const std::vector<int>& cellOf) {
    std::vector<RawAdjacency> out;
    for (const detail::TrapezoidLink& l : sweep.links) {
        const int a = cellOf[l.left], b = cellOf[l.right];
        if (a != b)
            out.push_back({Adjacency::Kind::AcrossSweep, a, b, l.x, l.x, l.y0, l.y1});
    }
    // Along-sweep borders: merge contiguous pieces between the same pair of cells.
    std::map<std::pair<int, int>, std::vector<RawAdjacency>> along;
    for (const detail::TrapezoidStack& s : sweep.stacks) {
        const int a = cellOf[s.lower], b = cellOf[s.upper];
        if (a == b)
            continue;
        const Trapezoid& t = sweep.trapezoids[s.lower];
        auto& list = along[{a, b}];
        if (!list.empty() && list.back().x1 == t.xa) {
            list.back().x1 = t.xb;
            list.back().y1 = t.cb;
        } else {
            list.push_back({Adjacency::Kind::AlongSweep, a, b, t.xa, t.xb, t.ca, t.cb});
        }
    }
    for (auto& [key, list] : along)
        out.insert(out.end(), list.begin(), list.end());
    return out;
}

std::vector<double> stripePositions(double x0, double x1, double w) {
    const double width = x1 - x0;
    const int n = std::max(1, static_cast<int>(std::ceil(width / w - 1e-9)));
    if (n == 1)
        return {0.5 * (x0 + x1)};
    std::vector<double> xs(n);
    for (int i = 0; i < n; ++i)
        xs[i] = x0 + 0.5 * w + i * (width - w) / (n - 1);
    return xs;
}

// The x-pieces one raw cell becomes (SPEC sect. 2.3, our rule for narrow cells):
// a cell gives up a W-wide transition strip at each critical side while a primary of
// positive width remains; a cell with no more stripes than critical sides becomes
// transition cells only (one per stripe; a one-stripe cell between two slices is one).
std::vector<std::pair<double, double>> pieceRanges(double x0, double x1, bool left, bool right,
                                                   double w, std::vector<CellKind>& kinds) {
    const int k = int(left) + int(right);
    const double width = x1 - x0;
    const int stripes = std::max(1, static_cast<int>(std::ceil(width / w - 1e-9)));
    kinds.clear();
    if (k == 0) {
        kinds = {CellKind::Primary};
        return {{x0, x1}};
    }
    if (stripes >= k + 1) {
        std::vector<std::pair<double, double>> out;
        const double a = left ? x0 + w : x0, b = right ? x1 - w : x1;
        if (left) {
            out.push_back({x0, a});
            kinds.push_back(CellKind::Transition);
        }
        out.push_back({a, b});
        kinds.push_back(CellKind::Primary);
        if (right) {
            out.push_back({b, x1});
            kinds.push_back(CellKind::Transition);
        }
        return out;
    }
    if (stripes == 2 && k == 2) {
        const double mid = 0.5 * (x0 + x1);
        kinds = {CellKind::Transition, CellKind::Transition};
        return {{x0, mid}, {mid, x1}};
    }
    kinds = {CellKind::Transition};
    return {{x0, x1}};
}

// Splits a raw cell where its clear region is interrupted (a passage narrower than W):
// returns x-ranges with a flag telling whether the robot fits there. Infeasible margins
// at the cell's own ends (next to walls) are not interruptions.
struct Range {
    double x0, x1;
    bool feasible;
};

std::vector<Range> feasibleRanges(const RawCell& raw, const ClearanceField& field) {
    Cell probe;
    probe.x0 = raw.x0, probe.x1 = raw.x1;
    probe.floor = raw.floor, probe.ceiling = raw.ceiling;
    const double r = field.radius();
    const double step = 0.25 * r;
    const int n = std::max(1, static_cast<int>(std::ceil((raw.x1 - raw.x0) / step)));
    std::vector<double> xs(n);
    std::vector<char> ok(n);
    for (int i = 0; i < n; ++i) {
        xs[i] = raw.x0 + (i + 0.5) * (raw.x1 - raw.x0) / n;
        ok[i] = !detail::spanAt(probe, xs[i], field).empty();
    }
    auto boundary = [&](double good, double bad) { // bisection to the feasibility edge
        for (int it = 0; it < 30; ++it) {
            const double mid = 0.5 * (good + bad);
            (detail::spanAt(probe, mid, field).empty() ? bad : good) = mid;
        }
        return good;
    };
    std::vector<Range> out;
    double start = raw.x0;
    int i = 0;
    while (i < n) {
        if (ok[i]) {
            ++i;
            continue;
        }
        int j = i;
        while (j < n && !ok[j])
            ++j;
        if (i > 0 && j < n) { // an interior interruption
            const double a = boundary(xs[i - 1], xs[i]), b = boundary(xs[j], xs[j - 1]);
            double cutA = std::min(a + r, raw.x1), cutB = std::max(b - r, raw.x0);
            if (cutA >= cutB)
                cutA = cutB = 0.5 * (a + b);
            out.push_back({start, cutA, true});
            if (cutB > cutA)
                out.push_back({cutA, cutB, false});
            start = cutB;
        }
        i = j;
    }
    const bool anyFeasible = std::any_of(ok.begin(), ok.end(), [](char c) { return c != 0; });
    out.push_back({start, raw.x1, anyFeasible});
    return out;
}

const Piece& pieceAt(const std::vector<Piece>& pieces, double x, bool leftOfX) {
    for (const Piece& p : pieces)
        if (leftOfX ? (p.x0 < x && x <= p.x1) : (p.x0 <= x && x < p.x1))
            return p;
    return leftOfX ? pieces.back() : pieces.front();
}

} // namespace

Decomposition decompose(const Plan& plan, const DecompositionOptions& options) {
    const double w = options.coverageWidth;
    Decomposition out;
    out.coverageWidth = w;
    const BoundingBox bounds = plan.bounds();
    out.frame = Frame({bounds.minX, bounds.minY}, options.stripeAngleDeg);
    const double extent = std::max({1.0, bounds.width(), bounds.height()});

    Ring boundary = out.frame.toLocal(plan.boundary);
    orient(boundary, true);
    std::vector<Ring> holes, rooms;
    for (const Ring& h : plan.obstacles) {
        holes.push_back(out.frame.toLocal(h));
        orient(holes.back(), false);
    }
    for (const Room& r : plan.rooms)
        rooms.push_back(out.frame.toLocal(r.outline));
    std::vector<Ring*> all{&boundary};
    for (Ring& h : holes)
        all.push_back(&h);
    for (Ring& r : rooms)
        all.push_back(&r);
    snapXs(all, 1e-9 * extent);

    out.freeSpace.push_back(boundary);
    out.freeSpace.insert(out.freeSpace.end(), holes.begin(), holes.end());
    SlabSweep sweep = detail::sweepSlabs(out.freeSpace, rooms, 1e-9 * extent);

    for (const Room& r : plan.rooms)
        out.roomNames.push_back(r.name);
    if (plan.rooms.empty()) {
        out.roomNames.push_back("Floor");
        for (Trapezoid& t : sweep.trapezoids)
            t.room = 0;
    } else {
        const int rooms = detail::assignLeftovers(sweep, static_cast<int>(plan.rooms.size()));
        for (int i = static_cast<int>(plan.rooms.size()); i < rooms; ++i)
            out.roomNames.push_back("Unassigned " + std::to_string(i - plan.rooms.size() + 1));
        detail::fuseSameRoomStacks(sweep, 1e-9 * extent);
    }

    // Merge trapezoids while the slice connectivity inside their room does not change.
    const int nt = static_cast<int>(sweep.trapezoids.size());
    std::vector<std::vector<int>> sameRight(nt), sameLeft(nt);
    for (const detail::TrapezoidLink& l : sweep.links) {
        if (sweep.trapezoids[l.left].room == sweep.trapezoids[l.right].room) {
            sameRight[l.left].push_back(l.right);
            sameLeft[l.right].push_back(l.left);
        }
    }
    std::vector<int> cellOf(nt, -1);
    std::vector<RawCell> raw;
    for (const auto& members : sweep.slabMembers) {
        for (int t : members) {
            const Trapezoid& z = sweep.trapezoids[t];
            const bool continues = sameLeft[t].size() == 1 && sameRight[sameLeft[t][0]].size() == 1;
            if (continues) {
                cellOf[t] = cellOf[sameLeft[t][0]];
            } else {
                cellOf[t] = static_cast<int>(raw.size());
                raw.push_back({z.room, z.xa, z.xb, {}, {}});
            }
            RawCell& c = raw[cellOf[t]];
            c.x1 = z.xb;
            detail::appendPiece(c.floor, z.xa, z.fa, z.xb, z.fb);
            detail::appendPiece(c.ceiling, z.xa, z.ca, z.xb, z.cb);
        }
    }

    const std::vector<RawAdjacency> adj = rawAdjacencies(sweep, cellOf);
    std::vector<char> leftCritical(raw.size(), 0), rightCritical(raw.size(), 0);
    for (const RawAdjacency& a : adj) {
        if (a.kind != Adjacency::Kind::AcrossSweep)
            continue;
        if (raw[a.first].x1 == a.x0)
            rightCritical[a.first] = 1;
        if (raw[a.second].x0 == a.x0)
            leftCritical[a.second] = 1;
    }

    // Split at narrow passages, cut transition strips and create the final cells.
    const ClearanceField field(out.freeSpace, 0.5 * w);
    std::vector<std::vector<Piece>> pieces(raw.size());
    std::vector<CellKind> kinds;
    for (size_t i = 0; i < raw.size(); ++i) {
        const RawCell& r = raw[i];
        std::vector<std::pair<double, double>> ranges;
        std::vector<CellKind> rangeKinds;
        for (const Range& part : feasibleRanges(r, field)) {
            const bool left = part.x0 == r.x0 && leftCritical[i];
            const bool right = part.x1 == r.x1 && rightCritical[i];
            if (options.transitionCells && part.feasible) {
                const auto sub = pieceRanges(part.x0, part.x1, left, right, w, kinds);
                ranges.insert(ranges.end(), sub.begin(), sub.end());
                rangeKinds.insert(rangeKinds.end(), kinds.begin(), kinds.end());
            } else {
                ranges.push_back({part.x0, part.x1});
                rangeKinds.push_back(CellKind::Primary);
            }
        }
        kinds = rangeKinds;
        for (size_t p = 0; p < ranges.size(); ++p) {
            Cell c;
            c.id = static_cast<int>(out.cells.size());
            c.kind = kinds[p];
            c.room = r.room;
            c.x0 = ranges[p].first, c.x1 = ranges[p].second;
            c.floor = detail::clipFunction(r.floor, c.x0, c.x1);
            c.ceiling = detail::clipFunction(r.ceiling, c.x0, c.x1);
            c.stripes = c.kind == CellKind::Transition ? std::vector<double>{0.5 * (c.x0 + c.x1)}
                                                       : stripePositions(c.x0, c.x1, w);
            pieces[i].push_back({c.id, c.x0, c.x1});
            if (p > 0) {
                const Cell& prev = out.cells.back();
                out.adjacencies.push_back({Adjacency::Kind::AcrossSweep, prev.id, c.id,
                                           {{c.x0, c.floorAt(c.x0)}, {c.x0, c.ceilingAt(c.x0)}}});
            }
            out.cells.push_back(std::move(c));
        }
    }

    for (const RawAdjacency& a : adj) {
        if (a.kind == Adjacency::Kind::AcrossSweep) {
            const Piece& l = pieceAt(pieces[a.first], a.x0, true);
            const Piece& r = pieceAt(pieces[a.second], a.x0, false);
            out.adjacencies.push_back(
                {a.kind, l.cell, r.cell, {{a.x0, a.y0}, {a.x0, a.y1}}});
            out.criticalSlices.push_back({a.x0, a.y0, a.y1});
            continue;
        }
        for (const Piece& lo : pieces[a.first]) {
            for (const Piece& up : pieces[a.second]) {
                const double x0 = std::max({a.x0, lo.x0, up.x0});
                const double x1 = std::min({a.x1, lo.x1, up.x1});
                if (x1 - x0 <= 1e-9 * extent)
                    continue;
                const Cell& c = out.cells[lo.cell];
                out.adjacencies.push_back({a.kind, lo.cell, up.cell,
                                           {{x0, c.ceilingAt(x0)}, {x1, c.ceilingAt(x1)}}});
            }
        }
    }

    detail::planStripeSpans(out);
    return out;
}

} // namespace fc
