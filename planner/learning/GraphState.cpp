// The graph-level state's per-corner features (see GraphState.h).
#include "learning/GraphState.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace fc {
namespace {

// The uncovered cells' centres in square buckets: a corner's nearest other uncovered cell
// and the count within the "near" radius come from the buckets around it instead of every
// cell (on a 1,500-cell floor that scan was most of a rollout). The values are those of the
// full scan: the same distances and minimum, and the capped feature beyond `limit`.
// Feature 13 counts the uncovered cells near a corner up to this many.
constexpr int kNearCellsCap = 8;

class CentreGrid {
public:
    // About as many buckets as cells, so that a search crosses few empty ones; searches
    // stop at `limit`.
    CentreGrid(const std::vector<Vec2>& centres, const std::vector<int>& cells, double limit)
        : centres_(centres), limit_(limit), cells_(static_cast<int>(cells.size())) {
        if (cells.empty())
            return;
        min_ = max_ = centres[static_cast<std::size_t>(cells.front())];
        for (int c : cells) {
            const Vec2& p = centres[static_cast<std::size_t>(c)];
            min_ = {std::min(min_.x, p.x), std::min(min_.y, p.y)};
            max_ = {std::max(max_.x, p.x), std::max(max_.y, p.y)};
        }
        const double extent = std::max({max_.x - min_.x, max_.y - min_.y, 1e-6});
        const double area =
            std::max(max_.x - min_.x, extent * 1e-3) * std::max(max_.y - min_.y, extent * 1e-3);
        size_ = std::max(std::sqrt(area / static_cast<double>(cells.size())), extent * 1e-3);
        columns_ = bucketOf(max_.x - min_.x) + 1;
        rows_ = bucketOf(max_.y - min_.y) + 1;
        buckets_.resize(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_));
        for (int c : cells) {
            const Vec2& p = centres[static_cast<std::size_t>(c)];
            buckets_[index(bucketOf(p.x - min_.x), bucketOf(p.y - min_.y))].push_back(c);
        }
    }

    // The distance from `from` to the nearest centre other than `exclude`'s (infinity when
    // there is none, at least `limit` when all lie at least that far) and how many of them
    // lie within `radius`, counted exactly up to `enough` (the feature's cap).
    // excludeListed: `exclude` is one of the cells.
    void nearestAndCount(Vec2 from, int exclude, bool excludeListed, double radius, int enough,
                         double& nearest, int& count) const {
        nearest = std::numeric_limits<double>::infinity();
        count = 0;
        if (cells_ - (excludeListed ? 1 : 0) <= 0)
            return;
        const int cx = std::clamp(bucketOf(from.x - min_.x), -1, columns_);
        const int cy = std::clamp(bucketOf(from.y - min_.y), -1, rows_);
        const int rings = std::max({cx + 1, columns_ - cx, cy + 1, rows_ - cy});
        auto visit = [&](int x, int y) {
            if (x < 0 || y < 0 || x >= columns_ || y >= rows_)
                return;
            for (int other : buckets_[index(x, y)]) {
                if (other == exclude)
                    continue;
                const double d = distance(from, centres_[static_cast<std::size_t>(other)]);
                nearest = std::min(nearest, d);
                count += d <= radius ? 1 : 0;
            }
        };
        for (int r = 0; r <= rings; ++r) {
            // Every centre in ring r or beyond is at least r - 1 bucket sizes away.
            const double beyond = static_cast<double>(r - 1) * size_;
            const bool nearestKnown = nearest <= beyond || beyond >= limit_;
            const bool countKnown = count >= enough || beyond > radius;
            if (r >= 1 && nearestKnown && countKnown) {
                nearest = std::min(nearest, std::max(beyond, limit_));
                return;
            }
            if (r == 0) {
                visit(cx, cy);
                continue;
            }
            for (int x = cx - r; x <= cx + r; ++x) { // the ring's top and bottom rows
                visit(x, cy - r);
                visit(x, cy + r);
            }
            for (int y = cy - r + 1; y <= cy + r - 1; ++y) { // and its sides
                visit(cx - r, y);
                visit(cx + r, y);
            }
        }
    }

private:
    int bucketOf(double offset) const { return static_cast<int>(std::floor(offset / size_)); }
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(columns_) +
               static_cast<std::size_t>(x);
    }

    const std::vector<Vec2>& centres_;
    double limit_;
    int cells_ = 0;
    double size_ = 1.0;
    Vec2 min_, max_;
    int columns_ = 0, rows_ = 0;
    std::vector<std::vector<int>> buckets_;
};

} // namespace

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

} // namespace

