// Ant Colony System: ants build tours from waypoint 0 over candidate lists (the cheapest
// moves of each waypoint), choosing by pheromone x (1/cost)^beta; the pheromone of used
// moves decays locally, the best tour so far deposits 1/cost.
#include "tiling/RandomSource.h"
#include "tiling/WaypointIndex.h"
#include "tiling/WaypointOrder.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fc::tiling {
namespace {

struct Colony {
    const OrderingProblem& problem;
    AntColonyOptions options;
    int n;
    std::vector<std::vector<int>> candidates;
    std::vector<std::vector<double>> attractiveness; // (1/cost)^beta per candidate move
    std::vector<std::vector<double>> pheromone;
    double initialPheromone = 0.0;
    std::vector<double> scratch; // move values, reused between steps

    Colony(const OrderingProblem& p, const AntColonyOptions& o, const WaypointIndex& index,
           double referenceCost)
        : problem(p), options(o), n(p.size()) {
        const int count = std::min(options.candidates, n - 1);
        initialPheromone = 1.0 / (n * referenceCost);
        for (int i = 0; i < n; ++i) {
            candidates.push_back(index.cheapestMoves(i, count));
            std::vector<double> weights;
            for (int j : candidates.back())
                weights.push_back(
                    std::pow(1.0 / std::max(problem.cost(i, j), 1e-12), options.beta));
            attractiveness.push_back(weights);
            pheromone.emplace_back(candidates.back().size(), initialPheromone);
        }
    }

    int candidateSlot(int from, int to) const {
        const auto& list = candidates[from];
        const auto it = std::find(list.begin(), list.end(), to);
        return it == list.end() ? -1 : static_cast<int>(it - list.begin());
    }

    // Next waypoint among the unvisited candidates, or -1 when all are visited.
    int chooseMove(int from, const std::vector<char>& visited, RandomSource& random) {
        const auto& list = candidates[from];
        std::vector<double>& values = scratch;
        values.assign(list.size(), 0.0);
        double sum = 0.0;
        int best = -1;
        for (std::size_t c = 0; c < list.size(); ++c) {
            if (visited[list[c]])
                continue;
            values[c] = pheromone[from][c] * attractiveness[from][c];
            sum += values[c];
            if (best < 0 || values[c] > values[best])
                best = static_cast<int>(c);
        }
        if (best < 0)
            return -1;
        if (random.uniform() >= options.q0) { // explore: roulette wheel
            double pick = random.uniform() * sum;
            for (std::size_t c = 0; c < list.size(); ++c) {
                if (visited[list[c]] || values[c] <= 0.0)
                    continue;
                best = static_cast<int>(c);
                pick -= values[c];
                if (pick <= 0.0)
                    break;
            }
        }
        pheromone[from][best] =
            (1.0 - options.rho) * pheromone[from][best] + options.rho * initialPheromone;
        return list[best];
    }

    Tour buildTour(const WaypointIndex& fullIndex, RandomSource& random) {
        WaypointIndex remaining = fullIndex; // for moves beyond the candidate lists
        std::vector<char> visited(n, 0);
        Tour tour{0};
        visited[0] = 1;
        remaining.remove(0);
        while (static_cast<int>(tour.size()) < n) {
            int next = chooseMove(tour.back(), visited, random);
            if (next < 0)
                next = remaining.cheapestFrom(tour.back());
            visited[next] = 1;
            remaining.remove(next);
            tour.push_back(next);
        }
        return tour;
    }

    void deposit(const Tour& tour, double cost) {
        for (std::size_t k = 0; k < tour.size(); ++k) {
            const int from = tour[k], to = tour[(k + 1) % tour.size()];
            const int slot = candidateSlot(from, to);
            if (slot >= 0)
                pheromone[from][slot] =
                    (1.0 - options.rho) * pheromone[from][slot] + options.rho / cost;
        }
    }
};

} // namespace

Tour orderAntColony(const OrderingProblem& problem, const AntColonyOptions& options) {
    const int n = problem.size();
    Tour best = orderGreedy(problem);
    if (n <= 3)
        return best;
    // The greedy tour only sets the initial pheromone (as in ACS); the result is the best
    // tour an ant built.
    const WaypointIndex index(problem);
    Colony colony(problem, options, index, tourCost(problem, best));
    double bestCost = INFINITY;
    RandomSource random(options.seed);
    // About 3e5 ant steps per ant in all: hundreds of iterations on small floors, tens on
    // large ones, so that the run time grows roughly linearly with the floor.
    const int iterations =
        options.iterations > 0 ? options.iterations : std::clamp(300000 / n, 10, 300);
    for (int it = 0; it < iterations; ++it) {
        if (options.cancelled && options.cancelled())
            throw OrderingCancelled();
        for (int ant = 0; ant < options.ants; ++ant) {
            Tour tour = colony.buildTour(index, random);
            const double cost = tourCost(problem, tour);
            if (cost < bestCost) {
                bestCost = cost;
                best = std::move(tour);
            }
        }
        colony.deposit(best, bestCost);
    }
    return best;
}

} // namespace fc::tiling
