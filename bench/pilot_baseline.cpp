// floorcover-pilot-baseline PLAN [K]: a policy that needs no learning, measured as
// floorcover-dqn-report measures the learnt policy alone (docs/dqn.md): at each step the
// corner whose transit plus a nearest-neighbour completion (static graph costs, to the end
// corner) is cheapest, among the K cheapest transits (all by default). The same 100 queries
// (seed 1) and references (exact up to 12 cells, else heuristic). It asks whether a feature
// "cost to go by a greedy completion" could lift the policy: it does no better than it.
#include "formats/PlanIO.h"
#include "learning/CoverageEnvironment.h"
#include "learning/GraphState.h"
#include "learning/dqn/DqnPolicy.h"
#include "pipeline/Planner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <string>

using namespace fc;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<std::vector<double>> allPairs(const CornerGraph& g) {
    const size_t n = g.nodes.size();
    std::vector<std::vector<double>> d(n, std::vector<double>(n, kInf));
    for (size_t s = 0; s < n; ++s) {
        auto& dist = d[s];
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
        dist[s] = 0;
        heap.push({0, (int)s});
        while (!heap.empty()) {
            auto [c, u] = heap.top();
            heap.pop();
            if (c > dist[u])
                continue;
            for (int id : g.incident[u]) {
                const GraphEdge& e = g.edges[id];
                const double price = edgeCost(e, true);
                const int v = e.other(u);
                if (c + price < dist[v])
                    dist[v] = c + price, heap.push({c + price, v});
            }
        }
    }
    return d;
}
} // namespace

int main(int argc, char** argv) {
    const std::string name = argc > 1 ? argv[1] : "office";
    const int K = argc > 2 ? std::stoi(argv[2]) : 1000000;
    const Project project = loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson");
    const PreparedPlan prepared = preparePlan(project.plan, project.robot, 90.0);
    const CornerGraph& graph = prepared.graph;
    const auto D = allPairs(graph);
    const GraphStateTables tables(graph);
    const QuerySet kind =
        name == "office" || name == "ward" ? QuerySet::RoomSubsets : QuerySet::AllCells;
    double sumPilot = 0, sumGreedy = 0, ms = 0;
    int n = 0;
    for (const Query& q : randomQueries(graph, 100, 1 * 1000003ULL + 17ULL, kind)) {
        const int cells = (int)std::count(q.required.begin(), q.required.end(), 1);
        const double ref = std::max(cells <= 12 ? solveExact(graph, q).graphCost
                                                : solveHeuristic(graph, q).graphCost,
                                    1e-9);
        const auto t0 = std::chrono::steady_clock::now();
        EnvironmentOptions o;
        o.rewardIsNegativeGraphCost = true;
        CoverageEnvironment env(graph, o);
        env.reset(q);
        while (!env.done()) {
            const auto mask = env.actionMask();
            const auto& T = env.transitCosts();
            const auto& cov = env.covered();
            std::vector<int> cand;
            for (int a = 0; a < env.actionCount(); ++a)
                if (mask[a])
                    cand.push_back(a);
            std::sort(cand.begin(), cand.end(), [&](int a, int b) { return T[a] < T[b]; });
            if ((int)cand.size() > K)
                cand.resize(K);
            int best = -1;
            double bestScore = kInf;
            for (int a : cand) {
                const int ca = graph.nodes[a].cell;
                std::vector<char> c2(cov.begin(), cov.end());
                c2[ca] = 1;
                int pos = tables.exitNode[a];
                double total = T[a];
                while (true) {
                    int bk = -1;
                    double bd = kInf;
                    for (const GraphNode& nd : graph.nodes)
                        if (nd.cell >= 0 && !c2[nd.cell] && tables.exitNode[nd.id] >= 0 &&
                            D[pos][nd.id] < bd)
                            bd = D[pos][nd.id], bk = nd.id;
                    if (bk < 0)
                        break;
                    total += bd;
                    c2[graph.nodes[bk].cell] = 1;
                    pos = tables.exitNode[bk];
                }
                total += D[pos][env.endNode()];
                if (total < bestScore)
                    bestScore = total, best = a;
            }
            env.step(best);
        }
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                  .count();
        const Solution s = policyWalkSolution(graph, q, env.walk());
        sumPilot += s.graphCost / ref - 1;
        sumGreedy += solveGreedy(graph, q).graphCost / ref - 1;
        ++n;
    }
    std::printf("%s K=%d: pilot %.2f%%  greedy %.2f%%  %.1f ms/query  (%zu nodes, %zu cells)\n",
                name.c_str(), K, 100 * sumPilot / n, 100 * sumGreedy / n, ms / n,
                graph.nodes.size(), graph.cells.size());
}
