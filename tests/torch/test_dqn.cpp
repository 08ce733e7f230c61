// The Double-DQN agent (SPEC sect. 5): the target arithmetic by hand, the network's output
// shape on a real corner graph, masked acting, and a short reproducible training run.
#include "../planner/TestGraphs.h"
#include "SmallNetwork.h"
#include "decomposition/Decomposition.h"
#include "graph/CornerGraph.h"
#include "learning/CoverageEnvironment.h"
#include "learning/torch/DqnAgent.h"
#include "learning/torch/DqnTargets.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <thread>

using namespace fc;
using namespace fc::test;

namespace {

// Small network and schedule so that the tests run in seconds.
DqnHyperParameters smallParameters(std::uint64_t seed) {
    DqnHyperParameters p;
    shrinkForTests(p);
    p.replayCapacity = 1000;
    p.epsilonDecaySteps = 200;
    p.seed = seed;
    return p;
}

struct RunResult {
    std::vector<double> losses;
    std::vector<int> actions;
};

RunResult train(const CornerGraph& graph, DqnHyperParameters params, int steps) {
    CoverageEnvironment env(graph);
    DqnAgent agent(env.size(), env.actionCount(), params);
    std::mt19937_64 rng(params.seed);
    RunResult result;
    std::vector<float> obs = env.reset(rng);
    for (int step = 0; step < steps; ++step) {
        const int action = agent.act(obs, env.actionMask(), agent.epsilon(), rng);
        result.actions.push_back(action);
        const StepResult r = env.step(action);
        Transition t;
        t.observation = obs;
        t.action = action;
        t.reward = static_cast<float>(r.reward);
        t.nextObservation = env.observation();
        t.nextMask = env.actionMask();
        t.done = r.done;
        const double loss = agent.observe(std::move(t));
        if (!std::isnan(loss))
            result.losses.push_back(loss);
        obs = r.done ? env.reset(rng) : env.observation();
    }
    return result;
}

} // namespace

TEST(DoubleDqnTargets, HandComputedWithMaskAndDone) {
    DoubleDqnBatch b;
    b.actionCount = 3;
    b.rewards = {1.0f, -0.5f, 2.0f, 0.25f};
    b.dones = {0.0f, 0.0f, 1.0f, 0.0f};
    b.nextOnlineQ = {0.1f, 0.5f, 0.3f, 0.1f, 0.5f, 0.3f, 9.0f, 9.0f, 9.0f, 0.7f, 0.2f, 0.1f};
    b.nextTargetQ = {1.0f, 2.0f, 3.0f, 1.0f, 2.0f, 3.0f, 5.0f, 5.0f, 5.0f, 4.0f, 6.0f, 8.0f};
    b.nextMask = {1, 1, 1, 1, 0, 1, 1, 1, 1, 0, 0, 0};
    // 0: argmax online = 1 -> target 2.        y = 1 + 0.9 x 2 = 2.8
    // 1: action 1 masked, argmax of {0, 2} = 2. y = -0.5 + 0.9 x 3 = 2.2
    // 2: done: no bootstrap.                     y = 2
    // 3: no valid next action: bootstraps 0.     y = 0.25
    const std::vector<float> masked = doubleDqnTargets(b, 0.9f, true);
    ASSERT_EQ(masked.size(), 4u);
    EXPECT_FLOAT_EQ(masked[0], 2.8f);
    EXPECT_FLOAT_EQ(masked[1], 2.2f);
    EXPECT_FLOAT_EQ(masked[2], 2.0f);
    EXPECT_FLOAT_EQ(masked[3], 0.25f);
    // Unmasked (the paper): 1 -> argmax 1, y = -0.5 + 1.8; 3 -> argmax 0, y = 0.25 + 0.9 x 4.
    const std::vector<float> plain = doubleDqnTargets(b, 0.9f, false);
    EXPECT_FLOAT_EQ(plain[0], 2.8f);
    EXPECT_FLOAT_EQ(plain[1], 1.3f);
    EXPECT_FLOAT_EQ(plain[2], 2.0f);
    EXPECT_FLOAT_EQ(plain[3], 3.85f);
    // Double DQN, not DQN: the target network's own maximum (8 for row 3) is not used.
    b.nextMask.clear();
    EXPECT_THROW(doubleDqnTargets(b, 0.9f, true), std::invalid_argument);
    EXPECT_NO_THROW(doubleDqnTargets(b, 0.9f, false));
    b.rewards.pop_back();
    EXPECT_THROW(doubleDqnTargets(b, 0.9f, false), std::invalid_argument);
}

