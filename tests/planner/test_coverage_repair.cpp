// Wall touch-ups (path/CoverageRepair.h): strokes along the walls sweep what the stripes
// leave; strokes that leave from nearly the same place are driven as one chain, shorter than
// each out and back alone, as clear of the walls and sweeping as much.
#include "importers/Import.h"
#include "path/CoverageRepair.h"
#include "pipeline/Planner.h"
#include "pipeline/PreparedPlans.h"

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
