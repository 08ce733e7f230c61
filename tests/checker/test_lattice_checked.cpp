// Halls with one large convex obstacle at any rotation and position (issue 13): the cells
// around it share one stripe lattice (decomposition/StripeLattice.h), so coverage there rests
// on the neighbours' stripes. The independent checker confirms that nothing is left
// uncovered unreported and that the path keeps clear of the walls.
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "formats/PlanIO.h"
#include "importers/Import.h"
#include "model/Validation.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>

namespace fcgen {
namespace {

fc::Plan hallWithBox(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<>(a, b)(rng); };
    const double width = uniform(9, 16), depth = uniform(7, 12);
    fc::Plan plan;
    plan.boundary = {{0, 0}, {width, 0}, {width, depth}, {0, depth}};
    // A box of 2-4 m turned by any angle, at least 1.5 m from every wall.
    const double a = uniform(1, 2), b = uniform(1, 2), turn = uniform(0, M_PI);
    const double reach = std::hypot(a, b) + 1.5;
    const fc::Vec2 centre{uniform(reach, width - reach), uniform(reach, depth - reach)};
    const fc::Vec2 u{std::cos(turn), std::sin(turn)}, v{-std::sin(turn), std::cos(turn)};
    fc::Ring box;
    for (const auto& [s, t] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
        box.push_back(centre + u * (s * a) + v * (t * b));
    plan.obstacles.push_back(box);
    const double rotation = oddAngles(seed, 1).front();
    const fc::Vec2 offset = seed % 2 ? fc::Vec2{512345.0, 5432109.0} : fc::Vec2{-7.0, 3.0};
    return transformPlan(plan, rotation, offset);
}

// Plans `plan` with and without the lattice offer; the offer never makes a plan slower or
// less complete, and its path is clear of the walls and covers what the checker can sweep.
// Returns the plans' metrics (with, without).
std::pair<fc::Metrics, fc::Metrics> checkOffer(const fc::Plan& plan, const std::string& name) {
    fc::PlanRequest request = defaultRequest(plan);
    const Outcome outcome = planAndCheck(request);
    request.stripeLattice = false;
    const Outcome even = planAndCheck(request);
    std::printf("%s: %s\n  without the lattice: %.1f m, %d turns, %.0f s\n", name.c_str(),
                outcome.summary().c_str(), even.metrics.length, even.metrics.turns,
                even.metrics.time);
    EXPECT_TRUE(outcome.planned && even.planned) << name << outcome.error << even.error;
    EXPECT_TRUE(outcome.collisionFree) << name << outcome.summary();
    EXPECT_TRUE(outcome.covers || outcome.reportsLoss) << name << outcome.summary();
    EXPECT_GE(outcome.check.coverage, kRequiredCoverage) << name << outcome.summary();
    EXPECT_LE(outcome.metrics.time, even.metrics.time * (1 + 1e-9)) << name;
    EXPECT_LE(outcome.metrics.uncoveredArea,
              even.metrics.uncoveredArea + 0.005 * outcome.metrics.requiredArea)
        << name;
    return {outcome.metrics, even.metrics};
}

TEST(LatticeChecked, HallsWithATurnedBoxAreCoveredAndClear) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed)
        checkOffer(hallWithBox(seed), "hall seed " + std::to_string(seed));
}

// The sample plan the lattice was made for, at odd rotations and UTM-sized offsets: the cells
// around its diamond take the lattice wherever the plan is drawn, and it pays.
TEST(LatticeChecked, TheDiamondHallTakesTheLatticeAtAnyRotation) {
    const fc::Plan diamond = fc::normalizedPlan(
        fc::loadProjectFile(std::string(FC_PLANS_DIR) + "/simple-diamond.geojson").plan);
    int turn = 0;
    for (double angle : oddAngles(13, 3)) {
        const fc::Vec2 offset = turn++ % 2 ? fc::Vec2{512345.0, 5432109.0} : fc::Vec2{};
        const auto [with, without] = checkOffer(transformPlan(diamond, angle, offset),
                                                "simple-diamond turned " + std::to_string(angle));
        EXPECT_LT(with.time, 0.85 * without.time) << angle;
    }
}

// A real laser map (tests/data/real-maps, the faculty: 1,165 m^2): its ragged outline and
// traced furniture start cells a few centimetres wide across the whole hall, each of which
// restarted its stripes. The dense lattice sweeps them with one line every W; the checker
// confirms that the shorter path still covers the floor and keeps clear of the walls.
TEST(LatticeChecked, ARealMapsSliversAreSweptByTheDenseLattice) {
    const fc::Plan map =
        fc::importPlanFile(std::string(FC_TEST_DATA_DIR) + "/real-maps/telecom-faculty.yaml")
            .project.plan;
    const auto [with, without] = checkOffer(map, "telecom-faculty map");
    EXPECT_LT(with.time, 0.95 * without.time);
    EXPECT_LT(with.length, 0.85 * without.length);
}

} // namespace
} // namespace fcgen
