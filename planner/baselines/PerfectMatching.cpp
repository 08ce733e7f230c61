#include "baselines/PerfectMatching.h"

#include <algorithm>
#include <cstdint>
#include <lemon/full_graph.h>
#include <lemon/matching.h>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace fc::baselines {

std::vector<int> exactPerfectMatching(const std::vector<std::vector<double>>& cost) {
    const int n = static_cast<int>(cost.size());
    std::vector<int> mate(n, -1);
    if (n == 0)
        return mate;
    const std::uint32_t full = (1u << n) - 1;
    // best[m]: cheapest matching of the points not in m; partner[m]: whom the lowest free
    // point of m is paired with.
    std::vector<double> best(std::size_t(full) + 1, std::numeric_limits<double>::infinity());
    std::vector<signed char> partner(std::size_t(full) + 1, -1);
    best[full] = 0;
    for (std::uint32_t m = full; m-- > 0;) {
        int i = 0;
        while (m & (1u << i))
            ++i;
        for (int j = i + 1; j < n; ++j) {
            if (m & (1u << j))
                continue;
            const double c = cost[i][j] + best[m | (1u << i) | (1u << j)];
            if (c < best[m]) {
                best[m] = c;
                partner[m] = static_cast<signed char>(j);
            }
        }
    }
    for (std::uint32_t m = 0; m != full;) {
        int i = 0;
        while (m & (1u << i))
            ++i;
        const int j = partner[m];
        mate[i] = j, mate[j] = i;
        m |= (1u << i) | (1u << j);
    }
    return mate;
}

std::vector<int> greedyPerfectMatching(const std::vector<std::vector<double>>& cost) {
    const int n = static_cast<int>(cost.size());
    std::vector<std::tuple<double, int, int>> pairs;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            pairs.emplace_back(cost[i][j], i, j);
    std::sort(pairs.begin(), pairs.end());
    std::vector<int> mate(n, -1);
    for (const auto& [c, i, j] : pairs)
        if (mate[i] < 0 && mate[j] < 0)
            mate[i] = j, mate[j] = i;
    // Re-pair a-b, c-d as a-c, b-d or a-d, b-c while that is cheaper.
    for (bool improved = true; improved;) {
        improved = false;
        for (int a = 0; a < n; ++a) {
            for (int c = 0; c < n; ++c) {
                const int b = mate[a], d = mate[c];
                if (c == a || c == b)
                    continue;
                const double now = cost[a][b] + cost[c][d];
                if (cost[a][c] + cost[b][d] < now - 1e-12) {
                    mate[a] = c, mate[c] = a, mate[b] = d, mate[d] = b;
                    improved = true;
                } else if (cost[a][d] + cost[b][c] < now - 1e-12) {
                    mate[a] = d, mate[d] = a, mate[b] = c, mate[c] = b;
                    improved = true;
                }
            }
        }
    }
    return mate;
}

std::vector<int> blossomPerfectMatching(const std::vector<std::vector<double>>& cost) {
    const int n = static_cast<int>(cost.size());
    std::vector<int> mate(cost.size(), -1);
    if (n == 0)
        return mate;
    lemon::FullGraph graph(n);
    lemon::FullGraph::EdgeMap<double> weight(graph);
    for (lemon::FullGraph::EdgeIt e(graph); e != lemon::INVALID; ++e)
        weight[e] = -cost[graph.id(graph.u(e))][graph.id(graph.v(e))];
    lemon::MaxWeightedPerfectMatching<lemon::FullGraph, lemon::FullGraph::EdgeMap<double>> matching(
        graph, weight);
    if (!matching.run()) // a complete graph of even size always has one
        throw std::logic_error("no perfect matching on a complete graph of even size");
    for (lemon::FullGraph::NodeIt v(graph); v != lemon::INVALID; ++v)
        mate[graph.id(v)] = graph.id(matching.mate(v));
    return mate;
}

std::vector<int> minimumWeightPerfectMatching(const std::vector<std::vector<double>>& cost) {
    return static_cast<int>(cost.size()) <= kExactMatchingLimit ? exactPerfectMatching(cost)
                                                                : blossomPerfectMatching(cost);
}

double matchingCost(const std::vector<std::vector<double>>& cost, const std::vector<int>& mate) {
    double total = 0;
    for (size_t i = 0; i < mate.size(); ++i)
        if (static_cast<int>(i) < mate[i])
            total += cost[i][mate[i]];
    return total;
}

} // namespace fc::baselines
