// Graph solvers (SPEC sect. 3-4) on hand-built corner graphs, checked against hand-computed
// costs and an independent brute force over cell orders and cover options.
#include "TestGraphs.h"
#include "formats/PlanIO.h"
#include "pipeline/Planner.h"
#include "solvers/FlatHashMap.h"
#include "solvers/OrderEvaluator.h"
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"
#include "solvers/TourBound.h"
#include "solvers/TransitSearch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <queue>
#include <random>
#include <tuple>

using namespace fc;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using Stretch = std::function<double()>; // factor (>= 1) applied to each new edge's length
const Stretch kNoStretch = [] { return 1.0; };

// Builds corner graphs cell by cell: nodes at the cell corners, the coverage pair by stripe
// parity, contour edges, and inter edges joining the corners on a shared boundary.
class GraphBuilder {
public:
    CornerGraph graph;

    // Returns the cell id; its nodes are LB, LT, RB, RT.
    int primary(double x0, double x1, double y0, double y1, int stripes,
                const Stretch& stretch = kNoStretch) {
        const int cell = newCell(CellKind::Primary);
        const int lb = graph.addNode(cell, CornerKind::LB, {x0, y0});
        const int lt = graph.addNode(cell, CornerKind::LT, {x0, y1});
        const int rb = graph.addNode(cell, CornerKind::RB, {x1, y0});
        const int rt = graph.addNode(cell, CornerKind::RT, {x1, y1});
        const double sweep = stripes * (y1 - y0) + (x1 - x0);
        if (stripes % 2 == 0) {
            edge(lb, rb, EdgeKind::Coverage, cell, false, sweep * stretch());
            edge(lt, rt, EdgeKind::Coverage, cell, false, sweep * stretch());
        } else {
            edge(lb, rt, EdgeKind::Coverage, cell, false, sweep * stretch());
            edge(lt, rb, EdgeKind::Coverage, cell, false, sweep * stretch());
        }
        edge(lb, rb, EdgeKind::Contour, cell, false, (x1 - x0) * stretch());
        edge(lt, rt, EdgeKind::Contour, cell, false, (x1 - x0) * stretch());
        edge(lb, lt, EdgeKind::Contour, cell, true, (y1 - y0) * stretch());
        edge(rb, rt, EdgeKind::Contour, cell, true, (y1 - y0) * stretch());
        return cell;
    }

    int transition(double x, double y0, double y1) {
        const int cell = newCell(CellKind::Transition);
        const int bottom = graph.addNode(cell, CornerKind::Bottom, {x, y0});
        const int top = graph.addNode(cell, CornerKind::Top, {x, y1});
        edge(bottom, top, EdgeKind::Coverage, cell, false, y1 - y0);
        return cell;
    }

    // Every corner of `a` on side `aSide` to every corner of `b` on `bSide` (0 = left/bottom
    // corners, 1 = right/top; a transition cell has both of its nodes on every side).
    void join(int a, int aSide, int b, int bSide, const Stretch& stretch = kNoStretch) {
        for (int u : side(a, aSide))
            for (int v : side(b, bSide))
                edge(u, v, EdgeKind::Inter, -1, false,
                     distance(graph.nodes[u].position, graph.nodes[v].position) * stretch());
    }
    void joinAcross(int left, int right) { join(left, 1, right, 0); }

    int edge(int u, int v, EdgeKind kind, int cell, bool parallel, double length) {
        return fc::test::addEdge(graph, u, v, kind, cell, parallel, length);
    }

private:
    int newCell(CellKind kind) {
        GraphCell cell;
        cell.id = static_cast<int>(graph.cells.size());
        cell.kind = kind;
        graph.cells.push_back(cell);
        return cell.id;
    }
    std::vector<int> side(int cell, int which) const {
        const std::vector<int>& n = graph.cells[cell].nodes;
        if (graph.cells[cell].kind == CellKind::Transition)
            return n;
        return which == 0 ? std::vector<int>{n[0], n[1]} : std::vector<int>{n[2], n[3]};
    }
};

struct Instance {
    CornerGraph graph;
    Query query;
};

