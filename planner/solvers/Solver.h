// What every solver answers (SPEC sect. 4): a walk over the corner graph from the start
// node to the end node that traverses one coverage edge of every required cell.
#pragma once

#include "graph/CornerGraph.h"
#include "model/CoveragePath.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fc {

struct Query {
    std::vector<char> required; // per cell: 1 = must be covered
    int startNode = 0;
    int endNode = 0;
    std::uint64_t seed = 1;
    // Optional, one per cell: when the cell came in a plan made before (lower first; the
    // path the editor showed before an edit, see orderHintFrom). The greedy solver also walks
    // the required cells in this order and keeps the cheaper walk, so the heuristic's polish,
    // which starts from greedy's walk, is warm-started too. Empty: none.
    std::vector<double> orderHint;
};

// A walk: nodes[0] = start, nodes.back() = end, edges[i] joins nodes[i] and nodes[i+1].
struct Walk {
    std::vector<int> nodes;
    std::vector<int> edges;
};

// A robot-centre path planned without the corner graph (the paper's baselines), in the
// sweep frame, with the seal excursions the path builder may drop (indices into points).
struct DirectPath {
    CoveragePath path;
    std::vector<Excursion> excursions;
};

struct Solution {
    std::string solver;
    Walk walk;
    std::vector<int> cellOrder; // cells in the order their coverage edge is traversed
    double graphCost = 0.0;     // recomputed by evaluateWalk, never trusted from a solver
    // Set by solvers that plan the path themselves instead of a walk (walk stays empty,
    // graphCost 0: they do not walk the corner graph).
    std::optional<DirectPath> directPath;
    // A proven lower bound on the graph cost of every walk answering the query (negative when
    // unknown); graphCost / lowerBound - 1 is a true optimality gap. provenOptimal: the walk
    // is optimal (then lowerBound == graphCost).
    double lowerBound = -1.0;
    bool provenOptimal = false;
    // Other walks the solver found nearly as cheap (the heuristic's distinct local optima):
    // the graph cost is a proxy for the path's time, so the pipeline builds each as a path
    // and keeps the fastest (see pipeline/PathChoice.h). Empty for most solvers.
    std::vector<Walk> alternatives;
};

struct WalkEvaluation {
    double graphCost = 0.0;
    std::vector<int> cellOrder;
    bool coversAllRequired = false;
    bool connected = false; // consecutive edges/nodes agree, starts and ends right
};

// The single implementation of the graph cost of a walk.
WalkEvaluation evaluateWalk(const CornerGraph& graph, const Query& query, const Walk& walk);

// Thrown when a solver cannot answer (e.g. exact above its size limit, unreachable cells).
class SolverError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Cooperative cancellation and progress for long solves (GUI workers).
struct SolveControl {
    std::function<bool()> cancelled;      // may be empty
    std::function<void(double)> progress; // 0..1, may be empty
};

struct ExactOptions {
    // (covered set x corner) states stored at most (about 40 bytes each); when the search
    // needs more it stops: it refuses, or with bestOnBudget answers the best walk known
    // (the heuristic's) with the proven lower bound reached so far.
    std::size_t maxStates = 25'000'000;
    int maxRequiredCells = 40; // at most 48 (task sets are 48-bit masks)
    bool bestOnBudget = false;
    double timeLimitSeconds = 0.0; // > 0: also stops (as for maxStates) after this long
};

// The time limit of the `exact` solver as the pipeline runs it (CLI, editor): a query it
// cannot prove within this is refused with the gap reached, never left running for minutes.
inline constexpr double kExactTimeLimitSeconds = 60.0;

Solution solveExact(const CornerGraph& graph, const Query& query, const ExactOptions& options = {},
                    const SolveControl& control = {});
Solution solveHeuristic(const CornerGraph& graph, const Query& query,
                        const SolveControl& control = {});
Solution solveGreedy(const CornerGraph& graph, const Query& query);

// How far a learnt solver's walk is refined (switchable, so the learnt policy alone stays
// measurable): None keeps it; Corners keeps the cell order and re-chooses every entry/exit
// corner and transit exactly for that order (an option flip per cell); LocalSearch also
// reorders cells (Or-opt, 2-opt, swaps) under the true graph cost within `workBudget`
// settled search nodes. The cheaper of the given and the refined walk is returned.
enum class OrderRefinement { None, Corners, LocalSearch };
Solution refineCellOrder(const CornerGraph& graph, const Query& query, const Solution& given,
                         OrderRefinement refinement, std::uint64_t workBudget = 200'000,
                         const SolveControl& control = {});
// The heuristic solver's whole search (proxy local search with its kicks, then the true-cost
// polish with its budget), started from the given walk's cell order instead of the
// nearest-neighbour tour; query.seed drives the kicks. Returns the cheaper of the given and
// the searched walk. For a learnt policy's walks: with a good start the same search effort
// reaches better optima (floorcover-dqn-budget).
Solution searchFromWalk(const CornerGraph& graph, const Query& query, const Solution& given,
                        const SolveControl& control = {});

} // namespace fc
