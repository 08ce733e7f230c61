// Wall touch-ups (path/CoverageRepair.h): strokes along the walls sweep what the stripes
// leave; strokes that leave from nearly the same place are driven as one chain, shorter than
// each out and back alone, as clear of the walls and sweeping as much.
#include "importers/Import.h"
#include "path/CoverageRepair.h"
#include "pipeline/Planner.h"
#include "pipeline/PreparedPlans.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace fc;

namespace {

// A laser map (tests/data/real-maps, the 60 m corridor): its traced walls run a little off
// the stripes, and the stripe ends there are traced in many short steps.
PlanRequest laserMap() {
    PlanRequest r;
    r.plan = importPlanFile(std::string(FC_TEST_DATA_DIR) + "/real-maps/localization-demo.yaml")
                 .project.plan;
    r.solver = "greedy";
    return r;
}

bool clearOf(const Decomposition& dec, const CoveragePath& path) {
    for (std::size_t i = 0; i + 1 < path.points.size(); ++i)
        if (!dec.clearance().segmentIsClear(dec.frame.toLocal(path.points[i]),
                                            dec.frame.toLocal(path.points[i + 1])))
            return false;
    return true;
}

} // namespace

TEST(CoverageRepair, StrokesFromOnePlaceAreDrivenAsOneChain) {
    const PlanRequest request = laserMap();
    const PreparedPlans prepared(request.plan, request.robot, true);
    const PlanResult draft = draftCoverage(request, prepared);
    ASSERT_FALSE(draft.metrics.uncovered.empty()) << "the wedge is left to the touch-ups";
    const double reach = kTouchUpReachInWidths * request.robot.coverageWidth;

    CoveragePath chained = draft.path, alone = draft.path;
    const CoverageRepairStats withChains =
        repairCoverage(draft.prepared.decomposition, chained, draft.metrics.uncovered, reach, true);
    const CoverageRepairStats withoutChains =
        repairCoverage(draft.prepared.decomposition, alone, draft.metrics.uncovered, reach, false);
    ASSERT_GT(withoutChains.touchUps, 2);
    EXPECT_EQ(withChains.touchUps, withoutChains.touchUps) << "the same strokes";
    EXPECT_GE(withChains.chains, 1);
    EXPECT_EQ(withoutChains.chains, 0);
    EXPECT_LT(withChains.added, withoutChains.added);
    EXPECT_LT(polylineLength(chained.points), polylineLength(alone.points));

    const Metrics a = measurePath(draft.prepared, {}, chained);
    const Metrics b = measurePath(draft.prepared, {}, alone);
    EXPECT_GT(a.coveredArea, draft.metrics.coveredArea);
    EXPECT_GE(a.coveredArea, b.coveredArea - 0.002 * b.requiredArea);
    EXPECT_TRUE(clearOf(draft.prepared.decomposition, chained));
    EXPECT_TRUE(clearOf(draft.prepared.decomposition, alone));
}

// Floor missed along one stretch of wall (a ragged wall's pockets, one after another, where
// the robot fits): the strokes that sweep it lie on one line and overlap, and the chain
// drives them as one stroke from end to end, not up, back a little and up again for each.
TEST(CoverageRepair, OverlappingStrokesAlongOneWallAreDrivenAsOne) {
    PlanRequest request;
    request.plan.boundary = {{0, 0}, {6, 0}, {6, 4}, {0, 4}};
    request.solver = "greedy";
    const PreparedPlans prepared(request.plan, request.robot, true);
    const PlanResult draft = draftCoverage(request, prepared);
    const Decomposition& dec = draft.prepared.decomposition;
    // Clear points 0.35 m from the wall along the sweep frame's x (a stroke through a clear
    // point runs along that axis).
    BoundingBox local;
    for (const Vec2& p : request.plan.boundary)
        local.add(dec.frame.toLocal(p));
    const double lineY = local.minY + 0.35;
    std::vector<Vec2> missed;
    for (double x = local.minX + 1.0; x <= local.minX + 2.45; x += 0.05)
        missed.push_back(dec.frame.toWorld({x, lineY}));
    const double reach = kTouchUpReachInWidths * request.robot.coverageWidth;
    CoveragePath chained = draft.path, alone = draft.path;
    const CoverageRepairStats withChains = repairCoverage(dec, chained, missed, reach, true);
    const CoverageRepairStats withoutChains = repairCoverage(dec, alone, missed, reach, false);
    ASSERT_GE(withoutChains.touchUps, 3) << "several strokes along the wall";
    EXPECT_EQ(withChains.touchUps, withoutChains.touchUps);
    EXPECT_EQ(withChains.chains, 1);
    auto cornersOnTheLine = [&](const CoveragePath& path) {
        int count = 0;
        for (const Vec2& p : path.points)
            count += std::abs(dec.frame.toLocal(p).y - lineY) < 1e-6 ? 1 : 0;
        return count;
    };
    // A lone stroke is W/2 long; the merged one sweeps its run from end to end.
    double longest = 0.0;
    for (std::size_t i = 0; i + 1 < chained.points.size(); ++i) {
        const Vec2 p = dec.frame.toLocal(chained.points[i]);
        const Vec2 q = dec.frame.toLocal(chained.points[i + 1]);
        if (std::abs(p.y - lineY) < 1e-6 && std::abs(q.y - lineY) < 1e-6)
            longest = std::max(longest, distance(p, q));
    }
    EXPECT_GT(longest, 0.9 * request.robot.coverageWidth) << "overlapping strokes driven as one";
    EXPECT_LT(cornersOnTheLine(chained), cornersOnTheLine(alone));
    EXPECT_LT(polylineLength(chained.points), polylineLength(alone.points));
    const Metrics a = measurePath(draft.prepared, {}, chained);
    const Metrics b = measurePath(draft.prepared, {}, alone);
    EXPECT_GE(a.coveredArea, b.coveredArea - 1e-9);
    EXPECT_TRUE(clearOf(dec, chained));
}

