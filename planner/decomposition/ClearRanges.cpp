#include "decomposition/ClearRanges.h"

#include <algorithm>
#include <cmath>

namespace fc::detail {

std::vector<Interval> spansAt(const Cell& cell, double x, const ClearanceField& field,
                              double margin) {
    const double r = field.radius() + margin;
    const double lo = cell.floorAt(x) + r, hi = cell.ceilingAt(x) - r;
    if (hi < lo - 1e-12)
        return {};
    std::vector<Interval> pieces = field.clearPieces(x, lo, std::max(lo, hi), margin);
    // Pieces split by numerical noise are one piece.
    std::vector<Interval> merged;
    for (const Interval& p : pieces) {
        if (!merged.empty() && p.lo - merged.back().hi < 1e-9 * field.radius())
            merged.back().hi = std::max(merged.back().hi, p.hi);
        else
            merged.push_back(p);
    }
    return merged;
}

namespace {

int countAt(const Cell& cell, double x, const ClearanceField& field) {
    return static_cast<int>(spansAt(cell, x, field).size());
}

// The x in (good, bad) where the span count stops being `count` (bisection).
double edgeOf(const Cell& cell, double good, double bad, int count, const ClearanceField& f) {
    for (int it = 0; it < 30; ++it) {
        const double mid = 0.5 * (good + bad);
        (countAt(cell, mid, f) == count ? good : bad) = mid;
    }
    return 0.5 * (good + bad);
}

// Lines between stacked spans over [x0, x1], through the middles of the gaps.
std::vector<Polyline> pinchLines(const Cell& cell, double x0, double x1, int layers,
                                 const ClearanceField& field) {
    std::vector<Polyline> lines(layers - 1);
    const double step = 0.25 * field.radius();
    const int n = std::max(1, static_cast<int>(std::ceil((x1 - x0) / step)));
    for (int i = 0; i <= n; ++i) {
        // Sample just inside the ends, where the count is the range's own.
        const double t = std::clamp(static_cast<double>(i) / n, 1e-6, 1 - 1e-6);
        const double x = x0 + t * (x1 - x0);
        const std::vector<Interval> spans = spansAt(cell, x, field);
        if (static_cast<int>(spans.size()) != layers)
            continue;
        for (int k = 0; k + 1 < layers; ++k)
            lines[k].push_back({x, 0.5 * (spans[k].hi + spans[k + 1].lo)});
    }
    for (Polyline& line : lines) { // stretch to the exact range ends
        if (line.empty())
            line = {{x0, 0.5 * (cell.floorAt(x0) + cell.ceilingAt(x0))}};
        line.front().x = x0;
        if (line.size() == 1)
            line.push_back({x1, line.front().y});
        line.back().x = x1;
    }
    return lines;
}

} // namespace

double narrowStripeX(const Cell& cell, const ClearanceField& field, double preferred) {
    const double r = field.inset();
    const double mid = 0.5 * (cell.x0 + cell.x1);
    const double a = std::min(cell.x1 - r, mid), b = std::max(cell.x0 + r, mid);
    const double target = std::isnan(preferred) ? mid : std::clamp(preferred, a, b);
    double bestX = target, best = -1;
    const int candidates = std::isnan(preferred) ? 16 : 17; // and the preferred x itself
    for (int i = 0; i <= candidates; ++i) {
        const double x = i == 17 ? target : a + (b - a) * i / 16;
        double total = 0;
        for (const Interval& span : spansAt(cell, x, field))
            total += span.length() + 1e-9; // a zero-length span still counts
        if (total > best + 1e-9 ||
            (std::abs(total - best) <= 1e-9 && std::abs(x - target) < std::abs(bestX - target)))
            best = total, bestX = x;
    }
    return bestX;
}

std::vector<ClearRange> clearRanges(const Cell& cell, const ClearanceField& field, double placed) {
    const double r = field.inset();
    const double step = 0.25 * r;
    // Stripes lie at least W/2 inside the cell's ends; closer to an end, the slice sees
    // the geometry across it (an obstacle starting there splits the clear span), which
    // says nothing about this cell.
    double from = cell.x0 + r, to = cell.x1 - r;
    if (to < from) {
        // A cell narrower than W holds one stripe anywhere its head still spans the whole
        // cell, x in [x1 - W/2, x0 + W/2] (possibly outside the cell, e.g. W/2 from a bed
        // whose side is the cell's end): take the slice with the longest clear spans.
        std::vector<Interval> spans;
        if (!std::isnan(placed))
            spans = spansAt(cell, placed, field);
        if (spans.empty())
            spans = spansAt(cell, narrowStripeX(cell, field), field);
        ClearRange whole{cell.x0, cell.x1, static_cast<int>(spans.size()), {}};
        for (size_t k = 0; k + 1 < spans.size(); ++k) {
            const double y = 0.5 * (spans[k].hi + spans[k + 1].lo);
            whole.pinches.push_back({{cell.x0, y}, {cell.x1, y}});
        }
        return {whole};
    }
    const int n = std::max(1, static_cast<int>(std::ceil((to - from) / step)) + 1);
    std::vector<double> xs(n);
    std::vector<int> count(n);
    for (int i = 0; i < n; ++i) {
        xs[i] = n == 1 ? from : from + i * (to - from) / (n - 1);
        count[i] = countAt(cell, xs[i], field);
    }
    // Nothing clear next to the cell's own ends is the wall margin, not a range.
    int first = 0, last = n - 1;
    while (first < n && count[first] == 0)
        ++first;
    while (last >= 0 && count[last] == 0)
        --last;
    if (first > last)
        return {{cell.x0, cell.x1, 0, {}}};

    std::vector<ClearRange> out;
    double start = cell.x0;
    for (int i = first; i <= last;) {
        int j = i;
        while (j <= last && count[j] == count[i])
            ++j;
        if (j > last) {
            out.push_back({start, cell.x1, count[i], {}});
            break;
        }
        const double edge = edgeOf(cell, xs[j - 1], xs[j], count[i], field);
        if (count[j] == 0) {
            // A passage too narrow for the robot: keep what the heads reach on both sides
            // (W/2 past the last clear slice) and report the rest as unreachable.
            int k = j;
            while (k <= last && count[k] == 0)
                ++k;
            const double back = edgeOf(cell, xs[k], xs[k - 1], count[k], field);
            double cutA = std::min(edge + r, cell.x1), cutB = std::max(back - r, cell.x0);
            if (cutA >= cutB)
                cutA = cutB = 0.5 * (edge + back);
            out.push_back({start, cutA, count[i], {}});
            if (cutB > cutA)
                out.push_back({cutA, cutB, 0, {}});
            start = cutB;
            i = k;
        } else {
            out.push_back({start, edge, count[i], {}});
            start = edge;
            i = j;
        }
    }
    for (ClearRange& range : out)
        if (range.layers >= 2)
            range.pinches = pinchLines(cell, range.x0, range.x1, range.layers, field);
    return out;
}

} // namespace fc::detail