// A rows x columns layout of primary cells with random sizes, stripes and stretched
// lengths; transition cells between some horizontal neighbours; a random required subset.
Instance randomInstance(unsigned seed, int primaries, double requiredShare, int maxRequired) {
    std::mt19937 rng(seed);
    auto uniform = [&](double lo, double hi) {
        return lo + (hi - lo) * std::generate_canonical<double, 32>(rng);
    };
    auto stretch = [&] { return uniform(1.0, 1.4); };
    GraphBuilder b;
    const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(primaries * 1.5))));
    std::vector<int> grid;
    for (int i = 0; i < primaries; ++i) {
        const int row = i / columns, column = i % columns;
        const double x0 = column * 5.0 + uniform(0, 1), y0 = row * 7.0 + uniform(0, 1);
        const int stripes = 1 + static_cast<int>(rng() % 4);
        grid.push_back(
            b.primary(x0, x0 + uniform(1.5, 3.5), y0, y0 + uniform(2, 5), stripes, stretch));
        if (column > 0 && uniform(0, 1) < 0.3) {
            const int t = b.transition(x0 - 0.5, y0, y0 + 2);
            b.join(grid[i - 1], 1, t, 0, stretch);
            b.join(t, 1, grid[i], 0, stretch);
        } else if (column > 0) {
            b.join(grid[i - 1], 1, grid[i], 0, stretch);
        }
        if (row > 0 && (column == 0 || uniform(0, 1) < 0.5))
            b.join(grid[i - columns], 1, grid[i], 0, stretch); // from the cell below
    }
    Instance inst{std::move(b.graph), {}};
    inst.query.required.assign(inst.graph.cells.size(), 0);
    int required = 0;
    for (std::size_t c = 0; c < inst.graph.cells.size() && required < maxRequired; ++c)
        if (uniform(0, 1) < requiredShare) {
            inst.query.required[c] = 1;
            ++required;
        }
    const int nodes = static_cast<int>(inst.graph.nodes.size());
    inst.query.startNode = static_cast<int>(rng() % nodes);
    inst.query.endNode = static_cast<int>(rng() % nodes);
    inst.query.seed = seed;
    return inst;
}

// Independent reference: every order of the required cells and every way through each
// coverage edge, with transits from a plain Dijkstra under the covered state at that time
// (never crossing the coverage edge of an uncovered required cell).
double bruteForceCost(const CornerGraph& g, const Query& q) {
    auto transit = [&](int from, const std::vector<char>& covered) {
        std::vector<double> dist(g.nodes.size(), kInf);
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
        dist[from] = 0;
        heap.push({0, from});
        while (!heap.empty()) {
            auto [d, n] = heap.top();
            heap.pop();
            if (d > dist[n])
                continue;
            for (int e : g.incident[n]) {
                const GraphEdge& edge = g.edges[e];
                const bool cov = edge.cell < 0 || covered[edge.cell];
                if (edge.kind == EdgeKind::Coverage && !cov)
                    continue;
                const int m = edge.other(n);
                if (d + edgeCost(edge, cov) < dist[m]) {
                    dist[m] = d + edgeCost(edge, cov);
                    heap.push({dist[m], m});
                }
            }
        }
        return dist;
    };
    std::vector<char> covered(g.cells.size());
    for (std::size_t c = 0; c < g.cells.size(); ++c)
        covered[c] = !q.required[c];
    double best = kInf;
    std::function<void(int, double)> visit = [&](int node, double cost) {
        if (cost >= best)
            return;
        const std::vector<double> dist = transit(node, covered);
        bool all = true;
        for (const GraphCell& cell : g.cells) {
            if (covered[cell.id])
                continue;
            all = false;
            covered[cell.id] = 1;
            for (int e : cell.coverageEdges)
                for (int dir = 0; dir < 2; ++dir) {
                    const int entry = dir ? g.edges[e].v : g.edges[e].u;
                    visit(g.edges[e].other(entry), cost + dist[entry]);
                }
            covered[cell.id] = 0;
        }
        if (all)
            best = std::min(best, cost + dist[q.endNode]);
    };
    visit(q.startNode, 0.0);
    return best;
}

