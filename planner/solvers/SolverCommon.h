// Internal to the graph solvers: the query turned into "tasks" (required cells) with the
// ways each can be covered, validation shared by every solver, and how a walk becomes a
// Solution.
#pragma once

#include "solvers/Solver.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace fc::solver_detail {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One way to cover a cell: stand at `entry`, traverse coverage edge `edge`, end at `exit`.
struct CoverOption {
    int entry = -1;
    int exit = -1;
    int edge = -1;
};

// Nodes reachable from `start` over every edge (costs aside, any edge can be walked).
std::vector<char> reachableFrom(const CornerGraph& graph, int start);

// A cell the walk must cover. Unreachable cells (no stripe fits) are never required.
bool isRequiredCell(const CornerGraph& graph, const Query& query, int cell);

struct Problem {
    const CornerGraph* graph = nullptr;
    int startNode = 0;
    int endNode = 0;
    std::uint64_t seed = 1;
    std::vector<int> taskCells;  // task index -> cell id, in cell id order
    std::vector<int> taskOfCell; // cell id -> task index, -1 when not required
    // Per task; options 2i and 2i+1 are the two directions of one coverage edge.
    std::vector<std::vector<CoverOption>> options;
    int reachableNodeCount = 0; // nodes in the start node's connected component

    int taskCount() const { return static_cast<int>(taskCells.size()); }
};

// Validates the query (node ids, sizes, every required cell and the end reachable from the
// start) and lists the tasks. Throws SolverError naming the solver and the problem.
Problem makeProblem(const CornerGraph& graph, const Query& query, const char* solverName);

// Evaluates the walk (the one graph cost) and packs it; a walk that is not connected or
// misses a required cell is a solver bug and throws.
Solution finishSolution(const CornerGraph& graph, const Query& query, const char* solverName,
                        Walk walk);

// The task order of a given walk's cell order (each required cell's first cover); throws
// SolverError when it misses a required cell.
std::vector<int> taskOrderOf(const Problem& problem, const Solution& given);

void throwIfCancelled(const SolveControl& control, const char* solverName);
void reportProgress(const SolveControl& control, double fraction);

// Seeded pseudo-random numbers that are identical on every platform and standard library
// (std:: distributions are not), so a seed always gives the same walk.
class SeededRandom {
public:
    explicit SeededRandom(std::uint64_t seed);
    std::uint64_t next();
    int below(int bound); // uniform in [0, bound), bound > 0

private:
    std::uint64_t state_;
};

} // namespace fc::solver_detail
