#include "geometry/OpenRegions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
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

// Labels of the 8-connected components of the marked nodes (-1: unmarked).
std::vector<int> labelComponents(const std::vector<char>& marked, int nx, int ny) {
    std::vector<int> label(marked.size(), -1);
    int next = 0;
    std::vector<size_t> stack;
    for (size_t s = 0; s < marked.size(); ++s) {
        if (!marked[s] || label[s] >= 0)
            continue;
        stack.assign(1, s);
        label[s] = next;
        while (!stack.empty()) {
            const size_t c = stack.back();
            stack.pop_back();
            const int i = static_cast<int>(c % nx), j = static_cast<int>(c / nx);
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= nx || b >= ny)
                        continue;
                    const size_t n = static_cast<size_t>(b) * nx + a;
                    if (marked[n] && label[n] < 0) {
                        label[n] = next;
                        stack.push_back(n);
                    }
                }
        }
        ++next;
    }
    return label;
}
} // namespace

OpenRegions::OpenRegions(const SegmentIndex& walls, BoundingBox extent, double r,
                         Classification classification)
    : box_(extent), r_(r) {
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
    surelyClear_.assign(open.size(), 0);
    OpenClassifier clearClassifier{walls, box_, h_, r + h_ * std::sqrt(2.0) / 2, nx_, surelyClear_};
    if (classification == Classification::Pruned)
        clearClassifier.classify(0, nx_, 0, ny_);
    else
        clearClassifier.testEach(0, nx_, 0, ny_);
    label_ = labelComponents(open, nx_, ny_);
    clearLabel_ = labelComponents(surelyClear_, nx_, ny_);
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

void OpenRegions::addPortals(const std::vector<Portal>& portals,
                             const std::function<bool(Vec2, Vec2)>& sees) {
    // Far enough to leave a traced channel a metre long. The way out runs straight along the
    // gap to a point beside a surely clear node (the hop onto it is clear: every point within
    // h sqrt(2)/2 of such a node is); the node's own row may lie a little off the gap's line
    // and its far jamb hide it from the middle.
    const int steps = static_cast<int>(std::ceil(6 * r_ / h_));
    auto exit = [&](const Portal& portal, double side) -> std::optional<std::pair<size_t, Vec2>> {
        for (int s = 1; s <= steps; ++s) {
            const Vec2 q = portal.middle + portal.along * (side * s * h_);
            const int i = static_cast<int>(std::lround((q.x - box_.minX) / h_));
            const int j = static_cast<int>(std::lround((q.y - box_.minY) / h_));
            if (i < 0 || j < 0 || i >= nx_ || j >= ny_)
                return std::nullopt;
            if (surelyClear_[index(i, j)])
                return sees(portal.middle, q) ? std::optional(std::pair{index(i, j), q})
                                              : std::nullopt;
        }
        return std::nullopt;
    };
    for (const Portal& portal : portals) {
        const auto from = exit(portal, 1.0), to = exit(portal, -1.0);
        if (from && to && clearLabel_[from->first] != clearLabel_[to->first])
            bridges_.push_back({from->first, to->first, {from->second, portal.middle, to->second}});
    }
}

Polyline OpenRegions::clearRoute(Vec2 a, Vec2 b, const BoundingBox& window,
                                 const std::function<bool(Vec2, Vec2)>& sees) const {
    const int i0 = std::max(0, static_cast<int>(std::ceil((window.minX - box_.minX) / h_)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((window.minY - box_.minY) / h_)));
    const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((window.maxX - box_.minX) / h_)));
    const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((window.maxY - box_.minY) / h_)));
    if (i1 < i0 || j1 < j0)
        return {};
    const int w = i1 - i0 + 1;
    const size_t count = static_cast<size_t>(w) * (j1 - j0 + 1);
    auto nodeAt = [&](size_t k) {
        return Vec2{box_.minX + (i0 + static_cast<int>(k % w)) * h_,
                    box_.minY + (j0 + static_cast<int>(k / w)) * h_};
    };
    // Surely clear nodes a few nodes around p that p sees: where the search may start or end.
    auto gates = [&](Vec2 p) {
        std::vector<std::pair<double, size_t>> near;
        const int ci = static_cast<int>(std::lround((p.x - box_.minX) / h_));
        const int cj = static_cast<int>(std::lround((p.y - box_.minY) / h_));
        for (int j = std::max(j0, cj - 3); j <= std::min(j1, cj + 3); ++j)
            for (int i = std::max(i0, ci - 3); i <= std::min(i1, ci + 3); ++i)
                if (surelyClear_[index(i, j)]) {
                    const size_t k = static_cast<size_t>(j - j0) * w + (i - i0);
                    near.push_back({distance(p, nodeAt(k)), k});
                }
        std::sort(near.begin(), near.end());
        std::vector<std::pair<double, size_t>> seen;
        for (const auto& entry : near) {
            if (seen.size() >= 4)
                break;
            if (sees(p, nodeAt(entry.second)))
                seen.push_back(entry);
        }
        return seen;
    };
    const auto starts = gates(a);
    if (starts.empty())
        return {};
    const auto ends = gates(b);
    auto localOf = [&](size_t global) -> std::optional<size_t> {
        const int i = static_cast<int>(global % nx_), j = static_cast<int>(global / nx_);
        if (i < i0 || i > i1 || j < j0 || j > j1)
            return std::nullopt;
        return static_cast<size_t>(j - j0) * w + (i - i0);
    };
    // The portals inside the window, by the local node on either side.
    std::vector<std::pair<size_t, size_t>> crossings; // (local node, bridge), sorted
    std::map<int, int> joinedTo;                      // component -> its representative
    std::function<int(int)> find = [&](int c) {
        const auto it = joinedTo.find(c);
        return it == joinedTo.end() || it->second == c ? c : it->second = find(it->second);
    };
    for (size_t k = 0; k < bridges_.size(); ++k) {
        const auto from = localOf(bridges_[k].from), to = localOf(bridges_[k].to);
        if (!from || !to)
            continue;
        crossings.push_back({*from, k});
        crossings.push_back({*to, k});
        joinedTo[find(clearLabel_[bridges_[k].from])] = find(clearLabel_[bridges_[k].to]);
    }
    std::sort(crossings.begin(), crossings.end());
    // Gates in different components of the surely clear nodes (joined by no portal): no route
    // anywhere, and the search below would explore the whole window to find that out.
    auto componentOf = [&](size_t k) {
        return find(clearLabel_[index(i0 + static_cast<int>(k % w), j0 + static_cast<int>(k / w))]);
    };
    const bool joined = std::any_of(starts.begin(), starts.end(), [&](const auto& s) {
        return std::any_of(ends.begin(), ends.end(), [&](const auto& e) {
            return componentOf(s.second) == componentOf(e.second);
        });
    });
    if (!joined)
        return {};
    constexpr size_t kNone = std::numeric_limits<size_t>::max();
    std::vector<float> g(count, INFINITY);
    std::vector<size_t> parent(count, kNone), via(count, kNone); // via: the bridge taken
    std::vector<float> toEnd(count, INFINITY);                   // cost from an end gate on to b
    for (const auto& [d, k] : ends)
        toEnd[k] = static_cast<float>(d);
    struct Entry {
        float f, g; // f: g + the straight distance on to b
        size_t node;
        bool operator>(const Entry& o) const { return f > o.f; }
    };
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    for (const auto& [d, k] : starts) {
        g[k] = static_cast<float>(d);
        open.push({static_cast<float>(d + distance(nodeAt(k), b)), g[k], k});
    }
    float best = INFINITY;
    size_t bestEnd = kNone;
    const float diagonal = static_cast<float>(h_ * std::sqrt(2.0));
    auto relax = [&](size_t k, size_t n, float step, size_t bridge) {
        if (g[k] + step < g[n]) {
            g[n] = g[k] + step;
            parent[n] = k;
            via[n] = bridge;
            open.push({g[n] + static_cast<float>(distance(nodeAt(n), b)), g[n], n});
        }
    };
    while (!open.empty()) {
        const Entry top = open.top();
        open.pop();
        if (top.f >= best)
            break;
        const size_t k = top.node;
        if (top.g > g[k])
            continue; // a shorter way here was found after this entry
        if (g[k] + toEnd[k] < best)
            best = g[k] + toEnd[k], bestEnd = k;
        const int i = static_cast<int>(k % w), j = static_cast<int>(k / w);
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                const int x = i + di, y = j + dj;
                if ((di == 0 && dj == 0) || x < 0 || y < 0 || x >= w || y > j1 - j0 ||
                    !surelyClear_[index(i0 + x, j0 + y)])
                    continue;
                relax(k, static_cast<size_t>(y) * w + x,
                      di != 0 && dj != 0 ? diagonal : static_cast<float>(h_), kNone);
            }
        for (auto it =
                 std::lower_bound(crossings.begin(), crossings.end(), std::pair{k, size_t{0}});
             it != crossings.end() && it->first == k; ++it) {
            const Bridge& bridge = bridges_[it->second];
            const bool forward = localOf(bridge.from) == k; // way runs from `from` to `to`
            const size_t n = *localOf(forward ? bridge.to : bridge.from);
            const Vec2 in = forward ? bridge.way.front() : bridge.way.back();
            const Vec2 out = forward ? bridge.way.back() : bridge.way.front();
            relax(k, n,
                  static_cast<float>(distance(nodeAt(k), in) + polylineLength(bridge.way) +
                                     distance(out, nodeAt(n))),
                  it->second);
        }
    }
    if (bestEnd == kNone)
        return {};
    Polyline chain{b};
    for (size_t k = bestEnd; k != kNone; k = parent[k]) {
        chain.push_back(nodeAt(k));
        if (via[k] == kNone)
            continue;
        // The bridge's way, from the node before it (parent) to this one.
        const Bridge& bridge = bridges_[via[k]];
        Polyline way = bridge.way;
        if (localOf(bridge.from) == k)
            std::reverse(way.begin(), way.end()); // way runs from `from` to `to`
        chain.insert(chain.end(), way.rbegin(), way.rend());
    }
    chain.push_back(a);
    std::reverse(chain.begin(), chain.end());
    // Pulled tight: from each kept point, on to the last point of the chain it still sees.
    Polyline route{a};
    size_t anchor = 0;
    for (size_t next = 2; next < chain.size(); ++next)
        if (!sees(chain[anchor], chain[next])) {
            anchor = next - 1;
            route.push_back(chain[anchor]);
        }
    route.push_back(b);
    return route;
}

} // namespace fc
