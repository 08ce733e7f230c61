#include "decomposition/Decomposition.h"

#include <algorithm>

namespace fc {
namespace {

// Value of a piecewise-linear function at x; at a jump, the lower or upper value.
double valueAt(const Polyline& f, double x, bool upper) {
    if (f.empty())
        return 0.0;
    if (x <= f.front().x)
        return f.front().y;
    if (x >= f.back().x)
        return f.back().y;
    double best = upper ? -INFINITY : INFINITY;
    bool found = false;
    // x is non-decreasing along f: only the segments from the first point at or after x to
    // the first one past it contain x (binary search; a round wall traced with thousands
    // of vertices made the scan quadratic: a 20,000-vertex circle planned in 78 s).
    const auto byX = [](const Vec2& p, double v) { return p.x < v; };
    const auto first = std::lower_bound(f.begin(), f.end(), x, byX);
    const auto last =
        std::upper_bound(first, f.end(), x, [](double v, const Vec2& p) { return v < p.x; });
    const size_t from = std::max<size_t>(1, first - f.begin());
    const size_t to = std::min<size_t>(f.size() - 1, last - f.begin());
    for (size_t i = from; i <= to; ++i) {
        const Vec2 a = f[i - 1], b = f[i];
        if (x < a.x || x > b.x)
            continue;
        const double y = (b.x == a.x) ? (upper ? std::max(a.y, b.y) : std::min(a.y, b.y))
                                      : a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
        best = upper ? std::max(best, y) : std::min(best, y);
        found = true;
    }
    return found ? best : f.back().y;
}

} // namespace

double Cell::floorAt(double x) const {
    return valueAt(floor, x, false);
}
double Cell::ceilingAt(double x) const {
    return valueAt(ceiling, x, true);
}

Ring Cell::outline() const {
    Ring ring(floor.begin(), floor.end());
    for (auto it = ceiling.rbegin(); it != ceiling.rend(); ++it)
        ring.push_back(*it);
    // Drop repeated points (closing duplicates at degenerate ends).
    Ring out;
    for (const Vec2& p : ring)
        if (out.empty() || out.back() != p)
            out.push_back(p);
    while (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

double Cell::area() const {
    return ringArea(outline());
}

int Decomposition::primaryCount() const {
    return static_cast<int>(std::count_if(
        cells.begin(), cells.end(), [](const Cell& c) { return c.kind == CellKind::Primary; }));
}

int Decomposition::transitionCount() const {
    return static_cast<int>(cells.size()) - primaryCount();
}

} // namespace fc

namespace fc {
bool Cell::reachable() const {
    return std::any_of(stripeSpans.begin(), stripeSpans.end(),
                       [](const Interval& s) { return !s.empty(); });
}
} // namespace fc