TEST(DoubleDqnTargets, NStepTransitionsDiscountByGammaToTheN) {
    DoubleDqnBatch b;
    b.actionCount = 2;
    b.rewards = {1.5f, 1.5f, 1.5f};
    b.dones = {0.0f, 0.0f, 1.0f};
    b.nextOnlineQ = {0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f};
    b.nextTargetQ = {7.0f, 4.0f, 7.0f, 4.0f, 7.0f, 4.0f};
    b.steps = {1, 3, 3};
    const std::vector<float> y = doubleDqnTargets(b, 0.5f, false);
    EXPECT_FLOAT_EQ(y[0], 1.5f + 0.5f * 4.0f);   // one step: gamma
    EXPECT_FLOAT_EQ(y[1], 1.5f + 0.125f * 4.0f); // three steps: gamma^3
    EXPECT_FLOAT_EQ(y[2], 1.5f);                 // ended within the three steps
    b.steps = {1, 0, 1};
    EXPECT_THROW(doubleDqnTargets(b, 0.5f, false), std::invalid_argument);
    b.steps = {1};
    EXPECT_THROW(doubleDqnTargets(b, 0.5f, false), std::invalid_argument);
}

TEST(DoubleDqnTargets, MaskedArgmaxTiesAndEmpty) {
    const float q[] = {1.0f, 3.0f, 3.0f, -2.0f};
    const char all[] = {1, 1, 1, 1};
    const char last[] = {0, 0, 0, 1};
    const char none[] = {0, 0, 0, 0};
    EXPECT_EQ(maskedArgmax(q, all, 4), 1);
    EXPECT_EQ(maskedArgmax(q, nullptr, 4), 1);
    EXPECT_EQ(maskedArgmax(q, last, 4), 3);
    EXPECT_EQ(maskedArgmax(q, none, 4), -1);
}

TEST(ReplayMemory, RingOverwritesOldest) {
    ReplayMemory memory(3);
    for (int i = 0; i < 5; ++i) {
        Transition t;
        t.action = i;
        memory.push(t);
    }
    ASSERT_EQ(memory.size(), 3u);
    std::vector<int> kept;
    for (std::size_t i = 0; i < memory.size(); ++i)
        kept.push_back(memory.at(i).action);
    std::sort(kept.begin(), kept.end());
    EXPECT_EQ(kept, (std::vector<int>{2, 3, 4}));
    std::mt19937_64 rng(3);
    for (std::size_t index : memory.sample(50, rng))
        EXPECT_LT(index, 3u);
    EXPECT_THROW(ReplayMemory(0), std::invalid_argument);
}

TEST(DqnAgent, OutputShapeOnRealCornerGraph) {
    Plan plan;
    plan.boundary = {{20, 14}, {20, 3}, {15, 3}, {15, 0}, {0, 0}, {0, 10}, {4, 10}, {4, 14}};
    plan.obstacles = {{{7, 5}, {13, 5}, {13, 8}, {7, 8}}};
    const CornerGraph graph = buildCornerGraph(decompose(plan, {}));
    CoverageEnvironment env(graph);
    const int nodes = static_cast<int>(graph.nodes.size());
    ASSERT_GT(nodes, 4);
    EXPECT_EQ(env.size(), static_cast<int>(std::ceil(std::sqrt(static_cast<double>(nodes)))));

    DqnAgent agent(env.size(), env.actionCount()); // the paper's network
    std::mt19937_64 rng(5);
    std::vector<float> batch;
    const int batchSize = 3;
    for (int i = 0; i < batchSize; ++i) {
        const std::vector<float> obs = env.reset(rng);
        ASSERT_EQ(obs.size(), 3u * env.size() * env.size());
        batch.insert(batch.end(), obs.begin(), obs.end());
    }
    const std::vector<float> q = agent.qValues(batch, batchSize);
    EXPECT_EQ(q.size(), static_cast<std::size_t>(batchSize * nodes));
    for (float v : q)
        EXPECT_TRUE(std::isfinite(v));
    EXPECT_THROW(agent.qValues(batch, batchSize + 1), std::invalid_argument);
}

