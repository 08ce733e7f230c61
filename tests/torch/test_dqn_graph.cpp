// The graph-level state (GraphState.h) and the per-corner Q network: features by hand on a
// hand-built graph, the network's locality, the masked Double-DQN target through a real
// gradient step, the model file's state kind, masked inference and reproducibility.
#include "../planner/TestGraphs.h"
#include "DqnTestSupport.h"
#include "formats/PlanIO.h"
#include "learning/CoverageEnvironment.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/DqnTrainer.h"
#include "learning/torch/DqnAgent.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

using namespace fc;

namespace {

constexpr int F = kGraphFeatureCount;

float feature(const std::vector<float>& obs, int node, int index) {
    return obs[static_cast<std::size_t>(node * F + index)];
}

using fc::test::serialized;

PreparedPlan prepared(const std::string& name) {
    return fc::test::preparedSample(name);
}

TrainingOptions smallGraphOptions(std::uint64_t seed) {
    return fc::test::smallOptions(TrainingOptions::graph(seed));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

} // namespace

// threeCells(): cell 0 = nodes 0-3 (coverage 0-2, 1-3), cell 1 = nodes 4-5, cell 2 = nodes
// 6-9 (coverage 6-9, 7-8); longest edge 9, so a cost unit is 8 x 9 = 72; bounding-box
// diagonal sqrt(53). Start 0, end 9, every cell required.
TEST(GraphState, FeaturesMatchAHandComputedCase) {
    const CornerGraph g = fc::test::threeCells();
    EnvironmentOptions options;
    options.graphState = true;
    CoverageEnvironment env(g, options);
    Query q;
    q.startNode = 0;
    q.endNode = 9;
    q.required = {1, 1, 1};
    const std::vector<float> obs = env.reset(q);
    ASSERT_EQ(obs.size(), g.nodes.size() * F);
    ASSERT_EQ(env.observationSize(), obs.size());
    const double unit = 72.0, diagonal = std::sqrt(53.0), root5 = std::sqrt(5.0);
    // Corner 0 (the current one): covering cell 0 from it ends at 2; 2 -> 9 costs 4 + sqrt 5
    // (2-5 diagonal, 5-7, 7-9), the nearest other cell centre is cell 1's (3, 1).
    EXPECT_FLOAT_EQ(feature(obs, 0, 0), 1.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 1), 0.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 2), static_cast<float>((4 + root5) / unit));
    EXPECT_FLOAT_EQ(feature(obs, 0, 3), 0.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 4), 1.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 5), 1.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 6), 0.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 9), static_cast<float>(std::sqrt(2.0) / unit));
    EXPECT_FLOAT_EQ(feature(obs, 0, 10), 0.25f); // cell 1 borders cell 0
    EXPECT_FLOAT_EQ(feature(obs, 0, 11), 1.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 12), 1.0f);
    EXPECT_FLOAT_EQ(feature(obs, 0, 13), 0.25f); // two centres within 18 m
    EXPECT_FLOAT_EQ(feature(obs, 0, 14), 0.0f);  // the cheapest transit: greedy's choice
    EXPECT_FLOAT_EQ(feature(obs, 0, 15), 1.0f);
    // Corner 9 (the end): reached by 0-2, 2-5, 5-7, 7-9 = 6 + sqrt 5; its cell exits at 6.
    EXPECT_FLOAT_EQ(feature(obs, 9, 1), static_cast<float>((6 + root5) / unit));
    EXPECT_FLOAT_EQ(feature(obs, 9, 2), static_cast<float>((4 + root5) / unit));
    EXPECT_FLOAT_EQ(feature(obs, 9, 3), 1.0f);
    EXPECT_FLOAT_EQ(feature(obs, 9, 7), static_cast<float>(7 / diagonal));
    EXPECT_FLOAT_EQ(feature(obs, 9, 8), static_cast<float>(2 / diagonal));
    EXPECT_FLOAT_EQ(feature(obs, 9, 10), 0.25f);
    EXPECT_FLOAT_EQ(feature(obs, 9, 14), static_cast<float>((6 + root5) / 9)); // in edges
    EXPECT_FLOAT_EQ(feature(obs, 9, 15), 0.0f);

    // Cover cell 0 from corner 0: the robot stands at 2, two of three cells are left.
    env.step(0);
    const std::vector<float> next = env.observation();
    EXPECT_FLOAT_EQ(feature(next, 0, 0), 0.0f); // covered: not an action any more
    EXPECT_FLOAT_EQ(feature(next, 0, 1), 0.0f);
    EXPECT_FLOAT_EQ(feature(next, 2, 4), 1.0f);
    EXPECT_FLOAT_EQ(feature(next, 4, 0), 1.0f);
    EXPECT_FLOAT_EQ(feature(next, 4, 1), static_cast<float>(1 / unit));
    EXPECT_FLOAT_EQ(feature(next, 4, 5), 2.0f / 3.0f);
    EXPECT_FLOAT_EQ(feature(next, 4, 7), static_cast<float>(1 / diagonal));
    EXPECT_FLOAT_EQ(feature(next, 4, 10), 0.25f); // cell 0 is covered, cell 2 is not
    EXPECT_FLOAT_EQ(feature(next, 4, 11), 2.0f / 3.0f);
    env.step(4);
    const std::vector<float> last = env.observation();
    EXPECT_FLOAT_EQ(feature(last, 6, 6), 1.0f); // a single cell is left
    EXPECT_FLOAT_EQ(feature(last, 6, 9), 0.0f); // no other uncovered cell
}

