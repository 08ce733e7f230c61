#include "decomposition/Snapping.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fc::detail {

namespace {

// Every coordinate (x, or y with alongY) replaced by representative(sorted values), which
// gives one value per entry of the sorted list.
template <typename Representatives>
void replaceCoordinates(std::vector<Ring*>& rings, bool alongY, Representatives representatives) {
    auto coord = [alongY](Vec2& p) -> double& { return alongY ? p.y : p.x; };
    std::vector<double> values;
    for (Ring* r : rings)
        for (Vec2& p : *r)
            values.push_back(coord(p));
    std::sort(values.begin(), values.end());
    const std::vector<double> rep = representatives(values);
    for (Ring* r : rings)
        for (Vec2& p : *r)
            coord(p) =
                rep[std::lower_bound(values.begin(), values.end(), coord(p)) - values.begin()];
}

} // namespace

void snapCoordinates(std::vector<Ring*>& rings, double eps, bool alongY) {
    replaceCoordinates(rings, alongY, [eps](const std::vector<double>& values) {
        const double grid = std::exp2(std::floor(std::log2(eps)));
        std::vector<double> rep(values.size());
        double start = values.empty() ? 0 : values[0];
        for (size_t i = 0; i < values.size(); ++i) {
            if (values[i] - start > eps)
                start = values[i];
            rep[i] = std::round(start / grid) * grid;
        }
        return rep;
    });
}

void mergeCloseCoordinates(std::vector<Ring*>& rings, double eps, bool alongY) {
    // Groups of at most eps span; each becomes its most frequent value (the smallest of
    // equals), so that a group of one value, and every coordinate apart from others by
    // more than eps, stays as it is.
    replaceCoordinates(rings, alongY, [eps](const std::vector<double>& values) {
        std::vector<double> rep(values.size());
        for (size_t first = 0; first < values.size();) {
            size_t end = first;
            while (end < values.size() && values[end] - values[first] <= eps)
                ++end;
            double best = values[first];
            size_t bestCount = 0;
            for (size_t i = first; i < end;) {
                size_t j = i;
                while (j < end && values[j] == values[i])
                    ++j;
                if (j - i > bestCount)
                    best = values[i], bestCount = j - i;
                i = j;
            }
            std::fill(rep.begin() + first, rep.begin() + end, best);
            first = end;
        }
        return rep;
    });
}

void straightenNearVertical(std::vector<Ring*>& rings, size_t firstRoom, double eps) {
    std::vector<double> xs;
    for (Ring* r : rings)
        for (const Vec2& p : *r)
            xs.push_back(p.x);
    std::sort(xs.begin(), xs.end());
    std::vector<int> count;
    std::vector<double> values;
    for (double x : xs) {
        if (values.empty() || x != values.back())
            values.push_back(x), count.push_back(0);
        ++count.back();
    }
    auto index = [&](double x) {
        return static_cast<int>(std::lower_bound(values.begin(), values.end(), x) - values.begin());
    };
    std::vector<int> parent(values.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    bool any = false;
    for (Ring* r : rings)
        for (size_t i = 0; i < r->size(); ++i) {
            const Vec2 a = (*r)[i], b = (*r)[(i + 1) % r->size()];
            const double dx = std::abs(a.x - b.x);
            if (dx > 0 && dx <= eps && std::abs(a.y - b.y) >= 10 * dx) {
                parent[find(index(a.x))] = find(index(b.x));
                any = true;
            }
        }
    if (!any)
        return;
    std::vector<char> inRoom(values.size(), 0);
    for (size_t k = firstRoom; k < rings.size(); ++k)
        for (const Vec2& p : *rings[k])
            inRoom[find(index(p.x))] = 1;
    std::vector<double> lo(values.size(), INFINITY), hi(values.size(), -INFINITY);
    std::vector<int> best(values.size(), -1);
    for (size_t i = 0; i < values.size(); ++i) {
        const int root = find(static_cast<int>(i));
        lo[root] = std::min(lo[root], values[i]);
        hi[root] = std::max(hi[root], values[i]);
        if (best[root] < 0 || count[i] > count[best[root]])
            best[root] = static_cast<int>(i);
    }
    for (Ring* r : rings)
        for (Vec2& p : *r) {
            const int root = find(index(p.x));
            if (inRoom[root] && hi[root] - lo[root] <= eps)
                p.x = values[best[root]];
        }
}

} // namespace fc::detail
