#include "solvers/OrderEvaluator.h"

#include <algorithm>

namespace fc::solver_detail {

OrderEvaluator::OrderEvaluator(const TransitGraph& graph, TransitSearch& search)
    : graph_(graph), search_(search), covered_(graph.initialCoverage()),
      startSource_{{graph.problem->startNode, 0.0}} {}

const std::vector<NodeCost>& OrderEvaluator::sourcesFor(std::size_t position) {
    return position == 0 ? startSource_ : labels_[position - 1].exits;
}

void OrderEvaluator::advance(const std::vector<int>& order, std::size_t position) {
    const Problem& problem = *graph_.problem;
    targets_.clear();
    if (position == order.size()) {
        targets_.push_back(problem.endNode);
        search_.run(graph_.truePrices, covered_, sourcesFor(position), targets_);
        return;
    }
    const std::vector<CoverOption>& options = problem.options[order[position]];
    for (const CoverOption& option : options)
        targets_.push_back(option.entry);
    search_.run(graph_.truePrices, covered_, sourcesFor(position), targets_);

    StepLabels& step = labels_[position];
    step.exits.clear();
    step.optionOfExit.clear();
    for (std::size_t o = 0; o < options.size(); ++o) {
        const double reached = search_.cost(options[o].entry); // covering itself costs 0
        if (!(reached < kInfinity))
            continue;
        auto same = std::find_if(step.exits.begin(), step.exits.end(),
                                 [&](const NodeCost& x) { return x.node == options[o].exit; });
        if (same == step.exits.end()) {
            step.exits.push_back({options[o].exit, reached});
            step.optionOfExit.push_back(static_cast<int>(o));
        } else if (reached < same->cost) {
            same->cost = reached;
            step.optionOfExit[same - step.exits.begin()] = static_cast<int>(o);
        }
    }
}

double OrderEvaluator::cost(const std::vector<int>& order, double bound) {
    const Problem& problem = *graph_.problem;
    const std::size_t steps = order.size();
    std::size_t reuse = std::min({validSteps_, steps, cachedOrder_.size()});
    for (std::size_t i = 0; i < reuse; ++i) {
        if (order[i] != cachedOrder_[i]) {
            reuse = i;
            break;
        }
    }
    cachedOrder_ = order;
    validSteps_ = reuse;
    if (labels_.size() < steps)
        labels_.resize(steps);

    for (int cell : problem.taskCells)
        covered_[cell] = 0;
    for (std::size_t i = 0; i < reuse; ++i)
        covered_[problem.taskCells[order[i]]] = 1;

    for (std::size_t i = reuse; i < steps; ++i) {
        advance(order, i);
        validSteps_ = i + 1;
        double cheapest = kInfinity;
        for (const NodeCost& exit : labels_[i].exits)
            cheapest = std::min(cheapest, exit.cost);
        if (!(cheapest < bound)) // costs never fall, so this order cannot beat the bound
            return kInfinity;
        covered_[problem.taskCells[order[i]]] = 1;
    }
    advance(order, steps);
    const double total = search_.cost(problem.endNode);
    return total < bound ? total : kInfinity;
}

Walk OrderEvaluator::walk(const std::vector<int>& order) {
    const Problem& problem = *graph_.problem;
    const CornerGraph& graph = *problem.graph;
    if (!(cost(order) < kInfinity))
        throw SolverError("internal error: no walk covers the cells in the chosen order");

    // Walk back from the end, re-running each step's search under its covered set to
    // recover where its cheapest label came from.
    const std::size_t steps = order.size();
    std::vector<std::vector<int>> transits(steps + 1);
    std::vector<int> coverEdges(steps);
    int target = problem.endNode;
    for (std::size_t s = steps + 1; s-- > 0;) {
        if (s < steps)
            covered_[problem.taskCells[order[s]]] = 0;
        advance(order, s);
        transits[s] = search_.edgesTo(target);
        if (s == 0)
            break;
        const int exit = search_.sourceOf(target);
        const StepLabels& previous = labels_[s - 1];
        const auto at = std::find_if(previous.exits.begin(), previous.exits.end(),
                                     [&](const NodeCost& x) { return x.node == exit; });
        const CoverOption& option =
            problem.options[order[s - 1]][previous.optionOfExit[at - previous.exits.begin()]];
        coverEdges[s - 1] = option.edge;
        target = option.entry;
    }
    validSteps_ = 0; // the re-runs overwrote the last step's labels

    Walk walk;
    walk.nodes.push_back(problem.startNode);
    auto append = [&](int edge) {
        walk.edges.push_back(edge);
        walk.nodes.push_back(graph.edges[edge].other(walk.nodes.back()));
    };
    for (std::size_t s = 0; s <= steps; ++s) {
        for (int edge : transits[s])
            append(edge);
        if (s < steps)
            append(coverEdges[s]);
    }
    return walk;
}

} // namespace fc::solver_detail
