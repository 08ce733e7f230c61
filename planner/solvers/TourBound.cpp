#include "solvers/TourBound.h"

#include <algorithm>
#include <functional>
#include <numeric>

namespace fc::solver_detail {

namespace {

// The cheapest price each edge can have inside a transit (see the header).
EdgePrices transitMinimumPrices(const TransitGraph& transit) {
    EdgePrices prices;
    prices.uncovered.resize(transit.truePrices.uncovered.size());
    for (std::size_t e = 0; e < prices.uncovered.size(); ++e)
        prices.uncovered[e] =
            std::min(transit.truePrices.uncovered[e], transit.truePrices.covered[e]);
    prices.covered = prices.uncovered;
    return prices;
}

// Cheapest way to shrink bounds against rounding in the distance sums.
double shrunk(double bound) {
    return bound > 0.0 ? bound * (1.0 - 1e-9) : bound - 1e-9;
}

} // namespace

bool TourBound::affordable(const Problem& problem) {
    const double corners = 4.0 * problem.taskCount() + 2.0;
    return problem.taskCount() <= 1500 &&
           corners * static_cast<double>(problem.reachableNodeCount) <= 3e7;
}

TourBound::TourBound(const TransitGraph& transit, TransitSearch& search, double upper,
                     int subgradientIterations) {
    const Problem& problem = *transit.problem;
    tasks_ = problem.taskCount();
    endNode_ = problem.endNode;
    terminalOfNode_.assign(transit.nodeCount(), -1);
    auto addTerminal = [&](int node) {
        if (terminalOfNode_[node] < 0) {
            terminalOfNode_[node] = static_cast<int>(terminalNodes_.size());
            terminalNodes_.push_back(node);
        }
    };
    addTerminal(problem.startNode);
    for (const std::vector<CoverOption>& options : problem.options)
        for (const CoverOption& option : options)
            addTerminal(option.entry);
    computeDistances(transit, search);
    buildPorts(problem);
    pi_.assign(portTerminals_.size(), 0.0);
    root_ = shrunk(lagrangian(pi_, nullptr, nullptr));
    optimisePenalties(upper, subgradientIterations);
    if (tasks_ <= 63) // at() takes task sets as 64-bit masks
        tabulate();
}

void TourBound::computeDistances(const TransitGraph& transit, TransitSearch& search) {
    const EdgePrices prices = transitMinimumPrices(transit);
    const std::vector<char> coverage = transit.initialCoverage();
    const int terminals = terminalCount();
    terminalDistance_.assign(terminals, std::vector<double>(terminals, kInfinity));
    toEnd_.assign(terminals, kInfinity);
    for (int t = 0; t < terminals; ++t) {
        search.run(prices, coverage, {{terminalNodes_[t], 0.0}}, {});
        for (int u = 0; u < terminals; ++u)
            terminalDistance_[t][u] = search.cost(terminalNodes_[u]);
        toEnd_[t] = search.cost(endNode_);
    }
}

void TourBound::buildPorts(const Problem& problem) {
    // One port per corner; a cover option uses its entry and its exit port once each.
    std::vector<int> portOfTerminal(terminalCount(), -1);
    taskPorts_.assign(tasks_, {});
    taskOptions_.assign(tasks_, {});
    for (int task = 0; task < tasks_; ++task)
        for (const CoverOption& option : problem.options[task]) {
            int ends[2] = {option.entry, option.exit};
            for (int& end : ends) {
                const int terminal = terminalOfNode_[end];
                if (portOfTerminal[terminal] < 0) {
                    portOfTerminal[terminal] = static_cast<int>(portTerminals_.size());
                    portTerminals_.push_back({terminal});
                    taskPorts_[task].push_back(portOfTerminal[terminal]);
                }
                end = portOfTerminal[terminal];
            }
            taskOptions_[task].push_back({ends[0], ends[1]});
        }
    const int ports = static_cast<int>(portTerminals_.size());
    portDistance_.assign(ports, std::vector<double>(ports, kInfinity));
    fromTerminal_.assign(terminalCount(), std::vector<double>(ports, kInfinity));
    portToEnd_.assign(ports, kInfinity);
    for (int p = 0; p < ports; ++p)
        for (int a : portTerminals_[p]) {
            portToEnd_[p] = std::min(portToEnd_[p], toEnd_[a]);
            for (int t = 0; t < terminalCount(); ++t)
                fromTerminal_[t][p] = std::min(fromTerminal_[t][p], terminalDistance_[t][a]);
        }
    for (int p = 0; p < ports; ++p)
        for (int q = 0; q < ports; ++q)
            for (int b : portTerminals_[q])
                portDistance_[p][q] = std::min(portDistance_[p][q], fromTerminal_[b][p]);
}

std::pair<int, int> TourBound::heaviestOption(int task, const std::vector<double>& pi) const {
    std::pair<int, int> best = taskOptions_[task].front();
    for (const std::pair<int, int>& option : taskOptions_[task])
        if (pi[option.first] + pi[option.second] > pi[best.first] + pi[best.second])
            best = option;
    return best;
}

double TourBound::lagrangian(const std::vector<double>& pi, std::vector<int>* degree,
                             std::vector<int>* target) const {
    const int start = 0; // terminal of the start node
    if (tasks_ == 0)
        return toEnd_[start];
    if (degree)
        degree->assign(pi.size(), 0);
    // Cheapest penalised link between two tasks, and which ports it uses.
    auto link = [&](int i, int j, int* pi_, int* pj_) {
        double best = kInfinity;
        for (int p : taskPorts_[i])
            for (int q : taskPorts_[j]) {
                const double w = portDistance_[p][q] + pi[p] + pi[q];
                if (w < best) {
                    best = w;
                    *pi_ = p;
                    *pj_ = q;
                }
            }
        return best;
    };
    auto leaf = [&](const std::vector<double>& distance, int i, int* port) {
        double best = kInfinity;
        for (int p : taskPorts_[i])
            if (distance[p] + pi[p] < best) {
                best = distance[p] + pi[p];
                *port = p;
            }
        return best;
    };
    // Prim over the tasks.
    std::vector<double> key(tasks_, kInfinity);
    std::vector<int> keyPorts(2 * tasks_, -1);
    std::vector<char> in(tasks_, 0);
    double total = 0.0;
    key[0] = 0.0;
    for (int step = 0; step < tasks_; ++step) {
        int next = -1;
        for (int i = 0; i < tasks_; ++i)
            if (!in[i] && (next < 0 || key[i] < key[next]))
                next = i;
        in[next] = 1;
        total += key[next];
        if (step > 0 && degree) {
            ++(*degree)[keyPorts[2 * next]];
            ++(*degree)[keyPorts[2 * next + 1]];
        }
        for (int i = 0; i < tasks_; ++i) {
            if (in[i])
                continue;
            int p = -1, q = -1;
            const double w = link(next, i, &q, &p);
            if (w < key[i]) {
                key[i] = w;
                keyPorts[2 * i] = p;
                keyPorts[2 * i + 1] = q;
            }
        }
    }
    double bestStart = kInfinity, bestEnd = kInfinity;
    int startPort = -1, endPort = -1;
    for (int i = 0; i < tasks_; ++i) {
        int port = -1;
        const double s = leaf(fromTerminal_[start], i, &port);
        if (s < bestStart)
            bestStart = s, startPort = port;
        const double e = leaf(portToEnd_, i, &port);
        if (e < bestEnd)
            bestEnd = e, endPort = port;
    }
    if (degree && startPort >= 0 && endPort >= 0) {
        ++(*degree)[startPort];
        ++(*degree)[endPort];
    }
    total += bestStart + bestEnd;
    if (target)
        target->assign(pi.size(), 0);
    for (int i = 0; i < tasks_; ++i) {
        const auto [p, q] = heaviestOption(i, pi);
        total -= pi[p] + pi[q];
        if (target) {
            ++(*target)[p];
            ++(*target)[q];
        }
    }
    return total;
}

void TourBound::optimisePenalties(double upper, int iterations) {
    if (tasks_ < 2 || iterations <= 0 || !(root_ < kInfinity))
        return;
    std::vector<double> pi = pi_;
    std::vector<int> degree, target;
    double lambda = 2.0;
    int sinceBest = 0;
    // Without a known walk, steps are sized on the tree itself.
    for (int it = 0; it < iterations; ++it) {
        const double value = lagrangian(pi, &degree, &target);
        if (shrunk(value) > root_) {
            root_ = shrunk(value);
            pi_ = pi;
            sinceBest = 0;
        } else if (++sinceBest >= 15) {
            lambda *= 0.5;
            sinceBest = 0;
            if (lambda < 1e-4)
                break;
        }
        double norm = 0.0;
        for (std::size_t p = 0; p < pi.size(); ++p)
            norm += double(degree[p] - target[p]) * double(degree[p] - target[p]);
        if (norm == 0.0)
            break; // the tree is a walk: the bound is tight for this relaxation
        const double gap = upper < kInfinity ? std::max(upper - value, 1e-3 * std::abs(upper))
                                             : 0.05 * std::abs(value) + 1.0;
        const double step = lambda * gap / norm;
        for (std::size_t p = 0; p < pi.size(); ++p)
            pi[p] += step * (degree[p] - target[p]);
    }
}

void TourBound::tabulate() {
    const int terminals = terminalCount();
    const std::vector<double> zero(pi_.size(), 0.0);
    for (int k = 0; k < 2; ++k) {
        const std::vector<double>& pi = k == 0 ? pi_ : zero;
        pair_[k].assign(static_cast<std::size_t>(tasks_) * tasks_, kInfinity);
        leafFrom_[k].assign(static_cast<std::size_t>(terminals) * tasks_, kInfinity);
        leafEnd_[k].assign(tasks_, kInfinity);
        offset_[k].assign(tasks_, 0.0);
        for (int i = 0; i < tasks_; ++i) {
            const auto [heavyP, heavyQ] = heaviestOption(i, pi);
            offset_[k][i] = -(pi[heavyP] + pi[heavyQ]);
            for (int p : taskPorts_[i]) {
                leafEnd_[k][i] = std::min(leafEnd_[k][i], portToEnd_[p] + pi[p]);
                for (int t = 0; t < terminals; ++t) {
                    double& leaf = leafFrom_[k][static_cast<std::size_t>(t) * tasks_ + i];
                    leaf = std::min(leaf, fromTerminal_[t][p] + pi[p]);
                }
                for (int j = 0; j < tasks_; ++j)
                    for (int q : taskPorts_[j]) {
                        double& w = pair_[k][static_cast<std::size_t>(i) * tasks_ + j];
                        w = std::min(w, portDistance_[p][q] + pi[p] + pi[q]);
                    }
            }
        }
    }
    scratchKey_.resize(tasks_);
    scratchIn_.resize(tasks_);
}

double TourBound::at(std::uint64_t uncovered, int terminal) {
    if (uncovered == 0)
        return shrunk(toEnd_[terminal]);
    scratchTasks_.clear();
    for (std::uint64_t rest = uncovered; rest != 0; rest &= rest - 1)
        scratchTasks_.push_back(__builtin_ctzll(rest));
    const int n = static_cast<int>(scratchTasks_.size());

    const auto [slot, added] =
        treeIndex_.emplace(uncovered, static_cast<std::uint32_t>(treeWeights_.size() / 2));
    const std::uint32_t index = *slot;
    if (added) {
        for (int k = 0; k < 2; ++k) { // Prim over the set, plus the penalties' offset
            double total = 0.0;
            for (int a = 0; a < n; ++a) {
                scratchKey_[a] = kInfinity;
                scratchIn_[a] = 0;
                total += offset_[k][scratchTasks_[a]];
            }
            scratchKey_[0] = 0.0;
            for (int step = 0; step < n; ++step) {
                int next = -1;
                for (int a = 0; a < n; ++a)
                    if (!scratchIn_[a] && (next < 0 || scratchKey_[a] < scratchKey_[next]))
                        next = a;
                scratchIn_[next] = 1;
                total += scratchKey_[next];
                const double* row =
                    &pair_[k][static_cast<std::size_t>(scratchTasks_[next]) * tasks_];
                for (int a = 0; a < n; ++a)
                    if (!scratchIn_[a])
                        scratchKey_[a] = std::min(scratchKey_[a], row[scratchTasks_[a]]);
            }
            treeWeights_.push_back(total);
        }
    }
    double best = -kInfinity;
    for (int k = 0; k < 2; ++k) {
        const double* from = &leafFrom_[k][static_cast<std::size_t>(terminal) * tasks_];
        double leafStart = kInfinity, leafEnd = kInfinity;
        for (int task : scratchTasks_) {
            leafStart = std::min(leafStart, from[task]);
            leafEnd = std::min(leafEnd, leafEnd_[k][task]);
        }
        best = std::max(best, treeWeights_[2 * index + k] + leafStart + leafEnd);
    }
    return shrunk(best);
}

// Large queries: Mehlhorn's construction. A search from every task corner at once (each
// node labelled by its nearest task) yields, through the edges joining two labels, a
// graph whose minimum spanning tree is one of the complete task distance graph.
double spanningTreeBound(const TransitGraph& transit, TransitSearch& search) {
    const Problem& problem = *transit.problem;
    const CornerGraph& graph = *problem.graph;
    const int tasks = problem.taskCount();
    const EdgePrices prices = transitMinimumPrices(transit);
    const std::vector<char> coverage = transit.initialCoverage();
    if (tasks == 0) {
        search.run(prices, coverage, {{problem.startNode, 0.0}}, {problem.endNode});
        return shrunk(search.cost(problem.endNode));
    }
    std::vector<int> taskOfCorner(transit.nodeCount(), -1);
    std::vector<NodeCost> corners;
    for (int task = 0; task < tasks; ++task)
        for (const CoverOption& option : problem.options[task])
            if (taskOfCorner[option.entry] < 0) {
                taskOfCorner[option.entry] = task;
                corners.push_back({option.entry, 0.0});
            }
    // Leaves: the start to its nearest corner, the nearest corner to the end.
    auto nearestCorner = [&](int node) {
        double found = kInfinity;
        search.explore(prices, coverage, {{node, 0.0}}, [&](int at, double cost) {
            if (taskOfCorner[at] >= 0) {
                found = cost;
                return true;
            }
            return false;
        });
        return found;
    };
    const double leaves = nearestCorner(problem.startNode) + nearestCorner(problem.endNode);

    const int nodes = transit.nodeCount();
    std::vector<double> distance(nodes, kInfinity);
    std::vector<int> label(nodes, -1);
    search.run(prices, coverage, corners, {});
    for (int n = 0; n < nodes; ++n)
        if (search.isSettled(n)) {
            distance[n] = search.cost(n);
            label[n] = taskOfCorner[search.sourceOf(n)];
        }
    struct Link {
        double weight;
        int a, b;
    };
    std::vector<Link> links;
    for (const GraphEdge& edge : graph.edges) {
        const double price = prices.covered[edge.id];
        if (!(price < kInfinity) || label[edge.u] < 0 || label[edge.v] < 0 ||
            label[edge.u] == label[edge.v])
            continue;
        links.push_back(
            {distance[edge.u] + price + distance[edge.v], label[edge.u], label[edge.v]});
    }
    std::sort(links.begin(), links.end(),
              [](const Link& x, const Link& y) { return x.weight < y.weight; });
    std::vector<int> parent(tasks);
    std::iota(parent.begin(), parent.end(), 0);
    std::function<int(int)> root = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    double tree = 0.0;
    int joined = 1;
    for (const Link& link : links) {
        const int a = root(link.a), b = root(link.b);
        if (a == b)
            continue;
        parent[a] = b;
        tree += link.weight;
        ++joined;
    }
    if (joined < tasks)
        return 0.0; // cannot happen for a valid query; stay safe
    return shrunk(tree + leaves);
}

double provenLowerBound(const TransitGraph& transit, TransitSearch& search, double upper) {
    if (TourBound::affordable(*transit.problem)) {
        const int tasks = transit.problem->taskCount();
        // Subgradient iterations cost tasks^2 each: fewer on large queries.
        const int iterations = tasks <= 200 ? 400 : tasks <= 600 ? 100 : 30;
        return TourBound(transit, search, upper, iterations).root();
    }
    return spanningTreeBound(transit, search);
}

} // namespace fc::solver_detail