// The exact solver as it was before it moved to (covered set x corner) states: A* over
// (covered set x every node), one edge at a time, with a max-over-cells bound and the greedy
// walk as incumbent. Kept as an independent reference for the optimum (cost only).
double nodeLevelOptimum(const CornerGraph& graph, const Query& query) {
    using namespace fc::solver_detail;
    const Problem problem = makeProblem(graph, query, "reference");
    const int tasks = problem.taskCount();
    const double upper = solveGreedy(graph, query).graphCost * (1.0 + 1e-12) + 1e-9;
    const TransitGraph transit(problem);
    TransitSearch search(transit);
    EdgePrices prices;
    prices.uncovered.resize(graph.edges.size());
    for (const GraphEdge& edge : graph.edges) {
        const bool task = edge.cell >= 0 && problem.taskOfCell[edge.cell] >= 0;
        prices.uncovered[edge.id] = task ? edgeCost(edge, false) : edgeCost(edge, true);
    }
    prices.covered = prices.uncovered;
    const std::vector<char> anyCoverage = transit.initialCoverage();
    auto distances = [&](const std::vector<NodeCost>& sources) {
        search.run(prices, anyCoverage, sources, {});
        std::vector<double> result(transit.nodeCount());
        for (int n = 0; n < transit.nodeCount(); ++n)
            result[n] = search.cost(n);
        return result;
    };
    const std::vector<double> toEnd = distances({{problem.endNode, 0.0}});
    std::vector<std::vector<double>> toTask;
    std::vector<double> taskToEnd;
    for (int task = 0; task < tasks; ++task) {
        std::vector<NodeCost> corners;
        double least = kInf;
        for (const CoverOption& option : problem.options[task]) {
            corners.push_back({option.entry, 0.0});
            least = std::min(least, toEnd[option.entry]);
        }
        toTask.push_back(distances(corners));
        taskToEnd.push_back(least);
    }
    auto estimate = [&](std::uint64_t uncovered, int node) {
        double bound = toEnd[node];
        for (int task = 0; task < tasks; ++task)
            if ((uncovered >> task) & 1)
                bound = std::max(bound, toTask[task][node] + taskToEnd[task]);
        return bound;
    };
    std::vector<int> taskOfEdge(graph.edges.size(), -1);
    for (const GraphEdge& edge : graph.edges)
        if (edge.cell >= 0)
            taskOfEdge[edge.id] = problem.taskOfCell[edge.cell];
    const std::uint64_t all = (std::uint64_t{1} << tasks) - 1;
    const std::uint64_t nodes = graph.nodes.size();
    FlatHashMap<double> best(1024);
    using Item = std::tuple<double, double, std::uint64_t>; // key, cost, state
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    auto reach = [&](std::uint64_t covered, int node, double cost) {
        const double key = cost + estimate(all & ~covered, node);
        if (!(key <= upper))
            return;
        const std::uint64_t state = covered * nodes + static_cast<std::uint64_t>(node);
        const auto [slot, added] = best.emplace(state, cost);
        if (!added && cost >= *slot)
            return;
        *slot = cost;
        heap.push({key, cost, state});
    };
    reach(0, problem.startNode, 0.0);
    while (!heap.empty()) {
        const auto [key, cost, state] = heap.top();
        heap.pop();
        if (cost > *best.find(state))
            continue;
        const std::uint64_t covered = state / nodes;
        const int node = static_cast<int>(state % nodes);
        if (covered == all && node == problem.endNode)
            return cost;
        for (int i = transit.adjacencyOffset[node]; i < transit.adjacencyOffset[node + 1]; ++i) {
            const int e = transit.adjacencyEdge[i];
            const int task = taskOfEdge[e];
            const bool uncovered = task >= 0 && !((covered >> task) & 1);
            if (uncovered && graph.edges[e].kind == EdgeKind::Coverage)
                reach(covered | (std::uint64_t{1} << task), transit.adjacencyNode[i], cost);
            else
                reach(covered, transit.adjacencyNode[i],
                      cost + (uncovered ? transit.truePrices.uncovered[e]
                                        : transit.truePrices.covered[e]));
        }
    }
    return solveGreedy(graph, query).graphCost; // only through rounding: greedy is optimal
}

void expectValid(const CornerGraph& g, const Query& q, const Solution& s) {
    const WalkEvaluation ev = evaluateWalk(g, q, s.walk);
    EXPECT_TRUE(ev.connected) << s.solver;
    EXPECT_TRUE(ev.coversAllRequired) << s.solver;
    EXPECT_DOUBLE_EQ(ev.graphCost, s.graphCost) << s.solver;
    EXPECT_EQ(ev.cellOrder, s.cellOrder) << s.solver;
    std::vector<int> cells = s.cellOrder, required;
    std::sort(cells.begin(), cells.end());
    for (std::size_t c = 0; c < q.required.size(); ++c)
        if (q.required[c])
            required.push_back(static_cast<int>(c));
    EXPECT_EQ(cells, required) << s.solver << ": only required cells are covered, once each";
}

