// The visibility search of ClearanceField (its window search, a lazy A* over the corner
// points) and the buckets that find a window's corner points.
#include "geometry/Clearance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>

namespace fc {
namespace {

// Pairs of search points already found blocked during one window search. A node that no
// closed node sees is re-tested against every closed node each time a new one pushes it, so
// on traced maps four in five segment tests repeated a known answer (faculty map: 11.7 of
// 15.0 million). Only blocked answers repeat: a clear one closes its node.
class BlockedPairs {
public:
    explicit BlockedPairs(int n) : n_(n) {
        if (n_ <= kDenseLimit)
            bits_.assign((static_cast<std::size_t>(n_) * n_ + 63) / 64, 0);
        else
            slots_.assign(std::size_t{1} << 12, kEmpty);
    }
    bool has(int i, int j) const {
        const std::uint64_t k = key(i, j);
        if (n_ <= kDenseLimit)
            return (bits_[k >> 6] >> (k & 63)) & 1u;
        for (std::size_t s = slotOf(k);; s = (s + 1) & (slots_.size() - 1)) {
            if (slots_[s] == k)
                return true;
            if (slots_[s] == kEmpty)
                return false;
        }
    }
    void add(int i, int j) {
        const std::uint64_t k = key(i, j);
        if (n_ <= kDenseLimit) {
            bits_[k >> 6] |= std::uint64_t{1} << (k & 63);
            return;
        }
        if (2 * (count_ + 1) > slots_.size())
            grow();
        insert(k);
    }

private:
    static constexpr int kDenseLimit = 4096; // 2 MB of bits at most
    // Above it an open-addressing set (linear probing, at most half full): a node-based
    // std::unordered_set spent more time in its lookups than the segment tests they saved.
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    std::uint64_t key(int i, int j) const {
        return static_cast<std::uint64_t>(std::min(i, j)) * static_cast<std::uint64_t>(n_) +
               static_cast<std::uint64_t>(std::max(i, j));
    }
    std::size_t slotOf(std::uint64_t k) const {
        return static_cast<std::size_t>((k * 0x9e3779b97f4a7c15ull) >> 20) & (slots_.size() - 1);
    }
    void insert(std::uint64_t k) {
        std::size_t s = slotOf(k);
        while (slots_[s] != kEmpty && slots_[s] != k)
            s = (s + 1) & (slots_.size() - 1);
        if (slots_[s] == kEmpty) {
            slots_[s] = k;
            ++count_;
        }
    }
    void grow() {
        std::vector<std::uint64_t> old(slots_.size() * 2, kEmpty);
        old.swap(slots_);
        count_ = 0;
        for (const std::uint64_t k : old)
            if (k != kEmpty)
                insert(k);
    }
    int n_;
    std::vector<std::uint64_t> bits_;
    std::vector<std::uint64_t> slots_;
    std::size_t count_ = 0;
};

} // namespace

void ClearanceField::bucketCornerPoints() const {
    const double width = std::max(extent_.maxX - extent_.minX, 1e-9);
    const double height = std::max(extent_.maxY - extent_.minY, 1e-9);
    // Buckets of 2 r at least (a search window is 8 r across or more), 128 a side at most.
    bucketSize_ = std::max({2 * radius_, width / 128, height / 128});
    bucketColumns_ = static_cast<int>(width / bucketSize_) + 1;
    bucketRows_ = static_cast<int>(height / bucketSize_) + 1;
    cornerBuckets_.assign(static_cast<std::size_t>(bucketColumns_) * bucketRows_, {});
    for (std::size_t i = 0; i < cornerPoints_.size(); ++i) {
        const Vec2 c = cornerPoints_[i];
        const int col =
            std::clamp(static_cast<int>((c.x - extent_.minX) / bucketSize_), 0, bucketColumns_ - 1);
        const int row =
            std::clamp(static_cast<int>((c.y - extent_.minY) / bucketSize_), 0, bucketRows_ - 1);
        cornerBuckets_[static_cast<std::size_t>(row) * bucketColumns_ + col].push_back(
            static_cast<int>(i));
    }
}

template <class Visit>
void ClearanceField::forBucketsIn(const BoundingBox& window, Visit&& visit) const {
    cornerPoints();
    auto index = [&](double v, double origin, int count) {
        return std::clamp(static_cast<int>(std::floor((v - origin) / bucketSize_)), 0, count - 1);
    };
    const int c0 = index(window.minX, extent_.minX, bucketColumns_);
    const int c1 = index(window.maxX, extent_.minX, bucketColumns_);
    const int r0 = index(window.minY, extent_.minY, bucketRows_);
    const int r1 = index(window.maxY, extent_.minY, bucketRows_);
    for (int row = r0; row <= r1; ++row)
        for (int col = c0; col <= c1; ++col) {
            // Edge buckets also hold the points clamped into them from outside the extent.
            const bool inside = col > c0 && col < c1 && row > r0 && row < r1 && col > 0 &&
                                col < bucketColumns_ - 1 && row > 0 && row < bucketRows_ - 1;
            visit(cornerBuckets_[static_cast<std::size_t>(row) * bucketColumns_ + col], inside);
        }
}

std::vector<int> ClearanceField::cornerIndicesIn(const BoundingBox& window) const {
    std::vector<int> found;
    forBucketsIn(window, [&](const std::vector<int>& bucket, bool inside) {
        for (const int i : bucket) {
            const Vec2 c = cornerPoints_[static_cast<std::size_t>(i)];
            if (inside || (c.x >= window.minX && c.x <= window.maxX && c.y >= window.minY &&
                           c.y <= window.maxY))
                found.push_back(i);
        }
    });
    // The order of a scan over all points, so that searches break ties as before.
    std::sort(found.begin(), found.end());
    return found;
}

std::size_t ClearanceField::cornersIn(const BoundingBox& window) const {
    std::size_t n = 0;
    forBucketsIn(window, [&](const std::vector<int>& bucket, bool inside) {
        if (inside) {
            n += bucket.size();
            return;
        }
        for (const int i : bucket) {
            const Vec2 c = cornerPoints_[static_cast<std::size_t>(i)];
            n += c.x >= window.minX && c.x <= window.maxX && c.y >= window.minY &&
                 c.y <= window.maxY;
        }
    });
    return n;
}

Polyline ClearanceField::searchWindow(Vec2 a, Vec2 b, const BoundingBox& window,
                                      const std::vector<Vec2>& hints,
                                      std::size_t& checksLeft) const {
    std::vector<Vec2> pts{a, b};
    for (const Vec2& h : hints)
        if (isClear(h))
            pts.push_back(h);
    for (const int i : cornerIndicesIn(window))
        pts.push_back(cornerPoints_[static_cast<std::size_t>(i)]);
    const int n = static_cast<int>(pts.size());
    // Lazy A*: an entry (v reached from u) is pushed unchecked and its segment tested
    // only when it is popped, so most of the n^2 visibility tests never run. Only an entry
    // that improves on v's best pushed one is pushed (the heap held n entries per closed
    // node: most of the time went into growing it on maps with thousands of corners); when
    // v's entry is found blocked, v is re-seated on the best closed node that sees it, which
    // is the entry the full heap would have tried next for v.
    std::vector<double> g(n, INFINITY), pushed(n, INFINITY);
    std::vector<int> from(n, -1), closedNodes;
    std::vector<char> closed(n, 0);
    struct Entry {
        double f, g;
        int v, parent;
        bool verified;
        bool operator>(const Entry& o) const { return f > o.f; }
    };
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    g[0] = 0;
    open.push({distance(a, b), 0, 0, -1, true});
    std::vector<std::pair<double, int>> parents;
    BlockedPairs blocked(n);
    // A known answer still counts against the budget, so that a search gives up where it
    // did before the memo: the budget bounds the questions, the memo their price.
    auto sees = [&](int i, int j) {
        if (blocked.has(i, j))
            return false;
        if (segmentIsClear(pts[i], pts[j]))
            return true;
        blocked.add(i, j);
        return false;
    };
    while (!open.empty()) {
        const Entry top = open.top();
        open.pop();
        const int u = top.v;
        if (closed[u] || (!top.verified && top.g > pushed[u]))
            continue;
        if (!top.verified) {
            if (checksLeft == 0)
                return {};
            --checksLeft;
            if (!sees(top.parent, u)) {
                parents.clear();
                for (const int c : closedNodes)
                    if (c != top.parent)
                        parents.push_back({g[c] + distance(pts[c], pts[u]), c});
                // Nearest first; a heap, as the first clear one is usually among the first.
                std::make_heap(parents.begin(), parents.end(), std::greater<>());
                pushed[u] = INFINITY;
                while (!parents.empty()) {
                    std::pop_heap(parents.begin(), parents.end(), std::greater<>());
                    const auto [nd, c] = parents.back();
                    parents.pop_back();
                    if (checksLeft == 0)
                        return {};
                    --checksLeft;
                    if (sees(c, u)) {
                        pushed[u] = nd;
                        open.push({nd + distance(pts[u], b), nd, u, c, true});
                        break;
                    }
                }
                continue;
            }
        }
        closed[u] = 1;
        closedNodes.push_back(u);
        g[u] = top.g;
        from[u] = top.parent;
        if (u == 1)
            break;
        for (int v = 0; v < n; ++v) {
            if (closed[v])
                continue;
            const double nd = g[u] + distance(pts[u], pts[v]);
            if (nd < pushed[v]) {
                pushed[v] = nd;
                open.push({nd + distance(pts[v], b), nd, v, u, false});
            }
        }
    }
    if (!closed[1])
        return {};
    Polyline path;
    for (int v = 1; v >= 0; v = from[v])
        path.push_back(pts[v]);
    std::reverse(path.begin(), path.end());
    return path;
}

} // namespace fc
