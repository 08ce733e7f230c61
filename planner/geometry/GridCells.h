// The cells of a square grid that a segment passes near, for the hash grids that find
// nearby segments (excursion pruning, traced rooms' pinches, the traced floor's opening).
#pragma once

#include "geometry/Geometry.h"

#include <algorithm>
#include <cmath>

namespace fc {

// Calls visit(x, y) for every cell (side `cell`, cell (x, y) = [x, x+1) * cell by
// [y, y+1) * cell) within `reach` of segment ab, walking the segment a cell's length at a
// time: by the segment's box, a 50 m stripe at W = 5 mm filled 10,000 cells and a long
// slanted wall thousands it never comes near. A cell may be visited more than once.
template <typename Visit>
void forEachCellNear(Vec2 a, Vec2 b, double cell, double reach, Visit&& visit) {
    auto cellOf = [cell](double v) { return static_cast<long long>(std::floor(v / cell)); };
    const int pieces = std::max(1, static_cast<int>(std::ceil(distance(a, b) / cell)));
    for (int k = 0; k < pieces; ++k) {
        const Vec2 p = a + (b - a) * (static_cast<double>(k) / pieces);
        const Vec2 q = a + (b - a) * (static_cast<double>(k + 1) / pieces);
        const long long x1 = cellOf(std::max(p.x, q.x) + reach);
        const long long y0 = cellOf(std::min(p.y, q.y) - reach);
        const long long y1 = cellOf(std::max(p.y, q.y) + reach);
        for (long long x = cellOf(std::min(p.x, q.x) - reach); x <= x1; ++x)
            for (long long y = y0; y <= y1; ++y)
                visit(x, y);
    }
}

} // namespace fc