// Two primary cells side by side: A (even stripes) then B (odd stripes).
Instance twoCells() {
    GraphBuilder b;
    const int a = b.primary(0, 2, 0, 4, 2); // nodes 0-3, edges 0-5
    const int c = b.primary(3, 5, 0, 4, 3); // nodes 4-7, edges 6-11
    b.joinAcross(a, c);                     // edges 12-15
    Instance inst{std::move(b.graph), {}};
    inst.query.required = {1, 1};
    return inst;
}

} // namespace

TEST(WalkEvaluation, HandComputedCosts) {
    Instance t = twoCells();
    // Edges as built: A 0-1 coverage (length 2*4+2 = 10), 2 floor, 3 ceiling (2 each),
    // 4-5 parallel (4 each); B 6 coverage LB-RT, 7 LT-RB (3*4+2 = 14), 8 floor, 9 ceiling,
    // 10-11 parallel; 12-15 inter (A.RB-B.LB = 1).
    t.query.startNode = 0;
    t.query.endNode = 2;
    const Walk w{{0, 2, 4, 6, 7, 4, 6, 4, 2, 0, 2}, {2, 12, 8, 11, 6, 8, 8, 12, 0, 0}};
    const WalkEvaluation ev = evaluateWalk(t.graph, t.query, w);
    EXPECT_TRUE(ev.connected);
    EXPECT_TRUE(ev.coversAllRequired);
    // A floor uncovered 1x + inter + B floor uncovered 1x + B parallel 3x + cover B (0)
    // + B floor covered 3x twice + inter + cover A (0) + A's coverage edge again 3x
    EXPECT_DOUBLE_EQ(ev.graphCost, 2 + 1 + 2 + 12 + 0 + 6 + 6 + 1 + 0 + 30);
    EXPECT_EQ(ev.cellOrder, (std::vector<int>{1, 0}));

    t.query.required = {0, 1}; // A not required: counts as covered from the start
    const WalkEvaluation partial = evaluateWalk(t.graph, t.query, w);
    EXPECT_DOUBLE_EQ(partial.graphCost, 6 + 1 + 2 + 12 + 0 + 6 + 6 + 1 + 30 + 30);
    EXPECT_EQ(partial.cellOrder, (std::vector<int>{1}));
    EXPECT_TRUE(partial.coversAllRequired);
}

TEST(WalkEvaluation, RejectsBrokenWalks) {
    Instance t = twoCells();
    t.query.startNode = 0;
    t.query.endNode = 2;
    Walk cover{{0, 2}, {0}}; // A's coverage edge LB-RB
    EXPECT_TRUE(evaluateWalk(t.graph, t.query, cover).connected);
    EXPECT_FALSE(evaluateWalk(t.graph, t.query, cover).coversAllRequired);
    Walk gap{{0, 2}, {6}}; // edge 6 does not join nodes 0 and 2
    EXPECT_FALSE(evaluateWalk(t.graph, t.query, gap).connected);
    Walk badId{{0, 2}, {99}};
    EXPECT_FALSE(evaluateWalk(t.graph, t.query, badId).connected);
    Walk wrongEnd{{2, 0}, {0}};
    EXPECT_FALSE(evaluateWalk(t.graph, t.query, wrongEnd).connected);

    Query nothing{{0, 0}, 3, 3, 1, {}};
    const WalkEvaluation empty = evaluateWalk(t.graph, nothing, Walk{{3}, {}});
    EXPECT_TRUE(empty.connected && empty.coversAllRequired);
    EXPECT_EQ(empty.graphCost, 0.0);
    nothing.required = {1, 0};
    EXPECT_FALSE(evaluateWalk(t.graph, nothing, Walk{{3}, {}}).coversAllRequired);
}

TEST(ExactSolver, MatchesBruteForceOnRandomSmallGraphs) {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        const Instance inst = randomInstance(seed, 3 + seed % 3, 0.8, 5);
        const Solution exact = solveExact(inst.graph, inst.query);
        expectValid(inst.graph, inst.query, exact);
        EXPECT_NEAR(exact.graphCost, bruteForceCost(inst.graph, inst.query), 1e-9)
            << "seed " << seed;
    }
}

TEST(HeuristicSolver, WithinOnePercentOfExact) {
    double worst = 0.0;
    for (unsigned seed = 100; seed < 160; ++seed) {
        const Instance inst = randomInstance(seed, 4 + seed % 7, 0.85, 10);
        const Solution exact = solveExact(inst.graph, inst.query);
        const Solution heuristic = solveHeuristic(inst.graph, inst.query);
        expectValid(inst.graph, inst.query, heuristic);
        EXPECT_GE(heuristic.graphCost, exact.graphCost - 1e-9) << "seed " << seed;
        EXPECT_LE(heuristic.graphCost, exact.graphCost * 1.01 + 1e-9) << "seed " << seed;
        worst = std::max(worst, heuristic.graphCost / std::max(exact.graphCost, 1e-12) - 1);
    }
    RecordProperty("worst_gap_percent", std::to_string(worst * 100));
}

