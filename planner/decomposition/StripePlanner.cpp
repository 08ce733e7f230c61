#include "decomposition/StripePlanner.h"

#include "decomposition/ClearRanges.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace fc::detail {

namespace {
// A border vertex turning by less than this (radians) is a sample of a smooth curve.
constexpr double kSmoothTurn = M_PI / 180.0;
} // namespace

Interval spanAt(const Cell& cell, double x, const ClearanceField& field, double margin) {
    const double r = field.radius() + margin;
    const double lo = cell.floorAt(x) + r, hi = cell.ceilingAt(x) - r;
    if (hi < lo - 1e-12)
        return {1, 0};
    Interval best{1, 0};
    for (const Interval& piece : field.clearPieces(x, lo, std::max(lo, hi), margin))
        if (best.empty() || piece.length() > best.length())
            best = piece;
    // The disc only needs L/2; the stripe ends keep W/2 from the cell's floor and ceiling
    // where the span allows, and a gap narrower than that is run down its middle.
    const double shrink = field.inset() - field.radius();
    if (!best.empty() && shrink > 0.0) {
        if (best.length() > 2.0 * shrink) {
            best.lo += shrink;
            best.hi -= shrink;
        } else {
            best.lo = best.hi = 0.5 * (best.lo + best.hi);
        }
    }
    return best;
}

Polyline traceBorder(const Cell& cell, double xa, double xb, bool top,
                     const ClearanceField& field) {
    const bool reversed = xa > xb;
    if (reversed)
        std::swap(xa, xb);
    const double r = field.radius();
    const double w = 2 * field.inset();
    // Interior points keep a small extra margin so that chords between them (which cut a
    // convex offset arc) still keep the full clearance; the ends are the exact corners.
    const double margin = 0.5 * field.acceptance();
    auto value = [&](double x, bool& ok) {
        Interval s = spanAt(cell, x, field, (x == xa || x == xb) ? 0.0 : margin);
        if (s.empty())
            s = spanAt(cell, x, field);
        ok = !s.empty();
        return top ? s.hi : s.lo;
    };
    // Seeds: ends, breakpoints of the cell's floor/ceiling and their +-r neighbours (where
    // clearance arcs start), and at most W/2 apart.
    // A round wall traced with thousands of vertices (hundredths of a degree each) has no
    // such arcs and no steps: its vertices are thinned to one per W/256 of x, which the
    // refinement below follows as a smooth curve (a 20,000-vertex circle took 40 s).
    std::vector<double> seeds{xa, xb};
    for (const Polyline* f : {&cell.floor, &cell.ceiling}) {
        const size_t n = f->size();
        const auto byX = [](const Vec2& p, double v) { return p.x < v; };
        double lastSmooth = -INFINITY;
        for (size_t i = std::lower_bound(f->begin(), f->end(), xa - r, byX) - f->begin();
             i < n && (*f)[i].x <= xb + r; ++i) {
            const Vec2 p = (*f)[i];
            const bool step =
                (i > 0 && (*f)[i - 1].x == p.x) || (i + 1 < n && (*f)[i + 1].x == p.x);
            bool corner = step || i == 0 || i + 1 == n;
            if (!corner) {
                const Vec2 in = p - (*f)[i - 1], out = (*f)[i + 1] - p;
                corner = std::abs(std::atan2(cross(in, out), dot(in, out))) > kSmoothTurn;
            }
            if (!corner) {
                if (p.x - lastSmooth < w / 32)
                    continue;
                lastSmooth = p.x;
            }
            const double xs[] = {p.x - r, p.x - 1e-9 * w, p.x, p.x + 1e-9 * w, p.x + r};
            for (int k = corner ? 0 : 2; k < (corner ? 5 : 3); ++k)
                if (xs[k] > xa && xs[k] < xb)
                    seeds.push_back(xs[k]);
        }
    }
    const int uniform = static_cast<int>(std::ceil((xb - xa) / (0.5 * w)));
    for (int i = 1; i < uniform; ++i)
        seeds.push_back(xa + (xb - xa) * i / uniform);
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());

    Polyline out;
    bool ok = true;
    const double tolerance = 0.25 * field.acceptance();
    std::function<void(double, double, double, double, int)> refine =
        [&](double x0, double y0, double x1, double y1, int depth) {
            const double xm = 0.5 * (x0 + x1);
            bool okMid = true;
            const double ym = value(xm, okMid);
            if (!okMid) {
                ok = false;
                return;
            }
            // Deviation of the midpoint from the chord, measured perpendicular to it.
            const Vec2 chord{x1 - x0, y1 - y0};
            const double deviation =
                std::abs(cross(chord, Vec2{xm - x0, ym - y0})) / std::max(norm(chord), 1e-12);
            if (depth < 14 && (x1 - x0) > w / 2048 && deviation > tolerance) {
                refine(x0, y0, xm, ym, depth + 1);
                refine(xm, ym, x1, y1, depth + 1);
                return;
            }
            out.push_back({xm, ym});
            out.push_back({x1, y1});
        };
    double px = seeds[0];
    double py = value(px, ok);
    if (!ok)
        return {};
    out.push_back({px, py});
    for (size_t i = 1; i < seeds.size() && ok; ++i) {
        bool okHere = true;
        const double y = value(seeds[i], okHere);
        if (!okHere)
            return {};
        refine(px, py, seeds[i], y, 0);
        px = seeds[i], py = y;
    }
    if (!ok)
        return {};
    // Remove collinear middle points.
    Polyline simple;
    for (const Vec2& p : out) {
        if (!simple.empty() && simple.back() == p)
            continue;
        while (simple.size() >= 2) {
            const Vec2 a = simple[simple.size() - 2], b = simple.back();
            if (std::abs(cross(b - a, p - b)) > 1e-12 * (1 + norm(p - a)) * (1 + norm(b - a)))
                break;
            simple.pop_back();
        }
        simple.push_back(p);
    }
    if (reversed)
        std::reverse(simple.begin(), simple.end());
    return simple;
}

