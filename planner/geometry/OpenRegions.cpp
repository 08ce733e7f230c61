#include "geometry/OpenRegions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <queue>

namespace fc {

namespace {
constexpr double kMaxGridCells = 1'000'000;
constexpr int kSmallBlock = 4; // nodes per side below which every node is tested

// Marks the nodes [i0, i1) x [j0, j1) open or closed. A block whose centre is far enough
// from every wall (or close enough to one) is decided for all its nodes at once, since the
// distance to walls changes by at most the distance moved; only blocks near the threshold
// are split, so the tests concentrate along the walls (a room's middle costs one query).
struct OpenClassifier {
    const SegmentIndex& walls;
    BoundingBox box;
    double h, threshold;
    int nx;
    std::vector<char>& open;

    void classify(int i0, int i1, int j0, int j1) {
        const int ni = i1 - i0, nj = j1 - j0;
        if (ni <= 0 || nj <= 0)
            return;
        if (ni <= kSmallBlock && nj <= kSmallBlock) {
            testEach(i0, i1, j0, j1);
            return;
        }
        const Vec2 centre = (node(i0, j0) + node(i1 - 1, j1 - 1)) * 0.5;
        const double halfDiagonal = 0.5 * h * std::hypot(ni - 1, nj - 1);
        const double d = walls.distanceToWalls(centre);
        if (d - halfDiagonal > threshold || d + halfDiagonal < threshold) {
            const char value = d - halfDiagonal > threshold ? 1 : 0;
            for (int j = j0; j < j1; ++j)
                std::fill_n(open.begin() + static_cast<long>(j) * nx + i0, ni, value);
            return;
        }
        const int im = i0 + (ni + 1) / 2, jm = j0 + (nj + 1) / 2;
        classify(i0, im, j0, jm);
        classify(im, i1, j0, jm);
        classify(i0, im, jm, j1);
        classify(im, i1, jm, j1);
    }

    void testEach(int i0, int i1, int j0, int j1) {
        for (int j = j0; j < j1; ++j)
            for (int i = i0; i < i1; ++i)
                open[static_cast<size_t>(j) * nx + i] =
                    walls.pointKeepsDistance(node(i, j), threshold);
    }

    Vec2 node(int i, int j) const { return {box.minX + i * h, box.minY + j * h}; }
};
} // namespace

OpenRegions::OpenRegions(const SegmentIndex& walls, BoundingBox extent, double r,
                         Classification classification)
    : box_(extent) {
    box_.minX -= r, box_.minY -= r, box_.maxX += r, box_.maxY += r;
    h_ = std::max(r / 6, std::sqrt(box_.width() * box_.height() / kMaxGridCells));
    nx_ = static_cast<int>(std::ceil(box_.width() / h_)) + 1;
    ny_ = static_cast<int>(std::ceil(box_.height() / h_)) + 1;
    const double threshold = r - h_ * std::sqrt(2.0) / 2;
    std::vector<char> open(static_cast<size_t>(nx_) * ny_, 1);
    OpenClassifier classifier{walls, box_, h_, threshold, nx_, open};
    if (threshold > 0 && classification == Classification::Pruned)
        classifier.classify(0, nx_, 0, ny_);
    else if (threshold > 0)
        classifier.testEach(0, nx_, 0, ny_); // else every node is open
    label_.assign(open.size(), -1);
    int next = 0;
    std::vector<size_t> stack;
    for (size_t s = 0; s < open.size(); ++s) {
        if (!open[s] || label_[s] >= 0)
            continue;
        stack.assign(1, s);
        label_[s] = next;
        while (!stack.empty()) {
            const size_t c = stack.back();
            stack.pop_back();
            const int i = static_cast<int>(c % nx_), j = static_cast<int>(c / nx_);
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= nx_ || b >= ny_)
                        continue;
                    const size_t n = index(a, b);
                    if (open[n] && label_[n] < 0) {
                        label_[n] = next;
                        stack.push_back(n);
                    }
                }
        }
        ++next;
    }
}

int OpenRegions::regionOf(Vec2 p) const {
    const int i = static_cast<int>(std::lround((p.x - box_.minX) / h_));
    const int j = static_cast<int>(std::lround((p.y - box_.minY) / h_));
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_)
        return -1;
    return label_[index(i, j)];
}

bool OpenRegions::mayJoinWithin(Vec2 a, Vec2 b, const BoundingBox& window) const {
    auto nodeOf = [&](Vec2 p, int& i, int& j) {
        i = static_cast<int>(std::lround((p.x - box_.minX) / h_));
        j = static_cast<int>(std::lround((p.y - box_.minY) / h_));
        return i >= 0 && j >= 0 && i < nx_ && j < ny_ && label_[index(i, j)] >= 0;
    };
    int ia, ja, ib, jb;
    if (!nodeOf(a, ia, ja) || !nodeOf(b, ib, jb))
        return true; // not a clear point's node: nothing proved
    if (label_[index(ia, ja)] != label_[index(ib, jb)])
        return false;
    const int i0 = std::max(0, static_cast<int>(std::floor((window.minX - box_.minX) / h_)) - 1);
    const int j0 = std::max(0, static_cast<int>(std::floor((window.minY - box_.minY) / h_)) - 1);
    const int i1 =
        std::min(nx_ - 1, static_cast<int>(std::ceil((window.maxX - box_.minX) / h_)) + 1);
    const int j1 =
        std::min(ny_ - 1, static_cast<int>(std::ceil((window.maxY - box_.minY) / h_)) + 1);
    if (ia < i0 || ia > i1 || ja < j0 || ja > j1 || ib < i0 || ib > i1 || jb < j0 || jb > j1)
        return true;
    const int w = i1 - i0 + 1;
    std::vector<char> seen(static_cast<size_t>(w) * (j1 - j0 + 1), 0);
    auto local = [&](int i, int j) { return static_cast<size_t>(j - j0) * w + (i - i0); };
    // Best first towards b: where a path exists it is found after a corridor of nodes, and
    // only a window without one is explored whole.
    using Entry = std::pair<int, int>; // (Chebyshev distance to b, node index)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    auto push = [&](int i, int j) {
        seen[local(i, j)] = 1;
        open.push({std::max(std::abs(i - ib), std::abs(j - jb)), static_cast<int>(index(i, j))});
    };
    push(ia, ja);
    while (!open.empty()) {
        const int c = open.top().second;
        open.pop();
        const int i = c % nx_, j = c / nx_;
        if (i == ib && j == jb)
            return true;
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                const int x = i + di, y = j + dj;
                if (x < i0 || y < j0 || x > i1 || y > j1 || seen[local(x, y)] ||
                    label_[index(x, y)] < 0)
                    continue;
                push(x, y);
            }
    }
    return false;
}

} // namespace fc
