#include "graph/ComponentBridges.h"

#include <algorithm>
#include <queue>

namespace fc {
namespace {

// Node pairs tried per component (nearest first), and the work bound on the pair search.
constexpr size_t kPairsTried = 6;
constexpr size_t kMaxBridgeChecks = 200'000; // segment tests per bridge search
constexpr size_t kMaxPairScan = 4'000'000;
} // namespace

std::vector<int> graphComponents(const CornerGraph& g, int& count) {
    std::vector<int> comp(g.nodes.size(), -1);
    count = 0;
    for (size_t s = 0; s < g.nodes.size(); ++s) {
        if (comp[s] >= 0)
            continue;
        std::queue<int> q;
        q.push(static_cast<int>(s));
        comp[s] = count;
        while (!q.empty()) {
            const int u = q.front();
            q.pop();
            for (int e : g.incident[u]) {
                const int v = g.edges[e].other(u);
                if (comp[v] < 0) {
                    comp[v] = count;
                    q.push(v);
                }
            }
        }
        ++count;
    }
    return comp;
}

int bridgeComponents(CornerGraph& graph, const ClearanceField& field) {
    int count = 0;
    std::vector<int> comp = graphComponents(graph, count);
    if (count < 2)
        return 0;
    // Corners of reachable cells, by component; the largest component is the trunk.
    std::vector<std::vector<int>> members(count);
    for (const GraphNode& node : graph.nodes)
        if (graph.cells[node.cell].reachable)
            members[comp[node.id]].push_back(node.id);
    std::vector<int> order;
    for (int c = 0; c < count; ++c)
        if (!members[c].empty())
            order.push_back(c);
    if (order.size() < 2)
        return 0;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return members[a].size() > members[b].size(); });
    std::vector<int> trunk = members[order.front()];
    std::vector<char> trunkRegion;
    auto addToTrunkRegions = [&](const std::vector<int>& nodes) {
        for (int v : nodes) {
            const int region = field.openRegionOf(graph.nodes[v].position);
            if (region < 0)
                continue;
            if (static_cast<size_t>(region) >= trunkRegion.size())
                trunkRegion.resize(region + 1, 0);
            trunkRegion[region] = 1;
        }
    };
    auto inTrunkRegion = [&](int v) {
        const int region = field.openRegionOf(graph.nodes[v].position);
        return region < 0 ||
               (static_cast<size_t>(region) < trunkRegion.size() && trunkRegion[region]);
    };
    addToTrunkRegions(trunk);
    int added = 0;
    for (size_t k = 1; k < order.size(); ++k) {
        const std::vector<int>& part = members[order[k]];
        if (std::none_of(part.begin(), part.end(), inTrunkRegion))
            continue; // no clear path can reach it
        const size_t stride = std::max<size_t>(1, part.size() * trunk.size() / kMaxPairScan + 1);
        std::vector<std::pair<double, std::pair<int, int>>> pairs;
        for (size_t i = 0; i < part.size(); i += stride)
            for (int t : trunk)
                if (field.openRegionOf(graph.nodes[part[i]].position) ==
                    field.openRegionOf(graph.nodes[t].position))
                    pairs.push_back(
                        {distance(graph.nodes[part[i]].position, graph.nodes[t].position),
                         {t, part[i]}});
        const size_t keep = std::min(pairs.size(), kPairsTried);
        std::partial_sort(pairs.begin(), pairs.begin() + keep, pairs.end());
        for (size_t i = 0; i < keep; ++i) {
            const auto [u, v] = pairs[i].second;
            // Both ends lie in one open region, and a search that fails there covers the
            // whole plan (seconds on a large map, for each pair): bounded, as a part whose
            // bridge is not found is left out and reported.
            Polyline line = field.findPath(graph.nodes[u].position, graph.nodes[v].position, {},
                                           INFINITY, kMaxBridgeChecks);
            if (line.empty())
                continue;
            GraphEdge edge;
            edge.u = u;
            edge.v = v;
            edge.kind = EdgeKind::Inter;
            edge.length = polylineLength(line);
            edge.geometry = std::move(line);
            graph.addEdge(std::move(edge));
            ++added;
            trunk.insert(trunk.end(), part.begin(), part.end());
            addToTrunkRegions(part);
            break;
        }
    }
    return added;
}

} // namespace fc
