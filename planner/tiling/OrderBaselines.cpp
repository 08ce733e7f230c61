// Tour evaluation, the constructive orders (zigzag, spiral, greedy), Held-Karp, dispatch.
#include "model/Plan.h"
#include "tiling/WaypointIndex.h"
#include "tiling/WaypointOrder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace fc::tiling {

bool isTour(const Tour& tour, int size) {
    if (static_cast<int>(tour.size()) != size || (size > 0 && tour[0] != 0))
        return false;
    std::vector<char> seen(size, 0);
    for (int w : tour) {
        if (w < 0 || w >= size || seen[w])
            return false;
        seen[w] = 1;
    }
    return true;
}

EnergyTerms tourEnergy(const OrderingProblem& problem, const Tour& tour) {
    EnergyTerms sum;
    for (std::size_t k = 0; k + 1 < tour.size(); ++k)
        sum += transitionEnergy(problem.robot, problem.poses[tour[k]], problem.poses[tour[k + 1]]);
    if (tour.size() > 1) // Eq. 5 closes the tour
        sum += transitionEnergy(problem.robot, problem.poses[tour.back()], problem.poses[tour[0]]);
    return sum;
}

double tourCost(const OrderingProblem& problem, const Tour& tour) {
    double sum = 0.0;
    for (std::size_t k = 0; k < tour.size() && tour.size() > 1; ++k)
        sum += problem.cost(tour[k], tour[(k + 1) % tour.size()]);
    return sum;
}

double tourLength(const OrderingProblem& problem, const Tour& tour) {
    double sum = 0.0;
    for (std::size_t k = 0; k < tour.size() && tour.size() > 1; ++k)
        sum += distance(problem.poses[tour[k]].waypoint(),
                        problem.poses[tour[(k + 1) % tour.size()]].waypoint());
    return sum;
}

int tourShapeChanges(const OrderingProblem& problem, const Tour& tour) {
    int changes = 0;
    for (std::size_t k = 0; k < tour.size() && tour.size() > 1; ++k)
        changes += problem.poses[tour[k]].shape != problem.poses[tour[(k + 1) % tour.size()]].shape;
    return changes;
}

Tour startingAtZero(Tour tour) {
    const auto zero = std::find(tour.begin(), tour.end(), 0);
    std::rotate(tour.begin(), zero, tour.end());
    return tour;
}

namespace {

BoundingBox waypointBounds(const OrderingProblem& problem) {
    BoundingBox box;
    for (const Pose& pose : problem.poses)
        box.add(pose.waypoint());
    return box;
}

// Waypoints sorted by (key, then position along the key's row), as a tour from 0.
template <class Key> Tour sortedTour(const OrderingProblem& problem, Key key) {
    Tour tour(problem.size());
    std::iota(tour.begin(), tour.end(), 0);
    std::stable_sort(tour.begin(), tour.end(), [&](int a, int b) { return key(a) < key(b); });
    return startingAtZero(tour);
}

} // namespace

Tour orderZigzag(const OrderingProblem& problem) {
    const BoundingBox box = waypointBounds(problem);
    const double band = 2.0 * problem.blockLeg();
    return sortedTour(problem, [&](int w) {
        const Vec2 p = problem.poses[w].waypoint();
        const int row = static_cast<int>(std::floor((p.y - box.minY) / band));
        return std::make_pair(row, row % 2 == 0 ? p.x : -p.x);
    });
}

