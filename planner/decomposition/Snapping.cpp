#include "decomposition/Snapping.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fc::detail {

void snapCoordinates(std::vector<Ring*>& rings, double eps, bool alongY) {
    auto coord = [alongY](Vec2& p) -> double& { return alongY ? p.y : p.x; };
    std::vector<double> values;
    for (Ring* r : rings)
        for (Vec2& p : *r)
            values.push_back(coord(p));
    std::sort(values.begin(), values.end());
    const double grid = std::exp2(std::floor(std::log2(eps)));
    std::vector<double> rep(values.size());
    double start = values.empty() ? 0 : values[0];
    for (size_t i = 0; i < values.size(); ++i) {
        if (values[i] - start > eps)
            start = values[i];
        rep[i] = std::round(start / grid) * grid;
    }
    for (Ring* r : rings)
        for (Vec2& p : *r)
            coord(p) =
                rep[std::lower_bound(values.begin(), values.end(), coord(p)) - values.begin()];
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