TEST(DqnAgent, ActNeverChoosesAMaskedAction) {
    const CornerGraph graph = threeCells();
    CoverageEnvironment env(graph);
    DqnAgent agent(env.size(), env.actionCount(), smallParameters(7));
    std::mt19937_64 rng(11);
    for (double epsilon : {0.0, 0.5, 1.0}) {
        for (int episode = 0; episode < 30; ++episode) {
            std::vector<float> obs = env.reset(rng);
            while (!env.done()) {
                const std::vector<char> mask = env.actionMask();
                const int action = agent.act(obs, mask, epsilon, rng);
                ASSERT_GE(action, 0);
                ASSERT_LT(action, env.actionCount());
                ASSERT_TRUE(mask[static_cast<std::size_t>(action)]) << "epsilon " << epsilon;
                env.step(action);
                obs = env.observation();
            }
        }
    }
}

TEST(DqnAgent, ShortTrainingIsFiniteAndReproducible) {
    const CornerGraph graph = threeCells();
    const RunResult first = train(graph, smallParameters(42), 300);
    ASSERT_EQ(first.losses.size(), 300u - 50u + 1u); // trains from step learningStarts on
    for (double loss : first.losses) {
        EXPECT_TRUE(std::isfinite(loss));
        EXPECT_GE(loss, 0.0);
    }
    const RunResult second = train(graph, smallParameters(42), 300);
    EXPECT_EQ(first.actions, second.actions);
    EXPECT_EQ(first.losses, second.losses); // bit-identical on one thread
    RunResult onWorker;                     // as the GUI trains: on a worker thread
    std::thread worker([&] { onWorker = train(graph, smallParameters(42), 300); });
    worker.join();
    EXPECT_EQ(first.losses, onWorker.losses);
    const RunResult other = train(graph, smallParameters(43), 300);
    EXPECT_NE(first.losses, other.losses);
}

TEST(DqnAgent, EpsilonScheduleAndTargetSync) {
    const DqnHyperParameters p = smallParameters(1); // learning at 50, sync every 100
    const CornerGraph graph = threeCells();
    CoverageEnvironment env(graph);
    DqnAgent agent(env.size(), env.actionCount(), p);
    EXPECT_DOUBLE_EQ(agent.epsilon(), 1.0);
    std::mt19937_64 rng(2);
    std::vector<float> obs = env.reset(rng);
    const std::vector<float> probe = obs;
    EXPECT_EQ(agent.qValues(probe, 1), agent.targetQValues(probe, 1));
    for (int step = 0; step < 100; ++step) {
        if (step == 99) { // trained since step 50, not yet synced
            EXPECT_NE(agent.qValues(probe, 1), agent.targetQValues(probe, 1));
        }
        const int action = agent.act(obs, env.actionMask(), 1.0, rng);
        const StepResult r = env.step(action);
        agent.observe({obs, action, static_cast<float>(r.reward), env.observation(),
                       env.actionMask(), r.done});
        obs = r.done ? env.reset(rng) : env.observation();
    }
    EXPECT_EQ(agent.qValues(probe, 1), agent.targetQValues(probe, 1)); // synced at step 100
    EXPECT_EQ(agent.stepCount(), 100);
    EXPECT_EQ(agent.trainStepCount(), 51);
    EXPECT_NEAR(agent.epsilon(), 1.0 - 0.5 * 0.95, 1e-12);
    agent.trainStep();
    EXPECT_NE(agent.qValues(probe, 1), agent.targetQValues(probe, 1));
    agent.syncTarget();
    EXPECT_EQ(agent.qValues(probe, 1), agent.targetQValues(probe, 1));
}

TEST(DqnAgent, WeightsRoundTripAndRefuseOtherArchitecture) {
    const CornerGraph graph = threeCells();
    CoverageEnvironment env(graph);
    std::mt19937_64 rng(4);
    const std::vector<float> obs = env.reset(rng);
    DqnAgent a(env.size(), env.actionCount(), smallParameters(1));
    DqnAgent b(env.size(), env.actionCount(), smallParameters(2));
    ASSERT_NE(a.qValues(obs, 1), b.qValues(obs, 1));
    std::stringstream stream;
    a.saveWeights(stream);
    b.loadWeights(stream);
    EXPECT_EQ(a.qValues(obs, 1), b.qValues(obs, 1));

    DqnAgent wider(env.size(), env.actionCount() + 1, smallParameters(3));
    const std::vector<float> before = wider.qValues(obs, 1);
    std::stringstream again;
    a.saveWeights(again);
    EXPECT_THROW(wider.loadWeights(again), std::runtime_error);
    EXPECT_EQ(wider.qValues(obs, 1), before);
    std::stringstream garbage("not a model");
    EXPECT_THROW(b.loadWeights(garbage), std::runtime_error);
}
