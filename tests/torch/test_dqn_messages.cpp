// The graph network's message rounds (DqnHyperParameters::messageRounds): each valid corner
// pools messages from its nearest valid corners of the same state. Messages never cross from
// one state of a batch to another, padding changes nothing, and the model file keeps the
// rounds, so a saved model scores exactly as it did.
#include "DqnTestSupport.h"
#include "learning/GraphState.h"
#include "learning/NearestCorners.h"
#include "learning/dqn/DqnModelFile.h"
#include "model/SyntheticPlans.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <sstream>

using namespace fc;

namespace {

constexpr int kChannels = kGraphFeatureCount;

std::vector<float> randomState(int corners, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    std::vector<float> obs(static_cast<std::size_t>(corners * kChannels));
    for (int c = 0; c < corners; ++c) {
        float* f = obs.data() + static_cast<std::size_t>(c * kChannels);
        f[0] = c % 4 == 3 ? 0.0f : 1.0f;
        for (int i = 1; i < kChannels; ++i)
            f[i] = value(rng);
    }
    return obs;
}

DqnHyperParameters messageParameters(int rounds) {
    DqnHyperParameters p;
    p.network = QNetworkKind::Graph;
    p.inputChannels = kChannels;
    p.hiddenUnits = 16;
    p.messageRounds = rounds;
    p.messageNeighbours = 4;
    p.batchSize = 4;
    p.learningStarts = 4;
    p.seed = 11;
    return p;
}

} // namespace

TEST(GraphMessages, StayWithinTheirStateAndIgnorePadding) {
    DqnAgent agent(3, 12, messageParameters(2));
    const std::vector<float> a = randomState(12, 1);
    const std::vector<float> b = randomState(12, 2);
    const std::vector<float> qa = agent.qValues(a, 1);
    std::vector<float> both = a;
    both.insert(both.end(), b.begin(), b.end());
    const std::vector<float> qBoth = agent.qValues(both, 2);
    for (std::size_t c = 0; c < qa.size(); ++c)
        EXPECT_NEAR(qBoth[c], qa[c], 1e-5f) << "corner " << c;

    std::vector<float> padded = a;
    padded.resize(static_cast<std::size_t>(20 * kChannels), 0.0f);
    const std::vector<float> qPadded = agent.qValues(padded, 1);
    for (std::size_t c = 0; c < qa.size(); ++c)
        EXPECT_NEAR(qPadded[c], qa[c], 1e-5f) << "corner " << c;

    // Fewer valid corners than neighbours: still scored, finite.
    std::vector<float> tiny = randomState(2, 3);
    for (float q : agent.qValues(tiny, 1))
        EXPECT_TRUE(std::isfinite(q));

    // A neighbour's features reach a corner's score: moving the other corners changes it.
    std::vector<float> moved = a;
    for (int c = 1; c < 12; ++c)
        moved[static_cast<std::size_t>(c * kChannels + 9)] += 0.5f;
    EXPECT_NE(agent.qValues(moved, 1)[0], qa[0]);
}

TEST(GraphMessages, TrainAndSurviveTheModelFile) {
    const PreparedPlan plan = fc::test::preparedSample("room-obstacle");
    TrainingOptions options = fc::test::smallOptions(TrainingOptions::graph(3));
    options.agent.messageRounds = 1;
    options.agent.messageNeighbours = 6;
    DqnTrainer trainer(plan.graph, options, 90.0, 1.0);
    trainer.train(10, 0.0);
    std::istringstream in(fc::test::serialized(trainer));
    const DqnModel model = readDqnModel(in, "memory");
    EXPECT_EQ(model.info.agent.messageRounds, 1);
    EXPECT_EQ(model.info.agent.messageNeighbours, 6);
    CoverageEnvironment env(plan.graph, trainer.options().environment);
    std::mt19937_64 rng(4);
    const std::vector<float> obs = env.reset(rng);
    EXPECT_EQ(model.agent->qValues(obs, 1), trainer.agent().qValues(obs, 1));

    // Messages need the corners' positions (features 7 and 8).
    DqnHyperParameters few = messageParameters(1);
    few.inputChannels = 6;
    EXPECT_THROW(DqnAgent(3, 12, few), std::invalid_argument);
}

// The R-tree's neighbours are those of a full scan: the same distances, the corner itself
// first, rows filled up with it when there are fewer corners than neighbours.
TEST(NearestCorners, AgreeWithAFullScan) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<float> value(-50.0f, 50.0f);
    std::vector<float> xy(2 * 300);
    for (float& v : xy)
        v = std::round(value(rng) * 4.0f) / 4.0f; // a grid: many equal distances
    const int k = 7;
    const NearestCorners near = nearestCorners(xy.data(), 300, k);
    auto dist = [&](int a, int b) {
        return std::hypot(double(xy[2 * a]) - xy[2 * b], double(xy[2 * a + 1]) - xy[2 * b + 1]);
    };
    for (int i = 0; i < 300; ++i) {
        std::vector<double> all;
        for (int j = 0; j < 300; ++j)
            if (j != i)
                all.push_back(dist(i, j));
        std::sort(all.begin(), all.end());
        EXPECT_EQ(near.index[static_cast<std::size_t>(i * k)], i);
        for (int j = 1; j < k; ++j)
            EXPECT_NEAR(dist(i, near.index[static_cast<std::size_t>(i * k + j)]),
                        all[static_cast<std::size_t>(j - 1)], 1e-9)
                << "corner " << i << ", neighbour " << j;
    }
    const NearestCorners few = nearestCorners(xy.data(), 3, 5);
    EXPECT_EQ(few.index[3], 0); // row 0: itself, its two others, then itself again
    EXPECT_EQ(few.index[4], 0);
    EXPECT_GT(few.meanDistance, 0.0);
    EXPECT_THROW(nearestCorners(xy.data(), 3, 0), std::invalid_argument);
}
