// The DRL environment of the paper's Table 1 (SPEC sect. 5) on a hand-built corner graph,
// checked against hand-computed rewards and against evaluateWalk.
#include "TestGraphs.h"
#include "learning/CoverageEnvironment.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace fc;
using namespace fc::test;

namespace {

Query allRequired(int start, int end) {
    Query q;
    q.required = {1, 1, 1};
    q.startNode = start;
    q.endNode = end;
    return q;
}

constexpr double kScale = 0.1 / 9.0; // costScale / maxEdgeLength

} // namespace

TEST(CoverageEnvironment, ImageSizeAndChannels) {
    const CornerGraph g = threeCells();
    ASSERT_DOUBLE_EQ(g.maxEdgeLength, 9.0);
    CoverageEnvironment env(g);
    EXPECT_EQ(env.size(), 4); // ceil(sqrt(10))
    EXPECT_EQ(env.actionCount(), 10);
    EXPECT_EQ(env.maxSteps(), 2 * 3 + 10);
    const std::vector<float> image = env.reset(allRequired(0, 9));
    ASSERT_EQ(image.size(), 3u * 16u);
    for (std::size_t i = 0; i < image.size(); ++i) {
        const bool hot = i == 0 || i == 32 + 9; // current node 0; end node 9 at row 2, col 1
        EXPECT_EQ(image[i], hot ? 1.0f : 0.0f) << "pixel " << i;
    }
    env.step(4); // cover the transition cell: its nodes 4 and 5 light up in channel 1
    const std::vector<float> after = env.observation();
    EXPECT_EQ(after[5], 1.0f); // current corner: the transition cell's top
    EXPECT_EQ(after[0], 0.0f);
    for (int node = 0; node < 10; ++node)
        EXPECT_EQ(after[16 + node], (node == 4 || node == 5) ? 1.0f : 0.0f) << node;
    EXPECT_EQ(after[32 + 9], 1.0f);
}

TEST(CoverageEnvironment, FullEpisodeRewardsByHand) {
    const CornerGraph g = threeCells();
    CoverageEnvironment env(g);
    env.reset(allRequired(0, 9));

    // Cover cell 0 from where the robot stands: no transit, lands on RB (node 2).
    StepResult r = env.step(0);
    EXPECT_TRUE(r.info.valid);
    EXPECT_FALSE(r.done);
    EXPECT_DOUBLE_EQ(r.reward, 0.05);
    EXPECT_EQ(env.currentNode(), 2);

    // Adjacent transition cell: transit 2 -> 4 (length 1), cover bottom -> top.
    r = env.step(4);
    EXPECT_NEAR(r.reward, -1.0 * kScale + 0.005, 1e-12);
    EXPECT_NEAR(r.info.costReward, -1.0 * kScale, 1e-12);
    EXPECT_EQ(env.currentNode(), 5);

    // A covered cell: -0.5, nothing moves.
    const std::vector<float> before = env.observation();
    r = env.step(3);
    EXPECT_FALSE(r.info.valid);
    EXPECT_DOUBLE_EQ(r.reward, -0.5);
    EXPECT_EQ(env.currentNode(), 5);
    EXPECT_EQ(env.observation(), before);
    EXPECT_EQ(env.walk().nodes.size(), 4u);

    // Last cell from LT (transit 5 -> 7, length 1), lands on RB (node 8); then the goal:
    // transit RB -> RT along the parallel contour of a covered cell, 3 x 2 = 6.
    r = env.step(7);
    EXPECT_TRUE(r.done);
    EXPECT_TRUE(r.info.reachedGoal);
    EXPECT_DOUBLE_EQ(r.info.graphCost, 7.0);
    EXPECT_NEAR(r.reward, -1.0 * kScale + 0.05 + 1.0 - 6.0 * kScale, 1e-12);
    EXPECT_EQ(env.currentNode(), 9);
    EXPECT_EQ(env.walk().nodes, (std::vector<int>{0, 2, 4, 5, 7, 8, 9}));

    const WalkEvaluation eval = evaluateWalk(g, env.episodeQuery(), env.walk());
    EXPECT_TRUE(eval.connected);
    EXPECT_TRUE(eval.coversAllRequired);
    EXPECT_DOUBLE_EQ(eval.graphCost, 8.0);
    EXPECT_EQ(eval.cellOrder, (std::vector<int>{0, 1, 2}));
    EXPECT_TRUE(env.actionMask() == std::vector<char>(10, 0));
    EXPECT_THROW(env.step(0), std::logic_error);
}

