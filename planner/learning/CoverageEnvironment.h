// The reinforcement-learning environment of the paper's Table 1 (graphEnvironment), on the
// corner graph of SPEC sect. 3, with the rewards of SPEC sect. 5.
//
// Choices (where the paper's pseudocode is loose or differs from the SPEC):
// - Overlap scale: the pseudocode's coverage_overlap_scale = 2 is charged on top of the plain
//   cost (1 + 2); SPEC sect. 5 says "x 3 where it overlaps". Both give 3; here the option is
//   the total factor (default 3, per the SPEC). Transit costs are then exactly the SPEC
//   sect. 3 graph cost, so the summed cost rewards of an episode equal
//   -graphCost x costScale / maxEdgeLength of its walk as computed by evaluateWalk for
//   episodeQuery() (with a non-default factor they differ from evaluateWalk by design).
// - A transit never traverses the coverage edge of an uncovered cell (that would cover it);
//   the chosen cell's coverage edge is then traversed at cost 0.
// - Observation channel 1 marks the pixels of every node of a covered cell, so all three
//   channels share the node-indexed layout (pixel = node id, row = id / SIZE, col = id % SIZE).
//   Cells that are not required count as covered (SPEC sect. 3).
// - reset(rng) draws the start among nodes of reachable cells and restricts the episode to
//   the start's graph component: the end corner is drawn there, and only reachable cells of
//   that component are required (cells elsewhere count as covered). Each required cell is
//   pre-covered with a probability drawn uniformly in [0,1) per episode; if that leaves no
//   cell to cover, one random cell is uncovered again.
// - Invalid actions (covered / non-required cell, unreachable corner, out of range) give
//   doubleCoverageReward and leave the state unchanged; actionMask() excludes them.
#pragma once

#include "graph/CornerGraph.h"
#include "learning/GraphState.h"
#include "solvers/Solver.h"

#include <memory>
#include <random>
#include <vector>

namespace fc {

struct EnvironmentOptions {
    double finalReward = 1.0;
    double doubleCoverageReward = -0.5;
    double primaryCellReward = 0.05;
    double transitionCellReward = 0.005;
    double costScale = 0.1;
    double coverageOverlapScale = kOverlapFactor; // total factor (pseudocode: 1 + 2)
    int maxSteps = 0;                             // <= 0: 2 x cell count + 10
    // "Improved" variant: reward = -(added graph cost) / maxEdgeLength x costScale, without the
    // per-cell bonuses; finalReward is still added at the goal.
    bool rewardIsNegativeGraphCost = false;
    // "Improved" variant: two more image channels with graph-level features in the same
    // node layout: 3 = cost of the transit from the current corner to each valid corner,
    // 4 = cost from each corner to the end corner (under the covered set at reset); both in
    // units of the longest edge, divided by kCostChannelScale and capped at 1.
    bool costChannels = false;
    // Graph-level state (GraphState.h): per corner kGraphFeatureCount features instead of the
    // image; the agent then needs the graph network (QNetworkKind::Graph).
    bool graphState = false;
    // Features per corner: kGraphFeatureCount, or kFirstGraphFeatureCount for models trained
    // before features 14-15 existed (they still load and plan).
    int graphFeatures = kGraphFeatureCount;
};

constexpr double kCostChannelScale = 8.0;

struct StepInfo {
    bool valid = false;       // the action covered a cell
    bool reachedGoal = false; // all required cells covered and the robot at the end corner
    bool truncated = false;   // ended by maxSteps
    int coveredCell = -1;     // cell covered by this step, -1 when none
    double graphCost = 0.0;   // graph cost added to the walk (transits, incl. the final one)
    double costReward = 0.0;  // -graphCost / maxEdgeLength x costScale
    double bonusReward = 0.0; // cell rewards and finalReward
};

struct StepResult {
    double reward = 0.0;
    bool done = false;
    StepInfo info;
};

class CoverageEnvironment {
public:
    CoverageEnvironment(const CornerGraph& graph, EnvironmentOptions options = {});

    // Training episode: random start, end and pre-covered set (see the header comment).
    std::vector<float> reset(std::mt19937_64& rng);
    // Inference: the query's start, end and required cells. Throws std::invalid_argument for
    // bad nodes or when the end or a required cell lies outside the start's graph component.
    std::vector<float> reset(const Query& query);

    // Throws std::logic_error when the episode is already done.
    StepResult step(int action);

    // Image state: channelCount() x SIZE x SIZE, channel-major: current corner, covered cells'
    // nodes, end corner (and the cost channels when enabled). Graph state: actionCount() x
    // channelCount() per-corner features, node-major (GraphState.h).
    std::vector<float> observation() const;
    int channelCount() const { return channelCountFor(options_); }
    static int channelCountFor(const EnvironmentOptions& options) {
        return options.graphState ? options.graphFeatures : options.costChannels ? 5 : 3;
    }
    std::size_t observationSize() const;
    // Per node: true for a corner of an uncovered required cell reachable by a transit.
    std::vector<char> actionMask() const;

    int size() const { return size_; }
    int actionCount() const { return static_cast<int>(graph_->nodes.size()); }
    int maxSteps() const { return maxSteps_; }
    int stepCount() const { return steps_; }
    bool done() const { return done_; }
    int currentNode() const { return current_; }
    int startNode() const { return start_; }
    int endNode() const { return end_; }
    const std::vector<char>& covered() const { return covered_; }
    // Per node: the cheapest transit cost from the current corner (infinity: none).
    const std::vector<double>& transitCosts() const { return transitCost_; }
    const Walk& walk() const { return walk_; }
    // The query under which evaluateWalk prices this episode's walk exactly as the rewards
    // did: required = the cells uncovered at reset.
    Query episodeQuery() const;
    const EnvironmentOptions& options() const { return options_; }

private:
    void begin();
    void computeTransits(); // cheapest transits from current_ under the covered set
    void appendTransitTo(int node);
    std::vector<char> componentOf(int node) const;
    double costReward(double graphCost) const;
    bool isValidAction(int node) const; // a corner of an uncovered required cell, reachable
    std::vector<float> imageObservation() const;

    const CornerGraph* graph_;
    EnvironmentOptions options_;
    int size_ = 0;
    int maxSteps_ = 0;
    int start_ = 0, end_ = 0, current_ = 0, steps_ = 0;
    bool done_ = true;
    std::vector<char> covered_;        // per cell (non-required cells count as covered)
    std::vector<char> initialCovered_; // at reset
    Walk walk_;
    std::vector<double> transitCost_; // node -> cheapest transit cost from current_
    std::vector<double> costToEnd_;   // node -> transit cost to end_ (covered set at reset)
    std::vector<int> parentEdge_;     // node -> last edge of that transit, -1 at the source
    std::shared_ptr<const GraphStateTables> graphTables_; // graph state only
};

} // namespace fc
