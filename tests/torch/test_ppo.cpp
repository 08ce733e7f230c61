// The PPO pointer network for the tiling robot's waypoint order: it trains, its decoded
// tours visit every waypoint once, and a seed reproduces it.
#include "learning/torch/PointerPpo.h"
#include "tiling/RandomInstances.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

using namespace fc;

namespace {

PointerPpoOptions tinyOptions() {
    PointerPpoOptions options;
    options.hidden = 16;
    options.batch = 8;
    options.trainingWaypoints = 8;
    options.seed = 5;
    return options;
}

} // namespace

TEST(PointerPpo, DecodedToursVisitEveryWaypointOnce) {
    PointerPpo ppo(tinyOptions());
    int updates = 0;
    ppo.train(3, [&updates](const PointerPpoProgress& p) {
        ++updates;
        EXPECT_GT(p.meanCost, 0.0);
        EXPECT_TRUE(std::isfinite(p.criticLoss));
    });
    EXPECT_EQ(updates, 3);
    for (int n : {0, 1, 2, 30}) {
        const tiling::OrderingProblem problem = tiling::randomOrderingProblem(n, 40 + n);
        EXPECT_TRUE(tiling::isTour(ppo.decode(problem), n)) << n;
    }
}

TEST(PointerPpo, SameSeedSameTours) {
    PointerPpo first(tinyOptions()), second(tinyOptions());
    first.train(2);
    second.train(2);
    const tiling::OrderingProblem problem = tiling::randomOrderingProblem(25, 3);
    EXPECT_EQ(first.decode(problem), second.decode(problem));
}

TEST(PointerPpo, SavedActorDecodesTheSame) {
    PointerPpo trained(tinyOptions());
    trained.train(2);
    const std::string path = ::testing::TempDir() + "/pointer-ppo.pt";
    trained.save(path);
    PointerPpoOptions other = tinyOptions();
    other.seed = 99; // different initial weights, replaced by the loaded ones
    PointerPpo loaded(other);
    loaded.load(path);
    const tiling::OrderingProblem problem = tiling::randomOrderingProblem(25, 4);
    EXPECT_EQ(trained.decode(problem), loaded.decode(problem));
}
