// Cutting wall teeth back to their wall's line (see WallTeeth.h).
#include "model/WallTeeth.h"

#include <algorithm>
#include <cmath>

namespace fc {
namespace {

// Vertices of one tooth at most: a traced tooth is a few points, a drawn pilaster four.
constexpr int kMaxToothVertices = 12;

struct RingShave {
    Ring ring;
    int teeth = 0;
    std::vector<std::pair<Vec2, Vec2>> newEdges; // each tooth's wall line
};

// freeLeft: the floor lies left of the ring's direction (a counter-clockwise boundary, a
// clockwise obstacle).
RingShave shaveRing(const Ring& input, bool freeLeft, double maxDepth, double maxSpan) {
    RingShave out;
    const int n = static_cast<int>(input.size());
    if (n < 6)
        return {input, 0, {}};
    const double side = freeLeft ? 1.0 : -1.0;
    const double straight = 1e-3 * maxSpan + 1e-9; // off the line: still the same wall
    auto at = [&](int k) { return input[static_cast<size_t>(((k % n) + n) % n)]; };
    // Signed distance of p from the line a->b, positive on the floor's side.
    auto offLine = [&](Vec2 a, Vec2 b, Vec2 p) {
        const Vec2 d = b - a;
        return side * cross(d, p - a) / norm(d);
    };
    std::vector<char> cut(static_cast<size_t>(n), 0);
    // Start after a vertex no tooth can hold: one where the ring turns (a corner).
    int start = 0;
    for (int k = 0; k < n; ++k) {
        const Vec2 a = at(k - 1), b = at(k), c = at(k + 1);
        if (std::abs(cross(b - a, c - b)) > 0.2 * norm(b - a) * norm(c - b)) {
            start = k;
            break;
        }
    }
    for (int s = 0; s < n;) {
        const int i = start + s;
        const Vec2 a = at(i);
        int best = -1;
        for (int j = i + 2; j <= i + kMaxToothVertices + 1 && j - start < n; ++j) {
            const Vec2 b = at(j);
            const double span = norm(b - a);
            if (span > maxSpan)
                break;
            if (span < 1e-9)
                continue;
            // The wall runs on straight through both ends.
            const Vec2 before = at(i - 1), after = at(j + 1);
            const Vec2 dir = (b - a) * (1.0 / span);
            if (std::abs(offLine(a, b, before)) > straight || dot(before - a, dir) >= 0 ||
                std::abs(offLine(a, b, after)) > straight || dot(after - b, dir) <= 0)
                continue;
            bool tooth = true, raised = false;
            for (int k = i + 1; k < j && tooth; ++k) {
                const Vec2 p = at(k);
                const double off = offLine(a, b, p);
                const double along = dot(p - a, dir);
                tooth = off > -straight && off <= maxDepth && along >= -straight &&
                        along <= span + straight;
                raised = raised || off > straight;
            }
            if (tooth && raised)
                best = j;
        }
        if (best < 0) {
            ++s;
            continue;
        }
        for (int k = i + 1; k < best; ++k)
            cut[static_cast<size_t>(((k % n) + n) % n)] = 1;
        ++out.teeth;
        out.newEdges.push_back({a, at(best)});
        s = best - start;
    }
    for (int k = 0; k < n; ++k)
        if (!cut[static_cast<size_t>(k)])
            out.ring.push_back(input[static_cast<size_t>(k)]);
    return out;
}

bool crosses(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Whether a new edge a-b of a shaved ring crosses an edge of any ring (the cut teeth lie
// on the floor's side of their wall, so only an unusual outline makes one cross).
bool crossesAny(Vec2 a, Vec2 b, const std::vector<const Ring*>& rings) {
    for (const Ring* ring : rings)
        for (size_t k = 0; k < ring->size(); ++k)
            if (crosses(a, b, (*ring)[k], (*ring)[(k + 1) % ring->size()]))
                return true;
    return false;
}

} // namespace

ShavedTeeth shaveWallTeeth(const Plan& plan, double maxDepth, double maxSpan) {
    ShavedTeeth result;
    result.plan = plan;
    if (!(maxDepth > 0) || !(maxSpan > 0))
        return result;
    std::vector<Ring*> rings{&result.plan.boundary};
    for (Ring& obstacle : result.plan.obstacles)
        rings.push_back(&obstacle);
    std::vector<const Ring*> originals{&plan.boundary};
    for (const Ring& obstacle : plan.obstacles)
        originals.push_back(&obstacle);
    for (size_t r = 0; r < rings.size(); ++r) {
        Ring& ring = *rings[r];
        const bool ccw = signedArea(ring) > 0;
        const bool freeLeft = r == 0 ? ccw : !ccw;
        RingShave shaved = shaveRing(ring, freeLeft, maxDepth, maxSpan);
        if (shaved.teeth == 0)
            continue;
        // Every wall line the shaving drew must stay clear of the rings as drawn.
        if (std::any_of(shaved.newEdges.begin(), shaved.newEdges.end(),
                        [&](const auto& e) { return crossesAny(e.first, e.second, originals); }))
            continue;
        result.area += std::abs(std::abs(signedArea(shaved.ring)) - std::abs(signedArea(ring)));
        result.teeth += shaved.teeth;
        ring = std::move(shaved.ring);
    }
    return result;
}

} // namespace fc