TEST(GraphNetwork, ScoresValidCornersOnlyAndInvalidOnesChangeNothing) {
    const PreparedPlan plan = prepared("simple");
    TrainingOptions options = smallGraphOptions(3);
    CoverageEnvironment env(plan.graph, options.environment);
    options.agent.inputChannels = env.channelCount();
    const DqnAgent agent(env.size(), env.actionCount(), options.agent);
    std::mt19937_64 rng(5);
    std::vector<float> obs = env.reset(rng);
    const std::vector<char> mask = env.actionMask();
    const std::vector<float> before = agent.qValues(obs, 1);
    ASSERT_EQ(before.size(), static_cast<std::size_t>(env.actionCount()));
    int invalid = -1;
    for (int a = 0; a < env.actionCount() && invalid < 0; ++a)
        if (!mask[static_cast<std::size_t>(a)] && a != env.currentNode() && a != env.endNode())
            invalid = a;
    ASSERT_GE(invalid, 0);
    for (int k = 1; k < F; ++k)
        obs[static_cast<std::size_t>(invalid * F + k)] += 0.5f;
    const std::vector<float> after = agent.qValues(obs, 1);
    EXPECT_EQ(after[static_cast<std::size_t>(invalid)], 0.0f); // never scored
    for (int a = 0; a < env.actionCount(); ++a) {
        if (a != invalid) {
            EXPECT_FLOAT_EQ(after[static_cast<std::size_t>(a)],
                            before[static_cast<std::size_t>(a)]);
        }
    }
}

// One transition in the memory: every sampled row is it, so the step's Huber loss is that of
// r + gamma x Q_target(s', a*) with a* the online argmax over the valid corners of s'.
TEST(GraphNetwork, MaskedDoubleDqnTargetInAGradientStep) {
    const PreparedPlan plan = prepared("simple");
    TrainingOptions options = smallGraphOptions(4);
    CoverageEnvironment env(plan.graph, options.environment);
    options.agent.inputChannels = env.channelCount();
    DqnAgent agent(env.size(), env.actionCount(), options.agent);
    Transition t;
    t.observation = env.reset(randomQueries(plan.graph, 1, 8, QuerySet::AllCells).front());
    t.action = agent.greedyAction(t.observation, env.actionMask());
    t.reward = static_cast<float>(env.step(t.action).reward);
    ASSERT_FALSE(env.done());
    t.nextObservation = env.observation();
    t.nextMask = env.actionMask();
    const std::vector<float> online = agent.qValues(t.nextObservation, 1);
    const std::vector<float> target = agent.targetQValues(t.nextObservation, 1);
    int best = -1;
    for (int a = 0; a < env.actionCount(); ++a)
        if (t.nextMask[static_cast<std::size_t>(a)] &&
            (best < 0 ||
             online[static_cast<std::size_t>(a)] > online[static_cast<std::size_t>(best)]))
            best = a;
    ASSERT_GE(best, 0);
    const double y = t.reward + options.agent.gamma * target[static_cast<std::size_t>(best)];
    const double q = agent.qValues(t.observation, 1)[static_cast<std::size_t>(t.action)];
    const double d = std::abs(q - y);
    const double expected = d <= 1.0 ? 0.5 * d * d : d - 0.5;
    agent.remember(t);
    EXPECT_NEAR(agent.trainStep(), expected, 1e-4 * std::max(1.0, expected));
}

