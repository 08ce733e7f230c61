#include "geometry/SegmentIndex.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <limits>

namespace fc {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BBox = bg::model::box<BPoint>;
using Value = std::pair<BBox, int>;

struct SegmentIndex::Tree {
    bgi::rtree<Value, bgi::rstar<16>> rtree;
};

SegmentIndex::SegmentIndex() : tree_(std::make_unique<Tree>()) {}
SegmentIndex::SegmentIndex(const std::vector<Ring>& rings) : SegmentIndex() {
    build(rings);
}
SegmentIndex::~SegmentIndex() = default;
SegmentIndex::SegmentIndex(SegmentIndex&&) noexcept = default;
SegmentIndex& SegmentIndex::operator=(SegmentIndex&&) noexcept = default;

void SegmentIndex::build(const std::vector<Ring>& rings) {
    segments_.clear();
    std::vector<Value> values;
    for (const Ring& ring : rings) {
        for (size_t i = 0; i < ring.size(); ++i) {
            const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
            const int id = static_cast<int>(segments_.size());
            segments_.push_back({a, b});
            values.emplace_back(BBox(BPoint(std::min(a.x, b.x), std::min(a.y, b.y)),
                                     BPoint(std::max(a.x, b.x), std::max(a.y, b.y))),
                                id);
        }
    }
    tree_->rtree = bgi::rtree<Value, bgi::rstar<16>>(values.begin(), values.end());
}

void SegmentIndex::query(const BoundingBox& box, std::vector<int>& out) const {
    out.clear();
    const BBox q(BPoint(box.minX, box.minY), BPoint(box.maxX, box.maxY));
    for (auto it = tree_->rtree.qbegin(bgi::intersects(q)); it != tree_->rtree.qend(); ++it)
        out.push_back(it->second);
}

double SegmentIndex::distanceToWalls(Vec2 p) const {
    double best = std::numeric_limits<double>::infinity();
    // Nearest by box distance, then refine: box distance is a lower bound.
    for (auto it = tree_->rtree.qbegin(bgi::nearest(BPoint(p.x, p.y), 64));
         it != tree_->rtree.qend(); ++it) {
        const double boxD = bg::distance(BPoint(p.x, p.y), it->first);
        if (boxD > best)
            break;
        const Segment& s = segments_[it->second];
        best = std::min(best, pointSegmentDistance(p, s.a, s.b));
    }
    return best;
}

double SegmentIndex::segmentClearance(Vec2 a, Vec2 b) const {
    double best = std::numeric_limits<double>::infinity();
    // Grow the search box until it contains a wall closer than the box margin.
    double margin = std::max(1.0, 0.25 * distance(a, b));
    std::vector<int> hits;
    for (int round = 0; round < 40; ++round) {
        BoundingBox box;
        box.add(a);
        box.add(b);
        box.minX -= margin, box.minY -= margin, box.maxX += margin, box.maxY += margin;
        query(box, hits);
        for (int id : hits) {
            const Segment& s = segments_[id];
            best = std::min(best, segmentSegmentDistance(a, b, s.a, s.b));
        }
        if (best <= margin || hits.size() == segments_.size())
            return best;
        margin *= 4.0;
    }
    return best;
}

bool SegmentIndex::pointKeepsDistance(Vec2 p, double d) const {
    const BBox q(BPoint(p.x - d, p.y - d), BPoint(p.x + d, p.y + d));
    for (auto it = tree_->rtree.qbegin(bgi::intersects(q)); it != tree_->rtree.qend(); ++it) {
        const Segment& s = segments_[it->second];
        if (pointSegmentDistance(p, s.a, s.b) < d)
            return false;
    }
    return true;
}

bool SegmentIndex::segmentKeepsDistance(Vec2 a, Vec2 b, double d) const {
    // A slanted segment's bounding box holds far more walls than its d-neighbourhood
    // (a 20 m diagonal: 400 m² against 12 m²), and every wall in it was tested; visibility
    // searches on traced maps spent most of their time there. So the segment is cut into
    // pieces about 2d across in the shorter direction and each piece's box is asked: their
    // union still holds the whole neighbourhood, so the answer is the same.
    const double spanX = std::abs(b.x - a.x), spanY = std::abs(b.y - a.y);
    const int pieces =
        d > 0.0 ? static_cast<int>(std::clamp(std::min(spanX, spanY) / (2.0 * d), 1.0, 256.0)) : 1;
    for (int k = 0; k < pieces; ++k) {
        const Vec2 p = a + (b - a) * (static_cast<double>(k) / pieces);
        const Vec2 q = k + 1 == pieces ? b : a + (b - a) * (static_cast<double>(k + 1) / pieces);
        const BBox box(BPoint(std::min(p.x, q.x) - d, std::min(p.y, q.y) - d),
                       BPoint(std::max(p.x, q.x) + d, std::max(p.y, q.y) + d));
        for (auto it = tree_->rtree.qbegin(bgi::intersects(box)); it != tree_->rtree.qend(); ++it) {
            const Segment& s = segments_[it->second];
            if (segmentSegmentDistance(a, b, s.a, s.b) < d)
                return false;
        }
    }
    return true;
}

double SegmentIndex::polylineClearance(const Polyline& line) const {
    double best = std::numeric_limits<double>::infinity();
    if (line.size() == 1)
        return distanceToWalls(line[0]);
    for (size_t i = 1; i < line.size(); ++i)
        best = std::min(best, segmentClearance(line[i - 1], line[i]));
    return best;
}

} // namespace fc
