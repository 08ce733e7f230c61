// adjacency-ga-centres (Tung & Liu 2019 as the first paper reads it): the adjacency graph of the
// classic decomposition's cells, a genetic algorithm for the travelling-salesman order of the
// cells with four entry/exit options per cell (start at any corner; the stripe parity fixes
// the exit), transits between cells that are not neighbours through the centres of the cells
// on the way (the one left and the one entered included), back to the start. Like the TSP
// tour it solves, the tour begins at its start node: the robot covers the cell it starts in
// first (in the paper's figure 14B it then returns through the middle of cells 4 and 1).
#include "solvers/BaselineSupport.h"
#include "solvers/SolverCommon.h"

#include <algorithm>

namespace fc {
namespace {

using namespace baseline_detail;

constexpr const char* kName = "adjacency-ga-centres";

// One way to cover a cell: its boustrophedon from one of the four corners.
struct CoverOption {
    Pattern pattern;
    Vec2 entry, exit;
    double length = 0;
};

class CellTransits {
public:
    explicit CellTransits(const BaselineWorld& w) : centre_(w.graph.cells.size()) {
        neighbours_.resize(w.graph.cells.size());
        for (const GraphCell& c : w.graph.cells)
            if (w.usable[c.id])
                centre_[c.id] = cellCentre(w.decomposition.cells[c.id]);
        for (const auto& [a, b] : connectedCellPairs(w.graph)) {
            if (!w.usable[a] || !w.usable[b])
                continue;
            neighbours_[a].push_back(b);
            neighbours_[b].push_back(a);
        }
        routes_.resize(w.graph.cells.size());
    }

    void computeRoutesFrom(int cell) { routes_[cell] = dijkstra(cell); }

    // Cells whose centres a transit from cell a to cell b passes: none between neighbours
    // (straight across their border), otherwise a, the cells between and b, as in the
    // paper's figure 14B where the robot returns through the middle of cells 4 and 1.
    std::vector<int> through(int a, int b) const {
        std::vector<int> cells;
        if (a == b || adjacent(a, b))
            return cells;
        const ShortestPaths& r = routes_[a];
        if (r.dist[b] == kInf)
            throw SolverError(std::string(kName) + ": a required cell is not connected");
        for (int c = b; c >= 0; c = r.via[c])
            cells.push_back(c);
        std::reverse(cells.begin(), cells.end());
        return cells;
    }

    double cost(int a, Vec2 p, int b, Vec2 q) const {
        if (a == b || adjacent(a, b))
            return distance(p, q);
        return distance(p, centre_[a]) + routes_[a].dist[b] + distance(centre_[b], q);
    }

    Vec2 centre(int cell) const { return centre_[cell]; }

private:
    bool adjacent(int a, int b) const {
        return std::find(neighbours_[a].begin(), neighbours_[a].end(), b) != neighbours_[a].end();
    }

    // Shortest routes between cell centres over the adjacency graph.
    ShortestPaths dijkstra(int source) const {
        return shortestPaths(centre_.size(), {source}, [&](int u, auto&& visit) {
            for (int v : neighbours_[u])
                visit(v, distance(centre_[u], centre_[v]), u);
        });
    }

    std::vector<Vec2> centre_;
    std::vector<std::vector<int>> neighbours_;
    std::vector<ShortestPaths> routes_; // from a cell: via = the previous cell
};

struct Individual {
    std::vector<int> order;  // tasks after the first one
    std::vector<int> option; // per task
    double cost = kInf;
};

class GeneticTour {
public:
    // firstTask: the task covered first (the start cell), or -1 when it is not required.
    GeneticTour(const BaselineWorld& w, const CellTransits& transits, std::vector<int> cells,
                std::vector<std::vector<CoverOption>> options, int firstTask,
                const SolveControl& control)
        : w_(w), transits_(transits), cells_(std::move(cells)), options_(std::move(options)),
          firstTask_(firstTask), random_(w.seed), control_(control) {}