// A budget (TouchUpBudget): the strokes that pay best are taken until what stays missed is
// what may stay missed; the ones left out would each have cost more time per square metre
// than the ones taken. A plan that misses a little more than it may no longer gets a hundred
// turns for its last square metre.
TEST(CoverageRepair, ABudgetTakesTheBestPayingStrokesUntilWhatMayStayMissed) {
    const PlanRequest request = laserMap();
    const PreparedPlans prepared(request.plan, request.robot, true);
    const PlanResult draft = draftCoverage(request, prepared);
    const Metrics& before = draft.metrics;
    ASSERT_GT(before.uncovered.size(), 10u);
    const Decomposition& dec = draft.prepared.decomposition;
    const double reach = kTouchUpReachInWidths * request.robot.coverageWidth;

    CoveragePath every = draft.path;
    const CoverageRepairStats all = repairCoverage(dec, every, before.uncovered, reach);
    const Metrics allAfter = measurePath(draft.prepared, {}, every);
    ASSERT_GT(all.touchUps, 4);
    ASSERT_EQ(all.skipped, 0);

    TouchUpBudget budget;
    budget.pointArea = before.uncoveredArea / static_cast<double>(before.uncovered.size());
    budget.missedArea = before.uncoveredArea;
    budget.keepMissed = 0.5 * (before.uncoveredArea + allAfter.uncoveredArea);
    budget.minRate = INFINITY; // nothing beyond what must be swept
    budget.speed = request.robot.speed;
    budget.turnTime = request.robot.turnTime;
    CoveragePath some = draft.path;
    const CoverageRepairStats taken =
        repairCoverage(dec, some, before.uncovered, reach, true, &budget);
    const Metrics someAfter = measurePath(draft.prepared, {}, some);
    EXPECT_GT(taken.touchUps, 0);
    EXPECT_GT(taken.skipped, 0);
    EXPECT_EQ(taken.touchUps + taken.skipped, all.touchUps) << "the same strokes, fewer driven";
    EXPECT_TRUE(clearOf(dec, some));
    // Close to what may stay missed (the strokes' sweep is estimated): below the draft, and
    // within a quarter of the way from it.
    EXPECT_LT(someAfter.uncoveredArea,
              budget.keepMissed + 0.25 * (before.uncoveredArea - budget.keepMissed));
    EXPECT_LT(someAfter.time, allAfter.time);
    // Seconds per square metre swept: the strokes taken pay better than the ones left out.
    const double takenRate =
        (someAfter.time - before.time) / (before.uncoveredArea - someAfter.uncoveredArea);
    const double leftRate =
        (allAfter.time - someAfter.time) / (someAfter.uncoveredArea - allAfter.uncoveredArea);
    EXPECT_LT(takenRate, leftRate);

    // Nothing needed and no stroke pays enough: the path stays as it was.
    budget.keepMissed = before.uncoveredArea;
    CoveragePath none = draft.path;
    const CoverageRepairStats nothing =
        repairCoverage(dec, none, before.uncovered, reach, true, &budget);
    EXPECT_EQ(nothing.touchUps, 0);
    EXPECT_EQ(nothing.skipped, all.touchUps);
    EXPECT_EQ(none.points, draft.path.points);
}