TEST(GreedySolver, ValidAndNeverBelowExact) {
    for (unsigned seed = 200; seed < 230; ++seed) {
        const Instance inst = randomInstance(seed, 3 + seed % 6, 0.7, 8);
        const Solution greedy = solveGreedy(inst.graph, inst.query);
        expectValid(inst.graph, inst.query, greedy);
        EXPECT_GE(greedy.graphCost, solveExact(inst.graph, inst.query).graphCost - 1e-9);
    }
}

TEST(ExactSolver, RefusesAboveItsLimits) {
    const Instance inst = randomInstance(7, 45, 1.0, 45);
    try {
        solveExact(inst.graph, inst.query);
        FAIL() << "expected a refusal";
    } catch (const SolverError& e) {
        EXPECT_NE(std::string(e.what()).find("45 required cells"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("--solver heuristic"), std::string::npos);
    }
    const Instance small = randomInstance(8, 10, 1.0, 10);
    ExactOptions tight;
    tight.maxStates = 2;
    try {
        solveExact(small.graph, small.query, tight);
        FAIL() << "expected a refusal";
    } catch (const SolverError& e) {
        EXPECT_NE(std::string(e.what()).find("no proof of optimality"), std::string::npos)
            << e.what();
    }
    // With bestOnBudget it answers the best walk known and a proven bound instead.
    tight.bestOnBudget = true;
    const Solution answered = solveExact(small.graph, small.query, tight);
    expectValid(small.graph, small.query, answered);
    const double optimum = solveExact(small.graph, small.query).graphCost;
    EXPECT_GT(answered.lowerBound, 0.0);
    EXPECT_LE(answered.lowerBound, optimum + 1e-9);
    EXPECT_GE(answered.graphCost, optimum - 1e-9);
    EXPECT_EQ(answered.provenOptimal, answered.lowerBound >= answered.graphCost);
}

// A query it cannot prove in time is refused with the gap reached, naming the limit, never
// left running: four office rooms (20 required cells) take minutes to prove.
TEST(ExactSolver, RefusesWhenItsTimeLimitPasses) {
    const Project project = loadProjectFile(std::string(FC_PLANS_DIR) + "/office.geojson");
    const PreparedPlan prepared = preparePlan(project.plan, project.robot, 90.0);
    std::vector<std::string> warnings;
    const Query query =
        makeQuery(prepared, {"S01", "S02", "S03", "N01"}, std::nullopt, std::nullopt, 1, warnings);
    ExactOptions options;
    options.timeLimitSeconds = 0.5;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        solveExact(prepared.graph, query, options);
        FAIL() << "expected a refusal";
    } catch (const SolverError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no proof of optimality"), std::string::npos) << what;
        EXPECT_NE(what.find("or 0.5 s"), std::string::npos) << what;
        EXPECT_NE(what.find("% of optimal"), std::string::npos) << what;
        EXPECT_NE(what.find("--solver heuristic"), std::string::npos) << what;
    }
    // The heuristic incumbent and the search together, well within a few seconds.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
}

TEST(ExactSolver, SameOptimumAsTheNodeLevelSearchUpToTwelveCells) {
    for (unsigned seed = 500; seed < 530; ++seed) {
        const int cells = 4 + static_cast<int>(seed % 9); // 4..12
        const Instance inst = randomInstance(seed, cells, 0.9, 12);
        const Solution exact = solveExact(inst.graph, inst.query);
        expectValid(inst.graph, inst.query, exact);
        const double reference = nodeLevelOptimum(inst.graph, inst.query);
        EXPECT_NEAR(exact.graphCost, reference, 1e-9 * (1.0 + reference)) << "seed " << seed;
        EXPECT_TRUE(exact.provenOptimal);
        EXPECT_EQ(exact.lowerBound, exact.graphCost);
    }
}