    // The whole visiting order of an individual: the first task, then its order.
    std::vector<int> visits(const Individual& ind) const {
        std::vector<int> all;
        if (firstTask_ >= 0)
            all.push_back(firstTask_);
        all.insert(all.end(), ind.order.begin(), ind.order.end());
        return all;
    }

    Individual run() {
        const int n = static_cast<int>(cells_.size());
        const int generations = std::clamp(50 * n, 500, 10000);
        std::vector<Individual> population{nearestNeighbour()};
        while (static_cast<int>(population.size()) < kPopulation)
            population.push_back(randomIndividual());
        for (Individual& ind : population)
            ind.cost = cost(ind);
        for (int g = 0; g < generations; ++g) {
            // Thousands of generations on large floors: the editor's Cancel must be heard.
            solver_detail::throwIfCancelled(control_, kName);
            solver_detail::reportProgress(control_, static_cast<double>(g) / generations);
            std::stable_sort(
                population.begin(), population.end(),
                [](const Individual& a, const Individual& b) { return a.cost < b.cost; });
            std::vector<Individual> next(population.begin(), population.begin() + kElite);
            while (static_cast<int>(next.size()) < kPopulation) {
                Individual child = crossover(tournament(population), tournament(population));
                mutate(child);
                child.cost = cost(child);
                next.push_back(std::move(child));
            }
            population = std::move(next);
        }
        return *std::min_element(
            population.begin(), population.end(),
            [](const Individual& a, const Individual& b) { return a.cost < b.cost; });
    }

private:
    static constexpr int kPopulation = 60;
    static constexpr int kElite = 2;

    double cost(const Individual& ind) const {
        int cell = w_.startCell;
        Vec2 at = w_.start;
        double total = 0;
        for (int t : visits(ind)) {
            const CoverOption& o = options_[t][ind.option[t]];
            total += transits_.cost(cell, at, cells_[t], o.entry) + o.length;
            cell = cells_[t], at = o.exit;
        }
        return total + transits_.cost(cell, at, w_.startCell, w_.start);
    }

    // Seeds the population with the nearest uncovered cell next (best option each time).
    Individual nearestNeighbour() const {
        const int n = static_cast<int>(cells_.size());
        Individual ind{{}, std::vector<int>(n, 0), kInf};
        std::vector<char> done(n, 0);
        int cell = w_.startCell;
        Vec2 at = w_.start;
        for (int step = 0; step < n; ++step) {
            int bestTask = -1, bestOption = 0;
            double best = kInf;
            for (int t = 0; t < n; ++t)
                for (size_t k = 0; !done[t] && (step > 0 || firstTask_ < 0 || t == firstTask_) &&
                                   k < options_[t].size();
                     ++k) {
                    const CoverOption& o = options_[t][k];
                    const double c = transits_.cost(cell, at, cells_[t], o.entry) + o.length;
                    if (bestTask < 0 || c < best)
                        best = c, bestTask = t, bestOption = static_cast<int>(k);
                }
            done[bestTask] = 1;
            if (bestTask != firstTask_)
                ind.order.push_back(bestTask);
            ind.option[bestTask] = bestOption;
            cell = cells_[bestTask], at = options_[bestTask][bestOption].exit;
        }
        return ind;
    }

    Individual randomIndividual() {
        const int n = static_cast<int>(cells_.size());
        Individual ind{{}, std::vector<int>(n), kInf};
        for (int i = 0; i < n; ++i) {
            ind.option[i] = random_.below(optionCount(i));
            if (i != firstTask_)
                ind.order.push_back(i);
        }
        for (int i = static_cast<int>(ind.order.size()) - 1; i > 0; --i)
            std::swap(ind.order[i], ind.order[random_.below(i + 1)]);
        return ind;
    }

    int optionCount(int task) const { return static_cast<int>(options_[task].size()); }

    const Individual& tournament(const std::vector<Individual>& population) {
        const Individual* best = &population[random_.below(kPopulation)];
        for (int k = 0; k < 2; ++k) {
            const Individual& other = population[random_.below(kPopulation)];
            if (other.cost < best->cost)
                best = &other;
        }
        return *best;
    }

