// Ordering the tiles' waypoints (seeds/001 sect. 4): a closed tour through every waypoint
// whose cost is the sum of the transition energies (the paper's Eq. 5), by the paper's
// baselines (zigzag, spiral, ant colony), greedy, a genetic algorithm, and Held-Karp for
// small sets. Tours start at waypoint 0 and return to it.
#pragma once

#include "tiling/TilingRobot.h"

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fc::tiling {

using Tour = std::vector<int>;

struct OrderingProblem {
    TilingRobotProfile robot;
    std::vector<Pose> poses;
    double blockLeg() const { return robot.blockLeg; }
    int size() const { return static_cast<int>(poses.size()); }
    double cost(int from, int to) const {
        return transitionEnergy(robot, poses[from], poses[to]).total();
    }
};

bool isTour(const Tour& tour, int size); // a permutation of 0..size-1 starting at 0
double tourCost(const OrderingProblem& problem, const Tour& tour);
EnergyTerms tourEnergy(const OrderingProblem& problem, const Tour& tour);
double tourLength(const OrderingProblem& problem, const Tour& tour); // waypoint to waypoint
int tourShapeChanges(const OrderingProblem& problem, const Tour& tour);
// The same cyclic tour, rotated to start at waypoint 0.
Tour startingAtZero(Tour tour);

// Boustrophedon over rows of waypoints 2 legs high, alternating direction.
Tour orderZigzag(const OrderingProblem& problem);
// Rings of waypoints 2 legs wide from the outside in, each counter-clockwise.
Tour orderSpiral(const OrderingProblem& problem);
// The cheapest unvisited waypoint next.
Tour orderGreedy(const OrderingProblem& problem);

// Ant Colony System (Dorigo and Gambardella 1997) on candidate lists of the cheapest moves.
struct AntColonyOptions {
    int ants = 10;
    int iterations = 0; // 0: scaled to the problem size (see AntColony.cpp)
    int candidates = 12;
    double beta = 3.0; // weight of the move's cost against the pheromone
    double rho = 0.1;  // evaporation
    double q0 = 0.9;   // probability of the best move instead of a random one
    std::uint64_t seed = 1;
    std::function<bool()> cancelled; // may be empty; checked every iteration
};
Tour orderAntColony(const OrderingProblem& problem, const AntColonyOptions& options = {});

// Generational GA: order crossover, inversion and swap mutations, tournament selection,
// elitism; the first individuals are the greedy and zigzag tours.
struct GeneticOptions {
    int population = 40;
    int generations = 0; // 0: scaled to the problem size (see Genetic.cpp)
    double mutationRate = 0.3;
    std::uint64_t seed = 1;
    std::function<bool()> cancelled; // may be empty; checked every generation
};
Tour orderGenetic(const OrderingProblem& problem, const GeneticOptions& options = {});

// Held-Karp dynamic programme: the optimal tour. Refuses (InputError) above kExactLimit.
constexpr int kExactLimit = 16;
Tour orderExact(const OrderingProblem& problem);

// Energy-aware 2-opt and Or-opt on each waypoint's 8 cheapest moves until no move helps
// (LocalSearch.cpp); returns the tour rotated to start at 0. Used by "aco+2opt" and "ppo".
Tour polishTour(const OrderingProblem& problem, Tour tour);

// Methods from outside the core (e.g. "ppo", which needs LibTorch) register themselves here.
using OrderingMethod = std::function<Tour(const OrderingProblem&, std::uint64_t seed)>;
void registerOrderingMethod(const std::string& name, OrderingMethod method);

// The built-in methods, then the registered ones.
std::vector<std::string> orderingSolverNames();
// Thrown when the caller's cancellation callback returns true.
class OrderingCancelled : public std::runtime_error {
public:
    OrderingCancelled() : std::runtime_error("tiling cancelled") {}
};

// Throws InputError for an unknown solver name. `cancelled` (may be empty) stops aco and ga
// between iterations (OrderingCancelled).
Tour solveOrdering(const std::string& solver, const OrderingProblem& problem, std::uint64_t seed,
                   const std::function<bool()>& cancelled = {});

} // namespace fc::tiling
