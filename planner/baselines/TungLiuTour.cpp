// The Tung & Liu tour over the model's cells: a genetic algorithm over the cell order and
// each cell's option (order crossover, swap and inversion mutation, option mutation, elitism;
// seeded), and their dynamic programme (Held-Karp) as the exact reference.
#include "baselines/BaselineModel.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>

namespace fc::baselines {
namespace detail {

namespace {

double leg(const Model& m, int from, int to) {
    return m.transits->distance(from, to);
}

} // namespace

double tourCost(const Model& m, const std::vector<int>& order, const std::vector<int>& options) {
    double cost = 0;
    int at = m.start;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const CoverOption& o = m.cells[order[k]].options[options[order[k]]];
        if (!(o.length < INFINITY))
            return INFINITY;
        cost += leg(m, at, o.entry) + o.length;
        at = o.exit;
    }
    return cost + leg(m, at, m.end);
}

Tour assembleTour(const Model& m, const std::vector<int>& order, const std::vector<int>& options) {
    Tour tour;
    Polyline local;
    std::vector<SegmentKind> kinds;
    auto append = [&](const Polyline& piece, SegmentKind kind) {
        for (std::size_t i = 0; i < piece.size(); ++i) {
            if (!local.empty() && i == 0) {
                if (distance(local.back(), piece[0]) < 1e-12)
                    continue;
                kinds.push_back(SegmentKind::Transit);
            } else if (!local.empty()) {
                kinds.push_back(kind);
            }
            local.push_back(piece[i]);
        }
    };
    int at = m.start;
    for (int cell : order) {
        const CoverOption& o = m.cells[cell].options[options[cell]];
        append(m.transits->path(at, o.entry), SegmentKind::Transit);
        append(o.points, SegmentKind::Stripe);
        at = o.exit;
        tour.order.push_back(cell);
        tour.options.push_back(options[cell]);
    }
    append(m.transits->path(at, m.end), SegmentKind::Transit);
    tour.path.points = m.frame.toWorld(local);
    tour.path.kinds = std::move(kinds);
    tour.length = polylineLength(tour.path.points);
    tour.modelCost = tourCost(m, order, options);
    tour.cells = m.cellCount;
    tour.unreachableCells = m.unreachable;
    return tour;
}

namespace {

std::vector<int> validOptions(const Cell& cell) {
    std::vector<int> valid;
    for (int o = 0; o < 4; ++o)
        if (cell.options[o].length < INFINITY)
            valid.push_back(o);
    return valid;
}

// Every cell must be coverable and reachable from the start, or there is no tour.
void requireTour(const Model& m) {
    if (m.cells.empty())
        throw TourError("adjacency-ga: the rooms contain no cell the robot can sweep");
    for (const Cell& cell : m.cells) {
        bool reachable = false;
        for (int o : validOptions(cell))
            reachable = reachable || leg(m, m.start, cell.options[o].entry) < INFINITY;
        if (!reachable)
            throw TourError("adjacency-ga: a cell cannot be reached from the start");
    }
}

struct Individual {
    std::vector<int> order, options;
    double cost = INFINITY;
};

// Order crossover (OX1): a slice of the first parent in place, the rest in the second's
// order; each cell keeps the option of the parent whose order placed it (an option is good
// with its neighbours in the order, not on its own).
Individual orderCrossover(const Individual& p1, const Individual& p2, std::mt19937_64& rng) {
    const std::size_t n = p1.order.size();
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    std::size_t a = pick(rng), b = pick(rng);
    if (a > b)
        std::swap(a, b);
    Individual child;
    child.order.assign(n, -1);
    child.options = p2.options;
    std::vector<char> used(n, 0);
    for (std::size_t i = a; i <= b; ++i) {
        const int cell = p1.order[i];
        child.order[i] = cell, used[cell] = 1, child.options[cell] = p1.options[cell];
    }
    std::size_t at = (b + 1) % n;
    for (std::size_t k = 0; k < n; ++k) {
        const int gene = p2.order[(b + 1 + k) % n];
        if (used[gene])
            continue;
        child.order[at] = gene;
        used[gene] = 1;
        at = (at + 1) % n;
    }
    return child;
}

} // namespace

Tour solveGa(const Model& m, const Options& opt) {
    requireTour(m);
    const int n = static_cast<int>(m.cells.size());
    std::mt19937_64 rng(opt.seed);
    std::vector<std::vector<int>> valid(n);
    for (int c = 0; c < n; ++c)
        valid[c] = validOptions(m.cells[c]);
    auto randomOption = [&](int cell) {
        std::uniform_int_distribution<std::size_t> pick(0, valid[cell].size() - 1);
        return valid[cell][pick(rng)];
    };
    auto evaluate = [&](Individual& ind) { ind.cost = tourCost(m, ind.order, ind.options); };
    const int size = std::max(4, opt.population);
    std::vector<Individual> population(size);
    for (Individual& ind : population) {
        ind.order.resize(n);
        std::iota(ind.order.begin(), ind.order.end(), 0);
        std::shuffle(ind.order.begin(), ind.order.end(), rng);
        ind.options.resize(n);
        for (int c = 0; c < n; ++c)
            ind.options[c] = randomOption(c);
        evaluate(ind);
    }
    auto byCost = [](const Individual& a, const Individual& b) { return a.cost < b.cost; };
    std::sort(population.begin(), population.end(), byCost);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> anyPosition(0, n - 1), anyMember(0, size - 1);
    auto tournament = [&]() -> const Individual& {
        int best = anyMember(rng);
        for (int k = 0; k < 2; ++k)
            best = std::min(best, anyMember(rng)); // sorted: a lower index is fitter
        return population[best];
    };
    double bestCost = population.front().cost;
    int stall = 0;
    for (int generation = 0; generation < opt.generations && stall < opt.stallGenerations;
         ++generation) {
        if (opt.cancelled && opt.cancelled())
            throw TourError("cancelled");
        std::vector<Individual> next(population.begin(), population.begin() + 2); // elites
        while (static_cast<int>(next.size()) < size) {
            const Individual &a = tournament(), &b = tournament();
            Individual child = n > 1 && unit(rng) < 0.9 ? orderCrossover(a, b, rng) : a;
            if (n > 1 && unit(rng) < 0.3)
                std::swap(child.order[anyPosition(rng)], child.order[anyPosition(rng)]);
            if (n > 2 && unit(rng) < 0.3) {
                int i = anyPosition(rng), j = anyPosition(rng);
                if (i > j)
                    std::swap(i, j);
                std::reverse(child.order.begin() + i, child.order.begin() + j + 1);
            }
            if (n > 2 && unit(rng) < 0.3) { // insertion: one cell moved elsewhere in the order
                const int from = anyPosition(rng), to = anyPosition(rng);
                const int cell = child.order[from];
                child.order.erase(child.order.begin() + from);
                child.order.insert(child.order.begin() + to, cell);
            }
            for (int c = 0; c < n; ++c)
                if (unit(rng) < 1.0 / n)
                    child.options[c] = randomOption(c);
            evaluate(child);
            next.push_back(std::move(child));
        }
        population = std::move(next);
        std::sort(population.begin(), population.end(), byCost);
        if (population.front().cost < bestCost - 1e-9)
            bestCost = population.front().cost, stall = 0;
        else
            ++stall;
    }
    const Individual& best = population.front();
    if (!(best.cost < INFINITY))
        throw TourError("adjacency-ga: no collision-free tour found");
    return assembleTour(m, best.order, best.options);
}

Tour solveDp(const Model& m) {
    requireTour(m);
    const int n = static_cast<int>(m.cells.size());
    const std::size_t states = (std::size_t{1} << n) * n * 4;
    std::vector<float> cost(states, INFINITY);
    std::vector<std::int32_t> parent(states, -1);
    auto index = [n](std::size_t mask, int last, int option) {
        return (mask * n + last) * 4 + option;
    };
    for (int c = 0; c < n; ++c)
        for (int o = 0; o < 4; ++o) {
            const CoverOption& opt = m.cells[c].options[o];
            if (opt.length < INFINITY)
                cost[index(std::size_t{1} << c, c, o)] =
                    static_cast<float>(leg(m, m.start, opt.entry) + opt.length);
        }
    for (std::size_t mask = 1; mask < (std::size_t{1} << n); ++mask)
        for (int last = 0; last < n; ++last) {
            if (!(mask >> last & 1))
                continue;
            for (int o = 0; o < 4; ++o) {
                const float here = cost[index(mask, last, o)];
                if (!(here < INFINITY))
                    continue;
                const int exit = m.cells[last].options[o].exit;
                for (int c = 0; c < n; ++c) {
                    if (mask >> c & 1)
                        continue;
                    for (int p = 0; p < 4; ++p) {
                        const CoverOption& opt = m.cells[c].options[p];
                        if (!(opt.length < INFINITY))
                            continue;
                        const float v =
                            here + static_cast<float>(leg(m, exit, opt.entry) + opt.length);
                        const std::size_t to = index(mask | std::size_t{1} << c, c, p);
                        if (v < cost[to])
                            cost[to] = v, parent[to] = static_cast<std::int32_t>(last * 4 + o);
                    }
                }
            }
        }
    const std::size_t full = (std::size_t{1} << n) - 1;
    double best = INFINITY;
    int bestLast = -1, bestOption = -1;
    for (int last = 0; last < n; ++last)
        for (int o = 0; o < 4; ++o) {
            const double v =
                cost[index(full, last, o)] + leg(m, m.cells[last].options[o].exit, m.end);
            if (v < best)
                best = v, bestLast = last, bestOption = o;
        }
    if (bestLast < 0)
        throw TourError("adjacency-ga: no collision-free tour found");
    std::vector<int> order, options(n, 0);
    std::size_t mask = full;
    for (int last = bestLast, o = bestOption; last >= 0;) {
        order.push_back(last);
        options[last] = o;
        const std::int32_t p = parent[index(mask, last, o)];
        mask &= ~(std::size_t{1} << last);
        last = p < 0 ? -1 : p / 4, o = p < 0 ? 0 : p % 4;
    }
    std::reverse(order.begin(), order.end());
    return assembleTour(m, order, options);
}

} // namespace detail

namespace {

// The GA's table of legs holds every pair of cell ends (16 x cells^2 distances, each a
// visibility test across the floor): above this many cells it would take minutes, so the GA
// refuses (a generated 100-room office floor, 636 cells, plans in about 25 s).
constexpr int kGaMaxCells = 800;

} // namespace

Tour planTungLiuGa(const Plan& plan, const std::vector<std::string>& rooms, Vec2 start, Vec2 end,
                   const Options& options) {
    detail::Model model =
        detail::buildModel(plan, rooms, start, end, options, kGaMaxCells, "adjacency-ga");
    model.transits->solve();
    return detail::solveGa(model, options);
}

std::optional<Tour> planTungLiuDp(const Plan& plan, const std::vector<std::string>& rooms,
                                  Vec2 start, Vec2 end, const Options& options, int maxCells) {
    detail::Model model = detail::buildModel(plan, rooms, start, end, options);
    if (static_cast<int>(model.cells.size()) > std::min(maxCells, 24))
        return std::nullopt;
    model.transits->solve();
    return detail::solveDp(model);
}

} // namespace fc::baselines