GraphStateTables::GraphStateTables(const CornerGraph& graph) {
    exitNode.assign(graph.nodes.size(), -1);
    cellNeighbours.assign(graph.cells.size(), {});
    cellCentre.assign(graph.cells.size(), Vec2{});
    for (const GraphEdge& e : graph.edges) {
        if (e.kind == EdgeKind::Coverage) {
            exitNode[static_cast<std::size_t>(e.u)] = e.v;
            exitNode[static_cast<std::size_t>(e.v)] = e.u;
        }
        const int a = graph.nodes[static_cast<std::size_t>(e.u)].cell;
        const int b = graph.nodes[static_cast<std::size_t>(e.v)].cell;
        if (a >= 0 && b >= 0 && a != b) {
            auto& na = cellNeighbours[static_cast<std::size_t>(a)];
            if (std::find(na.begin(), na.end(), b) == na.end()) {
                na.push_back(b);
                cellNeighbours[static_cast<std::size_t>(b)].push_back(a);
            }
        }
    }
    for (const GraphCell& c : graph.cells) {
        Vec2 sum;
        for (int n : c.nodes)
            sum = sum + graph.nodes[static_cast<std::size_t>(n)].position;
        if (!c.nodes.empty())
            cellCentre[static_cast<std::size_t>(c.id)] = sum * (1.0 / c.nodes.size());
    }
    if (!graph.nodes.empty()) {
        Vec2 lo = graph.nodes.front().position, hi = lo;
        for (const GraphNode& n : graph.nodes) {
            lo = {std::min(lo.x, n.position.x), std::min(lo.y, n.position.y)};
            hi = {std::max(hi.x, n.position.x), std::max(hi.y, n.position.y)};
        }
        diagonal = std::max(norm(hi - lo), 1e-9);
    }
}

