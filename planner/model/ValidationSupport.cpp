// Plan clean-up before validation, and the helpers validation shares with it.
#include "model/ValidationSupport.h"

#include "model/Validation.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

namespace fc {

namespace validation {

namespace {
// m: a projected coordinate beyond this is no place on Earth, and leaves under 0.2 mm of
// a double's precision.
constexpr double kMaxCoordinate = 1e12;
} // namespace

double planTolerance(const Plan& plan) {
    BoundingBox bounds;
    double largest = 0.0;
    auto addRing = [&](const Ring& ring) {
        for (const Vec2& p : ring) {
            if (std::isfinite(p.x) && std::isfinite(p.y)) {
                bounds.add(p);
                largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
            }
        }
    };
    addRing(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        addRing(obstacle);
    for (const Room& room : plan.rooms)
        addRing(room.outline);
    const double extent = bounds.empty() ? 0.0 : std::max(bounds.width(), bounds.height());
    return std::max({1e-9 * extent, 64.0 * DBL_EPSILON * largest, 1e-300});
}

void checkRingShape(const Ring& ring, const std::string& name, double tolerance) {
    for (size_t i = 0; i < ring.size(); ++i) {
        if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y))
            throw InputError(name + " has a non-finite coordinate at vertex " +
                             std::to_string(i + 1));
        // Beyond this a double keeps no millimetres, and the tolerances below (relative to
        // the plan's size) merge vertices: the messages would blame the ring's shape.
        if (std::abs(ring[i].x) > kMaxCoordinate || std::abs(ring[i].y) > kMaxCoordinate) {
            char text[96];
            std::snprintf(text, sizeof text, " has a coordinate of %.3g m at vertex %zu",
                          std::abs(ring[i].x) > kMaxCoordinate ? ring[i].x : ring[i].y, i + 1);
            throw InputError(name + text +
                             ", beyond any map projection's range: is the plan in metres?");
        }
    }
    std::vector<std::pair<double, double>> sorted;
    for (const Vec2& p : ring)
        sorted.emplace_back(p.x, p.y);
    std::sort(sorted.begin(), sorted.end());
    const size_t distinct = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
    if (distinct < 3)
        throw InputError(name + " has only " + std::to_string(distinct) +
                         " distinct vertices; a ring needs at least 3");
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2 next = ring[(i + 1) % ring.size()];
        if (distance(ring[i], next) <= tolerance)
            throw InputError(name + " repeats vertex " + std::to_string(i + 1) + " at " +
                             formatPoint(ring[i]));
    }
    // All vertices on one line (within the tolerance). A zero signed area alone is not
    // enough: a bow-tie has one, and is reported as self-intersecting instead.
    const Vec2 first = ring.front();
    Vec2 farthest = first;
    for (const Vec2& p : ring)
        if (distance(p, first) > distance(farthest, first))
            farthest = p;
    const Vec2 axis = farthest - first;
    const bool onOneLine = std::all_of(ring.begin(), ring.end(), [&](Vec2 p) {
        return std::abs(cross(axis, p - first)) <= tolerance * norm(axis);
    });
    if (onOneLine)
        throw InputError(name + " has zero area (its vertices lie on one line)");
}

std::string formatNumber(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3f", value);
    std::string text = buffer;
    const size_t dot = text.find('.');
    if (dot != std::string::npos)
        text.erase(std::max(text.find_last_not_of('0') + 1, dot + 2));
    return text == "-0.0" ? "0.0" : text;
}

std::string formatPoint(Vec2 p) {
    return "(" + formatNumber(p.x) + ", " + formatNumber(p.y) + ")";
}

std::string formatArea(double area) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, std::abs(area) < 0.01 ? "%.2g" : "%.2f", area);
    return std::string(buffer) + " m^2";
}

} // namespace validation

namespace {

// b lies within the tolerance of the straight line from a to c, strictly between them.
bool isStraightThrough(Vec2 a, Vec2 b, Vec2 c, double tolerance) {
    const Vec2 ac = c - a;
    const double length = norm(ac);
    if (length == 0.0 || dot(b - a, ac) <= 0.0 || dot(b - c, a - c) <= 0.0)
        return false;
    // Differences only, so UTM-sized coordinates keep their precision.
    return std::abs(cross(ac, b - a)) / length <= tolerance;
}

Ring normalizedRing(const Ring& ring, double tolerance) {
    Ring out;
    out.reserve(ring.size());
    for (const Vec2& p : ring) {
        if (!out.empty() && distance(out.back(), p) <= tolerance)
            continue;
        while (out.size() >= 2 && isStraightThrough(out[out.size() - 2], out.back(), p, tolerance))
            out.pop_back();
        out.push_back(p);
    }
    // The ring wraps around: clean the seam between the last and the first vertex.
    for (bool changed = true; changed && out.size() >= 3;) {
        changed = true;
        if (distance(out.back(), out.front()) <= tolerance)
            out.pop_back();
        else if (isStraightThrough(out[out.size() - 2], out.back(), out.front(), tolerance))
            out.pop_back();
        else if (isStraightThrough(out.back(), out.front(), out[1], tolerance))
            out.erase(out.begin());
        else
            changed = false;
    }
    return out.size() >= 3 ? out : ring; // a degenerate ring is left for validation to name
}

} // namespace

Plan normalizedPlan(const Plan& plan) {
    const double tolerance = validation::planTolerance(plan);
    Plan out = plan;
    out.boundary = normalizedRing(plan.boundary, tolerance);
    for (Ring& obstacle : out.obstacles)
        obstacle = normalizedRing(obstacle, tolerance);
    for (Room& room : out.rooms)
        room.outline = normalizedRing(room.outline, tolerance);
    return out;
}

} // namespace fc