bool appendStripeEndSeal(Polyline& path, const Cell& cell, double x, double endY, bool top,
                         int side, bool evenIfFlat, const ClearanceField& field, double width) {
    const double xe = std::clamp(x + side * 0.5 * width, cell.x0, cell.x1);
    if (std::abs(xe - x) < 0.125 * width)
        return false;
    const Polyline line = traceBorder(cell, x, xe, top, field);
    if (line.size() < 2 || !field.polylineIsClear(line))
        return false;
    double deviation = 0;
    for (const Vec2& p : line)
        deviation = std::max(deviation, std::abs(p.y - endY));
    if (deviation < 0.2 * width && !evenIfFlat)
        return false;
    path.insert(path.end(), line.begin() + 1, line.end());
    path.insert(path.end(), line.rbegin() + 1, line.rend());
    return true;
}

namespace {

// First x from `from` towards `to` where the cell has a clear span (bisected to 1e-6 W);
// NaN when there is none. Needed where a cell ends in a wedge: the clear region then
// starts further in than W/2 from the cell's end.
double firstFeasible(const Cell& cell, double from, double to, const ClearanceField& field) {
    const double step = 0.125 * field.radius() * (to > from ? 1 : -1);
    const int n = static_cast<int>(std::ceil((to - from) / step));
    double previous = from;
    for (int i = 1; i <= n; ++i) {
        const double x = i == n ? to : from + i * step;
        if (!spanAt(cell, x, field).empty()) {
            double bad = previous, good = x;
            for (int it = 0; it < 40 && std::abs(good - bad) > 1e-6 * field.radius(); ++it) {
                const double mid = 0.5 * (good + bad);
                (spanAt(cell, mid, field).empty() ? bad : good) = mid;
            }
            return good;
        }
        previous = x;
    }
    return NAN;
}

std::vector<double> evenStripes(double a, double b, double w) {
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / w - 1e-9)) + 1);
    if (n == 1 || b - a < 1e-9 * w)
        return {0.5 * (a + b)};
    std::vector<double> xs(n);
    for (int i = 0; i < n; ++i)
        xs[i] = a + i * (b - a) / (n - 1);
    return xs;
}