TEST(LowerBounds, NeverAboveTheOptimum) {
    using namespace fc::solver_detail;
    for (unsigned seed = 600; seed < 640; ++seed) {
        const Instance inst = randomInstance(seed, 3 + seed % 6, 0.8, 6);
        const double optimum = bruteForceCost(inst.graph, inst.query);
        const Solution heuristic = solveHeuristic(inst.graph, inst.query);
        EXPECT_LE(heuristic.lowerBound, optimum + 1e-9) << "seed " << seed;
        EXPECT_GE(heuristic.lowerBound, 0.0) << "seed " << seed;
        EXPECT_EQ(heuristic.provenOptimal, heuristic.lowerBound >= heuristic.graphCost);
        const Problem problem = makeProblem(inst.graph, inst.query, "test");
        const TransitGraph transit(problem);
        TransitSearch search(transit);
        const double tree = spanningTreeBound(transit, search);
        EXPECT_LE(tree, optimum + 1e-9) << "seed " << seed;
        // The penalised tree is at least the plain one.
        EXPECT_GE(TourBound(transit, search, heuristic.graphCost).root(), tree - 1e-6)
            << "seed " << seed;
    }
}

TEST(LowerBounds, LargeFloorGetsABoundQuickly) {
    const Instance inst = randomInstance(34, 600, 0.95, 100000);
    const Solution heuristic = solveHeuristic(inst.graph, inst.query);
    EXPECT_GT(heuristic.lowerBound, 0.0);
    EXPECT_LE(heuristic.lowerBound, heuristic.graphCost);
    using namespace fc::solver_detail;
    const Problem problem = makeProblem(inst.graph, inst.query, "test");
    const TransitGraph transit(problem);
    TransitSearch search(transit);
    EXPECT_LE(spanningTreeBound(transit, search), heuristic.lowerBound + 1e-6);
}

TEST(ExactSolver, ProvesTwentySixCellsOfTheWard) {
    // 26 required cells (rooms S01, N01, S02 and part of N02): optimality proven in a few
    // seconds (floorcover-exact-bench times it, and larger office queries).
    const Project project = loadProjectFile(std::string(FC_PLANS_DIR) + "/ward.geojson");
    RobotProfile robot;
    robot.robotDiameter = 0.6;
    robot.coverageWidth = 1.0;
    robot.cleaningDiameter = 1.0;
    const PreparedPlan prepared = preparePlan(project.plan, robot, 90.0);
    std::vector<std::string> warnings;
    Query query =
        makeQuery(prepared, {"S01", "N01", "S02", "N02"}, std::nullopt, std::nullopt, 1, warnings);
    int kept = 0;
    for (char& required : query.required)
        if (required && ++kept > 26)
            required = 0;
    ASSERT_EQ(std::count(query.required.begin(), query.required.end(), 1), 26);
    const Solution exact = solveExact(prepared.graph, query);
    expectValid(prepared.graph, query, exact);
    EXPECT_TRUE(exact.provenOptimal);
    const Solution heuristic = solveHeuristic(prepared.graph, query);
    EXPECT_LE(exact.graphCost, heuristic.graphCost + 1e-9);
    // It starts from the heuristic's walk but answers only its optimal walk: no alternatives
    // for the pipeline's path-time choice to swap in.
    EXPECT_FALSE(heuristic.alternatives.empty());
    EXPECT_TRUE(exact.alternatives.empty());
}

TEST(ExactSolver, RunsFastOnTwelveCells) {
    const Instance inst = randomInstance(11, 12, 1.0, 12);
    ASSERT_EQ(std::count(inst.query.required.begin(), inst.query.required.end(), 1), 12);
    const auto start = std::chrono::steady_clock::now();
    const Solution exact = solveExact(inst.graph, inst.query);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expectValid(inst.graph, inst.query, exact);
    EXPECT_LT(seconds, 2.0); // typically well under a second, with slack for slow machines
}

TEST(ExactSolver, HonoursCancellation) {
    const Instance inst = randomInstance(9, 8, 1.0, 8);
    SolveControl control;
    control.cancelled = [] { return true; };
    EXPECT_THROW(solveExact(inst.graph, inst.query, {}, control), SolverError);
    EXPECT_THROW(solveHeuristic(inst.graph, inst.query, control), SolverError);
}

TEST(HeuristicSolver, DeterministicPerSeed) {
    Instance inst = randomInstance(21, 120, 0.9, 1000);
    const Solution first = solveHeuristic(inst.graph, inst.query);
    const Solution again = solveHeuristic(inst.graph, inst.query);
    EXPECT_EQ(first.walk.edges, again.walk.edges);
    EXPECT_EQ(first.graphCost, again.graphCost);
    expectValid(inst.graph, inst.query, first);
    EXPECT_LE(first.graphCost, solveGreedy(inst.graph, inst.query).graphCost + 1e-9);
}

