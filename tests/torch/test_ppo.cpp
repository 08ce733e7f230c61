// The PPO ordering policy of the tiling robot: candidate features by hand, the clipped loss
// on a hand-made batch, masking, valid tours, reproducibility and the saved model.
#include "model/Plan.h"
#include "tiling/RandomInstances.h"
#include "tiling/ppo/TourBuilder.h"
#include "tiling/ppo/torch/PointerPpo.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numeric>
#include <string>

using namespace fc;
using namespace fc::tiling;

namespace {

PointerPpoOptions tinyOptions() {
    PointerPpoOptions options;
    options.hidden = 8;
    options.window = 6;
    options.batch = 4;
    options.roomWaypoints = 12;
    options.trainingRooms = 2;
    options.seed = 5;
    return options;
}

// A pose whose blocks are the waypoint shifted by fixed offsets turned with the heading.
Pose poseAt(Vec2 waypoint, double heading, Shape shape) {
    Pose pose;
    pose.shape = shape;
    pose.heading = heading;
    const double c = std::cos(heading), s = std::sin(heading);
    const Vec2 offsets[kBlockCount] = {{-0.1, 0.0}, {0.0, 0.0}, {0.1, 0.0}, {0.1, 0.1}};
    for (int b = 0; b < kBlockCount; ++b)
        pose.blocks[b] = {waypoint.x + c * offsets[b].x - s * offsets[b].y,
                          waypoint.y + s * offsets[b].x + c * offsets[b].y};
    return pose;
}

} // namespace

TEST(PpoFeatures, MoveFeaturesByHand) {
    OrderingProblem problem; // leg 0.21 m, so the position unit 4a is 0.84 m
    problem.poses = {poseAt({1.0, 1.0}, M_PI / 2, Shape::Rectangle),
                     poseAt({1.0, 1.84}, M_PI, Shape::Triangle),
                     poseAt({0.58, 1.0}, M_PI / 2, Shape::Rectangle)};
    const double unit = problem.robot.totalMass() * 0.21; // 4.1 kg x 0.21 m
    float f[kCandidateFeatures];
    // Waypoint 1 is 0.84 m straight ahead of a robot heading +y: (1, 0) in its frame.
    moveFeatures(problem, 0, 1, problem.cost(0, 2), 3, 1, 4, f);
    EXPECT_NEAR(f[0], 1.0 / std::sqrt(1.0 + 1.0 / 16.0), 1e-6);
    EXPECT_NEAR(f[1], 0.0, 1e-6);
    EXPECT_NEAR(f[2], 0.0, 1e-6); // a quarter turn to the left
    EXPECT_NEAR(f[3], 1.0, 1e-6);
    EXPECT_EQ(f[4], 1.0f); // rectangle to triangle
    EXPECT_NEAR(f[5], std::log1p(problem.cost(0, 1) / unit), 1e-6);
    EXPECT_NEAR(f[6], std::log1p((problem.cost(0, 1) - problem.cost(0, 2)) / unit), 1e-6);
    EXPECT_NEAR(f[7], 3.0 / 8.0, 1e-7);
    EXPECT_NEAR(f[8], 0.25, 1e-7);
    // Waypoint 2 is 0.42 m towards -x, which is to the left of a robot heading +y:
    // (0, 0.5) in units of 4a, squashed.
    moveFeatures(problem, 0, 2, problem.cost(0, 2), 0, 0, 4, f);
    EXPECT_NEAR(f[0], 0.0, 1e-6);
    EXPECT_NEAR(f[1], 0.5 / std::sqrt(1.0 + 0.25 / 16.0), 1e-6);
    EXPECT_NEAR(f[2], 1.0, 1e-6);
    EXPECT_EQ(f[4], 0.0f);
    EXPECT_NEAR(f[6], 0.0, 1e-7);
    // The builder lists both moves, cheapest first; each target's isolation counts the
    // other unvisited waypoint only.
    const TourBuilder builder(problem, 4, neighbourhoodOf(problem));
    ASSERT_EQ(builder.candidates(), (std::vector<int>{2, 1}));
    EXPECT_NEAR(builder.features()[7], 1.0 / 8.0, 1e-7);
    EXPECT_NEAR(builder.features()[kCandidateFeatures + 8], 0.25, 1e-7);
    EXPECT_EQ(builder.features()[2 * kCandidateFeatures + 5], 0.0f); // padding
}

