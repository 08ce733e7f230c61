#include "pipeline/RingTour.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace fc::detail {
namespace {

// Up to kRingTourSamples of the ring's corners, evenly spaced: the gaps between rings are
// estimated from these.
Polyline sampledCorners(const Ring& ring) {
    const size_t n = ring.size(), step = std::max<size_t>(1, n / kRingTourSamples);
    Polyline out;
    for (size_t i = 0; i < n; i += step)
        out.push_back(ring[i]);
    return out;
}

double gapBetween(const Polyline& a, const Polyline& b) {
    double gap = std::numeric_limits<double>::infinity();
    for (const Vec2& p : a)
        for (const Vec2& q : b)
            gap = std::min(gap, norm(p - q));
    return gap;
}

} // namespace

std::vector<size_t> tourOrder(const std::vector<Ring>& rings, Vec2 from, std::optional<Vec2> to) {
    const size_t n = rings.size();
    std::vector<Polyline> samples;
    for (const Ring& ring : rings)
        samples.push_back(sampledCorners(ring));
    std::vector<double> gap(n * n, 0.0), fromGap(n), toGap(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
        fromGap[i] = gapBetween({from}, samples[i]);
        if (to)
            toGap[i] = gapBetween({*to}, samples[i]);
        for (size_t j = i + 1; j < n; ++j)
            gap[i * n + j] = gap[j * n + i] = gapBetween(samples[i], samples[j]);
    }
    std::vector<size_t> order;
    std::vector<bool> done(n, false);
    for (size_t visited = 0; visited < n; ++visited) {
        const auto gapTo = [&](size_t k) {
            return order.empty() ? fromGap[k] : gap[order.back() * n + k];
        };
        size_t next = n;
        for (size_t k = 0; k < n; ++k)
            if (!done[k] && (next == n || gapTo(k) < gapTo(next)))
                next = k;
        done[next] = true;
        order.push_back(next);
    }
    // Position -1 is `from`, position n is `to` (gap 0 where there is none).
    const auto cost = [&](std::ptrdiff_t a, std::ptrdiff_t b) {
        if (a < 0)
            return b >= static_cast<std::ptrdiff_t>(n) ? 0.0 : fromGap[order[b]];
        if (b >= static_cast<std::ptrdiff_t>(n))
            return toGap[order[a]];
        return gap[order[a] * n + order[b]];
    };
    for (bool improved = true; improved;) {
        improved = false;
        for (std::ptrdiff_t i = 0; i + 1 < static_cast<std::ptrdiff_t>(n); ++i)
            for (std::ptrdiff_t j = i + 1; j < static_cast<std::ptrdiff_t>(n); ++j) {
                // Reversing order[i..j]: the edges (i-1, i) and (j, j+1) become (i-1, j), (i, j+1).
                const double before = cost(i - 1, i) + cost(j, j + 1);
                const double after = cost(i - 1, j) + cost(i, j + 1);
                if (after < before - 1e-9) {
                    std::reverse(order.begin() + i, order.begin() + j + 1);
                    improved = true;
                }
            }
    }
    return order;
}

} // namespace fc::detail