TEST(CoverageEnvironment, MaskExcludesCoveredAndNonRequiredCells) {
    const CornerGraph g = threeCells();
    CoverageEnvironment env(g);
    Query q = allRequired(0, 9);
    q.required[2] = 0; // not required: counts as covered
    const std::vector<float> image = env.reset(q);
    for (int node = 0; node < 10; ++node)
        EXPECT_EQ(image[16 + node], node >= 6 ? 1.0f : 0.0f) << node;
    EXPECT_EQ(env.actionMask(), (std::vector<char>{1, 1, 1, 1, 1, 1, 0, 0, 0, 0}));
    env.step(1); // cover cell 0 from LT (transit 0 -> 1: parallel contour, 3 x 2)
    EXPECT_EQ(env.currentNode(), 3);
    EXPECT_EQ(env.actionMask(), (std::vector<char>{0, 0, 0, 0, 1, 1, 0, 0, 0, 0}));
    const StepResult r = env.step(7); // non-required cell: invalid
    EXPECT_DOUBLE_EQ(r.reward, -0.5);
    EXPECT_EQ(env.currentNode(), 3);
}

TEST(CoverageEnvironment, TransitNeverCrossesAnUncoveredCell) {
    // From cell 0 the far cell is reachable only through the uncovered transition cell, whose
    // coverage edge is closed to transits: the far cell is masked until it is covered.
    CornerGraph g;
    primary(g, 0, 2, 0, 2, 2);
    transition(g, 3, 0, 2);
    primary(g, 4, 7, 0, 2, 3);
    join(g, {2}, {4});
    join(g, {5}, {6, 7});
    CoverageEnvironment env(g);
    env.reset(allRequired(0, 9));
    // The transition cell's top (node 5) too: only its own coverage edge leads there.
    EXPECT_EQ(env.actionMask(), (std::vector<char>{1, 1, 1, 1, 1, 0, 0, 0, 0, 0}));
    const StepResult r = env.step(6);
    EXPECT_FALSE(r.info.valid);
    EXPECT_DOUBLE_EQ(r.reward, -0.5);
    EXPECT_EQ(env.currentNode(), 0);
    env.step(4); // transit 0 -> 1 -> 3 -> 2 is dearer than 0 -> 2 along the floor (2)
    EXPECT_EQ(env.walk().nodes, (std::vector<int>{0, 2, 4, 5}));
    EXPECT_EQ(env.actionMask(), (std::vector<char>{1, 1, 1, 1, 0, 0, 1, 1, 1, 1}));
}

TEST(CoverageEnvironment, MaxStepsEndsEpisode) {
    const CornerGraph g = threeCells();
    EnvironmentOptions options;
    options.maxSteps = 2;
    CoverageEnvironment env(g, options);
    env.reset(allRequired(0, 9));
    EXPECT_FALSE(env.step(0).done);
    const StepResult r = env.step(1); // covered: invalid, and the step limit is reached
    EXPECT_TRUE(r.done);
    EXPECT_TRUE(r.info.truncated);
    EXPECT_FALSE(r.info.reachedGoal);
    EXPECT_DOUBLE_EQ(r.reward, -0.5);
    EXPECT_TRUE(env.done());
}

TEST(CoverageEnvironment, NegativeGraphCostVariant) {
    const CornerGraph g = threeCells();
    EnvironmentOptions options;
    options.rewardIsNegativeGraphCost = true;
    CoverageEnvironment env(g, options);
    env.reset(allRequired(0, 9));
    EXPECT_DOUBLE_EQ(env.step(0).reward, 0.0);
    EXPECT_NEAR(env.step(4).reward, -1.0 * kScale, 1e-12);
    EXPECT_NEAR(env.step(7).reward, -7.0 * kScale + 1.0, 1e-12);
}