std::vector<float> graphStateFeatures(const CornerGraph& graph, const GraphStateTables& tables,
                                      const GraphStateInput& state, int featureCount) {
    if (featureCount != kGraphFeatureCount && featureCount != kFirstGraphFeatureCount)
        throw std::invalid_argument("graphStateFeatures: unknown feature count");
    if (!state.covered || !state.initialCovered || !state.transitCost || !state.costToEnd)
        throw std::invalid_argument("graphStateFeatures: incomplete state");
    const std::vector<char>& covered = *state.covered;
    const std::vector<char>& initial = *state.initialCovered;
    const std::size_t cellCount = graph.cells.size();
    const double edge = std::max(graph.maxEdgeLength, 1e-9);
    const double unit = edge * kGraphCostUnit;
    auto cost = [unit](double c) {
        return static_cast<float>(c < kInfinity ? std::min(c / unit, kGraphCostCap)
                                                : kGraphCostCap);
    };

    // Per-cell and per-room counts of the episode.
    std::vector<int> uncoveredCells;
    int required = 0;
    int roomSlots = 0;
    for (const GraphCell& c : graph.cells)
        roomSlots = std::max(roomSlots, c.room + 1);
    std::vector<int> roomRequired(static_cast<std::size_t>(roomSlots), 0);
    std::vector<int> roomLeft(static_cast<std::size_t>(roomSlots), 0);
    for (std::size_t c = 0; c < cellCount; ++c) {
        const int room = graph.cells[c].room;
        if (!initial[c]) {
            ++required;
            if (room >= 0)
                ++roomRequired[static_cast<std::size_t>(room)];
        }
        if (!covered[c]) {
            uncoveredCells.push_back(static_cast<int>(c));
            if (room >= 0)
                ++roomLeft[static_cast<std::size_t>(room)];
        }
    }
    const float leftFraction =
        required > 0 ? static_cast<float>(uncoveredCells.size()) / static_cast<float>(required)
                     : 0.0f;
    const float lastCell = uncoveredCells.size() == 1 ? 1.0f : 0.0f;
    const GraphNode& current = graph.nodes[static_cast<std::size_t>(state.current)];
    const int currentRoom = current.cell >= 0 ? graph.cells[current.cell].room : -1;
    const double nearRadius = 2.0 * edge;

    double cheapestTransit = kInfinity;
    for (const GraphNode& n : graph.nodes)
        if (n.cell >= 0 && !covered[static_cast<std::size_t>(n.cell)])
            cheapestTransit =
                std::min(cheapestTransit, (*state.transitCost)[static_cast<std::size_t>(n.id)]);

    // Beyond kGraphCostCap units the nearest-cell feature is capped: no need to look further.
    const CentreGrid grid(tables.cellCentre, uncoveredCells, unit * kGraphCostCap);
    const int F = featureCount;
    std::vector<float> out(graph.nodes.size() * static_cast<std::size_t>(F), 0.0f);
    for (const GraphNode& n : graph.nodes) {
        float* f = out.data() + static_cast<std::size_t>(n.id) * F;
        const auto id = static_cast<std::size_t>(n.id);
        const int cell = n.cell;
        const bool valid = cell >= 0 && !covered[static_cast<std::size_t>(cell)] &&
                           (*state.transitCost)[id] < kInfinity;
        const int exit = tables.exitNode[id];
        f[0] = valid ? 1.0f : 0.0f;
        f[3] = n.id == state.end ? 1.0f : 0.0f;
        f[4] = n.id == state.current ? 1.0f : 0.0f;
        f[5] = leftFraction;
        f[6] = lastCell;
        f[7] = static_cast<float>((n.position.x - current.position.x) / tables.diagonal);
        f[8] = static_cast<float>((n.position.y - current.position.y) / tables.diagonal);
        // The network reads valid corners only (feature 0): the rest stay 0, which on a
        // large floor late in an episode saves most of the work.
        if (cell < 0 || !valid)
            continue;
        const GraphCell& c = graph.cells[static_cast<std::size_t>(cell)];
        f[1] = cost((*state.transitCost)[id]);
        f[2] = exit >= 0 ? cost((*state.costToEnd)[static_cast<std::size_t>(exit)]) : kGraphCostCap;
        if (F > kFirstGraphFeatureCount) {
            const double margin = (*state.transitCost)[id] - cheapestTransit;
            f[14] = static_cast<float>(std::min(margin / edge, kGraphCostCap));
            f[15] = margin <= 1e-9 * edge ? 1.0f : 0.0f;
        }
        const Vec2 from =
            exit >= 0 ? graph.nodes[static_cast<std::size_t>(exit)].position : n.position;
        double nearest = kInfinity;
        int near = 0;
        grid.nearestAndCount(from, cell, !covered[static_cast<std::size_t>(cell)], nearRadius,
                             kNearCellsCap, nearest, near);
        f[9] = nearest < kInfinity ? cost(nearest) : 0.0f;
        int adjacent = 0;
        for (int other : tables.cellNeighbours[static_cast<std::size_t>(cell)])
            adjacent += covered[static_cast<std::size_t>(other)] ? 0 : 1;
        f[10] = std::min(1.0f, static_cast<float>(adjacent) / 4.0f);
        if (c.room >= 0 && roomRequired[static_cast<std::size_t>(c.room)] > 0)
            f[11] = static_cast<float>(roomLeft[static_cast<std::size_t>(c.room)]) /
                    static_cast<float>(roomRequired[static_cast<std::size_t>(c.room)]);
        f[12] = c.room == currentRoom ? 1.0f : 0.0f;
        f[13] = std::min(1.0f, static_cast<float>(near) / static_cast<float>(kNearCellsCap));
    }
    return out;
}

} // namespace fc
