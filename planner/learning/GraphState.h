// The graph-level state of the Double-DQN planner (issue 3's lever, docs/dqn.md): one feature
// vector per corner of the corner graph instead of the SIZE x SIZE image, so that the network
// (a shared per-corner MLP, learning/torch/DqnNetwork) costs O(corners), not O(SIZE^2 x
// channels), and generalises across start and end corners.
//
// Features of corner a (kGraphFeatureCount, all in [0, 1] or small multiples; costs are in
// units of kGraphCostUnit longest edges, capped at kGraphCostCap):
//   0 valid: a corner of an uncovered required cell reachable by a transit (the action mask)
//   1 transit cost from the current corner to a (valid corners, else 0)
//   2 cost to the end corner from exit(a), the far end of a's coverage edge, where the robot
//     stands after covering a's cell (costs to the end under the covered set at reset;
//     valid corners, else 0)
//   3 a is the end corner            4 a is the current corner
//   5 uncovered required cells / required cells at reset (the same for every corner)
//   6 1 when a single cell is left (the same for every corner)
//   7, 8 a's position minus the current corner's, divided by the floor's bounding-box diagonal
//   9 straight-line distance from exit(a) to the nearest centre of another uncovered cell
//     (0 when none is left besides a's)
//  10 uncovered cells adjacent to a's cell (joined by an edge), / 4, capped at 1
//  11 uncovered required cells in a's room / required cells of that room at reset
//  12 a's cell is in the current corner's room
//  13 uncovered cells other than a's whose centre lies within 2 longest edges of exit(a), / 8,
//     capped at 1
//  14 transit cost to a minus the cheapest transit to any valid corner, in longest edges
//     (finer than 1), capped at kGraphCostCap: the greedy choice's margin, which the coarse
//     feature 1 hides on large floors
//  15 a is a cheapest valid corner (the greedy solver's choice)
// Layout: node-major, features of node 0 first. Features 1, 2 and 9-15 are computed for
// valid corners only (0 elsewhere): the network reads only the rows of valid corners.
#pragma once

#include "graph/CornerGraph.h"

#include <vector>

namespace fc {

constexpr int kGraphFeatureCount = 16;
constexpr int kFirstGraphFeatureCount = 14; // model files of the first version
constexpr double kGraphCostUnit = 8.0;      // longest edges
constexpr double kGraphCostCap = 4.0;

// What depends on the graph only, computed once per environment.
struct GraphStateTables {
    explicit GraphStateTables(const CornerGraph& graph);
    std::vector<int> exitNode;                    // node -> other end of its coverage edge
    std::vector<std::vector<int>> cellNeighbours; // cells joined to a cell by an edge
    std::vector<Vec2> cellCentre;                 // mean of the cell's corners
    double diagonal = 1.0;                        // of the nodes' bounding box
};

// The episode's state, as CoverageEnvironment keeps it.
struct GraphStateInput {
    int current = 0;
    int end = 0;
    const std::vector<char>* covered = nullptr;        // per cell, now
    const std::vector<char>* initialCovered = nullptr; // per cell, at reset
    const std::vector<double>* transitCost = nullptr;  // per node, from current (inf: none)
    const std::vector<double>* costToEnd = nullptr;    // per node, to end (inf: none)
};

// nodes x featureCount features (see the header comment): the first featureCount of them,
// kGraphFeatureCount or kFirstGraphFeatureCount.
std::vector<float> graphStateFeatures(const CornerGraph& graph, const GraphStateTables& tables,
                                      const GraphStateInput& state,
                                      int featureCount = kGraphFeatureCount);

} // namespace fc