Tour orderSpiral(const OrderingProblem& problem) {
    const BoundingBox box = waypointBounds(problem);
    const double band = 2.0 * problem.blockLeg();
    const Vec2 centre{(box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2};
    constexpr double kPi = 3.14159265358979323846;
    return sortedTour(problem, [&](int w) {
        const Vec2 p = problem.poses[w].waypoint();
        const double inset =
            std::min({p.x - box.minX, box.maxX - p.x, p.y - box.minY, box.maxY - p.y});
        const int ring = static_cast<int>(std::floor(inset / band));
        // Counter-clockwise from the lower-left corner of each ring.
        const double angle = std::atan2(p.y - centre.y, p.x - centre.x);
        return std::make_pair(ring, std::fmod(angle + 3 * kPi / 4 + 2 * kPi, 2 * kPi));
    });
}

Tour orderGreedy(const OrderingProblem& problem) {
    Tour tour;
    if (problem.size() == 0)
        return tour;
    WaypointIndex index(problem);
    int current = 0;
    while (current >= 0) {
        tour.push_back(current);
        index.remove(current);
        current = index.cheapestFrom(current);
    }
    return tour;
}

Tour orderExact(const OrderingProblem& problem) {
    const int n = problem.size();
    if (n > kExactLimit)
        throw InputError("exact ordering is limited to " + std::to_string(kExactLimit) +
                         " waypoints (this floor has " + std::to_string(n) + ")");
    if (n <= 2) {
        Tour tour(n);
        std::iota(tour.begin(), tour.end(), 0);
        return tour;
    }
    // best[mask][j]: cheapest path from 0 through the waypoints of mask (bits for 1..n-1)
    // ending at j.
    const int m = n - 1;
    const std::size_t masks = std::size_t{1} << m;
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> best(masks * m, inf);
    std::vector<signed char> previous(masks * m, -1);
    for (int j = 0; j < m; ++j)
        best[(std::size_t{1} << j) * m + j] = problem.cost(0, j + 1);
    for (std::size_t mask = 1; mask < masks; ++mask)
        for (int j = 0; j < m; ++j) {
            const double here = best[mask * m + j];
            if (!((mask >> j) & 1) || here == inf)
                continue;
            for (int k = 0; k < m; ++k) {
                if ((mask >> k) & 1)
                    continue;
                const std::size_t next = (mask | std::size_t{1} << k) * m + k;
                const double c = here + problem.cost(j + 1, k + 1);
                if (c < best[next]) {
                    best[next] = c;
                    previous[next] = static_cast<signed char>(j);
                }
            }
        }
    const std::size_t full = masks - 1;
    int last = 0;
    double bestTotal = inf;
    for (int j = 0; j < m; ++j) {
        const double total = best[full * m + j] + problem.cost(j + 1, 0);
        if (total < bestTotal) {
            bestTotal = total;
            last = j;
        }
    }
    Tour reversed;
    std::size_t mask = full;
    for (int j = last; j >= 0;) {
        reversed.push_back(j + 1);
        const int before = previous[mask * m + j];
        mask &= ~(std::size_t{1} << j);
        j = before;
    }
    Tour tour{0};
    tour.insert(tour.end(), reversed.rbegin(), reversed.rend());
    return tour;
}

namespace {

std::map<std::string, OrderingMethod>& registeredMethods() {
    static std::map<std::string, OrderingMethod> methods;
    return methods;
}

} // namespace

void registerOrderingMethod(const std::string& name, OrderingMethod method) {
    registeredMethods()[name] = std::move(method);
}

std::vector<std::string> orderingSolverNames() {
    std::vector<std::string> names{"zigzag", "spiral", "greedy", "aco", "aco+2opt", "ga", "exact"};
    for (const auto& entry : registeredMethods())
        names.push_back(entry.first);
    return names;
}

Tour solveOrdering(const std::string& solver, const OrderingProblem& problem, std::uint64_t seed,
                   const std::function<bool()>& cancelled) {
    if (solver == "zigzag")
        return orderZigzag(problem);
    if (solver == "spiral")
        return orderSpiral(problem);
    if (solver == "greedy")
        return orderGreedy(problem);
    if (solver == "aco") {
        AntColonyOptions options;
        options.seed = seed;
        options.cancelled = cancelled;
        return orderAntColony(problem, options);
    }
    if (solver == "aco+2opt") {
        AntColonyOptions options;
        options.seed = seed;
        options.cancelled = cancelled;
        return polishTour(problem, orderAntColony(problem, options));
    }
    if (solver == "ga") {
        GeneticOptions options;
        options.seed = seed;
        options.cancelled = cancelled;
        return orderGenetic(problem, options);
    }
    if (solver == "exact")
        return orderExact(problem);
    const auto registered = registeredMethods().find(solver);
    if (registered != registeredMethods().end())
        return registered->second(problem, seed);
    std::string known;
    for (const std::string& name : orderingSolverNames())
        known += (known.empty() ? "" : ", ") + name;
    throw InputError("unknown tiling solver \"" + solver + "\" (" + known + ")");
}

} // namespace fc::tiling