TEST(GraphModelFile, RoundTripAndRefusalOfAnotherStateKind) {
    const PreparedPlan plan = prepared("room-obstacle");
    DqnTrainer trainer(plan.graph, smallGraphOptions(6), 90.0, 1.0);
    trainer.train(8, 0.0);
    const std::string bytes = serialized(trainer);
    {
        std::istringstream in(bytes);
        const DqnModel model = readDqnModel(in, "graph.fcdqn");
        EXPECT_EQ(model.info.setting, "graph");
        EXPECT_TRUE(model.info.environment.graphState);
        EXPECT_EQ(model.info.agent.network, QNetworkKind::Graph);
        EXPECT_EQ(model.info.agent.inputChannels, F);
        for (const Query& q : randomQueries(plan.graph, 4, 3, QuerySet::AllCells)) {
            const Solution a =
                solveWithPolicy(trainer.agent(), plan.graph, q, trainer.options().environment);
            const Solution b = solveWithPolicy(*model.agent, plan.graph, q, model.info.environment);
            EXPECT_EQ(a.walk.nodes, b.walk.nodes);
        }
    }
    auto refusal = [](const std::string& text) {
        std::istringstream in(text);
        try {
            readDqnModel(in, "edited.fcdqn");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    // The header says image but the network is the graph one.
    EXPECT_NE(refusal(replaced(bytes, "\"state\":\"graph\"", "\"state\":\"image\""))
                  .find("needs the conv network"),
              std::string::npos);
    EXPECT_NE(refusal(replaced(bytes, "\"state\":\"graph\"", "\"state\":\"voxel\""))
                  .find("unknown state kind"),
              std::string::npos);
    // A feature count this version does not know: named, not a size mismatch.
    std::string unknown =
        replaced(bytes, "\"input_channels\":" + std::to_string(F), "\"input_channels\":15");
    unknown = replaced(unknown, "\"graph_features\":" + std::to_string(F), "\"graph_features\":15");
    EXPECT_NE(refusal(unknown).find("graph state of 15 features per corner"), std::string::npos)
        << refusal(unknown);
    // A consistent image header over graph weights: the weights do not fit.
    std::string image = replaced(bytes, "\"state\":\"graph\"", "\"state\":\"image\"");
    image = replaced(image, "\"network\":\"graph\"", "\"network\":\"conv\"");
    image = replaced(image, "\"input_channels\":" + std::to_string(F), "\"input_channels\":3");
    EXPECT_NE(refusal(image).find("another architecture"), std::string::npos) << refusal(image);
    // The image solver's options with a graph model: refused by the policy, never run.
    std::istringstream in(bytes);
    const DqnModel model = readDqnModel(in, "graph.fcdqn");
    const Query q = randomQueries(plan.graph, 1, 3, QuerySet::AllCells).front();
    EXPECT_THROW(solveWithPolicy(*model.agent, plan.graph, q, EnvironmentOptions{}), SolverError);
}

TEST(GraphModelFile, VersionOneImageModelsStillLoad) {
    const PreparedPlan plan = prepared("simple");
    TrainingOptions options = TrainingOptions::improved(2);
    fc::test::shrinkForTests(options.agent);
    DqnTrainer trainer(plan.graph, options);
    trainer.train(2, 0.0);
    std::string old = replaced(serialized(trainer), "FLOORCOVER-DQN 2", "FLOORCOVER-DQN 1");
    old = replaced(old, "\"network\":\"conv\",", "");
    old = replaced(old, ",\"state\":\"image\"", "");
    std::istringstream in(old);
    const DqnModel model = readDqnModel(in, "old.fcdqn");
    EXPECT_FALSE(model.info.environment.graphState);
    EXPECT_EQ(model.info.agent.network, QNetworkKind::Convolutional);
}

TEST(GraphPolicy, MaskedInferenceAlwaysFinishesAndTrainingIsReproducible) {
    const PreparedPlan plan = prepared("room-obstacle");
    TrainingOptions options = smallGraphOptions(9);
    options.agent.learningStarts = 20;
    DqnTrainer untrained(plan.graph, options);
    for (const QuerySet kind : {QuerySet::AllCells, QuerySet::RoomSubsets})
        for (const Query& q : randomQueries(plan.graph, 20, 12, kind)) {
            const Solution s =
                solveWithPolicy(untrained.agent(), plan.graph, q, options.environment);
            const WalkEvaluation e = evaluateWalk(plan.graph, q, s.walk);
            EXPECT_TRUE(e.connected && e.coversAllRequired);
            EXPECT_EQ(s.walk.nodes.front(), q.startNode);
            EXPECT_EQ(s.walk.nodes.back(), q.endNode);
        }
    auto run = [&] {
        DqnTrainer trainer(plan.graph, options);
        std::vector<double> rewards;
        trainer.train(12, 0.0, [&](const TrainingProgress& p) { rewards.push_back(p.reward); });
        CoverageEnvironment env(plan.graph, options.environment);
        std::mt19937_64 rng(99);
        std::vector<float> q = trainer.agent().qValues(env.reset(rng), 1);
        rewards.insert(rewards.end(), q.begin(), q.end());
        EXPECT_GT(trainer.agent().trainStepCount(), 0);
        return rewards;
    };
    EXPECT_EQ(run(), run());
}

// Graph models saved before features 14-15 (14 per corner, no "graph_features" key) still
// load and plan with the features they were trained on.
TEST(GraphModelFile, FirstFeatureSetModelsStillLoadAndPlan) {
    const PreparedPlan plan = prepared("simple");
    TrainingOptions options = smallGraphOptions(4);
    options.environment.graphFeatures = kFirstGraphFeatureCount;
    DqnTrainer trainer(plan.graph, options);
    trainer.train(2, 0.0);
    ASSERT_EQ(trainer.agent().parameters().inputChannels, kFirstGraphFeatureCount);
    const std::string old = replaced(serialized(trainer), ",\"graph_features\":14", "");
    std::istringstream in(old);
    const DqnModel model = readDqnModel(in, "first.fcdqn");
    EXPECT_EQ(model.info.environment.graphFeatures, kFirstGraphFeatureCount);
    const Query q = randomQueries(plan.graph, 1, 5, QuerySet::AllCells).front();
    const Solution s = solveWithPolicy(*model.agent, plan.graph, q, model.info.environment);
    EXPECT_TRUE(evaluateWalk(plan.graph, q, s.walk).coversAllRequired);
}
