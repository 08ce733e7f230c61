// The graphEnvironment of the paper's Table 1 (see CoverageEnvironment.h for the choices).
#include "learning/CoverageEnvironment.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace fc {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

int imageSize(int nodeCount) {
    int size = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(nodeCount))));
    while (size * size < nodeCount)
        ++size;
    while (size > 1 && (size - 1) * (size - 1) >= nodeCount)
        --size;
    return size;
}

bool isOverlap(const GraphEdge& e, bool cellCovered) {
    switch (e.kind) {
    case EdgeKind::Coverage:
        return cellCovered;
    case EdgeKind::Contour:
        return e.parallel || cellCovered;
    case EdgeKind::Inter:
        break;
    }
    return false;
}

} // namespace

CoverageEnvironment::CoverageEnvironment(const CornerGraph& graph, EnvironmentOptions options)
    : graph_(&graph), options_(options) {
    if (graph.nodes.empty())
        throw std::invalid_argument("CoverageEnvironment: the corner graph has no nodes");
    size_ = imageSize(static_cast<int>(graph.nodes.size()));
    const int cellCount = static_cast<int>(graph.cells.size());
    maxSteps_ = options_.maxSteps > 0 ? options_.maxSteps : 2 * cellCount + 10;
    covered_.assign(graph.cells.size(), 1);
    initialCovered_ = covered_;
    if (options_.graphState)
        graphTables_ = std::make_shared<const GraphStateTables>(graph);
}

std::vector<char> CoverageEnvironment::componentOf(int node) const {
    std::vector<char> seen(graph_->nodes.size(), 0);
    std::vector<int> stack{node};
    seen[node] = 1;
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        for (int e : graph_->incident[n]) {
            const int next = graph_->edges[e].other(n);
            if (!seen[next]) {
                seen[next] = 1;
                stack.push_back(next);
            }
        }
    }
    return seen;
}

std::vector<float> CoverageEnvironment::reset(std::mt19937_64& rng) {
    const CornerGraph& g = *graph_;
    std::vector<int> candidates;
    for (const GraphNode& n : g.nodes)
        if (n.cell >= 0 && g.cells[n.cell].reachable)
            candidates.push_back(n.id);
    if (candidates.empty())
        throw std::invalid_argument("CoverageEnvironment: no node of a reachable cell");
    auto pick = [&rng](const std::vector<int>& from) {
        std::uniform_int_distribution<std::size_t> index(0, from.size() - 1);
        return from[index(rng)];
    };
    start_ = pick(candidates);
    const std::vector<char> component = componentOf(start_);
    std::vector<int> ends;
    for (int n : candidates)
        if (component[n])
            ends.push_back(n);
    end_ = pick(ends);

    std::vector<int> required;
    for (const GraphCell& cell : g.cells)
        if (cell.reachable && !cell.nodes.empty() && component[cell.nodes.front()])
            required.push_back(cell.id);
    covered_.assign(g.cells.size(), 1);
    const double p = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    std::uniform_real_distribution<double> coin(0.0, 1.0);
    bool anyUncovered = false;
    for (int cell : required) {
        covered_[cell] = coin(rng) < p ? 1 : 0;
        anyUncovered = anyUncovered || !covered_[cell];
    }
    if (!anyUncovered)
        covered_[pick(required)] = 0;
    begin();
    return observation();
}

std::vector<float> CoverageEnvironment::reset(const Query& query) {
    const CornerGraph& g = *graph_;
    const int nodeCount = static_cast<int>(g.nodes.size());
    if (query.startNode < 0 || query.startNode >= nodeCount || query.endNode < 0 ||
        query.endNode >= nodeCount)
        throw std::invalid_argument("CoverageEnvironment: start or end node out of range");
    start_ = query.startNode;
    end_ = query.endNode;
    const std::vector<char> component = componentOf(start_);
    if (!component[end_])
        throw std::invalid_argument("CoverageEnvironment: the end node cannot be reached");
    covered_.assign(g.cells.size(), 1);
    for (const GraphCell& cell : g.cells) {
        const bool required = cell.id < static_cast<int>(query.required.size()) &&
                              query.required[cell.id] && cell.reachable;
        if (!required)
            continue;
        if (cell.nodes.empty() || !component[cell.nodes.front()])
            throw std::invalid_argument("CoverageEnvironment: a required cell cannot be reached");
        covered_[cell.id] = 0;
    }
    begin();
    return observation();
}

