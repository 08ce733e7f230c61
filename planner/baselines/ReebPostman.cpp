// reeb-cpp on the independent baselines' model: the Reeb graph of the cells (a node where
// cells meet across a slice, a cell as the edge between its left and right node), the
// Chinese Postman tour over it (odd nodes paired by an exact minimum-weight perfect
// matching, LEMON's Edmonds blossom, along shortest paths; Hierholzer's circuit), and the
// path: a cell covered whole when the tour passes it once, as its top half on the first and
// its bottom half on the second pass when twice (Xu et al.), crossed on any further pass.
#include "baselines/BaselineModel.h"
#include "baselines/PerfectMatching.h"

#include <algorithm>
#include <numeric>
#include <queue>

namespace fc::baselines {
namespace {

using detail::Cell;
using detail::Model;

// Its visibility graph and step-by-step routes grow faster than the square of the cells: a
// generated 100-room office floor (636 cells) plans in 0.9 s, 300 rooms (1,873 cells) in
// 38 s. Above this it refuses.
constexpr int kReebMaxCells = 1000;

struct ReebGraph {
    int nodes = 0;
    std::vector<int> left, right; // per cell: its end nodes
    std::vector<double> weight;   // per cell: crossing it
};

ReebGraph reebGraphOf(const Model& m) {
    const int n = static_cast<int>(m.cells.size());
    std::vector<int> parent(2 * n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& [a, b] : m.links)
        parent[find(2 * a + 1)] = find(2 * b); // a's right end meets b's left end
    ReebGraph g;
    std::vector<int> id(2 * n, -1);
    for (int v = 0; v < 2 * n; ++v)
        if (id[find(v)] < 0)
            id[find(v)] = g.nodes++;
    for (int c = 0; c < n; ++c) {
        g.left.push_back(id[find(2 * c)]);
        g.right.push_back(id[find(2 * c + 1)]);
        g.weight.push_back(m.cells[c].x1 - m.cells[c].x0);
    }
    return g;
}

struct Paths {
    std::vector<double> dist;
    std::vector<int> viaCell; // cell crossed to reach the node, -1 at the source
};

Paths shortestPaths(const ReebGraph& g, int source) {
    Paths p{std::vector<double>(g.nodes, INFINITY), std::vector<int>(g.nodes, -1)};
    std::vector<std::vector<int>> incident(g.nodes);
    for (int c = 0; c < static_cast<int>(g.weight.size()); ++c)
        incident[g.left[c]].push_back(c), incident[g.right[c]].push_back(c);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    p.dist[source] = 0;
    heap.push({0, source});
    while (!heap.empty()) {
        const auto [d, u] = heap.top();
        heap.pop();
        if (d > p.dist[u])
            continue;
        for (int c : incident[u]) {
            const int v = g.left[c] == u ? g.right[c] : g.left[c];
            if (d + g.weight[c] < p.dist[v])
                p.dist[v] = d + g.weight[c], p.viaCell[v] = c, heap.push({p.dist[v], v});
        }
    }
    return p;
}

// Pairs the odd nodes of each component at the least total crossing distance (exact: Edmonds'
// blossom, baselines/PerfectMatching.h) and returns how often each cell is
// traversed: once, plus once per matched path through it.
std::vector<int> postmanMultiplicity(const ReebGraph& g) {
    std::vector<int> degree(g.nodes, 0), times(g.weight.size(), 1);
    for (std::size_t c = 0; c < g.weight.size(); ++c)
        ++degree[g.left[c]], ++degree[g.right[c]];
    std::vector<int> odd;
    for (int v = 0; v < g.nodes; ++v)
        if (degree[v] % 2)
            odd.push_back(v);
    if (odd.empty())
        return times;
    std::vector<Paths> paths;
    for (int v : odd)
        paths.push_back(shortestPaths(g, v));
    double far = 0;
    for (const Paths& p : paths)
        for (int v : odd)
            if (p.dist[v] < INFINITY)
                far = std::max(far, p.dist[v]);
    // Odd nodes of different components (an even number in each) never pair: their cost
    // exceeds any pairing within the components.
    const std::size_t k = odd.size();
    std::vector<std::vector<double>> cost(k, std::vector<double>(k, 0.0));
    for (std::size_t a = 0; a < k; ++a)
        for (std::size_t b = 0; b < k; ++b)
            cost[a][b] =
                paths[a].dist[odd[b]] < INFINITY ? paths[a].dist[odd[b]] : 10.0 * (far + 1.0) * k;
    const std::vector<int> mate = minimumWeightPerfectMatching(cost);
    for (std::size_t a = 0; a < k; ++a) {
        const std::size_t b = static_cast<std::size_t>(mate[a]);
        if (a > b)
            continue;
        const Paths& p = paths[a];
        for (int at = odd[b]; at != odd[a] && p.viaCell[at] >= 0;) {
            const int c = p.viaCell[at];
            ++times[c];
            at = g.left[c] == at ? g.right[c] : g.left[c];
        }
    }
    return times;
}

struct Step {
    int cell;
    bool leftToRight;
};

// Hierholzer's circuit from `start` over the cells traversed `times` each; appends the
// steps and marks the cells used.
void eulerCircuit(const ReebGraph& g, const std::vector<int>& times, int start,
                  std::vector<Step>& steps) {
    std::vector<std::vector<std::pair<int, int>>> incident(g.nodes); // (edge copy, cell)
    std::vector<int> copyCell;
    for (int c = 0; c < static_cast<int>(times.size()); ++c)
        for (int k = 0; k < times[c]; ++k) {
            const int e = static_cast<int>(copyCell.size());
            copyCell.push_back(c);
            incident[g.left[c]].push_back({e, c});
            incident[g.right[c]].push_back({e, c});
        }
    std::vector<char> used(copyCell.size(), 0);
    std::vector<std::size_t> next(g.nodes, 0);
    std::vector<std::pair<int, int>> stack{{start, -1}}; // node, edge copy that led here
    std::vector<std::pair<int, int>> circuit;
    while (!stack.empty()) {
        const int u = stack.back().first;
        while (next[u] < incident[u].size() && used[incident[u][next[u]].first])
            ++next[u];
        if (next[u] == incident[u].size()) {
            circuit.push_back(stack.back());
            stack.pop_back();
            continue;
        }
        const auto [e, c] = incident[u][next[u]];
        used[e] = 1;
        stack.push_back({g.left[c] == u ? g.right[c] : g.left[c], e});
    }
    std::reverse(circuit.begin(), circuit.end());
    for (std::size_t i = 1; i < circuit.size(); ++i) {
        const int c = copyCell[circuit[i].second];
        steps.push_back({c, g.left[c] == circuit[i - 1].first});
    }
}

// A boustrophedon over the stripes of `cell` in the given direction, over the whole span or
// one half of it (half: +1 top, -1 bottom); the first stripe's direction is the one whose
// first end lies nearer `from`.
Polyline pattern(const Model& m, const Cell& cell, bool leftToRight, int half, Vec2 from) {
    std::vector<detail::Stripe> stripes = cell.stripes;
    if (!leftToRight)
        std::reverse(stripes.begin(), stripes.end());
    auto endsOf = [&](const detail::Stripe& s) {
        const double mid = 0.5 * (s.span.lo + s.span.hi);
        const double lo = half > 0 ? mid : s.span.lo, hi = half < 0 ? mid : s.span.hi;
        return std::pair{lo, hi};
    };
    const auto [lo0, hi0] = endsOf(stripes.front());
    bool up = distance(from, {stripes.front().x, lo0}) <= distance(from, {stripes.front().x, hi0});
    Polyline points;
    for (const detail::Stripe& s : stripes) {
        const auto [lo, hi] = endsOf(s);
        const Vec2 a{s.x, up ? lo : hi}, b{s.x, up ? hi : lo};
        if (!points.empty()) {
            const Polyline link = m.transits->route(points.back(), a);
            if (link.empty())
                throw TourError("reeb-cpp: a cell's stripes cannot be joined");
            points.insert(points.end(), link.begin() + 1, link.end());
        } else {
            points.push_back(a);
        }
        points.push_back(b);
        up = !up;
    }
    return points;
}

} // namespace

Tour planReebPostman(const Plan& plan, const std::vector<std::string>& rooms, Vec2 start, Vec2 end,
                     const Options& options) {
    const Model m = detail::buildModel(plan, rooms, start, end, options, kReebMaxCells, "reeb-cpp");
    if (m.cells.empty())
        throw TourError("reeb-cpp: the rooms contain no cell the robot can sweep");
    const ReebGraph g = reebGraphOf(m);
    const std::vector<int> times = postmanMultiplicity(g);
    // One circuit per connected part of the Reeb graph, the part nearest the robot first.
    const Vec2 startLocal = m.frame.toLocal(start);
    std::vector<char> done(m.cells.size(), 0);
    std::vector<Step> steps;
    Vec2 at = startLocal;
    while (std::find(done.begin(), done.end(), 0) != done.end()) {
        int nearest = -1;
        double best = INFINITY;
        for (std::size_t c = 0; c < m.cells.size(); ++c) {
            if (done[c])
                continue;
            const Cell& cell = m.cells[c];
            for (const detail::Stripe& s : {cell.stripes.front(), cell.stripes.back()})
                for (double y : {s.span.lo, s.span.hi})
                    if (distance(at, {s.x, y}) < best)
                        best = distance(at, {s.x, y}), nearest = static_cast<int>(c);
        }
        const Cell& first = m.cells[nearest];
        const bool fromLeft =
            distance(at, {first.stripes.front().x, first.stripes.front().span.lo}) <=
            distance(at, {first.stripes.back().x, first.stripes.back().span.lo});
        const std::size_t before = steps.size();
        eulerCircuit(g, times, fromLeft ? g.left[nearest] : g.right[nearest], steps);
        for (std::size_t i = before; i < steps.size(); ++i)
            done[steps[i].cell] = 1;
        if (steps.size() == before) // a cell no circuit reaches (cannot happen: its own node)
            done[nearest] = 1;
        const Step& last = steps.back();
        const Cell& lastCell = m.cells[last.cell];
        at = last.leftToRight ? Vec2{lastCell.stripes.back().x, lastCell.stripes.back().span.lo}
                              : Vec2{lastCell.stripes.front().x, lastCell.stripes.front().span.lo};
    }

    Tour tour;
    Polyline local{startLocal};
    std::vector<SegmentKind> kinds;
    auto travelTo = [&](Vec2 target) {
        if (distance(local.back(), target) < 1e-12)
            return;
        const Polyline route = m.transits->route(local.back(), target);
        if (route.empty())
            throw TourError("reeb-cpp: a cell cannot be reached from the start");
        for (std::size_t i = 1; i < route.size(); ++i)
            local.push_back(route[i]), kinds.push_back(SegmentKind::Transit);
    };
    std::vector<int> passes(m.cells.size(), 0);
    for (const Step& step : steps) {
        const Cell& cell = m.cells[step.cell];
        const int pass = passes[step.cell]++;
        if (pass >= 2) {
            // Crossed only: to the far side of the cell.
            const detail::Stripe& far =
                step.leftToRight ? cell.stripes.back() : cell.stripes.front();
            travelTo({far.x, 0.5 * (far.span.lo + far.span.hi)});
            continue;
        }
        const int half = times[step.cell] >= 2 ? (pass == 0 ? 1 : -1) : 0;
        const Polyline points = pattern(m, cell, step.leftToRight, half, local.back());
        travelTo(points.front());
        for (std::size_t i = 1; i < points.size(); ++i)
            local.push_back(points[i]), kinds.push_back(SegmentKind::Stripe);
        tour.order.push_back(step.cell);
    }
    travelTo(startLocal);
    travelTo(m.frame.toLocal(end));
    tour.path.points = m.frame.toWorld(local);
    tour.path.kinds = std::move(kinds);
    tour.length = polylineLength(tour.path.points);
    tour.modelCost = tour.length;
    tour.cells = m.cellCount;
    tour.unreachableCells = m.unreachable;
    return tour;
}

} // namespace fc::baselines