TEST(PpoFeatures, CandidatesAreNeverVisited) {
    const OrderingProblem problem = randomOrderingProblem(40, 7);
    TourBuilder builder(problem, 6, neighbourhoodOf(problem));
    while (!builder.done()) {
        const Tour& tour = builder.tour();
        for (int c : builder.candidates())
            EXPECT_EQ(std::find(tour.begin(), tour.end(), c), tour.end());
        builder.step(static_cast<int>(builder.candidates().size()) - 1); // the dearest
    }
    EXPECT_TRUE(isTour(builder.tour(), 40));
}

TEST(PointerPpo, ClippedLossOnAHandMadeBatch) {
    // Ratios 1.5, 0.5, 1.1 with advantages 1, -1, 2 and epsilon 0.2: min(1.5, 1.2) = 1.2,
    // min(-0.5, -0.8) = -0.8, min(2.2, 2.2) = 2.2; the loss is minus their mean.
    const double loss = ppoClippedLoss({std::log(1.5), std::log(0.5), std::log(1.1)},
                                       {0.0, 0.0, 0.0}, {1.0, -1.0, 2.0}, 0.2);
    EXPECT_NEAR(loss, -(1.2 - 0.8 + 2.2) / 3.0, 1e-12);
    EXPECT_NEAR(ppoClippedLoss({-1.0}, {-1.0}, {3.0}, 0.2), -3.0, 1e-12); // ratio 1
}

TEST(PointerPpo, MaskedSlotsHaveZeroProbability) {
    PointerPpo ppo(tinyOptions());
    const OrderingProblem problem = randomOrderingProblem(4, 9); // 3 candidates, window 6
    const std::vector<double> p = ppo.firstMoveProbabilities(problem);
    ASSERT_EQ(p.size(), 6u);
    EXPECT_NEAR(std::accumulate(p.begin(), p.end(), 0.0), 1.0, 1e-5);
    for (std::size_t slot = 3; slot < p.size(); ++slot)
        EXPECT_EQ(p[slot], 0.0) << slot;
    for (std::size_t slot = 0; slot < 3; ++slot)
        EXPECT_GT(p[slot], 0.0) << slot;
}

TEST(PointerPpo, DecodedToursVisitEveryWaypointOnce) {
    PointerPpo ppo(tinyOptions());
    int updates = 0;
    const int done = ppo.train(2, [&updates](const PointerPpoProgress& p) {
        ++updates;
        EXPECT_GT(p.meanCost, 0.0);
        EXPECT_TRUE(std::isfinite(p.criticLoss));
    });
    EXPECT_EQ(done, 2);
    EXPECT_EQ(updates, 2);
    for (int n : {0, 1, 2, 3, 5, 30}) {
        const OrderingProblem problem = randomOrderingProblem(n, 40 + n);
        EXPECT_TRUE(isTour(ppo.decode(problem), n)) << n;
        EXPECT_TRUE(isTour(ppo.decodeBest(problem, 8, 3), n)) << n;
    }
    // The best of the greedy and sampled tours is never dearer than the greedy one.
    const OrderingProblem problem = randomOrderingProblem(30, 12);
    EXPECT_LE(tourCost(problem, ppo.decodeBest(problem, 8, 3)),
              tourCost(problem, ppo.decode(problem)) + 1e-9);
}

TEST(PointerPpo, SameSeedSameTours) {
    PointerPpo first(tinyOptions()), second(tinyOptions());
    first.train(2);
    second.train(2);
    const OrderingProblem problem = randomOrderingProblem(25, 3);
    EXPECT_EQ(first.decode(problem), second.decode(problem));
    EXPECT_EQ(first.decodeBest(problem, 6, 2), second.decodeBest(problem, 6, 2));
}

TEST(PointerPpo, SavedModelDecodesTheSame) {
    PointerPpo trained(tinyOptions());
    trained.train(1);
    const std::string path = ::testing::TempDir() + "/pointer-ppo.pt";
    trained.save(path);
    PointerPpoOptions other = tinyOptions();
    other.seed = 99; // different initial weights and sizes, replaced by the loaded ones
    other.hidden = 12;
    PointerPpo loaded(other);
    loaded.load(path);
    const OrderingProblem problem = randomOrderingProblem(25, 4);
    EXPECT_EQ(trained.decode(problem), loaded.decode(problem));
    EXPECT_THROW(loaded.load(::testing::TempDir() + "/missing.pt"), InputError);
}
