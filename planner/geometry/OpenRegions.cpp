#include "geometry/OpenRegions.h"

#include <algorithm>
#include <cmath>

namespace fc {

namespace {
constexpr double kMaxGridCells = 1'000'000;
}

OpenRegions::OpenRegions(const SegmentIndex& walls, BoundingBox extent, double r) : box_(extent) {
    box_.minX -= r, box_.minY -= r, box_.maxX += r, box_.maxY += r;
    h_ = std::max(r / 6, std::sqrt(box_.width() * box_.height() / kMaxGridCells));
    nx_ = static_cast<int>(std::ceil(box_.width() / h_)) + 1;
    ny_ = static_cast<int>(std::ceil(box_.height() / h_)) + 1;
    const double threshold = r - h_ * std::sqrt(2.0) / 2;
    std::vector<char> open(static_cast<size_t>(nx_) * ny_);
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i)
            open[index(i, j)] =
                threshold <= 0 ||
                walls.pointKeepsDistance({box_.minX + i * h_, box_.minY + j * h_}, threshold);
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
