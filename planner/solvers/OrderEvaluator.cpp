#include "solvers/OrderEvaluator.h"

#include <algorithm>
#include <cmath>

namespace fc::solver_detail {

OrderEvaluator::OrderEvaluator(const TransitGraph& graph, TransitSearch& search)
    : graph_(graph), search_(search),
      covered_(graph.initialCoverage()), startSource_{{graph.problem->startNode, 0.0}} {}

void OrderEvaluator::cover(int task, bool covered) {
    covered_[graph_.problem->taskCells[task]] = covered ? 1 : 0;
}

void OrderEvaluator::setCoveredPrefix(int position) {
    while (coveredPrefix_ < position)
        cover(base_[coveredPrefix_++], true);
    while (coveredPrefix_ > position)
        cover(base_[--coveredPrefix_], false);
}

const std::vector<NodeCost>& OrderEvaluator::baseSources(int position) const {
    return position == 0 ? startSource_ : baseSteps_[position - 1].exits;
}

void OrderEvaluator::coverStep(const std::vector<NodeCost>& sources, int task, StepLabels& step) {
    const std::vector<CoverOption>& options = graph_.problem->options[task];
    targets_.clear();
    for (const CoverOption& option : options)
        targets_.push_back(option.entry);
    search_.run(graph_.truePrices, covered_, sources, targets_);

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

double OrderEvaluator::finish(const std::vector<NodeCost>& sources) {
    targets_.assign(1, graph_.problem->endNode);
    search_.run(graph_.truePrices, covered_, sources, targets_);
    return search_.cost(graph_.problem->endNode);
}

double OrderEvaluator::setBase(const std::vector<int>& order) {
    base_ = order;
    const int steps = static_cast<int>(order.size());
    baseSteps_.resize(steps);
    for (int cell : graph_.problem->taskCells)
        covered_[cell] = 0;
    coveredPrefix_ = 0;
    baseCost_ = kInfinity;
    for (int k = 0; k < steps; ++k) {
        coverStep(baseSources(k), order[k], baseSteps_[k]);
        if (baseSteps_[k].exits.empty())
            return baseCost_; // infeasible: a cell cannot be reached in this order
        setCoveredPrefix(k + 1);
    }
    baseCost_ = finish(baseSources(steps));
    return baseCost_;
}

double OrderEvaluator::baseStepCost(int position) const {
    auto cheapest = [](const std::vector<NodeCost>& labels) {
        double least = kInfinity;
        for (const NodeCost& label : labels)
            least = std::min(least, label.cost);
        return least;
    };
    return cheapest(baseSteps_[position].exits) - cheapest(baseSources(position));
}

OrderEvaluator::Comparison OrderEvaluator::compareWithBase(const StepLabels& step,
                                                           int position) const {
    // Later steps depend monotonically on these costs: shifting them all by d shifts the
    // final cost by d. So the final cost lies within the base's plus [min, max] difference.
    const StepLabels& base = baseSteps_[position];
    Comparison result;
    if (base.exits.size() != step.exits.size() || step.exits.empty())
        return result;
    double low = kInfinity, high = -kInfinity, tolerance = 0.0;
    for (std::size_t i = 0; i < step.exits.size(); ++i) {
        if (step.exits[i].node != base.exits[i].node)
            return result;
        const double difference = step.exits[i].cost - base.exits[i].cost;
        low = std::min(low, difference);
        high = std::max(high, difference);
        tolerance = std::max(tolerance, 1e-9 * (1.0 + std::abs(base.exits[i].cost)));
    }
    result.comparable = true;
    result.lowerBound = baseCost_ + low;
    result.synced = high - low <= tolerance;
    return result;
}

double OrderEvaluator::candidateCost(const std::vector<int>& candidate, int first, int last,
                                     double bound) {
    const int steps = static_cast<int>(base_.size());
    setCoveredPrefix(first);
    candidateFirst_ = first;
    candidateWindow_.assign(candidate.begin() + first, candidate.begin() + last + 1);
    candidateSynced_ = false;
    candidateCost_ = kInfinity;
    if (static_cast<int>(candidateSteps_.size()) < steps)
        candidateSteps_.resize(steps);

    double result = kInfinity;
    bool decided = false; // the result is known without computing to the end
    int k = first;
    while (k < steps && !decided) {
        const int position = k++;
        const std::vector<NodeCost>& sources =
            position == first ? baseSources(first) : candidateSteps_[position - 1].exits;
        StepLabels& step = candidateSteps_[position];
        coverStep(sources, candidate[position], step);
        cover(candidate[position], true);
        double cheapest = kInfinity;
        for (const NodeCost& exit : step.exits)
            cheapest = std::min(cheapest, exit.cost);
        if (!(cheapest < bound)) { // infeasible, or costs never fall enough to win
            decided = true;
        } else if (position >= last) {
            const Comparison comparison = compareWithBase(step, position);
            if (comparison.comparable && !(comparison.lowerBound < bound)) {
                decided = true; // cannot win, whatever follows
            } else if (comparison.synced) {
                candidateSynced_ = true;
                candidateOffset_ = comparison.lowerBound - baseCost_;
                result = comparison.lowerBound;
                decided = true;
            }
        }
    }
    if (!decided)
        result = finish(candidateSteps_[steps - 1].exits);
    candidateStop_ = k;
    for (int j = first; j < k; ++j) // back to the base's covered prefix at `first`
        cover(candidate[j], false);
    coveredPrefix_ = first;
    candidateCost_ = result < bound ? result : kInfinity;
    return candidateCost_;
}

void OrderEvaluator::acceptCandidate() {
    for (int j = candidateFirst_; j < candidateStop_; ++j)
        std::swap(baseSteps_[j], candidateSteps_[j]);
    std::copy(candidateWindow_.begin(), candidateWindow_.end(), base_.begin() + candidateFirst_);
    if (candidateSynced_) // later steps are the base's, shifted by a constant
        for (std::size_t j = candidateStop_; j < baseSteps_.size(); ++j)
            for (NodeCost& exit : baseSteps_[j].exits)
                exit.cost += candidateOffset_;
    baseCost_ = candidateCost_;
    candidateSynced_ = false;
    candidateStop_ = candidateFirst_; // a second accept would change nothing
    candidateWindow_.clear();
}

Walk OrderEvaluator::walk(const std::vector<int>& order) {
    const Problem& problem = *graph_.problem;
    const CornerGraph& graph = *problem.graph;
    if (!(setBase(order) < kInfinity))
        throw SolverError("internal error: no walk covers the cells in the chosen order");

    // Walk back from the end, re-running each step's search under its covered set to
    // recover where its cheapest label came from.
    const int steps = static_cast<int>(order.size());
    std::vector<std::vector<int>> transits(steps + 1);
    std::vector<int> coverEdges(steps);
    StepLabels scratch;
    int target = problem.endNode;
    for (int s = steps; s >= 0; --s) {
        setCoveredPrefix(s);
        if (s == steps)
            finish(baseSources(s));
        else
            coverStep(baseSources(s), order[s], scratch);
        transits[s] = search_.edgesTo(target);
        if (s == 0)
            break;
        const int exit = search_.sourceOf(target);
        const StepLabels& previous = baseSteps_[s - 1];
        const auto at = std::find_if(previous.exits.begin(), previous.exits.end(),
                                     [&](const NodeCost& x) { return x.node == exit; });
        const CoverOption& option =
            problem.options[order[s - 1]][previous.optionOfExit[at - previous.exits.begin()]];
        coverEdges[s - 1] = option.edge;
        target = option.entry;
    }

    Walk walk;
    walk.nodes.push_back(problem.startNode);
    auto append = [&](int edge) {
        walk.edges.push_back(edge);
        walk.nodes.push_back(graph.edges[edge].other(walk.nodes.back()));
    };
    for (int s = 0; s <= steps; ++s) {
        for (int edge : transits[s])
            append(edge);
        if (s < steps)
            append(coverEdges[s]);
    }
    return walk;
}

} // namespace fc::solver_detail