// Moves the outer stripes inward where the cell's ends are too tight for the robot.
void fitStripes(Cell& cell, const ClearanceField& field) {
    if (cell.stripes.empty())
        return;
    const double w = 2 * field.inset();
    if (cell.stripes.size() == 1 && cell.width() < w) {
        // A placed stripe (a lattice line, a hand-off) stays where the robot can drive it.
        if (cell.stripesPlaced && !spanAt(cell, cell.stripes[0], field).empty())
            return;
        cell.stripes[0] = cell.stripesPlaced ? narrowStripeX(cell, field, cell.stripes[0])
                                             : narrowStripeX(cell, field);
        return;
    }
    if (cell.stripes.size() == 1) { // one stripe: the nearest clear x to the planned one
        const double x = cell.stripes[0];
        if (!spanAt(cell, x, field).empty())
            return;
        const double right = firstFeasible(cell, x, cell.x1, field);
        const double left = firstFeasible(cell, x, cell.x0, field);
        if (!std::isnan(right) || !std::isnan(left))
            cell.stripes[0] =
                std::isnan(left) || (!std::isnan(right) && right - x < x - left) ? right : left;
        return;
    }
    if (cell.stripesPlaced) {
        // Placed on a lattice the neighbours share: only an end stripe the robot cannot
        // drive moves, to the nearest clear x inwards, or goes where it would pass the next.
        std::vector<double>& xs = cell.stripes;
        if (spanAt(cell, xs.front(), field).empty()) {
            const double x = firstFeasible(cell, xs.front(), xs.back(), field);
            if (std::isnan(x) || x >= xs[1])
                xs.erase(xs.begin());
            else
                xs.front() = x;
        }
        if (xs.size() >= 2 && spanAt(cell, xs.back(), field).empty()) {
            const double x = firstFeasible(cell, xs.back(), xs.front(), field);
            if (std::isnan(x) || x <= xs[xs.size() - 2])
                xs.pop_back();
            else
                xs.back() = x;
        }
        return;
    }
    double a = cell.stripes.front(), b = cell.stripes.back();
    const bool aBad = spanAt(cell, a, field).empty(), bBad = spanAt(cell, b, field).empty();
    if (!aBad && !bBad)
        return;
    const double fa = aBad ? firstFeasible(cell, a, cell.x1, field) : a;
    const double fb = bBad ? firstFeasible(cell, b, cell.x0, field) : b;
    if (std::isnan(fa) || std::isnan(fb))
        return; // nothing clear: the cell stays unreachable
    a = fa, b = fb;
    if (b < a)
        std::swap(a, b);
    cell.stripes = cell.kind == CellKind::Transition ? std::vector<double>{0.5 * (a + b)}
                                                     : evenStripes(a, b, w);
}

} // namespace

void planStripeSpans(Decomposition& dec) {
    const ClearanceField& field = dec.clearance();
    for (Cell& cell : dec.cells) {
        fitStripes(cell, field);
        cell.stripeSpans.clear();
        for (double x : cell.stripes)
            cell.stripeSpans.push_back(spanAt(cell, x, field));
        if (!cell.reachable() && !cell.sweptByNeighbours) {
            const Ring outline = cell.outline();
            Vec2 centre;
            for (const Vec2& p : outline)
                centre = centre + p * (1.0 / outline.size());
            dec.unreachable.push_back(
                {cell.area(), dec.frame.toWorld(centre), "too narrow for the robot"});
        }
    }
}

} // namespace fc::detail
