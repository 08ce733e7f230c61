#include "geometry/OpenRegions.h"

#include <algorithm>
#include <cmath>

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

} // namespace fc