TEST(CoverageEnvironment, CostChannelsHoldTransitCostsToActionsAndToTheEnd) {
    const CornerGraph g = threeCells();
    EnvironmentOptions options;
    options.costChannels = true;
    CoverageEnvironment env(g, options);
    EXPECT_EQ(env.channelCount(), 5);
    const std::vector<float> start = env.reset(allRequired(0, 9));
    ASSERT_EQ(start.size(), 5u * 16u);
    const float unit = static_cast<float>(1.0 / (9.0 * kCostChannelScale));
    EXPECT_FLOAT_EQ(start[3 * 16 + 0], 0.0f); // standing on a corner of an uncovered cell
    EXPECT_FLOAT_EQ(start[4 * 16 + 9], 0.0f); // the end corner is 0 away from the end
    env.step(0);                              // now on node 2; the transit to node 4 costs 1
    const std::vector<float> image = env.observation();
    EXPECT_FLOAT_EQ(image[3 * 16 + 4], 1.0f * unit);
    for (int node = 0; node < 4; ++node) // corners of the covered cell are no action
        EXPECT_EQ(image[3 * 16 + node], 0.0f) << node;
    for (std::size_t i = 3 * 16; i < image.size(); ++i) {
        EXPECT_GE(image[i], 0.0f);
        EXPECT_LE(image[i], 1.0f);
    }
    // The cost-to-end channel is fixed for the episode; the first three channels are the
    // paper's image unchanged.
    for (int node = 0; node < 10; ++node)
        EXPECT_EQ(image[4 * 16 + node], start[4 * 16 + node]) << node;
    CoverageEnvironment plain(g);
    plain.reset(allRequired(0, 9));
    plain.step(0);
    const std::vector<float> paper = plain.observation();
    EXPECT_TRUE(std::equal(paper.begin(), paper.end(), image.begin()));
}

TEST(CoverageEnvironment, SeededResetIsReproducible) {
    const CornerGraph g = threeCells();
    CoverageEnvironment a(g);
    CoverageEnvironment b(g);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rngA(seed);
        std::mt19937_64 rngB(seed);
        EXPECT_EQ(a.reset(rngA), b.reset(rngB));
        EXPECT_EQ(a.startNode(), b.startNode());
        EXPECT_EQ(a.endNode(), b.endNode());
        EXPECT_EQ(a.covered(), b.covered());
        EXPECT_FALSE(a.done());
        bool anyAction = false;
        for (char m : a.actionMask())
            anyAction = anyAction || m;
        EXPECT_TRUE(anyAction) << seed;
    }
}

TEST(CoverageEnvironment, EpisodeCostRewardsMatchEvaluateWalk) {
    const CornerGraph g = threeCells();
    const EnvironmentOptions options;
    CoverageEnvironment env(g, options);
    std::mt19937_64 rng(42);
    for (int episode = 0; episode < 50; ++episode) {
        env.reset(rng);
        double costSum = 0.0;
        double bonusSum = 0.0;
        bool goal = false;
        while (!env.done()) {
            std::vector<int> actions;
            const std::vector<char> mask = env.actionMask();
            for (int n = 0; n < env.actionCount(); ++n)
                if (mask[n])
                    actions.push_back(n);
            ASSERT_FALSE(actions.empty());
            std::uniform_int_distribution<std::size_t> pick(0, actions.size() - 1);
            const StepResult r = env.step(actions[pick(rng)]);
            costSum += r.info.costReward;
            bonusSum += r.info.bonusReward;
            goal = r.info.reachedGoal;
            EXPECT_NEAR(r.reward, r.info.costReward + r.info.bonusReward, 1e-12);
        }
        ASSERT_TRUE(goal);
        EXPECT_EQ(env.currentNode(), env.endNode());
        const WalkEvaluation eval = evaluateWalk(g, env.episodeQuery(), env.walk());
        EXPECT_TRUE(eval.connected);
        EXPECT_TRUE(eval.coversAllRequired);
        EXPECT_NEAR(costSum, -eval.graphCost * options.costScale / g.maxEdgeLength, 1e-9);
        EXPECT_GT(bonusSum, options.finalReward);
    }
}
