// Generational genetic algorithm over tours that start at waypoint 0: tournament
// selection, order crossover (OX1), inversion or swap mutation, two elites kept.
#include "tiling/RandomSource.h"
#include "tiling/WaypointOrder.h"

#include <algorithm>
#include <numeric>

namespace fc::tiling {
namespace {

struct Individual {
    Tour tour;
    double cost = 0.0;
};

// A random position among 1..n-1 (waypoint 0 stays first).
int innerPosition(RandomSource& random, int n) {
    return 1 + random.below(n - 1);
}

Tour orderCrossover(const Tour& first, const Tour& second, RandomSource& random) {
    const int n = static_cast<int>(first.size());
    int a = innerPosition(random, n), b = innerPosition(random, n);
    if (a > b)
        std::swap(a, b);
    Tour child(n, -1);
    std::vector<char> taken(n, 0);
    child[0] = 0;
    taken[0] = 1;
    for (int k = a; k <= b; ++k) {
        child[k] = first[k];
        taken[first[k]] = 1;
    }
    // The rest in the second parent's order, starting after the copied slice.
    int write = b + 1 < n ? b + 1 : 1;
    for (int step = 0; step < n - 1; ++step) {
        const int gene = second[1 + (b + step) % (n - 1)];
        if (taken[gene])
            continue;
        child[write] = gene;
        taken[gene] = 1;
        write = write + 1 < n ? write + 1 : 1;
    }
    return child;
}

void mutate(Tour& tour, RandomSource& random) {
    const int n = static_cast<int>(tour.size());
    int a = innerPosition(random, n), b = innerPosition(random, n);
    if (a > b)
        std::swap(a, b);
    if (random.uniform() < 0.5)
        std::reverse(tour.begin() + a, tour.begin() + b + 1);
    else
        std::swap(tour[a], tour[b]);
}

const Individual& tournament(const std::vector<Individual>& population, RandomSource& random) {
    const Individual* best = &population[random.below(static_cast<int>(population.size()))];
    for (int k = 1; k < 3; ++k) {
        const Individual& other = population[random.below(static_cast<int>(population.size()))];
        if (other.cost < best->cost)
            best = &other;
    }
    return *best;
}

} // namespace

Tour orderGenetic(const OrderingProblem& problem, const GeneticOptions& options) {
    const int n = problem.size();
    if (n <= 3)
        return orderGreedy(problem);
    RandomSource random(options.seed);
    const int size = std::max(4, options.population);
    std::vector<Individual> population;
    auto add = [&](Tour tour) { population.push_back({tour, tourCost(problem, tour)}); };
    const Tour greedy = orderGreedy(problem);
    add(greedy);
    add(orderZigzag(problem));
    add(orderSpiral(problem));
    while (static_cast<int>(population.size()) < size) {
        Tour tour = greedy;
        if (population.size() % 2 == 0) { // half perturbed greedy tours, half random ones
            for (int k = 0; k < 3; ++k)
                mutate(tour, random);
        } else {
            for (int k = n - 1; k > 1; --k)
                std::swap(tour[k], tour[1 + random.below(k)]);
        }
        add(tour);
    }
    // About 2e7 move costs in all, so that the run time grows roughly linearly with n.
    const int generations =
        options.generations > 0 ? options.generations : std::clamp(20000000 / (size * n), 20, 500);
    const auto byCost = [](const Individual& a, const Individual& b) { return a.cost < b.cost; };
    for (int g = 0; g < generations; ++g) {
        if (options.cancelled && options.cancelled())
            throw OrderingCancelled();
        std::sort(population.begin(), population.end(), byCost);
        std::vector<Individual> next(population.begin(), population.begin() + 2);
        while (static_cast<int>(next.size()) < size) {
            Tour child = orderCrossover(tournament(population, random).tour,
                                        tournament(population, random).tour, random);
            if (random.uniform() < options.mutationRate)
                mutate(child, random);
            next.push_back({child, tourCost(problem, child)});
        }
        population = std::move(next);
    }
    return std::min_element(population.begin(), population.end(), byCost)->tour;
}

} // namespace fc::tiling