TEST(Solvers, CoverOnlyRequiredCells) {
    for (unsigned seed = 300; seed < 310; ++seed) {
        Instance inst = randomInstance(seed, 8, 0.4, 8);
        inst.graph.cells[0].reachable = false; // reported elsewhere, never required
        inst.query.required[0] = 1;
        Query expected = inst.query;
        expected.required[0] = 0;
        for (const Solution& s :
             {solveExact(inst.graph, inst.query), solveHeuristic(inst.graph, inst.query),
              solveGreedy(inst.graph, inst.query)})
            expectValid(inst.graph, expected, s);
    }
}

TEST(Solvers, NothingRequiredIsTheCheapestTransit) {
    Instance inst = randomInstance(5, 6, 0.0, 0);
    inst.query.required.assign(inst.graph.cells.size(), 0);
    const double none = bruteForceCost(inst.graph, inst.query); // a plain cheapest transit
    for (const Solution& s :
         {solveExact(inst.graph, inst.query), solveHeuristic(inst.graph, inst.query),
          solveGreedy(inst.graph, inst.query)}) {
        EXPECT_NEAR(s.graphCost, none, 1e-9) << s.solver;
        EXPECT_TRUE(s.cellOrder.empty());
    }
}

TEST(Solvers, ExplainUnreachableCellsAndEnds) {
    Instance t = twoCells();
    GraphBuilder island;
    island.graph = t.graph;
    island.primary(20, 22, 0, 4, 2); // cell 2: no edges to the others
    const Query cutOff{{1, 1, 1}, 0, 2, 1, {}};
    using Solve = std::function<Solution(const CornerGraph&, const Query&)>;
    const Solve solvers[] = {
        [](const CornerGraph& g, const Query& query) { return solveExact(g, query); },
        [](const CornerGraph& g, const Query& query) { return solveHeuristic(g, query); },
        [](const CornerGraph& g, const Query& query) { return solveGreedy(g, query); }};
    for (const Solve& solve : solvers) {
        try {
            solve(island.graph, cutOff);
            FAIL() << "expected an unreachable-cell error";
        } catch (const SolverError& e) {
            EXPECT_NE(std::string(e.what()).find("1 required cell"), std::string::npos) << e.what();
        }
        EXPECT_THROW(solve(island.graph, Query{{1, 1, 0}, 0, 8, 1, {}}), SolverError);  // end
        EXPECT_THROW(solve(island.graph, Query{{1, 1, 0}, 0, 99, 1, {}}), SolverError); // bad id
    }
}

// Speed is measured by floorcover-bench and floorcover-exact-bench; here only a guard
// against a hang, generous enough for a loaded two-core machine.
TEST(HeuristicSolver, LargeGridGraphIsValidAndFinishes) {
    const Instance inst = randomInstance(33, 1000, 0.95, 100000);
    const auto start = std::chrono::steady_clock::now();
    const Solution heuristic = solveHeuristic(inst.graph, inst.query);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expectValid(inst.graph, inst.query, heuristic);
    EXPECT_LE(heuristic.graphCost, solveGreedy(inst.graph, inst.query).graphCost);
    EXPECT_GE(heuristic.lowerBound, 0.0);
    EXPECT_LE(heuristic.lowerBound, heuristic.graphCost + 1e-9);
    EXPECT_LT(seconds, 120.0);
}

TEST(HeuristicSolver, IncrementalOrderCostsMatchFullEvaluation) {
    using namespace fc::solver_detail;
    const Instance inst = randomInstance(41, 30, 0.9, 1000);
    const Problem problem = makeProblem(inst.graph, inst.query, "test");
    const TransitGraph transit(problem);
    TransitSearch search(transit), referenceSearch(transit);
    OrderEvaluator incremental(transit, search), reference(transit, referenceSearch);
    std::vector<int> order(problem.taskCount());
    for (int i = 0; i < problem.taskCount(); ++i)
        order[i] = i;
    std::mt19937 rng(5);
    std::shuffle(order.begin(), order.end(), rng);
    incremental.setBase(order);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<int> candidate = incremental.baseOrder();
        const int size = static_cast<int>(candidate.size());
        const int first = static_cast<int>(rng() % size);
        const int last = std::min(size - 1, first + 1 + static_cast<int>(rng() % 6));
        if (trial % 2 == 0)
            std::reverse(candidate.begin() + first, candidate.begin() + last + 1);
        else
            std::rotate(candidate.begin() + first, candidate.begin() + first + 1,
                        candidate.begin() + last + 1);
        const double full = reference.setBase(candidate);
        ASSERT_NEAR(incremental.candidateCost(candidate, first, last), full, 1e-7 * full);
        if (trial % 3 == 0) { // accepting shifts the later steps; costs must stay exact
            incremental.acceptCandidate();
            ASSERT_NEAR(incremental.baseCost(), full, 1e-7 * full);
        }
    }
}

