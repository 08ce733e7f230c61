// k nearest corners with a packed R-tree (see NearestCorners.h).
#include "learning/NearestCorners.h"

#include "geometry/BoostGeometry.h"

#include <algorithm>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace fc {

namespace bgi = boost::geometry::index;
using bgeo::BPoint;

NearestCorners nearestCorners(const float* xy, int n, int k) {
    if (n < 0 || k < 1)
        throw std::invalid_argument("nearestCorners: negative count or no neighbour");
    NearestCorners out;
    out.index.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(k), 0);
    std::vector<std::pair<BPoint, int>> points;
    points.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        points.emplace_back(BPoint(xy[2 * i], xy[2 * i + 1]), i);
    const bgi::rtree<std::pair<BPoint, int>, bgi::rstar<16>> tree(points.begin(), points.end());
    std::vector<std::pair<double, int>> found;
    double sum = 0.0;
    long counted = 0;
    for (int i = 0; i < n; ++i) {
        const BPoint& p = points[static_cast<std::size_t>(i)].first;
        found.clear();
        for (auto it = tree.qbegin(bgi::nearest(p, static_cast<unsigned>(std::min(k, n))));
             it != tree.qend(); ++it)
            if (it->second != i)
                found.emplace_back(boost::geometry::distance(p, it->first), it->second);
        // The query's order among equal distances is the tree's: sort by (distance, index).
        std::sort(found.begin(), found.end());
        int* row = out.index.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(k);
        row[0] = i;
        const int others = std::min(static_cast<int>(found.size()), k - 1);
        for (int j = 0; j < others; ++j) {
            row[j + 1] = found[static_cast<std::size_t>(j)].second;
            sum += found[static_cast<std::size_t>(j)].first;
        }
        counted += others;
        for (int j = others + 1; j < k; ++j)
            row[j] = i;
    }
    out.meanDistance = counted > 0 ? sum / static_cast<double>(counted) : 0.0;
    return out;
}

} // namespace fc