void CoverageEnvironment::begin() {
    initialCovered_ = covered_;
    if (options_.costChannels ||
        options_.graphState) { // transit costs are symmetric: from the end = to the end
        current_ = end_;
        computeTransits();
        costToEnd_ = transitCost_;
    }
    current_ = start_;
    steps_ = 0;
    walk_ = Walk{};
    walk_.nodes.push_back(start_);
    done_ = false;
    bool anyUncovered = false;
    for (char c : covered_)
        anyUncovered = anyUncovered || !c;
    computeTransits();
    if (!anyUncovered) {
        // Nothing to cover: the episode is only the transit to the end corner.
        appendTransitTo(end_);
        current_ = end_;
        done_ = true;
    }
}

Query CoverageEnvironment::episodeQuery() const {
    Query query;
    query.startNode = start_;
    query.endNode = end_;
    query.required.assign(initialCovered_.size(), 0);
    for (std::size_t i = 0; i < initialCovered_.size(); ++i)
        query.required[i] = initialCovered_[i] ? 0 : 1;
    return query;
}

void CoverageEnvironment::computeTransits() {
    const CornerGraph& g = *graph_;
    transitCost_.assign(g.nodes.size(), kInfinity);
    parentEdge_.assign(g.nodes.size(), -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    transitCost_[current_] = 0.0;
    heap.push({0.0, current_});
    while (!heap.empty()) {
        const auto [cost, node] = heap.top();
        heap.pop();
        if (cost > transitCost_[node])
            continue;
        for (int id : g.incident[node]) {
            const GraphEdge& e = g.edges[id];
            const bool cellCovered = e.cell < 0 || covered_[e.cell];
            if (e.kind == EdgeKind::Coverage && !cellCovered)
                continue; // covering a cell is a step, never part of a transit
            const double price =
                isOverlap(e, cellCovered) ? options_.coverageOverlapScale * e.length : e.length;
            const int next = e.other(node);
            if (cost + price < transitCost_[next]) {
                transitCost_[next] = cost + price;
                parentEdge_[next] = id;
                heap.push({cost + price, next});
            }
        }
    }
}

void CoverageEnvironment::appendTransitTo(int node) {
    std::vector<int> edges;
    for (int n = node; n != current_;) {
        const int id = parentEdge_[n];
        edges.push_back(id);
        n = graph_->edges[id].other(n);
    }
    for (auto it = edges.rbegin(); it != edges.rend(); ++it) {
        walk_.edges.push_back(*it);
        walk_.nodes.push_back(graph_->edges[*it].other(walk_.nodes.back()));
    }
}

double CoverageEnvironment::costReward(double graphCost) const {
    if (graphCost == 0.0 || graph_->maxEdgeLength <= 0.0)
        return 0.0;
    return -graphCost / graph_->maxEdgeLength * options_.costScale;
}

StepResult CoverageEnvironment::step(int action) {
    if (done_)
        throw std::logic_error("CoverageEnvironment::step: the episode is done; call reset");
    const CornerGraph& g = *graph_;
    ++steps_;
    StepResult result;
    const bool inRange = action >= 0 && action < static_cast<int>(g.nodes.size());
    const int cell = inRange ? g.nodes[action].cell : -1;
    const bool valid = inRange && isValidAction(action);
    if (!valid) {
        result.reward = options_.doubleCoverageReward;
    } else {
        // Travel to the chosen corner, then cover its cell along the coverage edge from it.
        result.info.valid = true;
        result.info.coveredCell = cell;
        result.info.graphCost = transitCost_[action];
        appendTransitTo(action);
        int coverage = -1;
        for (int id : g.cells[cell].coverageEdges)
            if (g.edges[id].u == action || g.edges[id].v == action)
                coverage = id;
        if (coverage < 0)
            throw std::logic_error("CoverageEnvironment: corner without a coverage edge");
        current_ = g.edges[coverage].other(action);
        walk_.edges.push_back(coverage);
        walk_.nodes.push_back(current_);
        covered_[cell] = 1;
        if (!options_.rewardIsNegativeGraphCost)
            result.info.bonusReward = g.cells[cell].kind == CellKind::Primary
                                          ? options_.primaryCellReward
                                          : options_.transitionCellReward;
        computeTransits();
        bool allCovered = true;
        for (char c : covered_)
            allCovered = allCovered && c;
        if (allCovered) {
            // The goal: travel to the end corner (always reachable within the component once
            // no coverage edge is closed to transits).
            result.info.graphCost += transitCost_[end_];
            appendTransitTo(end_);
            current_ = end_;
            result.info.bonusReward += options_.finalReward;
            result.info.reachedGoal = true;
            done_ = true;
        }
        result.info.costReward = costReward(result.info.graphCost);
        result.reward = result.info.costReward + result.info.bonusReward;
    }
    if (!done_ && steps_ >= maxSteps_) {
        done_ = true;
        result.info.truncated = true;
    }
    result.done = done_;
    return result;
}

std::size_t CoverageEnvironment::observationSize() const {
    const std::size_t perNode = static_cast<std::size_t>(channelCount());
    return options_.graphState ? perNode * graph_->nodes.size()
                               : perNode * static_cast<std::size_t>(size_ * size_);
}

std::vector<float> CoverageEnvironment::observation() const {
    if (!options_.graphState)
        return imageObservation();
    GraphStateInput state;
    state.current = current_;
    state.end = end_;
    state.covered = &covered_;
    state.initialCovered = &initialCovered_;
    state.transitCost = &transitCost_;
    state.costToEnd = &costToEnd_;
    return graphStateFeatures(*graph_, *graphTables_, state, options_.graphFeatures);
}

std::vector<float> CoverageEnvironment::imageObservation() const {
    const std::size_t plane = static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_);
    std::vector<float> image(static_cast<std::size_t>(channelCount()) * plane, 0.0f);
    image[static_cast<std::size_t>(current_)] = 1.0f;
    for (const GraphNode& n : graph_->nodes)
        if (n.cell >= 0 && covered_[n.cell])
            image[plane + static_cast<std::size_t>(n.id)] = 1.0f;
    image[2 * plane + static_cast<std::size_t>(end_)] = 1.0f;
    if (options_.costChannels) {
        const double unit = std::max(graph_->maxEdgeLength, 1e-9) * kCostChannelScale;
        auto feature = [unit](double cost) {
            return static_cast<float>(cost < kInfinity ? std::min(cost / unit, 1.0) : 1.0);
        };
        for (const GraphNode& n : graph_->nodes) {
            const auto id = static_cast<std::size_t>(n.id);
            if (isValidAction(n.id)) // without building the whole mask on every step
                image[3 * plane + id] = feature(transitCost_[id]);
            image[4 * plane + id] = feature(costToEnd_[id]);
        }
    }
    return image;
}

std::vector<char> CoverageEnvironment::actionMask() const {
    std::vector<char> mask(graph_->nodes.size(), 0);
    if (done_)
        return mask;
    for (const GraphNode& n : graph_->nodes)
        mask[n.id] = isValidAction(n.id);
    return mask;
}

bool CoverageEnvironment::isValidAction(int node) const {
    const int cell = graph_->nodes[static_cast<std::size_t>(node)].cell;
    return cell >= 0 && !covered_[cell] && transitCost_[node] < kInfinity;
}

} // namespace fc