TEST(OrderRefinement, EachLevelKeepsTheOrderValidAndNeverCostsMore) {
    int improvedByCorners = 0;
    for (unsigned seed = 300; seed < 330; ++seed) {
        const Instance inst = randomInstance(seed, 4 + seed % 6, 0.8, 9);
        // The greedy walk stands in for a learnt policy's walk.
        const Solution given = solveGreedy(inst.graph, inst.query);
        const Solution none = refineCellOrder(inst.graph, inst.query, given, OrderRefinement::None);
        EXPECT_EQ(none.walk.nodes, given.walk.nodes);
        const Solution corners =
            refineCellOrder(inst.graph, inst.query, given, OrderRefinement::Corners);
        const Solution local =
            refineCellOrder(inst.graph, inst.query, given, OrderRefinement::LocalSearch);
        expectValid(inst.graph, inst.query, corners);
        expectValid(inst.graph, inst.query, local);
        EXPECT_EQ(corners.solver, "greedy");
        EXPECT_LE(corners.graphCost, given.graphCost + 1e-9) << "seed " << seed;
        EXPECT_LE(local.graphCost, corners.graphCost + 1e-9) << "seed " << seed;
        EXPECT_GE(local.graphCost, solveExact(inst.graph, inst.query).graphCost - 1e-9);
        if (corners.graphCost < given.graphCost - 1e-9) {
            ++improvedByCorners;
            // Corners keeps the order of the cells.
            EXPECT_EQ(corners.cellOrder, given.cellOrder) << "seed " << seed;
        }
    }
    RecordProperty("improved_by_corner_choice", improvedByCorners);
}

// The local search level must repair a poor order on a real floor, not only polish a good
// one: a learnt policy early in training walks the cells in a far-from-good order. Here a
// shuffled order of every cell of the office plan (budgets count work, not time).
TEST(OrderRefinement, LocalSearchRepairsAPoorOrderOnALargeFloor) {
    const Project project = loadProjectFile(std::string(FC_PLANS_DIR) + "/office.geojson");
    const PreparedPlan prepared = preparePlan(project.plan, project.robot, 90.0);
    Query query;
    query.required.assign(prepared.graph.cells.size(), 0);
    for (const GraphCell& c : prepared.graph.cells)
        query.required[static_cast<std::size_t>(c.id)] = c.reachable ? 1 : 0;
    query.startNode = prepared.graph.cells.front().nodes.front();
    query.endNode = query.startNode;
    Solution poor = solveGreedy(prepared.graph, query);
    std::mt19937 shuffle(7);
    std::shuffle(poor.cellOrder.begin(), poor.cellOrder.end(), shuffle);
    poor.graphCost = std::numeric_limits<double>::infinity(); // not its walk any more
    const Solution refined =
        refineCellOrder(prepared.graph, query, poor, OrderRefinement::LocalSearch);
    expectValid(prepared.graph, query, refined);
    const double heuristic = solveHeuristic(prepared.graph, query).graphCost;
    RecordProperty("refined_over_heuristic_permille",
                   static_cast<int>(1000.0 * refined.graphCost / heuristic));
    EXPECT_LE(refined.graphCost, 1.05 * heuristic);
}

// One or two required cells: the proxy stage and the polish have nothing or little to move.
TEST(OrderRefinement, LocalSearchHandlesOneAndTwoCells) {
    for (int required = 1; required <= 2; ++required)
        for (unsigned seed = 500; seed < 510; ++seed) {
            const Instance inst = randomInstance(seed, 6, 1.0, required);
            const Solution given = solveGreedy(inst.graph, inst.query);
            const Solution local =
                refineCellOrder(inst.graph, inst.query, given, OrderRefinement::LocalSearch);
            expectValid(inst.graph, inst.query, local);
            EXPECT_LE(local.graphCost, given.graphCost + 1e-9) << "seed " << seed;
            EXPECT_NEAR(local.graphCost, solveExact(inst.graph, inst.query).graphCost,
                        1e-6 * local.graphCost + 1e-9)
                << "seed " << seed;
        }
}
