// reeb-cpp (Mannadiar & Rekleitis 2010; Xu et al. 2014), as the paper describes it: the Reeb
// graph of the classic decomposition (critical slices as nodes, cells as edges) made
// Eulerian by duplicating the edges on minimum-weight paths between odd nodes (perfect
// matching), an Euler tour from the start back to it, and each cell on a duplicated edge
// covered in two halves, the top half on its first pass and the bottom half on its second.
#include "solvers/BaselineSupport.h"
#include "solvers/PerfectMatching.h"

#include <algorithm>
#include <numeric>

namespace fc {
namespace {

using namespace baseline_detail;

constexpr const char* kName = "reeb-cpp";

class DisjointSets {
public:
    explicit DisjointSets(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int a) {
        while (parent_[a] != a)
            a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    void unite(int a, int b) { parent_[find(a)] = find(b); }

private:
    std::vector<int> parent_;
};

// A cell between two critical slices, or a link the classic Reeb graph lacks: a doorway in
// a room border along the sweep, or a border that does not end both cells.
struct ReebEdge {
    int u = -1, v = -1;
    int cell = -1; // -1 for a link
    double weight = 0;
};

struct ReebGraph {
    std::vector<int> nodeOfEnd;             // index 2 * cell + (right end)
    std::vector<std::vector<Vec2>> corners; // per node: the cell corners at it
    std::vector<ReebEdge> edges;
    std::vector<std::vector<int>> incident; // node -> edge ids

