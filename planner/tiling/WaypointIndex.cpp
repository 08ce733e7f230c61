#include "tiling/WaypointIndex.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fc::tiling {

WaypointIndex::WaypointIndex(const OrderingProblem& problem)
    : problem_(problem), totalMass_(problem.robot.totalMass()) {
    BoundingBox box;
    for (const Pose& pose : problem.poses) {
        Vec2 centre;
        for (int b = 0; b < kBlockCount; ++b)
            centre = centre + pose.blocks[b] * (problem.robot.blockMass[b] / totalMass_);
        centres_.push_back(centre);
        box.add(centre);
    }
    cellSize_ = 2.0 * problem.blockLeg();
    if (!box.empty()) {
        minX_ = box.minX;
        minY_ = box.minY;
        nx_ = static_cast<int>(box.width() / cellSize_) + 1;
        ny_ = static_cast<int>(box.height() / cellSize_) + 1;
    }
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
    slot_.resize(centres_.size());
    for (int w = 0; w < static_cast<int>(centres_.size()); ++w) {
        auto& bucket = buckets_[bucketOf(w)];
        slot_[w] = static_cast<int>(bucket.size());
        bucket.push_back(w);
    }
    remaining_ = static_cast<int>(centres_.size());
}

int WaypointIndex::bucketOf(int waypoint) const {
    const int bx = std::min(nx_ - 1, static_cast<int>((centres_[waypoint].x - minX_) / cellSize_));
    const int by = std::min(ny_ - 1, static_cast<int>((centres_[waypoint].y - minY_) / cellSize_));
    return by * nx_ + bx;
}

void WaypointIndex::remove(int waypoint) {
    if (slot_[waypoint] < 0)
        return;
    auto& bucket = buckets_[bucketOf(waypoint)];
    const int last = bucket.back();
    bucket[slot_[waypoint]] = last;
    slot_[last] = slot_[waypoint];
    bucket.pop_back();
    slot_[waypoint] = -1;
    --remaining_;
}

template <class Visit> void WaypointIndex::visitRing(int bx, int by, int r, Visit&& visit) const {
    for (int y = by - r; y <= by + r; ++y) {
        if (y < 0 || y >= ny_)
            continue;
        const bool edgeRow = y == by - r || y == by + r;
        for (int x = bx - r; x <= bx + r; x += (edgeRow || r == 0) ? 1 : 2 * r) {
            if (x >= 0 && x < nx_)
                for (int w : buckets_[y * nx_ + x])
                    visit(w);
        }
    }
}

std::vector<int> WaypointIndex::cheapestMoves(int from, int count) const {
    std::vector<std::pair<double, int>> best; // max-heap of the cheapest `count`
    if (count <= 0)
        return {};
    const int bucket = bucketOf(from);
    const int bx = bucket % nx_, by = bucket / nx_;
    const int maxRing = std::max(nx_, ny_);
    for (int r = 0; r <= maxRing; ++r) {
        // Everything in ring r moves the centre of mass at least (r - 1) buckets.
        if (static_cast<int>(best.size()) == count &&
            totalMass_ * (r - 1) * cellSize_ >= best.front().first)
            break;
        visitRing(bx, by, r, [&](int w) {
            if (w == from)
                return;
            const double c = problem_.cost(from, w);
            if (static_cast<int>(best.size()) < count) {
                best.emplace_back(c, w);
                std::push_heap(best.begin(), best.end());
            } else if (std::make_pair(c, w) < best.front()) {
                std::pop_heap(best.begin(), best.end());
                best.back() = {c, w};
                std::push_heap(best.begin(), best.end());
            }
        });
    }
    std::sort(best.begin(), best.end());
    std::vector<int> result;
    for (const auto& entry : best)
        result.push_back(entry.second);
    return result;
}

int WaypointIndex::cheapestFrom(int from) const {
    if (remaining_ == 0)
        return -1;
    const int bucket = bucketOf(from);
    const int bx = bucket % nx_, by = bucket / nx_;
    const int maxRing = std::max(nx_, ny_);
    double bestCost = INFINITY;
    int best = -1;
    for (int r = 0; r <= maxRing; ++r) {
        if (best >= 0 && totalMass_ * (r - 1) * cellSize_ >= bestCost)
            break;
        visitRing(bx, by, r, [&](int w) {
            if (w == from)
                return;
            const double c = problem_.cost(from, w);
            if (c < bestCost || (c == bestCost && w < best)) {
                bestCost = c;
                best = w;
            }
        });
    }
    return best;
}

} // namespace fc::tiling
