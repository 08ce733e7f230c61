// Issue 13, item 6: properties every plan must have, on plans the planner was never tuned
// on. Each case plans with the default request (W = 1 m, L = 0.6 m, solver heuristic, every
// room) and checks the path with the independent checker (tests/checker, Boost.Geometry):
//   (a) collision-free for the disc robot: clearance >= L/2 - 1e-3 L, waypoints inside;
//   (b) coverage >= 99.5 % of the sweepable area, or metrics.uncoveredArea matching the
//       checker's uncovered area within 0.2 % of the floor (a reported loss);
//   (c) no exception but fc::InputError with a message, no run over 30 s.
// Cases: 10 seeds of each generated family (tests/checker/PlanGenerator.h), floors the bench
// once failed, and every sample plan unrotated and rotated by two seeded odd angles.
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "formats/PlanIO.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace fcgen;

namespace {

constexpr int kSeedsPerFamily = 10;
// Floors beyond those seeds that `floorcover-property-bench --seed 7 --count 250` once failed,
// kept as cases: door rooms seed 36, where touch-ups within a budget left 0.44% of the floor
// missed by the planner's raster and 0.66% by the checker.
const std::pair<Family, int> kRegressionCases[] = {{Family::DoorRooms, 36}};
constexpr int kAnglesPerSample = 2;
constexpr std::uint64_t kAngleSeed = 13;

struct Case {
    std::string name;
    bool generated = true;
    Family family = Family::RotatedOffice;
    std::uint64_t seed = 0;
    std::string sample; // sample plan stem
    double angleDeg = 0.0;
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name;
}

std::string identifier(std::string s) {
    for (char& ch : s)
        if (!std::isalnum(static_cast<unsigned char>(ch)))
            ch = '_';
    return s;
}

std::vector<Case> generatedCases() {
    std::vector<Case> cases;
    auto add = [&cases](Family family, int seed) {
        Case c;
        c.family = family;
        c.seed = static_cast<std::uint64_t>(seed);
        c.name = identifier(familyName(family)) + "_" + std::to_string(seed);
        cases.push_back(c);
    };
    for (Family family : allFamilies())
        for (int seed = 1; seed <= kSeedsPerFamily; ++seed)
            add(family, seed);
    for (const auto& [family, seed] : kRegressionCases)
        add(family, seed);
    return cases;
}

std::vector<std::string> samplePlans() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(FC_PLANS_DIR))
        if (entry.path().extension() == ".geojson")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<Case> sampleCases() {
    std::vector<Case> cases;
    const std::vector<std::string> plans = samplePlans();
    for (std::size_t i = 0; i < plans.size(); ++i) {
        const std::string& plan = plans[i];
        std::vector<double> angles{0.0};
        // The quality report's angles for the same seed (its first two per plan).
        for (double a : oddAngles(kAngleSeed + i, kAnglesPerSample))
            angles.push_back(a);
        for (double a : angles) {
            Case c;
            c.generated = false;
            c.sample = plan;
            c.angleDeg = a;
            char deg[32];
            std::snprintf(deg, sizeof deg, "%.1f", a);
            c.name = identifier(plan) + "_rot" + identifier(deg);
            cases.push_back(c);
        }
    }
    return cases;
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    return info.param.name;
}

// Runs one plan and states every property; prints one line of figures either way.
void checkProperties(const fc::Plan& plan, const std::string& what) {
    const Outcome o = planAndCheck(defaultRequest(plan));
    std::cout << "[property] " << what << ": " << o.summary() << std::endl;
    ::testing::Test::RecordProperty("summary", o.summary());
    // (c)
    ASSERT_FALSE(o.otherError) << what << ": " << o.error;
    if (o.inputError) {
        EXPECT_FALSE(o.error.empty()) << what << ": an InputError without a message";
        return;
    }
    EXPECT_TRUE(o.inTime) << what << ": planning took " << o.seconds << " s";
    // (a)
    EXPECT_TRUE(o.check.clearance.inside)
        << what << ": waypoint " << o.check.clearance.outsideVertex << " is outside the free space";
    EXPECT_GE(o.check.clearance.minimum, 0.3 - 1e-3 * 0.6)
        << what << ": the robot centre comes within " << o.check.clearance.minimum
        << " m of a wall (segment " << o.check.clearance.segment << ", near ("
        << o.check.clearance.nearestWallPoint.first << ", "
        << o.check.clearance.nearestWallPoint.second << "))";
    // (b)
    std::string warnings;
    for (const std::string& w : o.warnings)
        warnings += "\n  warning: " + w;
    EXPECT_TRUE(o.covers || o.reportsLoss)
        << what << ": coverage " << 100.0 * o.check.coverage
        << "% of the sweepable area, and the planner reports " << o.metrics.uncoveredArea
        << " m^2 uncovered where the checker finds " << o.check.uncoveredArea << " m^2 (floor "
        << o.check.floorArea << " m^2, allowed difference "
        << kUncoveredAgreement * o.check.floorArea << " m^2)" << warnings;
}

class GeneratedPlans : public ::testing::TestWithParam<Case> {};
class SamplePlans : public ::testing::TestWithParam<Case> {};

} // namespace

TEST_P(GeneratedPlans, CollisionFreeAndCoveringOrReported) {
    const Case& c = GetParam();
    GeneratedPlan g;
    ASSERT_NO_THROW(g = generatePlan(c.family, c.seed));
    checkProperties(g.plan, g.description);
}

TEST_P(SamplePlans, CollisionFreeAndCoveringOrReported) {
    const Case& c = GetParam();
    const fc::Plan plan =
        fc::loadProjectFile(std::string(FC_PLANS_DIR) + "/" + c.sample + ".geojson").plan;
    checkProperties(transformPlan(plan, c.angleDeg, {}),
                    c.sample + " rotated " + std::to_string(c.angleDeg) + " deg");
}

INSTANTIATE_TEST_SUITE_P(Random, GeneratedPlans, ::testing::ValuesIn(generatedCases()), caseName);
INSTANTIATE_TEST_SUITE_P(Rotated, SamplePlans, ::testing::ValuesIn(sampleCases()), caseName);