    // Order crossover: a slice of the first parent in place, the rest in the second
    // parent's order; each cell keeps the option of the parent it came from.
    Individual crossover(const Individual& a, const Individual& b) {
        const int m = static_cast<int>(a.order.size());
        Individual child{std::vector<int>(m, -1), b.option, kInf};
        if (m == 0)
            return child;
        int i = random_.below(m);
        int j = random_.below(m);
        if (i > j)
            std::swap(i, j);
        std::vector<char> taken(cells_.size(), 0);
        for (int k = i; k <= j; ++k) {
            child.order[k] = a.order[k];
            child.option[a.order[k]] = a.option[a.order[k]];
            taken[a.order[k]] = 1;
        }
        int fill = 0;
        for (int t : b.order) {
            if (taken[t])
                continue;
            while (child.order[fill] >= 0)
                ++fill;
            child.order[fill] = t;
        }
        return child;
    }

    void mutate(Individual& ind) {
        const int n = static_cast<int>(cells_.size());
        const int m = static_cast<int>(ind.order.size());
        if (m > 1 && random_.below(100) < 30) { // inversion
            int i = random_.below(m);
            int j = random_.below(m);
            if (i > j)
                std::swap(i, j);
            std::reverse(ind.order.begin() + i, ind.order.begin() + j + 1);
        }
        if (m > 1 && random_.below(100) < 10) { // swap
            const int i = random_.below(m), j = random_.below(m);
            std::swap(ind.order[i], ind.order[j]);
        }
        for (int t = 0; t < n; ++t)
            if (random_.below(n) == 0)
                ind.option[t] = random_.below(optionCount(t));
    }

    const BaselineWorld& w_;
    const CellTransits& transits_;
    std::vector<int> cells_;
    std::vector<std::vector<CoverOption>> options_;
    int firstTask_;
    solver_detail::SeededRandom random_;
    const SolveControl& control_;
};

// Start at any of the four corners: stripes left to right or right to left, the first
// one up or down (the stripe parity then fixes the exit corner).
std::vector<CoverOption> coverOptions(const BaselineWorld& w, const ClearanceField& field,
                                      int cell) {
    std::vector<CoverOption> options;
    for (bool leftToRight : {true, false}) {
        for (bool startLow : {true, false}) {
            CoverOption o;
            o.pattern =
                boustrophedon(w.decomposition.cells[cell], field, w.decomposition.coverageWidth(),
                              CellPart::Whole, leftToRight, startLow);
            o.entry = o.pattern.points.front();
            o.exit = o.pattern.points.back();
            o.length = polylineLength(o.pattern.points);
            options.push_back(std::move(o));
        }
    }
    return options;
}

} // namespace

Solution solveAdjacencyGa(const PreparedPlan& prepared, const Query& query,
                          const SolveControl& control) {
    const BaselineWorld world = makeBaselineWorld(prepared, query, kName);
    const ClearanceField& field = world.decomposition.clearance();
    CellTransits transits(world);
    std::vector<int> cells;
    std::vector<std::vector<CoverOption>> options;
    int firstTask = -1;
    transits.computeRoutesFrom(world.startCell);
    for (const GraphCell& c : world.graph.cells) {
        if (!world.required[c.id])
            continue;
        if (c.id == world.startCell)
            firstTask = static_cast<int>(cells.size());
        cells.push_back(c.id);
        options.push_back(coverOptions(world, field, c.id));
        transits.computeRoutesFrom(c.id);
    }
    GeneticTour tour(world, transits, cells, options, firstTask, control);
    const Individual best = tour.run();
    if (best.cost == kInf)
        throw SolverError(std::string(kName) + ": a required cell is not connected");

    TourBuilder path(world.start, field, world.graph, kName);
    int cell = world.startCell;
    for (int t : tour.visits(best)) {
        for (int through : transits.through(cell, cells[t]))
            path.travelTo(transits.centre(through));
        path.follow(options[t][best.option[t]].pattern);
        cell = cells[t];
    }
    for (int through : transits.through(cell, world.startCell))
        path.travelTo(transits.centre(through));
    path.travelTo(world.start);
    return baselineSolution(kName, path.take());
}

} // namespace fc