    int nodeCount() const { return static_cast<int>(corners.size()); }
    int other(int edge, int node) const {
        return edges[edge].u == node ? edges[edge].v : edges[edge].u;
    }
};

int endIndex(int cell, bool right) {
    return 2 * cell + (right ? 1 : 0);
}

// The corners of one end of a cell (LB, LT or RB, RT; both of a transition cell).
std::vector<int> endCorners(const CornerGraph& g, int cell, bool right) {
    const std::vector<int>& n = g.cells[cell].nodes;
    if (n.size() != 4)
        return n;
    return right ? std::vector<int>{n[2], n[3]} : std::vector<int>{n[0], n[1]};
}

double closestDistance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    double best = kInf;
    for (const Vec2& p : a)
        for (const Vec2& q : b)
            best = std::min(best, distance(p, q));
    return best;
}

Vec2 closestTo(const std::vector<Vec2>& points, Vec2 from) {
    return *std::min_element(points.begin(), points.end(),
                             [&](Vec2 a, Vec2 b) { return distance(a, from) < distance(b, from); });
}

ReebGraph buildReebGraph(const BaselineWorld& w) {
    const std::vector<Cell>& cells = w.decomposition.cells;
    const int n = static_cast<int>(cells.size());
    const auto connected = connectedCellPairs(w.graph);
    DisjointSets ends(2 * n);
    std::vector<std::pair<int, int>> links;
    for (const Adjacency& a : w.decomposition.adjacencies) {
        if (!w.usable[a.first] || !w.usable[a.second] ||
            !connected.count({std::min(a.first, a.second), std::max(a.first, a.second)}))
            continue;
        const double x = a.shared.a.x;
        if (a.kind == Adjacency::Kind::AcrossSweep && cells[a.first].x1 == x &&
            cells[a.second].x0 == x)
            ends.unite(endIndex(a.first, true), endIndex(a.second, false));
        else
            links.push_back({a.first, a.second});
    }
    ReebGraph reeb;
    reeb.nodeOfEnd.assign(2 * n, -1);
    std::vector<int> nodeOfRoot(2 * n, -1);
    for (int c = 0; c < n; ++c) {
        if (!w.usable[c])
            continue;
        for (bool right : {false, true}) {
            const int root = ends.find(endIndex(c, right));
            if (nodeOfRoot[root] < 0) {
                nodeOfRoot[root] = reeb.nodeCount();
                reeb.corners.emplace_back();
            }
            reeb.nodeOfEnd[endIndex(c, right)] = nodeOfRoot[root];
            for (int k : endCorners(w.graph, c, right))
                reeb.corners[nodeOfRoot[root]].push_back(w.graph.nodes[k].position);
        }
    }
    reeb.incident.resize(reeb.nodeCount());
    auto addEdge = [&](int u, int v, int cell, double weight) {
        reeb.incident[u].push_back(static_cast<int>(reeb.edges.size()));
        if (v != u)
            reeb.incident[v].push_back(static_cast<int>(reeb.edges.size()));
        reeb.edges.push_back({u, v, cell, weight});
    };
    for (int c = 0; c < n; ++c) {
        if (!w.usable[c])
            continue;
        const int u = reeb.nodeOfEnd[endIndex(c, false)], v = reeb.nodeOfEnd[endIndex(c, true)];
        // The cost of an edge is the cost of covering its cell (Mannadiar & Rekleitis); a cell
        // that need not be covered is only crossed.
        const double weight = w.required[c]
                                  ? w.graph.edges[w.graph.cells[c].coverageEdges.front()].length
                                  : closestDistance(reeb.corners[u], reeb.corners[v]);
        addEdge(u, v, c, weight);
    }
    for (const auto& [a, b] : links) {
        int bestU = -1, bestV = -1;
        double best = kInf;
        for (bool ra : {false, true}) {
            for (bool rb : {false, true}) {
                const int u = reeb.nodeOfEnd[endIndex(a, ra)], v = reeb.nodeOfEnd[endIndex(b, rb)];
                const double d = closestDistance(reeb.corners[u], reeb.corners[v]);
                if (u != v && d < best)
                    best = d, bestU = u, bestV = v;
            }
        }
        if (bestU >= 0)
            addEdge(bestU, bestV, -1, best);
    }
    return reeb;
}

ShortestPaths reebPaths(const ReebGraph& reeb, const std::vector<int>& sources) {
    return shortestPaths(reeb.nodeCount(), sources, [&](int u, auto&& visit) {
        for (int e : reeb.incident[u])
            visit(reeb.other(e, u), reeb.edges[e].weight, e);
    });
}

// Adds the edges of the shortest path from a source to `node` to the tour (duplicates).
void addPathTo(const ReebGraph& reeb, const ShortestPaths& sp, int node, std::vector<int>& tour) {
    for (int v = node; sp.via[v] >= 0; v = reeb.other(sp.via[v], v))
        tour.push_back(sp.via[v]);
}

// The required cells may form several pieces of the Reeb graph (rooms left out): join each
// to the start's piece by the shortest path to it, traversed once.
void connectPieces(const ReebGraph& reeb, std::vector<int>& tour, int startNode) {
    for (;;) {
        DisjointSets pieces(reeb.nodeCount());
        std::vector<char> touched(reeb.nodeCount(), 0);
        for (int e : tour) {
            pieces.unite(reeb.edges[e].u, reeb.edges[e].v);
            touched[reeb.edges[e].u] = touched[reeb.edges[e].v] = 1;
        }
        std::vector<int> inStartPiece;
        for (int v = 0; v < reeb.nodeCount(); ++v)
            if (pieces.find(v) == pieces.find(startNode))
                inStartPiece.push_back(v);
        const ShortestPaths sp = reebPaths(reeb, inStartPiece);
        int nearest = -1;
        for (int v = 0; v < reeb.nodeCount(); ++v)
            if (touched[v] && pieces.find(v) != pieces.find(startNode) &&
                (nearest < 0 || sp.dist[v] < sp.dist[nearest]))
                nearest = v;
        if (nearest < 0)
            return;
        if (sp.dist[nearest] == kInf)
            throw SolverError(std::string(kName) + ": the required cells are not connected");
        addPathTo(reeb, sp, nearest, tour);
    }
}

// Chinese Postman: pair the odd nodes by a minimum-weight perfect matching of their shortest
// path distances and duplicate the edges on those paths.
void makeEulerian(const ReebGraph& reeb, std::vector<int>& tour) {
    std::vector<int> degree(reeb.nodeCount(), 0);
    for (int e : tour)
        ++degree[reeb.edges[e].u], ++degree[reeb.edges[e].v];
    std::vector<int> odd;
    for (int v = 0; v < reeb.nodeCount(); ++v)
        if (degree[v] % 2)
            odd.push_back(v);
    std::vector<ShortestPaths> from;
    std::vector<std::vector<double>> cost(odd.size(), std::vector<double>(odd.size(), 0));
    for (size_t i = 0; i < odd.size(); ++i) {
        from.push_back(reebPaths(reeb, {odd[i]}));
        for (size_t j = 0; j < odd.size(); ++j)
            cost[i][j] = from[i].dist[odd[j]];
    }
    const std::vector<int> mate = minimumWeightPerfectMatching(cost);
    for (size_t i = 0; i < odd.size(); ++i)
        if (static_cast<int>(i) < mate[i])
            addPathTo(reeb, from[i], odd[mate[i]], tour);
}

struct Step {
    int edge = -1;
    int from = -1, to = -1;
};

// Hierholzer's algorithm over the tour's edges (with their duplicates) from the start node.
std::vector<Step> eulerCircuit(const ReebGraph& reeb, const std::vector<int>& tour, int start) {
    std::vector<std::vector<int>> at(reeb.nodeCount()); // node -> tour entries
    for (size_t k = 0; k < tour.size(); ++k) {
        at[reeb.edges[tour[k]].u].push_back(static_cast<int>(k));
        if (reeb.edges[tour[k]].v != reeb.edges[tour[k]].u)
            at[reeb.edges[tour[k]].v].push_back(static_cast<int>(k));
    }
    std::vector<char> used(tour.size(), 0);
    std::vector<size_t> next(reeb.nodeCount(), 0);
    std::vector<std::pair<int, int>> stack{{start, -1}}; // node, entry that reached it
    std::vector<Step> circuit;
    while (!stack.empty()) {
        const auto [v, entry] = stack.back();
        while (next[v] < at[v].size() && used[at[v][next[v]]])
            ++next[v];
        if (next[v] < at[v].size()) {
            const int k = at[v][next[v]];
            used[k] = 1;
            stack.push_back({reeb.other(tour[k], v), k});
            continue;
        }
        stack.pop_back();
        if (entry >= 0)
            circuit.push_back({tour[entry], stack.back().first, v});
    }
    if (circuit.size() != tour.size())
        throw SolverError(std::string(kName) + ": the Reeb graph is not connected");
    std::reverse(circuit.begin(), circuit.end());
    return circuit;
}

// Covers a cell, or its top or bottom half, crossing it in the given direction from the
// stripe end nearer to the robot.
void coverPart(TourBuilder& tour, const BaselineWorld& w, const ClearanceField& field, int cell,
               CellPart part, bool leftToRight) {
    const Cell& c = w.decomposition.cells[cell];
    const double width = w.decomposition.coverageWidth();
    const Pattern up = boustrophedon(c, field, width, part, leftToRight, true);
    const Pattern down = boustrophedon(c, field, width, part, leftToRight, false);
    const bool upFirst = distance(up.points.front(), tour.position()) <=
                         distance(down.points.front(), tour.position());
    tour.follow(upFirst ? up : down);
}

} // namespace

Solution solveReebPostman(const PreparedPlan& prepared, const Query& query) {
    const BaselineWorld world = makeBaselineWorld(prepared, query, kName);
    const ReebGraph reeb = buildReebGraph(world);
    std::vector<int> tour;
    for (size_t e = 0; e < reeb.edges.size(); ++e)
        if (reeb.edges[e].cell >= 0 && world.required[reeb.edges[e].cell])
            tour.push_back(static_cast<int>(e));
    // The tour starts at the critical slice of a required cell nearest to the start.
    int startNode = -1;
    double nearest = kInf;
    for (int e : tour)
        for (int v : {reeb.edges[e].u, reeb.edges[e].v})
            if (closestDistance(reeb.corners[v], {world.start}) < nearest)
                nearest = closestDistance(reeb.corners[v], {world.start}), startNode = v;
    connectPieces(reeb, tour, startNode);
    makeEulerian(reeb, tour);
    const std::vector<Step> circuit = eulerCircuit(reeb, tour, startNode);

    const ClearanceField& field = world.decomposition.clearance();
    TourBuilder path(world.start, field, world.graph, kName);
    std::vector<int> passes(world.decomposition.cells.size(), 0), passesMade(passes.size(), 0);
    for (const Step& s : circuit)
        if (reeb.edges[s.edge].cell >= 0)
            ++passes[reeb.edges[s.edge].cell];
    for (const Step& s : circuit) {
        const int cell = reeb.edges[s.edge].cell;
        const int pass = cell >= 0 ? passesMade[cell]++ : 0;
        const bool leftToRight = cell >= 0 && reeb.nodeOfEnd[endIndex(cell, false)] == s.from;
        if (cell >= 0 && world.required[cell] && passes[cell] == 1)
            coverPart(path, world, field, cell, CellPart::Whole, leftToRight);
        else if (cell >= 0 && world.required[cell] && pass < 2)
            coverPart(path, world, field, cell, pass == 0 ? CellPart::Top : CellPart::Bottom,
                      leftToRight);
        else // a link, a cell that need not be covered, or a third pass: cross it
            path.travelTo(closestTo(reeb.corners[s.to], path.position()));
    }
    path.travelTo(world.start);
    return baselineSolution(kName, path.take());
}

} // namespace fc
